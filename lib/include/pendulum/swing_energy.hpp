#pragma once
/// \file swing_energy.hpp
/// \brief A swing's amplitude from what a sensor sees at one point of it,
/// by conservation of energy of the plane pendulum (damping neglected over
/// the quarter swing between the bottom and a turning point).
///
/// Energy per unit mass, with theta measured from the vertical:
/// (1/2) l^2 theta'^2 = g l (cos theta - cos theta0), so at the bottom
/// l theta'_max = 2 sqrt(g l) sin(theta0/2) (Nelson & Olsson 1986, Sec. III.A;
/// Kelley 1993, Eq. 12 at theta = 0). Every function is generic in the scalar
/// (double, ceres::Jet).

#include <cmath>

#include "pendulum/numeric.hpp"

namespace pendulum {

/// Amplitude from the peak angular rate at the bottom and the
/// small-amplitude period: omega_max = 2 sqrt(g/l) sin(theta0/2) =
/// (4 pi / T0) sin(theta0/2), so no g or l is needed.
/// \param omega_max peak angular rate (rad/s) >= 0;
/// \param t0 small-amplitude period 2 pi sqrt(l/g) (s) > 0.
/// \return theta0 (rad); valid for omega_max T0/(4 pi) < 1 (below 180 deg),
/// NaN beyond (the pendulum goes over the top).
/// Reference: Nelson & Olsson (1986) Sec. III.A, energy; Kelley (1993) Eq. (12).
template <class T>
T amplitude_from_peak_rate(const T& omega_max, const T& t0) {
  using std::asin;
  return 2.0 * asin(omega_max * t0 / (4.0 * kPi));  // omega_max = (4 pi/T0) sin(theta0/2)
}

/// Amplitude from the bob's speed at the bottom: v = 2 sqrt(g l) sin(theta0/2).
/// \param v speed at the bottom (m/s) >= 0 (a photogate: bob width / blocking time);
/// \param sqrt_gl sqrt(g l) (m/s) > 0, = 2 pi l / T0.
/// \return theta0 (rad); valid for v < 2 sqrt(g l), NaN beyond.
/// Reference: Nelson & Olsson (1986) Sec. III.A, energy.
template <class T>
T amplitude_from_bottom_speed(const T& v, const T& sqrt_gl) {
  using std::asin;
  return 2.0 * asin(v / (2.0 * sqrt_gl));  // v = 2 sqrt(g l) sin(theta0/2)
}

/// Amplitude from the ratio r = |a|max/|a|min of an accelerometer at the bob
/// (specific force along the string, l theta'^2 + g cos theta =
/// g (3 cos theta - 2 cos theta0)): g (3 - 2 cos theta0) at the bottom over
/// g cos theta0 at the turning points, so cos theta0 = 3/(r + 2), without g.
/// \param r ratio (dimensionless) >= 1.
/// \return theta0 (rad); valid for theta0 < 90 deg (beyond, |a|min is no
/// longer at the turning points' cos theta0 > 0).
/// Reference: energy as above; the string tension of the plane pendulum.
template <class T>
T amplitude_from_acceleration_ratio(const T& r) {
  using std::acos;
  return acos(3.0 / (r + 2.0));  // r = (3 - 2 cos theta0)/cos theta0
}

/// Amplitude from the tangential (kinematic) acceleration at a turning point,
/// where theta' = 0 and l theta'' = -g sin theta0.
/// \param a_turn |tangential acceleration| there (m/s^2) >= 0;
/// \param g gravity (m/s^2) > 0.
/// \return theta0 (rad); valid below 90 deg.
/// Reference: the equation of motion, Nelson & Olsson (1986) Eq. (1).
template <class T>
T amplitude_from_turning_acceleration(const T& a_turn, const T& g) {
  using std::asin;
  return asin(a_turn / g);  // l theta'' = -g sin theta0 at the turning point
}

}  // namespace pendulum
