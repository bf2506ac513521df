#pragma once
/// \file series_simulation.hpp
/// \brief Synthetic series of observations from the simple pendulum's period
/// model with Gaussian noise, seeded and identical on every platform, for
/// tests, benchmarks and data/.

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "simulations/decay_simulation.hpp"
#include "pendulum/models/simple_pendulum.hpp"
#include "pendulum/parsed_scene.hpp"

namespace pendulum {

/// What a simulated series is drawn from.
struct SeriesSimulation {
  double g;              ///< true g (m/s^2)
  double length_offset;  ///< true offset (m) added to every length
  std::vector<double> lengths;     ///< true measured lengths (m), one per observation
  std::vector<double> amplitudes;  ///< true amplitudes (rad), one per observation
  double period_sigma;     ///< standard deviation of each mean period (s)
  double length_sigma;     ///< of each recorded length (m)
  double amplitude_sigma;  ///< of each recorded amplitude (rad)
  std::uint64_t seed;      ///< NormalDeviates seed; the draws go period, length, amplitude per observation
  bool noise = true;       ///< false: the recorded values are the true ones
  bool fit_offset = true;  ///< the scene's "fit" holds length_offset
};

/// The period `Model` predicts at parameters p for `o`, whose own period
/// sets the corrections' working frequency (observation.hpp): the fixed
/// point T = predict(p, o with period T), reached to rounding in a few steps
/// from 1 s since T enters only second-order terms.
template <class Model = SimplePendulum>
double model_period(const double* p, Observation<double> o, const Apparatus<double>& app,
                    const AmplitudeChoice& amplitude) {
  o.period = 1.0;
  for (int i = 0; i < 16; ++i) {
    const double next = Model::predict(p, o, app, amplitude).period;
    if (next == o.period) break;
    o.period = next;
  }
  return o.period;
}

/// A series scene of `app` drawn from `sim`: each period from the model at
/// the truth (exact amplitude factor) plus N(0, period_sigma), each recorded
/// length and amplitude the true one plus its noise; the stated
/// uncertainties are the noise's standard deviations.
inline ParsedScene simulate_series(const Apparatus<double>& app, const SeriesSimulation& sim) {
  ParsedScene scene;
  scene.apparatus = app;
  scene.apparatus_uncertainty = convert_apparatus<double>(app, [](const Field&, double) { return 0.0; });
  scene.series = true;
  if (sim.fit_offset) scene.fit = {"length_offset"};
  NormalDeviates noise(sim.seed);
  const double p[2] = {sim.g, sim.length_offset};
  const double scale = sim.noise ? 1.0 : 0.0;
  for (std::size_t k = 0; k < sim.lengths.size(); ++k) {
    Observation<double> truth{0.0, sim.lengths[k], sim.amplitudes[k], 1};
    truth.period = model_period(p, truth, app, cheapest_amplitude_method(truth.amplitude, 0.0));
    Observation<double> recorded = truth;
    recorded.period += scale * sim.period_sigma * noise.next();
    recorded.length += scale * sim.length_sigma * noise.next();
    recorded.amplitude += scale * sim.amplitude_sigma * noise.next();
    scene.observations.push_back(recorded);
    scene.observation_uncertainties.push_back({sim.period_sigma, sim.length_sigma, sim.amplitude_sigma, 1});
    scene.sources.push_back({"observations[" + std::to_string(k) + "].", 1, recorded.amplitude, "rad"});
  }
  return scene;
}

}  // namespace pendulum
