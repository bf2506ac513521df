// Cost of one reduction of the Nelson-Olsson scene, next to parsing its JSON
// alone. Run: build/tests/benchmarks/bench_reduce
#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>


#include "pendulum/reduce_scene.hpp"
#include "pendulum/json/output.hpp"
#include "pendulum/json/scene_json.hpp"
#include "scene_files.hpp"

namespace {

void BM_ParseJsonOnly(benchmark::State& state) {
  const std::string text = pendulum::test::nelson_olsson_text();
  for (auto _ : state) benchmark::DoNotOptimize(nlohmann::json::parse(text));
}
BENCHMARK(BM_ParseJsonOnly);

void BM_ReduceDouble(benchmark::State& state) {
  const pendulum::ParsedScene scene = pendulum::parse_scene(pendulum::test::nelson_olsson_text());
  for (auto _ : state) benchmark::DoNotOptimize(pendulum::reduce(scene.apparatus, scene.observations.front()));
}
BENCHMARK(BM_ReduceDouble);

void BM_ParseScene(benchmark::State& state) {
  const std::string text = pendulum::test::nelson_olsson_text();
  for (auto _ : state) benchmark::DoNotOptimize(pendulum::parse_scene(text));
}
BENCHMARK(BM_ParseScene);

void BM_Analyse(benchmark::State& state) {
  const pendulum::ParsedScene scene = pendulum::parse_scene(pendulum::test::nelson_olsson_text());
  for (auto _ : state) benchmark::DoNotOptimize(pendulum::reduce_scene(scene));
}
BENCHMARK(BM_Analyse);

void BM_WriteJson(benchmark::State& state) {
  const pendulum::ParsedScene scene = pendulum::parse_scene(pendulum::test::nelson_olsson_text());
  const pendulum::AnalysisOptions options;
  const pendulum::Analysis analysis = pendulum::reduce_scene(scene, options);
  for (auto _ : state) {
    benchmark::DoNotOptimize(pendulum::result_json(scene, analysis, options, "-"));
  }
}
BENCHMARK(BM_WriteJson);

void BM_WholeReduction(benchmark::State& state) {
  const std::string text = pendulum::test::nelson_olsson_text();
  const pendulum::AnalysisOptions options;
  for (auto _ : state) {
    const pendulum::ParsedScene scene = pendulum::parse_scene(text);
    const pendulum::Analysis analysis = pendulum::reduce_scene(scene, options);
    benchmark::DoNotOptimize(pendulum::result_json(scene, analysis, options, "-", -1));
  }
}
BENCHMARK(BM_WholeReduction);

}  // namespace

BENCHMARK_MAIN();
