// Fit time of Eq. (25) against the number of points, pendulum-g's fit beside
// the textbook Ceres set-up (one automatically differentiated block per
// point). Data: 3 hours of Eq. (25) at the paper's alpha, beta (Eqs. 28-29),
// theta0m = 17.5 deg, sigma = 0.3 deg, seed 2026.
//
//   bench_decay_fit                      Google Benchmark timings
//   bench_decay_fit --export DIR         writes DIR/decay_N.csv (t s, theta rad,
//                                        sigma rad) and DIR/fits.json (our fit
//                                        and the truth) for the scipy comparison
// tests/benchmarks/compare_decay_fit.py runs both and scipy in one go.
#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <fstream>

#include "../textbook_decay_fit.hpp"
#include "bench_main.hpp"
#include "simulations/decay_simulation.hpp"

namespace {

constexpr double kDeg = pendulum::kPi / 180.0;
constexpr int kSizes[] = {10, 100, 1000, 10000, 100000};

pendulum::DecaySimulation simulation(int points) {
  return {2.49e-4, 3.17e-3, 17.5 * kDeg, 0.3 * kDeg, 10800.0, points, 2026};
}

void BM_PendulumFit(benchmark::State& state) {
  const pendulum::DecayData d = pendulum::simulate_decay(simulation(static_cast<int>(state.range(0))));
  for (auto _ : state) benchmark::DoNotOptimize(pendulum::fit_decay(d));
}
BENCHMARK(BM_PendulumFit)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);

void BM_TextbookCeres(benchmark::State& state) {
  const pendulum::DecaySimulation sim = simulation(static_cast<int>(state.range(0)));
  const pendulum::DecayData d = pendulum::simulate_decay(sim);
  for (auto _ : state) {
    benchmark::DoNotOptimize(pendulum::test::textbook_decay_fit(d, {sim.alpha, sim.beta, sim.theta0m}));
  }
}
BENCHMARK(BM_TextbookCeres)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);

int export_data(const std::string& dir) {
  nlohmann::json fits = nlohmann::json::array();
  for (int n : kSizes) {
    const pendulum::DecaySimulation sim = simulation(n);
    const pendulum::DecayData d = pendulum::simulate_decay(sim);
    std::ofstream csv(dir + "/decay_" + std::to_string(n) + ".csv");
    csv.precision(17);
    for (std::size_t i = 0; i < d.times.size(); ++i) {
      csv << d.times[i] << "," << d.amplitudes[i] << "," << d.sigmas[i] << "\n";
    }
    const pendulum::DecayFit f = pendulum::fit_decay(d, {pendulum::DecayModel::both});
    fits.push_back({{"points", n},
                    {"alpha", f.alpha.value},
                    {"beta", f.beta.value},
                    {"theta0m", f.initial_amplitude.value},
                    {"alpha_uncertainty", *f.alpha.uncertainty},
                    {"beta_uncertainty", *f.beta.uncertainty},
                    {"truth", {{"alpha", sim.alpha}, {"beta", sim.beta}, {"theta0m", sim.theta0m}}}});
  }
  std::ofstream(dir + "/fits.json") << fits.dump(2) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return pendulum::bench::main_with_export(argc, argv, export_data); }
