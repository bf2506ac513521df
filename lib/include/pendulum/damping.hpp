#pragma once
/// \file damping.hpp
/// \brief Damping: the decay law of the amplitude and its period corrections.
///
/// The amplitude obeys d theta0/dt = -alpha theta0 - beta theta0^2
/// (Nelson & Olsson 1986, Eq. 24): alpha (1/s) from linear drag, beta
/// (1/(s rad)) from quadratic drag. Angles in rad, times in s.

#include <cmath>

#include "pendulum/numeric.hpp"

namespace pendulum {

namespace detail {

/// (1 - exp(-y)) / y, exact at y = 0 (value 1) and smooth through it.
template <class T>
T one_minus_exp_over(const T& y) {
  using std::expm1;
  if (std::abs(value_of(y)) < 1e-4) {
    return 1.0 - y / 2.0 + y * y / 6.0 - y * y * y / 24.0;  // error < y^4/120
  }
  return -expm1(-y) / y;
}

/// log(1 + x) / x, exact at x = 0 (value 1).
template <class T>
T log1p_over(const T& x) {
  using std::log1p;
  if (std::abs(value_of(x)) < 1e-4) {
    return 1.0 - x / 2.0 + x * x / 3.0 - x * x * x / 4.0;  // error < x^4/5
  }
  return log1p(x) / x;
}

/// (x - log(1 + x)) / x^2 for x >= 0, value 1/2 at x = 0. The direct form
/// loses digits to cancellation for small x, so below 0.25 the alternating
/// series sum_k (-x)^k / (k + 2) is summed (27 terms: 0.25^27 < 1e-16).
template <class T>
T log1p_remainder(const T& x) {
  using std::log1p;
  if (value_of(x) < 0.25) {
    T sum = T(0.0);
    for (int k = 26; k >= 0; --k) sum = 1.0 / (k + 2.0) - x * sum;
    return sum;
  }
  return (x - log1p(x)) / (x * x);
}

}  // namespace detail

/// Eq. (25) with its exponential factors given: theta0(t) =
/// theta0m u / (1 + beta theta0m t E), u = e^{-alpha t}, E = (1 - u)/(alpha t)
/// (1 at alpha t = 0). The one implementation of Eq. (25): decayed_amplitude,
/// amplitude_decay (Eq. 50b) and the decay fit's vectorised kernel
/// (lib/src/decay_kernel.cpp, which forms E without expm1, so that it
/// vectorises) call it.
/// Always inlined: the kernel's file is compiled with -ffast-math, and an
/// out-of-line copy from there must not serve the other files.
/// \param theta0m initial amplitude (rad) > 0; \param beta (1/(s rad)) >= 0;
/// \param t time (s) >= 0; \param u e^{-alpha t}; \param e E(alpha t).
/// \return amplitude (rad). Reference: Nelson & Olsson (1986) Eq. (25).
template <class T>
[[gnu::always_inline]] inline T decayed_amplitude_from_factors(const T& theta0m, const T& beta,
                                                               const T& t, const T& u,
                                                               const T& e) {
  return theta0m * u / (1.0 + beta * theta0m * t * e);  // Eq. (25)
}

/// Amplitude after time t under linear and quadratic damping:
/// theta0(t) = alpha theta0m e^{-alpha t} / [beta theta0m (1 - e^{-alpha t}) + alpha],
/// evaluated as theta0m e^{-alpha t} / (1 + beta theta0m t E(alpha t)) with
/// E(y) = (1 - e^{-y})/y, which is exact for alpha = 0 (Eq. 46) and beta = 0
/// (Eq. 33).
/// \param theta0m initial amplitude (rad) > 0; \param alpha (1/s) >= 0;
/// \param beta (1/(s rad)) >= 0; \param t time (s) >= 0. \return amplitude (rad).
/// Reference: Nelson & Olsson (1986) Eq. (25).
template <class T>
T decayed_amplitude(const T& theta0m, const T& alpha, const T& beta,
                    const T& t) {
  using std::exp;
  return decayed_amplitude_from_factors(theta0m, beta, t, exp(-alpha * t),
                                        detail::one_minus_exp_over(alpha * t));
}

/// Linear damping: DeltaT/T0 = (1/2)(alpha/omega0)^2.
/// \param alpha (1/s); \param omega0 angular frequency (rad/s).
/// Reference: Nelson & Olsson (1986) Eq. (34).
template <class T>
T linear_damping(const T& alpha, const T& omega0) {
  const T r = alpha / omega0;
  return 0.5 * r * r;
}

/// Quadratic damping: DeltaT/T0 = (3/32)(pi beta/omega0)^2 theta0^2.
/// \param beta (1/(s rad)); \param omega0 (rad/s); \param theta0 amplitude (rad).
/// Reference: Nelson & Olsson (1986) Eq. (48).
template <class T>
T quadratic_damping(const T& beta, const T& omega0, const T& theta0) {
  const T r = kPi * beta / omega0 * theta0;
  return 3.0 / 32.0 * r * r;
}

/// Decay of the finite-amplitude correction over a timing of duration t_f
/// that starts at amplitude theta0m: the time average of theta0(t)^2/16 over
/// [0, t_f] (Eq. 49 with Eq. 25), minus the constant-amplitude value
/// theta0m^2/16 (Eq. 8), so DeltaT/T0 <= 0.
///
/// Eq. (50a) in the form
///   integral of theta0^2 dt = (D/A) [D q(x) + theta0f L(x)],
/// D = theta0m - theta0f, A = alpha + beta theta0f, x = beta D / A,
/// L(x) = log(1+x)/x, q(x) = (x - log(1+x))/x^2, with D formed without
/// subtraction. Both limits are exact: beta -> 0 gives Eq. (51) and
/// alpha -> 0 gives Eq. (52); alpha = beta = 0 gives 0.
/// \param theta0m amplitude at the start of the timing (rad) > 0;
/// \param alpha (1/s) >= 0; \param beta (1/(s rad)) >= 0;
/// \param t_f duration of the timing (s) > 0.
/// \return DeltaT/T0 (dimensionless).
/// Reference: Nelson & Olsson (1986) Eqs. (49), (50a), (50b), (51), (52).
/// Validity: small amplitudes (the theta0^2/16 term of Eq. 8; the relative
/// error of the result is about theta0m^2/10).
template <class T>
T amplitude_decay(const T& theta0m, const T& alpha, const T& beta,
                  const T& t_f) {
  using std::exp;
  if (value_of(alpha) == 0.0 && value_of(beta) == 0.0) return T(0.0);
  // A decay too slow to resolve, s = (alpha + beta theta0m) t_f < 1e-8: to
  // first order theta0^2 falls by 2 s theta0m^2 t / t_f, which averages to
  // the line below, good to a relative s; the exact form loses 1e-16/s to
  // the subtraction in its last line, and divides by a rate that may
  // underflow (fuzzing found NaN derivatives at a subnormal beta theta0f).
  const T s = (alpha + beta * theta0m) * t_f;
  if (value_of(s) < 1e-8) return -theta0m * theta0m * s / 16.0;
  const T e = detail::one_minus_exp_over(alpha * t_f);
  const T growth = 1.0 + beta * theta0m * t_f * e;
  const T theta0f = decayed_amplitude_from_factors(theta0m, beta, t_f, exp(-alpha * t_f), e);  // Eq. (50b)
  const T d = theta0m * t_f * e * (alpha + beta * theta0m) / growth;  // theta0m - theta0f
  const T a = alpha + beta * theta0f;
  const T x = beta * d / a;
  const T integral = d / a * (d * detail::log1p_remainder(x) +
                              theta0f * detail::log1p_over(x));
  return (integral / t_f - theta0m * theta0m) / 16.0;
}

}  // namespace pendulum
