#pragma once
/// \file pivot_scan_simulation.hpp
/// \brief Synthetic pivot scans of a rigid body (a metre stick, Kater's
/// reversible pendulum) from the physical pendulum's period model with
/// Gaussian noise, seeded and identical on every platform, for tests and
/// data/ (docs/physical.md).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "simulations/decay_simulation.hpp"
#include "pendulum/models/registry.hpp"
#include "pendulum/parsed_scene.hpp"
#include "simulations/series_simulation.hpp"

namespace pendulum {

/// What a simulated pivot scan is drawn from.
struct PivotScanSimulation {
  double g;                        ///< true g (m/s^2)
  double radius_of_gyration;       ///< true k (m)
  double center_of_mass_position;  ///< true x_c (m), in the frame of the pivot positions
  std::vector<double> pivot_positions;  ///< true pivot positions (m), one per observation
  std::vector<double> amplitudes;       ///< true amplitudes (rad), one per observation
  double period_sigma;     ///< standard deviation of each mean period (s)
  double position_sigma;   ///< of each recorded pivot position (m)
  double amplitude_sigma;  ///< of each recorded amplitude (rad)
  /// A centre located roughly (Kater): recorded as the truth plus
  /// N(0, center_sigma) and held in the fit; empty: fitted.
  std::optional<double> center_sigma;
  std::uint64_t seed;  ///< NormalDeviates seed; draws: period, position, amplitude per observation, then the centre
  bool noise = true;   ///< false: the recorded values are the true ones
};

/// A pivot-scan scene of `app` drawn from `sim`: each period from the model
/// at the truth (exact amplitude factor) plus N(0, period_sigma), each
/// recorded position and amplitude the true one plus its noise; the stated
/// uncertainties are the noise's standard deviations. The scene fits k, and
/// the centre unless it is measured.
inline ParsedScene simulate_pivot_scan(const Apparatus<double>& app, const PivotScanSimulation& sim) {
  using M = PhysicalPendulum;
  ParsedScene scene;
  scene.model = kind_of<PhysicalPendulum>();
  scene.apparatus = app;
  scene.apparatus_uncertainty = convert_apparatus<double>(app, [](const Field&, double) { return 0.0; });
  scene.series = true;
  scene.fit = {"radius_of_gyration"};
  if (!sim.center_sigma) scene.fit.push_back("center_of_mass_position");
  NormalDeviates noise(sim.seed);
  const double scale = sim.noise ? 1.0 : 0.0;
  double p[M::kParameters];
  p[M::g] = sim.g;
  p[M::radius_of_gyration] = sim.radius_of_gyration;
  p[M::center_of_mass_position] = sim.center_of_mass_position;
  Apparatus<double> truth_app = app;
  if (truth_app.body) truth_app.body->center_of_mass_position.reset();  // the truth's centre is p's
  for (std::size_t k = 0; k < sim.pivot_positions.size(); ++k) {
    Observation<double> truth{0.0, sim.pivot_positions[k], sim.amplitudes[k], 1, Setting::pivot_position};
    truth.period = model_period<PhysicalPendulum>(p, truth, truth_app, cheapest_amplitude_method(truth.amplitude, 0.0));
    Observation<double> recorded = truth;
    recorded.period += scale * sim.period_sigma * noise.next();
    recorded.length += scale * sim.position_sigma * noise.next();
    recorded.amplitude += scale * sim.amplitude_sigma * noise.next();
    scene.observations.push_back(recorded);
    scene.observation_uncertainties.push_back(
        {sim.period_sigma, sim.position_sigma, sim.amplitude_sigma, 1, Setting::pivot_position});
    scene.sources.push_back({"observations[" + std::to_string(k) + "].", 1, recorded.amplitude, "rad"});
  }
  if (sim.center_sigma) {
    auto& body = scene.apparatus.body ? *scene.apparatus.body : scene.apparatus.body.emplace();
    auto& sigma = scene.apparatus_uncertainty.body ? *scene.apparatus_uncertainty.body
                                                   : scene.apparatus_uncertainty.body.emplace();
    body.center_of_mass_position = sim.center_of_mass_position + scale * *sim.center_sigma * noise.next();
    sigma.center_of_mass_position = *sim.center_sigma;
  }
  return scene;
}

}  // namespace pendulum
