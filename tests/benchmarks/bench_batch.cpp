// Throughput of a class's worth of scenes: 10 000 variations of the
// Nelson-Olsson scene (lengths, trials, amplitudes, bob diameters drawn with
// seed 2026), and 1 000 of its decay-record version, side by side with
// parsing their JSON alone. Run: build/tests/benchmarks/bench_batch
// Items per second = scenes per second.
#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <thread>

#include "pendulum/reduce_scene.hpp"
#include "simulations/decay_simulation.hpp"
#include "pendulum/json/output.hpp"
#include "pendulum/json/scene_json.hpp"

namespace {

std::string read(const std::string& name) {
  std::ifstream in(std::string(PENDULUM_DATA_DIR) + "/" + name);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> make_scenes(const std::string& base, int count) {
  pendulum::NormalDeviates noise(2026);
  const auto scene = nlohmann::json::parse(base);
  std::vector<std::string> out;
  for (int i = 0; i < count; ++i) {
    auto s = scene;
    s["length"]["value"] = 3.0044 + 0.002 * noise.next();
    s["amplitude"]["value"] = 3.0 + 0.5 * noise.next();
    s["bob"]["diameter"]["value"] = 6.10 + 0.02 * noise.next();
    for (auto& t : s["timing"]["trials"]) t = t.get<double>() + 0.05 * noise.next();
    out.push_back(s.dump(2));
  }
  return out;
}

const std::vector<std::string>& plain_scenes() {
  static const std::vector<std::string> scenes = make_scenes(read("nelson_olsson_1986.json"), 10000);
  return scenes;
}
const std::vector<std::string>& decay_scenes() {
  static const std::vector<std::string> scenes = make_scenes(read("nelson_olsson_1986_decay.json"), 1000);
  return scenes;
}

/// Everything `pendulum-g batch` does for one scene but the file read.
std::string whole(const std::string& text) {
  const pendulum::ParsedScene scene = pendulum::parse_scene(text);
  return pendulum::batch_line("-", scene, pendulum::reduce_scene(scene)).text;
}

template <class F>
void over_scenes(benchmark::State& state, const std::vector<std::string>& scenes, F&& f, unsigned threads) {
  for (auto _ : state) {
    std::vector<std::thread> pool;
    for (unsigned k = 0; k < threads; ++k) {
      pool.emplace_back([&, k] {
        for (std::size_t i = k; i < scenes.size(); i += threads) benchmark::DoNotOptimize(f(scenes[i]));
      });
    }
    for (auto& t : pool) t.join();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * scenes.size()));
}

void BM_ParseJsonOnly(benchmark::State& state) {
  over_scenes(state, plain_scenes(), [](const std::string& t) { return nlohmann::json::parse(t); }, 1);
}
void BM_ParseScene(benchmark::State& state) {
  over_scenes(state, plain_scenes(), [](const std::string& t) { return pendulum::parse_scene(t); }, 1);
}
void BM_Analyse(benchmark::State& state) {
  std::vector<pendulum::ParsedScene> parsed;
  for (const auto& t : plain_scenes()) parsed.push_back(pendulum::parse_scene(t));
  for (auto _ : state) {
    for (const auto& p : parsed) benchmark::DoNotOptimize(pendulum::reduce_scene(p));
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * parsed.size()));
}
void BM_Whole(benchmark::State& state) {
  over_scenes(state, plain_scenes(), whole, static_cast<unsigned>(state.range(0)));
}
void BM_WholeWithDecayFit(benchmark::State& state) {
  over_scenes(state, decay_scenes(), whole, static_cast<unsigned>(state.range(0)));
}
void BM_DecayFitOnly(benchmark::State& state) {
  const pendulum::ParsedScene scene = pendulum::parse_scene(decay_scenes().front());
  for (auto _ : state) benchmark::DoNotOptimize(pendulum::fit_decay(*scene.decay_data));
  state.SetItemsProcessed(state.iterations());
}

BENCHMARK(BM_ParseJsonOnly)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ParseScene)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Analyse)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Whole)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_WholeWithDecayFit)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DecayFitOnly)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
