// Measures how often g's reported uncertainty covers the true g under rules
// for scaling it by the Birge ratio S = sqrt(chi2/dof), on seeded series and
// pivot scans whose stated uncertainties are right, or three times too small
// (the noise drawn as simulated, the stated sigmas divided by 3). The choice
// of kOverDispersedProbability (dispersion.hpp, docs/output.md) rests on it.
// Each rule's uncertainty is sqrt(sigma^2 + (f^2 - 1) sigma_obs^2), sigma and
// sigma_obs the fit's unscaled and observations' own (scaled_uncertainty):
//   none: f = 1;  always: f = S;  pdg: f = max(1, S);
//   p<P: f = max(1, S) when chi2's probability is below P, else 1.
//
// Usage: chi2_coverage [N]   (N seeds per case, default 400)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "pendulum/reduce_scene.hpp"
#include "pendulum/dispersion.hpp"
#include "simulations/pivot_scan_simulation.hpp"
#include "simulations/series_simulation.hpp"
#include "simulated_scans.hpp"

using namespace pendulum;

namespace {

constexpr double kDeg = kPi / 180.0;

/// The series of tests/test_series.cpp (lengths_series) at `n` lengths from 0.5 m to 3 m.
SeriesSimulation series(int n, std::uint64_t seed) {
  SeriesSimulation sim;
  sim.g = 9.8034;
  sim.length_offset = 0.0305;
  for (int i = 0; i < n; ++i) sim.lengths.push_back(0.5 + 2.5 * i / (n - 1));
  sim.amplitudes.assign(sim.lengths.size(), 3.0 * kDeg);
  sim.period_sigma = 2e-4;
  sim.length_sigma = 5e-4;
  sim.amplitude_sigma = 0.3 * kDeg;
  sim.seed = seed;
  return sim;
}

struct Rule {
  const char* name;
  std::function<double(const Dispersion&)> factor;
};

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 400;
  const std::vector<Rule> rules = {
      {"none", [](const Dispersion&) { return 1.0; }},
      {"always", [](const Dispersion& d) { return *d.birge_ratio; }},
      {"pdg", [](const Dispersion& d) { return std::max(1.0, *d.birge_ratio); }},
      {"p<0.05", [](const Dispersion& d) { return *d.probability < 0.05 ? std::max(1.0, *d.birge_ratio) : 1.0; }},
      {"p<0.01", [](const Dispersion& d) { return *d.probability < 0.01 ? std::max(1.0, *d.birge_ratio) : 1.0; }},
      {"p<0.001", [](const Dispersion& d) { return *d.probability < 1e-3 ? std::max(1.0, *d.birge_ratio) : 1.0; }},
  };
  struct Case {
    std::string name;
    std::function<ParsedScene(std::uint64_t)> scene;
    double truth;
  };
  const std::vector<Case> cases = {
      {"series, 6 lengths (dof 4)", [](std::uint64_t s) { return simulate_series({}, series(6, s)); }, 9.8034},
      {"series, 10 lengths (dof 8)", [](std::uint64_t s) { return simulate_series({}, series(10, s)); }, 9.8034},
      {"pivot scan, 18 holes (dof 15)", [](std::uint64_t s) { return simulate_pivot_scan({}, test::metre_stick(s)); }, 9.8034},
  };
  std::printf("%-30s %-11s", "case", "stated");
  for (const Rule& r : rules) std::printf(" %8s", r.name);
  std::printf("   (coverage of +-1 sigma over %d seeds; binomial sd at 0.683: %.3f)\n", n,
              std::sqrt(0.6827 * 0.3173 / n));
  for (const Case& c : cases) {
    for (const double understated : {1.0, 3.0}) {
      std::vector<int> in(rules.size(), 0);
      for (int s = 0; s < n; ++s) {
        ParsedScene scene = c.scene(5000 + s);
        test::understate(scene, understated);
        const Analysis a = reduce_scene(scene);
        const Dispersion d = dispersion(a.fit.chi2, a.fit.dof);
        const double sigma = *a.g_uncertainty_unscaled, own = *a.fit.parameters[0].uncertainty_from_observations;
        for (std::size_t r = 0; r < rules.size(); ++r) {
          in[r] += std::abs(a.g.value - c.truth) <= scaled_uncertainty(sigma, own, rules[r].factor(d));
        }
      }
      std::printf("%-30s %-11s", c.name.c_str(), understated == 1.0 ? "right" : "3x too small");
      for (int k : in) std::printf(" %8.3f", static_cast<double>(k) / n);
      std::printf("\n");
    }
  }
}
