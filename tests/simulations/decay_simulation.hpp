#pragma once
/// \file decay_simulation.hpp
/// \brief Synthetic decay records from Eq. (25) with Gaussian noise, seeded
/// and identical on every platform (std::normal_distribution is not: its
/// algorithm is left to the library), for tests, benchmarks and data/.

#include <cmath>
#include <cstdint>
#include <random>

#include "pendulum/damping.hpp"
#include "pendulum/decay_fit.hpp"
#include "pendulum/numeric.hpp"

namespace pendulum {

/// What a simulated record is drawn from.
struct DecaySimulation {
  double alpha;        ///< (1/s)
  double beta;         ///< (1/(s rad))
  double theta0m;      ///< initial amplitude (rad)
  double sigma;        ///< noise standard deviation (rad)
  double duration;     ///< last time (s); times are evenly spaced from 0
  int points;          ///< number of amplitudes, >= 2
  std::uint64_t seed;  ///< std::mt19937_64 seed
};

/// Standard normal deviates by the Box-Muller transform of std::mt19937_64
/// output (both fully specified by the C++ standard).
class NormalDeviates {
 public:
  explicit NormalDeviates(std::uint64_t seed) : engine_(seed) {}
  double next() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    // Uniform in (0, 1]: 53 random bits, offset by one so log() is finite.
    const double u1 = ((engine_() >> 11) + 1) * 0x1.0p-53;
    const double u2 = (engine_() >> 11) * 0x1.0p-53;
    const double r = std::sqrt(-2.0 * std::log(u1));
    spare_ = r * std::sin(2.0 * kPi * u2);
    has_spare_ = true;
    return r * std::cos(2.0 * kPi * u2);
  }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

/// A record of `points` amplitudes at t_i = i duration/(points - 1),
/// theta_i = Eq. (25)(t_i) + sigma N(0,1), with sigma stated per point.
/// Noise may make a late amplitude non-positive when sigma is large against
/// the decayed amplitude; callers choose parameters where it does not.
inline DecayData simulate_decay(const DecaySimulation& s) {
  DecayData data;
  NormalDeviates noise(s.seed);
  for (int i = 0; i < s.points; ++i) {
    const double t = s.duration * i / (s.points - 1);
    data.times.push_back(t);
    data.amplitudes.push_back(decayed_amplitude(s.theta0m, s.alpha, s.beta, t) + s.sigma * noise.next());
    data.sigmas.push_back(s.sigma);
  }
  return data;
}

}  // namespace pendulum
