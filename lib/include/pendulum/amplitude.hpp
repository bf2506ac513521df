#pragma once
/// \file amplitude.hpp
/// \brief Finite-amplitude correction to the period of a plane pendulum.
///
/// Each function returns the relative correction DeltaT/T0 = T/T0 - 1, where
/// T0 = 2 pi sqrt(l/g) is the small-oscillation period and T the period at
/// amplitude theta0. The exact value is 2K(k)/pi - 1 with k = sin(theta0/2)
/// (Nelson & Olsson 1986, Sec. III.A; Kelley 1993, Eq. 9).

#include <cmath>

#include "pendulum/numeric.hpp"

namespace pendulum {

/// Exact finite-amplitude correction by the arithmetic-geometric mean (AGM).
///
/// T/T0 = 1 / AGM(1, kc) with the complementary modulus kc = cos(theta0/2).
/// The correction is formed without subtracting nearly equal numbers: with
/// c_1 = (1 - kc)/2 = sin^2(theta0/4) and c_{n+1} = c_n^2 / (2 (a_n + b_n)),
/// 1 - AGM = sum of c_n, so DeltaT/T0 = (sum c_n) / AGM. This keeps full
/// relative accuracy as theta0 -> 0, where 2K/pi - 1 computed from K loses
/// every digit.
///
/// \param theta0 amplitude (rad), 0 <= theta0 < pi.
/// \return DeltaT/T0 (dimensionless), >= 0.
/// Reference: Nelson & Olsson (1986) Eq. (8), exact form; the AGM identity
/// K(k) = pi / (2 AGM(1, kc)).
/// Validity: any amplitude below pi. Near pi, kc = cos(theta0/2) carries the
/// absolute rounding error of theta0, so the relative error of the result
/// grows like 1e-16/kc; a deficit-based entry point is planned (issue 4).
template <class T>
T finite_amplitude_agm(const T& theta0) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T s = sin(theta0 / 4.0);
  T c = s * s;                 // c_1 = (1 - kc) / 2
  T a = T(1.0);
  T b = cos(theta0 / 2.0);     // kc
  T sum = c;
  // Quadratic convergence: 6 steps reach double precision for kc >= 1e-12.
  // The step after convergence is kept so that dual-number derivatives
  // converge too.
  for (int n = 0; n < 64; ++n) {
    const T a_next = (a + b) / 2.0;
    const T b_next = sqrt(a * b);
    const bool converged = value_of(c) <= 1e-17 * value_of(sum) &&
                           value_of(c) <= 1e-17 * value_of(a);
    c = c * c / (2.0 * (a_next + b_next));
    sum += c;
    a = a_next;
    b = b_next;
    if (converged) break;
  }
  return sum / a;
}

/// Finite-amplitude correction by the series of Nelson & Olsson Eq. (8),
/// truncated after `terms` terms:
/// DeltaT/T0 = sum_{n=1}^{terms} [(2n)! / (2^{2n} (n!)^2)]^2 sin^{2n}(theta0/2).
///
/// \param theta0 amplitude (rad), 0 <= theta0 < pi.
/// \param terms number of terms, >= 1.
/// \return DeltaT/T0 (dimensionless). Truncation error is below the first
/// omitted term divided by (1 - k^2), k = sin(theta0/2).
/// Reference: Nelson & Olsson (1986) Eq. (8).
template <class T>
T finite_amplitude_series(const T& theta0, int terms) {
  using std::sin;
  const T k = sin(theta0 / 2.0);
  const T k2 = k * k;
  T power = T(1.0);
  double coefficient = 1.0;  // [(2n)! / (2^{2n} (n!)^2)]
  T sum = T(0.0);
  for (int n = 1; n <= terms; ++n) {
    coefficient *= (2.0 * n - 1.0) / (2.0 * n);
    power *= k2;
    sum += coefficient * coefficient * power;
  }
  return sum;
}

/// Leading term of Eq. (8): DeltaT/T0 = theta0^2 / 16.
///
/// \param theta0 amplitude (rad).
/// \return DeltaT/T0 (dimensionless); relative error below 1e-3 only for
/// theta0 below about 7.6 degrees (the next term is 11 theta0^4 / 3072).
/// Reference: Nelson & Olsson (1986) Eq. (8), first term.
template <class T>
T finite_amplitude_small_angle(const T& theta0) {
  return theta0 * theta0 / 16.0;
}

}  // namespace pendulum
