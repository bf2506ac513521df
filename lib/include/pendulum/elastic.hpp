#pragma once
/// \file elastic.hpp
/// \brief Elastic corrections: dynamic stretch of the wire, motion of the support.
///
/// SI units: kg, m/s^2, Pa, m^2, N/m, rad, rad/s.

#include <cmath>

#include "pendulum/numeric.hpp"

namespace pendulum {

/// Dynamic stretch of the wire by the centrifugal and Coriolis forces:
/// DeltaT/T0 = (11/16) (m g / (E S)) theta0^2.
/// \param m bob mass (kg); \param g gravity (m/s^2); \param e Young's modulus
/// (Pa); \param s wire cross-section (m^2); \param theta0 amplitude (rad).
/// Validity: stiff wire, omega_pendulum << omega_string. The static stretch is
/// part of the measured length and is not corrected.
/// Reference: Nelson & Olsson (1986) Eq. (79).
template <class T>
T wire_stretch(const T& m, const T& g, const T& e, const T& s,
               const T& theta0) {
  return 11.0 / 16.0 * (m * g / (e * s)) * theta0 * theta0;
}

/// Elastic support of stiffness K (omega0 << support frequency):
/// DeltaT/T0 = (1/2) m g / (K l).
/// \param m bob mass (kg); \param g (m/s^2); \param k support stiffness
/// (N/m); \param l pivot to bob centre (m).
/// Reference: Nelson & Olsson (1986) Eq. (87).
template <class T>
T support_elastic(const T& m, const T& g, const T& k, const T& l) {
  return 0.5 * m * g / (k * l);
}

/// Inertial support of mass M (support frequency << omega0):
/// DeltaT/T0 = -(1/2) m / M.
/// \param m bob mass (kg); \param big_m support mass (kg).
/// Reference: Nelson & Olsson (1986) Eq. (88).
template <class T>
T support_inertial(const T& m, const T& big_m) {
  return -0.5 * m / big_m;
}

/// Support of mass M on a spring of stiffness K, any frequency ratio: the
/// pendulum mode of Eq. (83), omega^4 - B omega^2 + omega0^2 Omega^2 = 0 with
/// B = Omega^2 + (1 + m/M) omega0^2 and Omega^2 = K/M, taking the root
/// nearer omega0^2; the smaller root is formed as the product over the larger
/// so that neither loses digits. DeltaT/T0 = omega0/omega - 1.
/// \param m bob mass (kg); \param big_m support mass (kg); \param k support
/// stiffness (N/m); \param omega0 pendulum angular frequency (rad/s).
/// Reference: Nelson & Olsson (1986) Eqs. (80)-(83); Eqs. (87) and (88) are
/// its two limits.
template <class T>
T support_coupled(const T& m, const T& big_m, const T& k, const T& omega0) {
  using std::abs;
  using std::sqrt;
  const T w0sq = omega0 * omega0;
  const T big_omega_sq = k / big_m;
  const T b = big_omega_sq + (1.0 + m / big_m) * w0sq;
  const T root_large = (b + sqrt(b * b - 4.0 * w0sq * big_omega_sq)) / 2.0;
  const T root_small = w0sq * big_omega_sq / root_large;
  const T w_sq = abs(value_of(root_small) - value_of(w0sq)) <=
                         abs(value_of(root_large) - value_of(w0sq))
                     ? root_small
                     : root_large;
  return omega0 / sqrt(w_sq) - 1.0;
}

}  // namespace pendulum
