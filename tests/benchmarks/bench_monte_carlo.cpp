// GUM Supplement 1's Monte Carlo (issue 40): a fixed number of draws through
// the whole reduction, for Nelson & Olsson's scene (the closed form per
// draw) and for a series of ten lengths (a refit per draw). The call is
// timed whole: where S1 8 does not validate GUM's interval, the search for
// the input that bends g redraws the same number up to three times more
// (Nelson & Olsson's: once, for the period; the series: once, for the
// periods together).
// Run: build/tests/benchmarks/bench_monte_carlo --benchmark_min_time=0
#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <cmath>

#include "pendulum/analysis.hpp"
#include "pendulum/monte_carlo.hpp"
#include "pendulum/numeric.hpp"
#include "pendulum/json/scene_json.hpp"
#include "scene_files.hpp"

namespace {

/// Ten lengths from 0.3 to 1.2 m, each five trials of ten oscillations
/// (t with 4 dof), the length +- 0.5 mm, the amplitude 5 +- 0.5 deg.
std::string ten_lengths() {
  nlohmann::json observations = nlohmann::json::array();
  for (int k = 0; k < 10; ++k) {
    const double l = 0.3 + 0.1 * k, t = 20.0 * pendulum::kPi * std::sqrt(l / 9.81);
    observations.push_back({{"length", {{"value", l}, {"uncertainty", 0.0005}, {"unit", "m"}}},
                            {"amplitude", {{"value", 5.0}, {"uncertainty", 0.5}, {"unit", "deg"}}},
                            {"timing",
                             {{"oscillations_per_trial", 10},
                              {"unit", "s"},
                              {"trials", {t - 0.08, t + 0.05, t - 0.02, t + 0.11, t - 0.04}}}}});
  }
  return nlohmann::json{{"schema", "pendulum-g/scene/1"}, {"observations", observations}}.dump();
}

void run(benchmark::State& state, const std::string& text) {
  const pendulum::ParsedScene scene = pendulum::parse_scene(text);
  const pendulum::Analysis analysis = pendulum::analyse(scene);
  const long draws = state.range(0);
  for (auto _ : state) {
    benchmark::DoNotOptimize(pendulum::monte_carlo(scene, analysis, pendulum::MonteCarloOptions{1, draws}));
  }
}

void BM_MonteCarloNelsonOlsson(benchmark::State& state) { run(state, pendulum::test::nelson_olsson_text()); }
BENCHMARK(BM_MonteCarloNelsonOlsson)->Arg(1000000)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_MonteCarloTenLengths(benchmark::State& state) { run(state, ten_lengths()); }
BENCHMARK(BM_MonteCarloTenLengths)->Arg(10000)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
