// Fit time of a series against its number of observations: pendulum-g's
// Ceres fit of the simple pendulum with a length offset and the theta0^2/16
// amplitude term (no other part), as tests/benchmarks/compare_series_fit.py
// fits the same model with scipy's curve_fit. Data: lengths uniform in
// 0.3-2 m, amplitudes uniform in 2-10 deg, g = 9.81 m/s^2, offset 12 mm,
// each period with N(0, 1 ms) noise; std::mt19937_64 seed 2026.
//
//   bench_series_fit                    Google Benchmark timings
//   bench_series_fit --export DIR       writes DIR/series_N.csv (L m, theta0 rad,
//                                       T s, sigma s) and DIR/fits.json
#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <random>

#include "bench_main.hpp"
#include "pendulum/period_fit.hpp"
#include "simulations/series_simulation.hpp"

namespace {

constexpr int kSizes[] = {10, 100, 1000, 10000};
constexpr double kG = 9.81, kOffset = 0.012, kSigma = 1e-3;

struct Series {
  pendulum::Apparatus<double> apparatus;  // nothing but the pendulum
  std::vector<pendulum::Observation<double>> observations;
  std::vector<pendulum::AmplitudeChoice> amplitude;
  std::vector<double> weights;
  std::array<double, 2> start;  // g from T^2 against L through the origin, offset 0

  pendulum::PeriodFitProblem<pendulum::SimplePendulum> problem() const {
    return {&apparatus, &observations, &amplitude, &weights, {true, true}};
  }
};

Series make_series(int n) {
  Series s;
  std::mt19937_64 engine(2026);
  const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * ((engine() >> 11) * 0x1.0p-53); };
  pendulum::NormalDeviates noise(2026 + n);
  const double truth[2] = {kG, kOffset};
  double sxx = 0.0, sxy = 0.0;
  for (int k = 0; k < n; ++k) {
    pendulum::Observation<double> o{0.0, uniform(0.3, 2.0), uniform(2.0, 10.0) * pendulum::kPi / 180.0, 1};
    const pendulum::AmplitudeChoice small{pendulum::AmplitudeMethod::small_angle, 0, 0.0};
    o.period = pendulum::model_period(truth, o, s.apparatus, small) + kSigma * noise.next();
    s.observations.push_back(o);
    s.amplitude.push_back(small);
    s.weights.push_back(1.0 / kSigma);
    sxx += o.length * o.length;
    sxy += o.length * o.period * o.period;
  }
  s.start = {4.0 * pendulum::kPi * pendulum::kPi * sxx / sxy, 0.0};
  return s;
}

void BM_SeriesFit(benchmark::State& state) {
  const Series s = make_series(static_cast<int>(state.range(0)));
  const auto problem = s.problem();
  int iterations = 0;
  for (auto _ : state) iterations = pendulum::fit_periods(problem, s.start).iterations;
  state.counters["iterations"] = iterations;
}
BENCHMARK(BM_SeriesFit)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

int export_data(const std::string& dir) {
  nlohmann::json fits = nlohmann::json::array();
  for (int n : kSizes) {
    const Series s = make_series(n);
    std::ofstream csv(dir + "/series_" + std::to_string(n) + ".csv");
    csv.precision(17);
    for (const auto& o : s.observations) csv << o.length << "," << o.amplitude << "," << o.period << "," << kSigma << "\n";
    const pendulum::PeriodFitSolution f = pendulum::fit_periods(s.problem(), s.start, /*with_covariance=*/true);
    fits.push_back({{"observations", n},
                    {"g", f.parameters[0]},
                    {"length_offset", f.parameters[1]},
                    {"g_uncertainty", std::sqrt(f.covariance.at(0))},
                    {"length_offset_uncertainty", std::sqrt(f.covariance.at(3))},
                    {"converged", f.converged},
                    {"start", s.start},
                    {"truth", {{"g", kG}, {"length_offset", kOffset}}}});
  }
  std::ofstream(dir + "/fits.json") << fits.dump(2) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return pendulum::bench::main_with_export(argc, argv, export_data); }
