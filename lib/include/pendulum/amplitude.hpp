#pragma once
/// \file amplitude.hpp
/// \brief Finite-amplitude correction to the period of a plane pendulum, and
/// the pendulum's angle in time.
///
/// The correction functions return DeltaT/T0 = T/T0 - 1, where
/// T0 = 2 pi sqrt(l/g) is the small-oscillation period and T the period at
/// amplitude theta0. The exact value is 2K(k)/pi - 1 with k = sin(theta0/2)
/// (Nelson & Olsson 1986, Eq. 8; Kelley 1993, Eqs. 16-17). Every function is
/// generic in the scalar (double, ceres::Jet); branches look at value_of().

#include <array>
#include <cstddef>
#include <cmath>
#include <stdexcept>
#include <string>

#include "pendulum/argument_ranges.hpp"
#include "pendulum/numeric.hpp"

namespace pendulum {

/// How the finite-amplitude correction is computed, cheapest first.
/// `automatic` lets the reduction pick (see reduction.hpp).
enum class AmplitudeMethod { small_angle, series, agm, automatic };

/// The name the output uses for a method ("small_angle", "series", "agm",
/// "auto"); for a body on a string at its own amplitude, where the slow
/// mode's psi0^4 term joins the factor (corrections.hpp,
/// slow_mode_finite_amplitude), "slow_mode_agm" and so on.
inline const char* method_name(AmplitudeMethod m, bool slow_mode = false) {
  static constexpr const char* kNames[][2] = {{"small_angle", "slow_mode_small_angle"},
                                              {"series", "slow_mode_series"},
                                              {"agm", "slow_mode_agm"},
                                              {"auto", "slow_mode_auto"}};
  return kNames[static_cast<int>(m)][slow_mode];
}

namespace detail {

/// Coefficient of Eq. (8): [(2n)! / (2^{2n} (n!)^2)]^2 = [(1/2)_n / n!]^2.
constexpr double eq8_coefficient(int n) {
  double c = 1.0;
  for (int j = 1; j <= n; ++j) c *= (2.0 * j - 1.0) / (2.0 * j);
  return c * c;
}

/// c[B] + c[B+1] x + ... + c[B+L-1] x^{L-1}, split as low + x^h high with
/// h the largest power of two below L; powers[j] = x^(2^j).
template <std::size_t B, std::size_t L, class T, std::size_t N>
T estrin_part(const std::array<T, 4>& powers, const std::array<double, N>& c) {
  if constexpr (L == 1) {
    return T(c[B]);
  } else {
    constexpr std::size_t j = L > 8 ? 3 : L > 4 ? 2 : L > 2 ? 1 : 0;
    constexpr std::size_t h = std::size_t{1} << j;
    return estrin_part<B, h>(powers, c) + estrin_part<B + h, L - h>(powers, c) * powers[j];
  }
}

/// c[0] + c[1] x + ... + c[N-1] x^{N-1} (N <= 16) by Estrin's scheme: the
/// same operations as Horner's, but a dependency chain of log2(N)
/// multiply-adds instead of N, which is what the exact method's speed is
/// bound by. Unrolled at compile time.
template <class T, std::size_t N>
T estrin(const T& x, const std::array<double, N>& c) {
  static_assert(N >= 1 && N <= 16);
  const T x2 = x * x, x4 = x2 * x2;
  return estrin_part<0, N>(std::array<T, 4>{x, x2, x4, x4 * x4}, c);
}

/// sin x for 0 <= x <= pi/4 (rad): Taylor through x^17. The first omitted
/// term, (pi/4)^19/19!, is 8e-20 of sin x; the polynomial needs no range
/// reduction, which makes it three times cheaper than std::sin.
template <class T>
T sin_eighth_turn(const T& x) {
  static constexpr std::array<double, 8> c{
      -1.0 / 6.0,        1.0 / 120.0,        -1.0 / 5040.0,          1.0 / 362880.0,
      -1.0 / 39916800.0, 1.0 / 6227020800.0, -1.0 / 1307674368000.0, 1.0 / 355687428096000.0};
  const T y = x * x;
  return x + x * y * estrin(y, c);
}

/// Eq. (8) summed through m^10 for the parameter m <= 0.0295 left after the
/// AGM steps of finite_amplitude_exact: sum_{n=1}^{10} A_n m^n. The omitted
/// tail is below A_11 m^11 / (1 - m) < 1e-17 of the sum.
template <class T>
T eq8_ten_terms(const T& m) {
  static constexpr std::array<double, 10> a{
      eq8_coefficient(1), eq8_coefficient(2), eq8_coefficient(3), eq8_coefficient(4),
      eq8_coefficient(5), eq8_coefficient(6), eq8_coefficient(7), eq8_coefficient(8),
      eq8_coefficient(9), eq8_coefficient(10)};
  return m * estrin(m, a);
}

/// 4 e^{-pi}: the nome q' = e^{-pi} at theta0 = 90 deg, times 4.
inline constexpr double kFourExpMinusPi = 0.172855673055088999097670948687;

/// The first case of finite_amplitude_exact, theta0 (rad) <= 90 deg.
template <class T>
T exact_one_agm_step(const T& theta0) {
  const T s = sin_eighth_turn(theta0 / 4.0);
  const T c1 = s * s;
  const T inv_a1 = 1.0 / (1.0 - c1);
  const T k1 = c1 * inv_a1;
  return (c1 + eq8_ten_terms(k1 * k1)) * inv_a1;
}

/// The second case, from the deficit pi - theta0 (rad), 90 to 160 deg.
template <class T>
T exact_two_agm_steps(const T& deficit) {
  using std::sqrt;
  const T kc = sin_eighth_turn(deficit / 2.0);
  const T c1 = (1.0 - kc) / 2.0;
  const T inv_a2 = 2.0 / ((1.0 + kc) / 2.0 + sqrt(kc));
  const T c2 = c1 * c1 * inv_a2 / 4.0;
  const T k2 = c2 * inv_a2;
  return (c1 + c2 + eq8_ten_terms(k2 * k2)) * inv_a2;
}

/// The third case, from the deficit (rad), above 160 deg.
template <class T>
T exact_nome(const T& deficit) {
  using std::log;
  const T s = sin_eighth_turn(deficit / 4.0);
  const T c = s * s;
  const T t = c / (1.0 - c);  // tan^2(deficit/4), the Landen modulus of kc
  const T u = t * t / 16.0;
  // sqrt(q/u) and ln sqrt(q/u) through u^4; the next terms are below 1e-19.
  const T root = 1.0 + u * (4.0 + u * (34.0 + u * (360.0 + u * 4239.0)));
  const T log_root = u * (4.0 + u * (26.0 + u * (736.0 / 3.0 + u * 2701.0)));
  const T q = t / 4.0 * root;
  const T theta3_minus_1 = 2.0 * q * (1.0 + q * q * q);  // + 2 q^9 < 1e-21
  const T l_minus_pi = log(kFourExpMinusPi / t) - log_root;
  return l_minus_pi / kPi +
         theta3_minus_1 * (2.0 + theta3_minus_1) * (l_minus_pi / kPi + 1.0);
}

/// The deficit pi - theta0 (rad) of an amplitude theta0 >= pi/2 (rad),
/// rounded once: kPi - theta0 is exact (Sterbenz), and the true pi's
/// 1.2e-16 beyond the double kPi is added to it. From kPi alone, the
/// deficit near 180 deg was short by that much (1.0e-14 of DeltaT/T0 at
/// 179.9 deg, 1.6e-15 at 179 deg).
template <class T>
T deficit_of(const T& theta0) {
  constexpr double kPiBeyondDouble = 1.2246467991473532e-16;  // pi - kPi = sin(kPi), to 17 digits
  return (kPi - theta0) + kPiBeyondDouble;
}

/// The upper limits (rad) of the first two cases.
inline constexpr double kOneAgmStepLimit = kPi / 2.0;
inline constexpr double kTwoAgmStepsLimit = kPi * (8.0 / 9.0);

/// The exact DeltaT/T0 from the amplitude theta0 (rad) and its deficit
/// pi - theta0 (rad), each accurate to a few ulp in relative terms; the one
/// that is used is the one that carries the digits. No step subtracts
/// nearly equal numbers.
///  - theta0 <= 90 deg: one AGM step (Landen), closed by Eq. (8):
///    c1 = sin^2(theta0/4), a1 = 1 - c1, k1 = c1/a1,
///    DeltaT/T0 = (c1 + S(k1^2)) / a1, S the series of Eq. (8); k1^2 <= 0.0295.
///  - 90 to 160 deg: two AGM steps on kc = cos(theta0/2) = sin(deficit/2):
///    a2 = (a1 + sqrt(kc))/2, c2 = c1^2/(4 a2), k2 = c2/a2,
///    DeltaT/T0 = (c1 + c2 + S(k2^2)) / a2 (1 - AGM = sum c_n); k2^2 <= 0.0287.
///  - above 160 deg: Jacobi's nome q' of the complementary modulus,
///    2K/pi = theta3(q')^2 ln(1/q') / pi. With t = tan^2(deficit/4)
///    (one Landen step on kc), u = t^2/16: q' = (t/4) sqrt(q(u)/u) and
///    ln(1/q') = ln(4/t) - ln sqrt(q(u)/u), where q(u) = u + 8u^2 + 84u^3
///    + ... is the nome series; u <= 4e-6. The term L - pi = ln(4 e^{-pi}/t)
///    - ... is formed directly, so DeltaT/T0 = (L - pi)/pi
///    + (theta3^2 - 1)(L/pi) has no cancellation.
/// Accuracy: worst relative error 6.3e-16 against quad precision over 1e-8 to
/// 179.9999999 deg (tests/test_amplitude.cpp).
template <class T>
T finite_amplitude_exact(const T& theta0, const T& deficit) {
  const double angle = value_of(theta0);
  if (angle <= kOneAgmStepLimit) return exact_one_agm_step(theta0);
  if (angle <= kTwoAgmStepsLimit) return exact_two_agm_steps(deficit);
  return exact_nome(deficit);
}

/// Throws std::domain_error unless x lies in `range` (ranges::amplitude or
/// amplitude_deg; NaN refused), with the message the CLI and Python give.
inline void require_amplitude(double x, const ArgumentRange& range) {
  if (!accepts(range, x)) throw std::domain_error("amplitude: " + out_of_range(range, x));
}

}  // namespace detail

/// Exact finite-amplitude correction, amplitude in degrees:
/// DeltaT/T0 = 2K(sin(theta0/2))/pi - 1 = 1/AGM(1, cos(theta0/2)) - 1.
///
/// The deficit 180 - theta0 is exact in floating point (Sterbenz) for
/// theta0 >= 90 deg, so kc = cos(theta0/2) = sin(deficit/2) keeps every digit
/// up to 179.9999999 deg and beyond. See detail::finite_amplitude_exact.
/// \param theta0_deg amplitude (deg), 0 <= theta0 < 180; else std::domain_error.
/// \return DeltaT/T0 (dimensionless), relative error below 1e-15.
/// Reference: Nelson & Olsson (1986) Eq. (8), exact form; Kelley (1993)
/// Eq. (17); the AGM identity K(k) = pi / (2 AGM(1, kc)).
template <class T>
T finite_amplitude_agm_deg(const T& theta0_deg) {
  detail::require_amplitude(value_of(theta0_deg), ranges::amplitude_deg);
  return detail::finite_amplitude_exact(radians(theta0_deg), radians(180.0 - theta0_deg));
}

/// Exact finite-amplitude correction, amplitude in radians: as
/// finite_amplitude_agm_deg, the deficit pi - theta0 taken from the true pi
/// (detail::deficit_of), so that near 180 deg too the result is exact for
/// the amplitude given.
/// \param theta0 amplitude (rad), 0 <= theta0 < pi; else std::domain_error.
/// \return DeltaT/T0 (dimensionless), relative error below 1e-15.
/// Reference: Nelson & Olsson (1986) Eq. (8); Kelley (1993) Eq. (17).
template <class T>
T finite_amplitude_agm(const T& theta0) {
  detail::require_amplitude(value_of(theta0), ranges::amplitude);
  return detail::finite_amplitude_exact(theta0, detail::deficit_of(theta0));
}

/// finite_amplitude_agm at each of `n` amplitudes theta0[i] (rad) into
/// excess[i], bit for bit the same values, vectorised (lib/src/amplitude_many.cpp:
/// the amplitudes of each of detail::finite_amplitude_exact's three cases are
/// gathered into a block that the compiler vectorises for AVX-512, AVX2 or
/// SSE2, chosen at run time). \return the index of the first amplitude
/// outside 0 <= theta0 < pi (NaN included), from which on `excess` is not
/// written; `n` when there is none.
std::size_t finite_amplitude_agm_many(const double* theta0, double* excess, std::size_t n);

/// Finite-amplitude correction by the series of Nelson & Olsson Eq. (8),
/// truncated after `terms` terms:
/// DeltaT/T0 = sum_{n=1}^{terms} [(2n)! / (2^{2n} (n!)^2)]^2 sin^{2n}(theta0/2).
///
/// \param theta0 amplitude (rad), 0 <= theta0 < pi.
/// \param terms number of terms, >= 1.
/// \return DeltaT/T0 (dimensionless). Truncation error: amplitude_error_bound.
/// Reference: Nelson & Olsson (1986) Eq. (8); Kelley (1993) Eq. (19).
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
/// Reference: Nelson & Olsson (1986) Eq. (8), first term; Kelley (1993)
/// Eq. (37).
template <class T>
T finite_amplitude_small_angle(const T& theta0) {
  return theta0 * theta0 / 16.0;
}

/// DeltaT/T0 by `method` (not `automatic`); `terms` is for the series.
/// \param theta0 amplitude (rad), 0 <= theta0 < pi.
template <class T>
T finite_amplitude(AmplitudeMethod method, const T& theta0, int terms) {
  switch (method) {
    case AmplitudeMethod::small_angle: return finite_amplitude_small_angle(theta0);
    case AmplitudeMethod::series: return finite_amplitude_series(theta0, terms);
    case AmplitudeMethod::agm:
    case AmplitudeMethod::automatic: break;
  }
  return finite_amplitude_agm(theta0);
}

/// Relative error bound of the exact method: the worst error measured
/// against quad precision over 1e-8 to 179.9999999 deg is 6.3e-16
/// (tests/test_amplitude.cpp asserts this bound on that grid).
inline constexpr double kExactRelativeErrorBound = 1e-15;

/// A bound on |computed - exact| of DeltaT/T0 for `method` at amplitude
/// theta0 (rad), truncation and rounding together. With m = sin^2(theta0/2)
/// and A_n the coefficients of Eq. (8):
///  - small_angle: theta0^2/16 - A_1 m lies in [0, theta0^4/192]
///    (x^2 - sin^2 x <= x^4/3), and the omitted sum_{n>=2} A_n m^n lies in
///    [0, A_2 m^2 + A_3 m^3/(1 - m)]; the error is their difference.
///  - series of N terms: the omitted tail, below A_{N+1} m^{N+1}/(1 - m).
///  - agm: kExactRelativeErrorBound of the value.
/// Each adds (N + 4) units of roundoff (2^-53) of the value.
/// \return the bound (dimensionless, same units as DeltaT/T0).
inline double amplitude_error_bound(AmplitudeMethod method, double theta0, int terms) {
  constexpr double kUnitRoundoff = 1.1102230246251565e-16;  // 2^-53
  const double k = std::sin(theta0 / 2.0);
  const double m = k * k;
  // 1 - m as cos^2(theta0/2): from 179.9999999 deg on m rounds to 1, and 1 - m to 0 (an infinite bound).
  const double kc = std::cos(theta0 / 2.0);
  const double kc2 = kc * kc;
  switch (method) {
    case AmplitudeMethod::small_angle: {
      const double t4 = theta0 * theta0 * theta0 * theta0;
      const double omitted = detail::eq8_coefficient(2) * m * m +
                             detail::eq8_coefficient(3) * m * m * m / kc2;
      return std::fmax(omitted, t4 / 192.0) +
             4.0 * kUnitRoundoff * finite_amplitude_small_angle(theta0);
    }
    case AmplitudeMethod::series:
      return detail::eq8_coefficient(terms + 1) * std::pow(m, terms + 1) / kc2 +
             (terms + 4.0) * kUnitRoundoff * finite_amplitude_series(theta0, terms);
    case AmplitudeMethod::agm:
    case AmplitudeMethod::automatic: break;
  }
  return kExactRelativeErrorBound * finite_amplitude_agm(theta0);
}

/// A method with its series length and its error bound (see
/// amplitude_error_bound).
struct AmplitudeChoice {
  AmplitudeMethod method;
  int terms;     ///< terms of the Eq. (8) series; 0 for the other methods
  double bound;  ///< bound on |error| of DeltaT/T0 (dimensionless)
};

/// Longest Eq. (8) series the automatic choice considers: beyond it the
/// exact method costs less (docs/amplitude.md, benchmark).
inline constexpr int kMaxAutoSeriesTerms = 4;

/// The cheapest method whose bound at theta0 (rad) is below `tolerance`
/// (dimensionless, in units of DeltaT/T0): theta0^2/16, then Eq. (8) with
/// 1 to kMaxAutoSeriesTerms terms, then the exact method, which is always
/// taken when tolerance <= 0.
inline AmplitudeChoice cheapest_amplitude_method(double theta0, double tolerance) {
  if (tolerance > 0.0) {
    const double small = amplitude_error_bound(AmplitudeMethod::small_angle, theta0, 0);
    if (small < tolerance) return {AmplitudeMethod::small_angle, 0, small};
    for (int n = 1; n <= kMaxAutoSeriesTerms; ++n) {
      const double b = amplitude_error_bound(AmplitudeMethod::series, theta0, n);
      if (b < tolerance) return {AmplitudeMethod::series, n, b};
    }
  }
  return {AmplitudeMethod::agm, 0, amplitude_error_bound(AmplitudeMethod::agm, theta0, 0)};
}

/// sn(u | k) by the descending Landen (AGM) scale: a_0 = 1, b_0 = kc,
/// c_0 = k; phi_N = 2^N a_N u; phi_{n-1} = (phi_n + asin(c_n sin(phi_n)/a_n))/2;
/// sn = sin(phi_0). c_{n+1} = c_n^2/(4 a_{n+1}) keeps its relative digits.
/// \param u argument (rad-like, dimensionless); \param k modulus, 0 <= k < 1;
/// \param kc complementary modulus sqrt(1 - k^2), passed so that it keeps its
/// digits as k -> 1.
/// Reference: Abramowitz & Stegun 16.4 (the method Kelley's Appendix A and
/// Eq. 12 rest on).
template <class T>
T jacobi_sn(const T& u, const T& k, const T& kc) {
  using std::asin;
  using std::sin;
  using std::sqrt;
  constexpr int kMaxSteps = 16;  // quadratic convergence: 6 reach 1e-17 for kc >= 1e-9
  std::array<T, kMaxSteps + 1> a, c;
  a[0] = T(1.0);
  c[0] = k;
  T b = kc;
  int n = 0;
  while (n < kMaxSteps && value_of(c[n]) > 1e-17 * value_of(a[n])) {
    a[n + 1] = (a[n] + b) / 2.0;
    b = sqrt(a[n] * b);
    c[n + 1] = c[n] * c[n] / (4.0 * a[n + 1]);
    ++n;
  }
  T phi = std::ldexp(1.0, n) * a[n] * u;
  for (int j = n; j > 0; --j) phi = (phi + asin(c[j] * sin(phi) / a[j])) / 2.0;
  return sin(phi);
}

/// Angle of the undamped pendulum at time t after it passes the bottom
/// moving toward +theta0: sin(theta/2) = sin(theta0/2) sn(omega0 t | k),
/// k = sin(theta0/2), the inverse of Kelley's Eq. (12).
/// \param theta0 amplitude (rad), 0 <= theta0 < pi;
/// \param omega0_t omega0 t = sqrt(g/l) t (dimensionless).
/// \return theta (rad). Its period in omega0 t is 4K(k) = 2 pi T/T0.
/// Reference: Kelley (1993) Eq. (12); Nelson & Olsson (1986) Sec. III.A.
template <class T>
T pendulum_angle(const T& theta0, const T& omega0_t) {
  using std::asin;
  using std::cos;
  using std::sin;
  detail::require_amplitude(value_of(theta0), ranges::amplitude);
  const T k = sin(theta0 / 2.0);
  return 2.0 * asin(k * jacobi_sn(omega0_t, k, cos(theta0 / 2.0)));
}

}  // namespace pendulum
