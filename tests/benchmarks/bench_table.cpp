// A 10^4-row table of lengths and times of 10 oscillations (2000 lengths,
// 5 repeats each), read and reduced, against the same series given as a
// scene's JSON (docs/series.md, "Tables"): the table route's cost is the
// table reader's stages and the grouping, the JSON route's the JSON parser.
// Run: build/tests/benchmarks/bench_table --benchmark_repetitions=7 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include "pendulum/reduce_scene.hpp"
#include "pendulum/json/scene_json.hpp"

namespace {

constexpr int kLengths = 2000, kRepeats = 5;

/// The table's folder (written once) and the same series as a scene's JSON.
struct Data {
  std::string directory, json;
};

const Data& data() {
  static const Data d = [] {
    Data out;
    out.directory = (std::filesystem::temp_directory_path() / "pendulum_bench_table").string();
    std::filesystem::create_directories(out.directory);
    std::ofstream table(out.directory + "/lengths.csv");
    table << "L (cm),t10 (s)\n";
    std::mt19937_64 rng(2026);
    std::normal_distribution<double> hand(0.0, 0.06);
    nlohmann::json observations = nlohmann::json::array();
    char line[64];
    for (int k = 0; k < kLengths; ++k) {
      const double l = 30.0 + 170.0 * k / kLengths;  // cm
      std::vector<double> trials;
      for (int r = 0; r < kRepeats; ++r) {
        const double t = std::round((10.0 * 2.0 * M_PI * std::sqrt(l / 100.0 / 9.81) + hand(rng)) * 100.0) / 100.0;
        std::snprintf(line, sizeof line, "%.4f,%.2f\n", l, t);
        table << line;
        trials.push_back(std::stod(std::strchr(line, ',') + 1));
      }
      observations.push_back({{"length", {{"value", std::stod(line)}, {"unit", "cm"}}},
                              {"timing", {{"oscillations_per_trial", 10}, {"unit", "s"}, {"trials", trials}}}});
    }
    out.json = nlohmann::json{{"amplitude", "not recorded"}, {"observations", observations}}.dump();
    return out;
  }();
  return d;
}

void BM_TableReadAndReduce(benchmark::State& state) {
  const Data& d = data();
  const std::string scene = R"({"amplitude": "not recorded", "observations": {"table": "lengths.csv"}})";
  pendulum::SceneFiles files;
  files.directory = d.directory;
  for (auto _ : state) benchmark::DoNotOptimize(pendulum::reduce_scene(pendulum::parse_scene(scene, files)).g.value);
}
BENCHMARK(BM_TableReadAndReduce)->Unit(benchmark::kMillisecond);

void BM_JsonReadAndReduce(benchmark::State& state) {
  const Data& d = data();
  for (auto _ : state) benchmark::DoNotOptimize(pendulum::reduce_scene(pendulum::parse_scene(d.json)).g.value);
}
BENCHMARK(BM_JsonReadAndReduce)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
