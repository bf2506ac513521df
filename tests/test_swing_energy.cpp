// A swing's amplitude from one point of it (lib/include/pendulum/swing_energy.hpp):
// closed-form values of the energy relation, the exact undamped motion
// integrated by RK4 (tests/recording_simulation.hpp), and derivatives
// through ceres::Jet against the differentiated formulas.
#include <catch2/catch.hpp>
#include <ceres/jet.h>

#include <algorithm>
#include <cmath>

#include "pendulum/swing_energy.hpp"
#include "recording_simulation.hpp"

using namespace pendulum;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("Energy relation: closed-form points", "[swing_energy]") {
  // omega0 = 1 rad/s (T0 = 2 pi s): omega_max = 2 sin(theta0/2), so 1 rad/s
  // is 60 deg and sqrt(2) rad/s is 90 deg, exactly.
  CHECK_THAT(amplitude_from_peak_rate(1.0, 2.0 * kPi), WithinRel(kPi / 3.0, 1e-15));
  CHECK_THAT(amplitude_from_peak_rate(std::sqrt(2.0), 2.0 * kPi), WithinRel(kPi / 2.0, 1e-15));
  CHECK(amplitude_from_peak_rate(0.0, 2.0) == 0.0);  // no swing
  // v = 2 sqrt(g l) sin(theta0/2): v = sqrt(g l) is 60 deg.
  CHECK_THAT(amplitude_from_bottom_speed(2.8, 2.8), WithinRel(kPi / 3.0, 1e-15));
  // |a| ratio (3 - 2 cos theta0)/cos theta0: 60 deg gives (3 - 1)/0.5 = 4;
  // no swing gives 1.
  CHECK_THAT(amplitude_from_acceleration_ratio(4.0), WithinRel(kPi / 3.0, 1e-15));
  CHECK_THAT(amplitude_from_acceleration_ratio(1.0), WithinAbs(0.0, 1e-15));
  // g sin theta0 at a turning point: half of g is 30 deg.
  CHECK_THAT(amplitude_from_turning_acceleration(9.81 / 2.0, 9.81), WithinRel(kPi / 6.0, 1e-15));
  // Beyond 180 deg there is no swing.
  CHECK(std::isnan(amplitude_from_peak_rate(2.1, 2.0 * kPi)));
}

TEST_CASE("Energy relation against the integrated undamped motion", "[swing_energy]") {
  // theta0 = 0.25 rad, l = 0.80 m, no damping, no noise, 20 kHz: the largest
  // sampled |theta'| is within (omega0 dt)^2/8 = 4e-9 relative of the true
  // peak, the sampled |a| extremes likewise.
  test::RecordingSimulation s;
  s.alpha = 0.0, s.beta = 0.0, s.noise = 0.0, s.jitter = 0.0, s.drop = 0.0;
  s.bias = {0.0, 0.0, 0.0};
  s.rate_hz = 20000.0, s.duration = 2.0;
  const auto sim = test::simulate_recording(s);
  const double t0 = 2.0 * kPi / sim.omega0;
  double peak = 0.0, a_max = 0.0, a_min = 1e9;
  for (std::size_t k = 0; k < sim.t.size(); ++k) {
    peak = std::max(peak, std::fabs(sim.omega[k]));
    const double a = s.length * sim.omega[k] * sim.omega[k] + s.g * std::cos(sim.theta[k]);  // along the string
    a_max = std::max(a_max, a), a_min = std::min(a_min, a);
  }
  CHECK_THAT(amplitude_from_peak_rate(peak, t0), WithinAbs(s.theta0, 1e-8));
  CHECK_THAT(amplitude_from_bottom_speed(s.length * peak, std::sqrt(s.g * s.length)), WithinAbs(s.theta0, 1e-8));
  CHECK_THAT(amplitude_from_acceleration_ratio(a_max / a_min), WithinAbs(s.theta0, 1e-7));
  const double a_turn = s.g * std::sin(s.theta0);  // l theta'' at theta' = 0, Eq. (1)
  CHECK_THAT(amplitude_from_turning_acceleration(a_turn, s.g), WithinAbs(s.theta0, 1e-15));
}

TEST_CASE("Energy relation: derivatives through ceres::Jet", "[swing_energy]") {
  // d theta0/d omega_max = (T0/(2 pi)) / cos(theta0/2), from
  // sin(theta0/2) = omega_max T0/(4 pi).
  using Jet = ceres::Jet<double, 1>;
  const double t0 = 1.8, w = 0.9;
  const Jet theta = amplitude_from_peak_rate(Jet(w, 0), Jet(t0));
  CHECK_THAT(theta.v[0], WithinRel(t0 / (2.0 * kPi) / std::cos(theta.a / 2.0), 1e-14));
  // d theta0/d r = 3 / ((r + 2)^2 sin theta0), from cos theta0 = 3/(r + 2).
  const Jet from_ratio = amplitude_from_acceleration_ratio(Jet(1.1, 0));
  CHECK_THAT(from_ratio.v[0], WithinRel(3.0 / (3.1 * 3.1 * std::sin(from_ratio.a)), 1e-14));
}
