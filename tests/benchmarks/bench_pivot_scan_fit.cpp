// Fit time of a pivot scan against its number of observations:
// pendulum-g's Ceres fit of the physical pendulum (g, k and the centre of
// mass fitted) with the theta0^2/16 amplitude term and no other part, as
// tests/benchmarks/compare_pivot_scan_fit.py fits the same model with scipy's
// curve_fit. Data: a metre stick (k = 0.2889 m, centre 0.5003 m), pivot
// positions uniform in 0.02-0.45 m and 0.55-0.98 m (alternating), amplitudes
// uniform in 2-10 deg, g = 9.81 m/s^2, each period with N(0, 1 ms) noise;
// std::mt19937_64 seed 2026. Start: the analysis's (a straight line in h^2,
// the centre from a grid), computed once outside the timing.
//
//   bench_pivot_scan_fit                Google Benchmark timings
//   bench_pivot_scan_fit --export DIR   writes DIR/scan_N.csv (x m, theta0 rad,
//                                       T s, sigma s) and DIR/fits.json
#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <random>

#include "bench_main.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/period_fit.hpp"
#include "simulations/pivot_scan_simulation.hpp"

namespace {

using pendulum::PhysicalPendulum;
constexpr int kSizes[] = {10, 20, 100, 1000};
constexpr double kG = 9.81, kK = 0.2889, kCenter = 0.5003, kSigma = 1e-3;

struct Scan {
  pendulum::Apparatus<double> apparatus;  // nothing but the body
  std::vector<pendulum::Observation<double>> observations;
  std::vector<pendulum::AmplitudeChoice> amplitude;
  std::vector<double> weights;
  std::array<double, 3> start;

  pendulum::PeriodFitProblem<PhysicalPendulum> problem() const {
    return {&apparatus, &observations, &amplitude, &weights, {true, true, true}};
  }
};

Scan make_scan(int n) {
  Scan s;
  std::mt19937_64 engine(2026);
  const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * ((engine() >> 11) * 0x1.0p-53); };
  pendulum::NormalDeviates noise(2026 + n);
  const double truth[3] = {kG, kK, kCenter};
  const pendulum::AmplitudeChoice small{pendulum::AmplitudeMethod::small_angle, 0, 0.0};
  for (int k = 0; k < n; ++k) {
    const double x = k % 2 ? uniform(0.55, 0.98) : uniform(0.02, 0.45);
    pendulum::Observation<double> o{0.0, x, uniform(2.0, 10.0) * pendulum::kPi / 180.0, 1,
                                    pendulum::Setting::pivot_position};
    o.period = pendulum::model_period<pendulum::PhysicalPendulum>(truth, o, s.apparatus, small) + kSigma * noise.next();
    s.observations.push_back(o);
    s.amplitude.push_back(small);
    s.weights.push_back(1.0 / kSigma);
  }
  // The analysis's start, from a scene of the same observations.
  pendulum::ParsedScene scene;
  scene.model = pendulum::kind_of<pendulum::PhysicalPendulum>();
  scene.observations = s.observations;
  scene.fit = {"radius_of_gyration", "center_of_mass_position"};
  s.start = pendulum::physical_start(scene, {true, true, true});
  return s;
}

void BM_PivotScanFit(benchmark::State& state) {
  const Scan s = make_scan(static_cast<int>(state.range(0)));
  const auto problem = s.problem();
  int iterations = 0;
  for (auto _ : state) iterations = pendulum::fit_periods(problem, s.start).iterations;
  state.counters["iterations"] = iterations;
}
BENCHMARK(BM_PivotScanFit)->Arg(10)->Arg(20)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

int export_data(const std::string& dir) {
  nlohmann::json fits = nlohmann::json::array();
  for (int n : kSizes) {
    const Scan s = make_scan(n);
    std::ofstream csv(dir + "/scan_" + std::to_string(n) + ".csv");
    csv.precision(17);
    for (const auto& o : s.observations) csv << o.length << "," << o.amplitude << "," << o.period << "," << kSigma << "\n";
    const pendulum::PeriodFitSolution f = pendulum::fit_periods(s.problem(), s.start);
    fits.push_back({{"observations", n},
                    {"parameters", f.parameters},
                    {"converged", f.converged},
                    {"start", s.start},
                    {"truth", {kG, kK, kCenter}}});
  }
  std::ofstream(dir + "/fits.json") << fits.dump(2) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return pendulum::bench::main_with_export(argc, argv, export_data); }
