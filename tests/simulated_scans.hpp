#pragma once
// Simulated scenes shared by the tests and tools/chi2_coverage.cpp.
#include <cmath>
#include <cstdint>

#include "pendulum/reduce_scene.hpp"
#include "pendulum/bodies.hpp"
#include "pendulum/parsed_scene.hpp"
#include "simulations/pivot_scan_simulation.hpp"

namespace pendulum::test {

/// A metre stick (1 m by 28 mm, k = sqrt((L^2 + w^2)/12) = 0.28890 m) hung
/// at 18 holes 5 cm apart, 5 deg, a stopwatch's 0.5 ms on each mean period,
/// 0.5 mm on each position, 0.5 deg on each amplitude.
inline PivotScanSimulation metre_stick(std::uint64_t seed) {
  constexpr double kDegree = kPi / 180.0;
  PivotScanSimulation sim;
  sim.g = 9.8034;
  sim.radius_of_gyration = std::sqrt(box(1.0, 0.028, 0.006).gyration_squared);
  sim.center_of_mass_position = 0.5003;
  for (int i = 1; i <= 19; ++i) {
    if (i != 10) sim.pivot_positions.push_back(0.05 * i);
  }
  sim.amplitudes.assign(sim.pivot_positions.size(), 5.0 * kDegree);
  sim.period_sigma = 5e-4;
  sim.position_sigma = 5e-4;
  sim.amplitude_sigma = 0.5 * kDegree;
  sim.seed = seed;
  return sim;
}

/// Every observation's stated uncertainties (period, setting, amplitude)
/// divided by `factor`, the noise left as drawn: understated uncertainties.
inline void understate(ParsedScene& scene, double factor) {
  for (auto& u : scene.observation_uncertainties) u.period /= factor, u.length /= factor, u.amplitude /= factor;
}

struct Coverage {
  int scaled = 0;    ///< times g +- its reported uncertainty held the truth
  int unscaled = 0;  ///< ... +- the uncertainty from the stated ones alone
};

/// Over the scenes scene_of(0) ... scene_of(n - 1), their stated
/// uncertainties divided by `factor`: how often g's interval holds `truth`.
template <class SceneOf>
Coverage coverage_of_g(SceneOf scene_of, int n, double truth, double factor) {
  Coverage c;
  for (int k = 0; k < n; ++k) {
    ParsedScene scene = scene_of(k);
    understate(scene, factor);
    const Analysis a = reduce_scene(scene);
    c.scaled += std::abs(a.g.value - truth) <= *a.g.uncertainty;
    c.unscaled += std::abs(a.g.value - truth) <= *a.g_uncertainty_unscaled;
  }
  return c;
}

}  // namespace pendulum::test
