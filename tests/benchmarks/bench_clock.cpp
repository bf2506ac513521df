// Speed against error of the four impulse-error routes of clock.hpp
// (Feinstein 2005, Table 2), in one run.
//
// Scene: Feinstein's 1-second pendulum, semi-amplitude 240', Q = 10 000,
// impulses at 64 locations x = (i + 1/2)/64 of the swing (x = 0.0078 to
// 0.992). Time: CPU ns per call over those 64 locations (CPU time: the
// machine is shared), Google Benchmark repetitions, median. Error: the worst |error| of the impulse error (s/day)
// over the locations against
//  - the undamped circle exactly: Eq. (D-1) in __float128 (Carlson's R_F of
//    tests/quad_reference.hpp on the quad angles);
//  - the damped circle: RK4 at 16384 steps a period (converged to 1e-8
//    s/day, tests/test_clock.cpp).
// The cycloid routes stand for the circle at equal energy.
//
// Run (the table in docs/clock.md comes from this command):
//   build/tests/benchmarks/bench_clock --benchmark_repetitions=5 \
//       --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "../quad_reference.hpp"
#include "pendulum/clock.hpp"

namespace {

using pendulum::ClockPath;
using pendulum::ClockRoute;
using pendulum::kPi;
using pendulum::test::Quad;

constexpr double kTheta0 = 240.0 * kPi / 10800.0;  // rad
constexpr double kQ = 1e4;
constexpr int kLocations = 64;

std::vector<double> locations() {
  std::vector<double> v;
  for (int i = 0; i < kLocations; ++i) v.push_back((i + 0.5) / kLocations * kTheta0);
  return v;
}

/// Eq. (D-1) in quad precision, normalised as impulse_error_elliptic.
double elliptic_quad(double theta0_d, double theta_d, double q_d) {
  const Quad theta0 = theta0_d, theta = theta_d, q = q_d;
  const Quad k = sinq(theta0 / 2), s = sinq(theta / 2), c = cosq(theta / 2);
  const Quad eps = M_PIq / q, k2 = k * k, ki2 = (1 + eps) * k2;
  const Quad d = sinq((theta0 - theta) / 2) * sinq((theta0 + theta) / 2), di = d + eps * k2;
  const Quad f = s / k * pendulum::test::carlson_rf_quad(d / k2, c * c, 1);
  const Quad fi = s / sqrtq(ki2) * pendulum::test::carlson_rf_quad(di / ki2, c * c, 1);
  const Quad ratio = pendulum::test::delta_ratio_quad(theta0_d * 180.0 / kPi);
  return static_cast<double>(86400 / (M_PIq * (1 + ratio)) * (f - fi));
}

struct Route {
  std::string name;
  std::function<double(double)> error;  // s/day at a location (rad)
};

std::vector<Route> routes() {
  auto route = [](ClockRoute r, int steps) {
    return [r, steps](double theta) {
      return pendulum::impulse_error(r, ClockPath::circular, kTheta0, theta, kQ, steps).error;
    };
  };
  return {
      {"cycloid (App. H)", route(ClockRoute::cycloid, 0)},
      {"circular_elliptic (D-1)", route(ClockRoute::circular_elliptic, 0)},
      {"cycloid_damped (App. I)", route(ClockRoute::cycloid_damped, 0)},
      {"circular_rk4, 64 steps", route(ClockRoute::circular_rk4, 64)},
      {"circular_rk4, 256 steps", route(ClockRoute::circular_rk4, 256)},
      {"circular_rk4, 1024 steps", route(ClockRoute::circular_rk4, 1024)},
  };
}

class MedianCollector : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> median_ns;
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.aggregate_name == "median" || (run.aggregate_name.empty() && !median_ns.count(run.run_name.str()))) {
        median_ns[run.run_name.str()] = run.GetAdjustedCPUTime() / kLocations;
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }
};

}  // namespace

int main(int argc, char** argv) {
  const std::vector<Route> all = routes();
  const std::vector<double> where = locations();
  for (const Route& r : all) {
    benchmark::RegisterBenchmark(r.name.c_str(), [&r, &where](benchmark::State& state) {
      for (auto _ : state) {
        for (double theta : where) benchmark::DoNotOptimize(r.error(theta));
      }
    })->Unit(benchmark::kNanosecond);
  }
  benchmark::Initialize(&argc, argv);
  MedianCollector times;
  benchmark::RunSpecifiedBenchmarks(&times);

  std::vector<double> exact, damped;
  for (double theta : where) {
    exact.push_back(elliptic_quad(kTheta0, theta, kQ));
    damped.push_back(pendulum::impulse_error_rk4(kTheta0, theta, kQ, 16384).error);
  }
  std::printf("\n| route | ns/call (median) | worst error vs undamped circle (s/day) | worst error vs damped circle "
              "(s/day) |\n|---|---:|---:|---:|\n");
  for (const Route& r : all) {
    double worst_exact = 0.0, worst_damped = 0.0;
    for (int i = 0; i < kLocations; ++i) {
      const double v = r.error(where[i]);
      worst_exact = std::fmax(worst_exact, std::fabs(v - exact[i]));
      worst_damped = std::fmax(worst_damped, std::fabs(v - damped[i]));
    }
    std::printf("| %s | %.0f | %.1e | %.1e |\n", r.name.c_str(), times.median_ns.at(r.name), worst_exact,
                worst_damped);
  }
  return 0;
}
