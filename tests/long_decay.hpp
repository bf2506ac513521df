#pragma once
// A long decaying swing as a rotary-motion sensor logs it, and the scenes that
// reduce it one way or another (docs/recordings.md, "A long decay, swing by
// swing"), for tests/test_swing_series.cpp and
// tests/benchmarks/bench_long_decay.cpp.
//
// The motion is tests/recording_simulation.hpp's at l = 2.72 m (T = 3.31 s),
// g = 9.80665 m/s^2, alpha = 2e-3 1/s and beta = 3.33e-3 1/(s rad), which take
// 81 deg to 17 deg in 375 s (the decay); logged at 50 Hz with no
// jitter and no dropped samples, the angle plus Gaussian noise of 0.05 deg,
// printed as "Time (s),Angle (Degrees)" to 0.001 (PublishedLayout::rotary_degrees).
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>

#include "recording_simulation.hpp"

namespace pendulum::test {

constexpr double kLongDecayLength = 2.72;  // m
constexpr double kLongDecayG = 9.80665;    // m/s^2

/// Writes the recording released at `start_deg` to `path`.
inline void write_long_decay(const std::string& path, double start_deg, double duration, std::uint64_t seed) {
  RecordingSimulation s;
  s.length = kLongDecayLength, s.g = kLongDecayG;
  s.theta0 = start_deg * M_PI / 180.0, s.alpha = 2e-3, s.beta = 3.33e-3;
  s.rate_hz = 50.0, s.duration = duration, s.jitter = 0.0, s.drop = 0.0, s.seed = seed;
  std::ofstream(path, std::ios::binary)
      << published_csv(simulate_recording(s), s.length, PublishedLayout::rotary_degrees, 0.05 * M_PI / 180.0, seed);
}

/// How a scene reduces the recording.
enum class LongDecayMethod {
  start,            ///< one mean period at the start amplitude, no decay correction (as typed)
  start_with_decay, ///< one mean period at the start amplitude with the decay correction (Eq. 50)
  mean_amplitude,   ///< one mean period at the swings' mean amplitude `mean_deg`
  swing_by_swing,   ///< the series of its groups of swings, the decay's Eqs. 34 and 48 at each
};

/// A scene of the exact length (no uncertainty, so g's is the period's alone)
/// whose timing names `file`, in the scene's folder.
inline std::string long_decay_scene(const std::string& file, LongDecayMethod m, double mean_deg = 0.0) {
  const bool by_swing = m == LongDecayMethod::swing_by_swing;
  std::string s = "{\"length\": {\"value\": 2.72, \"unit\": \"m\"}, \"timing\": {\"recording\": \"" + file +
                  "\", \"reduce\": \"" + (by_swing ? "swing_by_swing" : "mean_period") + "\"}";
  if (m == LongDecayMethod::mean_amplitude) {
    s += ", \"amplitude\": {\"value\": " + std::to_string(mean_deg) + ", \"unit\": \"deg\"}";
  }
  if (m == LongDecayMethod::start_with_decay || by_swing) s += ", \"decay\": {\"data\": {\"recording\": \"" + file + "\"}}";
  return s + "}";
}

}  // namespace pendulum::test
