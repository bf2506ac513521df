#pragma once
/// \file clock.hpp
/// \brief Clock pendulums: circular error, impulse (escapement) error and Q,
/// after Feinstein (2005), "Impulsing the Pendulum: Escapement Error",
/// NAWCC Horological Science Chapter Newsletter 2005-3 and its Appendices.
///
/// A clock counts swings. The circular error is the free swing's excess over
/// the small-amplitude half period T0/2 = pi sqrt(l/g), as a fraction of it,
/// times 86400 s (Feinstein's Table 1: Delta T_c times 43200 cycles a day of
/// his 2-s pendulum). The impulse error is the impulsed swing's excess dt
/// over the free swing T/2 at the same amplitude, as a fraction of T/2, times
/// 86400 s: a clock regulated at that amplitude makes 86400/(T/2) swings a
/// day. Feinstein's Tables 2 and 3 divide by this T/2, circular error
/// included (docs/clock.md). Both errors are independent of l and g: they
/// are functions of the semi-amplitude, the impulse location and Q alone.
///
/// Angles in rad; daily rates in s/day; their rates of change in s/day per
/// rad (multiply by kRadPerArcsecond for Feinstein's sec/day/asec).
/// Every function is generic in the scalar (double, ceres::Jet); branches and
/// loop counts look at value_of().

#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include <ceres/jet.h>

#include "pendulum/amplitude.hpp"
#include "pendulum/numeric.hpp"

namespace pendulum {

inline constexpr double kSecondsPerDay = 86400.0;
/// One second of arc (rad).
inline constexpr double kRadPerArcsecond = kPi / 648000.0;

// ---------------------------------------------------------------------------
// Elliptic integrals
// ---------------------------------------------------------------------------

/// Carlson's symmetric integral R_F(x, y, z) = (1/2) int_0^inf
/// dt / sqrt((t+x)(t+y)(t+z)), by duplication closed with the fifth-order
/// series (DLMF 19.36.1; Carlson 1995, Numer. Algorithms 10, 13).
/// \param x, y, z >= 0, at most one of them 0 (dimensionless).
/// The loop runs until (3r)^(-1/6) max|A0 - x0| 4^-n < |A_n| with r = 1e-16,
/// where the omitted series terms are below r: 5 to 12 steps in double.
template <class T>
T carlson_rf(T x, T y, T z) {
  using std::sqrt;
  using std::fabs;
  const T x0 = x, y0 = y, a0 = (x + y + z) / 3.0;
  T a = a0;
  double q = 340.0 * std::fmax(std::fabs(value_of(a0 - x)),
                               std::fmax(std::fabs(value_of(a0 - y)), std::fabs(value_of(a0 - z))));
  double scale = 1.0;  // 4^-n
  while (q * scale >= std::fabs(value_of(a)) && scale > 1e-60) {
    const T sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
    const T lambda = sx * sy + sy * sz + sz * sx;
    x = (x + lambda) / 4.0;
    y = (y + lambda) / 4.0;
    z = (z + lambda) / 4.0;
    a = (a + lambda) / 4.0;
    scale /= 4.0;
  }
  const T dx = (a0 - x0) * scale / a;  // (A0 - x0) / (4^n A_n) = (A_n - x_n) / A_n:
  const T dy = (a0 - y0) * scale / a;  // the deviations shrink by 4 a step
  const T dz = -(dx + dy);
  const T e2 = dx * dy - dz * dz, e3 = dx * dy * dz;
  return (1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0) / sqrt(a);  // DLMF 19.36.1
}

/// Carlson's R_D(x, y, z) = (3/2) int_0^inf dt / (sqrt((t+x)(t+y)) (t+z)^(3/2)),
/// by duplication closed with the fifth-order series (DLMF 19.36.2).
/// \param x, y >= 0 (not both 0), z > 0 (dimensionless).
template <class T>
T carlson_rd(T x, T y, T z) {
  using std::sqrt;
  const T x0 = x, y0 = y, a0 = (x + y + 3.0 * z) / 5.0;
  T a = a0;
  double q = 1.2e3 * std::fmax(std::fabs(value_of(a0 - x)),
                               std::fmax(std::fabs(value_of(a0 - y)), std::fabs(value_of(a0 - z))));
  double scale = 1.0;  // 4^-n
  T sum = T(0.0);
  while (q * scale >= std::fabs(value_of(a)) && scale > 1e-60) {
    const T sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
    const T lambda = sx * sy + sy * sz + sz * sx;
    sum += scale / (sz * (z + lambda));
    x = (x + lambda) / 4.0;
    y = (y + lambda) / 4.0;
    z = (z + lambda) / 4.0;
    a = (a + lambda) / 4.0;
    scale /= 4.0;
  }
  const T dx = (a0 - x0) * scale / a, dy = (a0 - y0) * scale / a;
  const T dz = -(dx + dy) / 3.0;
  const T xy = dx * dy, z2 = dz * dz;
  const T e2 = xy - 6.0 * z2, e3 = (3.0 * xy - 8.0 * z2) * dz, e4 = 3.0 * (xy - z2) * z2,
          e5 = xy * z2 * dz;
  const T series = 1.0 - 3.0 * e2 / 14.0 + e3 / 6.0 + 9.0 * e2 * e2 / 88.0 - 3.0 * e4 / 22.0 -
                   9.0 * e2 * e3 / 52.0 + 3.0 * e5 / 26.0;
  return 3.0 * sum + scale * series / (a * sqrt(a));  // DLMF 19.36.2
}

/// Incomplete elliptic integral of the first kind from the parts of its
/// integrand that carry the digits:
/// F = sin(phi) R_F(cos^2 phi, 1 - m sin^2 phi, 1) (DLMF 19.25.5).
/// Passing cos^2 phi and Delta^2 = 1 - m sin^2 phi, each formed without
/// subtraction by the caller, keeps F accurate as phi -> pi/2 and m -> 1.
/// \param sin_phi sin(phi), 0 <= sin_phi <= 1; \param cos2_phi cos^2(phi);
/// \param delta2 1 - m sin^2(phi); not both of cos2_phi and delta2 zero.
template <class T>
T ellint_f_parts(const T& sin_phi, const T& cos2_phi, const T& delta2) {
  return sin_phi * carlson_rf(cos2_phi, delta2, T(1.0));  // DLMF 19.25.5
}

/// F(phi | m) = int_0^phi dt / sqrt(1 - m sin^2 t), 0 <= phi <= pi/2,
/// 0 <= m <= 1 (m < 1 at phi = pi/2), with its complementary parameter
/// m1 = 1 - m passed so that it keeps its digits as m -> 1 (as jacobi_sn
/// takes kc). 1 - m sin^2 phi = cos^2 phi + m1 sin^2 phi: a sum, no
/// cancellation. Relative error a few ulp (tests/test_clock.cpp).
/// Reference: Feinstein (2005) Eq. (B-5) (there F(k, phi), k^2 = m);
/// Kelley (1993) Appendix A (there F(phi | alpha), m = sin^2 alpha).
template <class T>
T ellint_f(const T& phi, const T& m, const T& m1) {
  using std::cos;
  using std::sin;
  if (!(value_of(phi) >= 0.0 && value_of(phi) <= kPi / 2.0 && value_of(m) >= 0.0 &&
        value_of(m1) >= 0.0 && value_of(m) <= 1.0)) {
    throw std::domain_error("F(phi|m) needs 0 <= phi <= pi/2 and 0 <= m <= 1");
  }
  const T s = sin(phi), c = cos(phi);
  return ellint_f_parts(s, c * c, c * c + m1 * s * s);
}

/// F(phi | m) with m1 = 1 - m formed here (exact for m >= 1/2, Sterbenz).
template <class T>
T ellint_f(const T& phi, const T& m) {
  return ellint_f(phi, m, 1.0 - m);
}

// ---------------------------------------------------------------------------
// The pendulum and its circular error
// ---------------------------------------------------------------------------

/// Speed at the bottom of the swing, v = sqrt(2 g h), h = l (1 - cos theta0)
/// = 2 l sin^2(theta0/2): v = 2 sqrt(g l) sin(theta0/2) (m/s).
/// l (m), g (m/s^2), theta0 semi-amplitude (rad). Feinstein Eq. (B-3).
template <class T>
T maximum_velocity(const T& length, const T& g, const T& theta0) {
  using std::sin;
  using std::sqrt;
  return 2.0 * sqrt(g * length) * sin(theta0 / 2.0);  // Feinstein Eq. (B-3)
}

/// Circular error: the free swing at semi-amplitude theta0 (rad) is longer
/// than T0/2 by the fraction 2K(k)/pi - 1, k = sin(theta0/2); in s/day
/// 86400 (2K/pi - 1). Feinstein Eq. (E-2) (his series, summed exactly by
/// the AGM of amplitude.hpp). 0 <= theta0 < pi.
template <class T>
T circular_error(const T& theta0) {
  return kSecondsPerDay * finite_amplitude_agm(theta0);  // Feinstein Eq. (E-2)
}

/// Rate of change of the circular error with the semi-amplitude (s/day per
/// rad): 86400 d(2K/pi)/d theta0 = 86400 sin(theta0) R_D(0, 1, cos^2(theta0/2))
/// / (6 pi), from dK/dk = (E - k'^2 K)/(k k'^2) = (k/3) R_D(0, 1, k'^2)
/// (DLMF 19.4.1, 19.25.1): no cancellation as theta0 -> 0, where it is
/// 86400 theta0 / 8. Feinstein Eq. (E-4) summed exactly. 0 <= theta0 < pi.
template <class T>
T circular_error_rate(const T& theta0) {
  using std::cos;
  using std::sin;
  const T kc = cos(theta0 / 2.0);
  return kSecondsPerDay * sin(theta0) * carlson_rd(T(0.0), T(1.0), kc * kc) / (6.0 * kPi);  // Eq. (E-4)
}

/// The semi-amplitude after an impulse that adds pi E / Q to the energy E of
/// the swing (Rawlings' Q = pi E / Delta E per swing):
/// cos(theta_i) = (1 + pi/Q) cos(theta0) - pi/Q, written as
/// sin^2(theta_i/2) = (1 + pi/Q) sin^2(theta0/2) so that no digits cancel.
/// \param theta0 semi-amplitude (rad), 0 <= theta0 < pi; \param q Q > 0.
/// \return theta_i (rad); std::domain_error when the impulse would carry the
/// pendulum over the top. Feinstein Eq. (F-1).
template <class T>
T impulsed_amplitude(const T& theta0, const T& q) {
  using std::asin;
  using std::sin;
  using std::sqrt;
  const T k_i = sqrt(1.0 + kPi / q) * sin(theta0 / 2.0);  // Feinstein Eq. (F-1)
  if (!(value_of(k_i) < 1.0)) throw std::domain_error("the impulsed swing goes over the top");
  return 2.0 * asin(k_i);
}

// ---------------------------------------------------------------------------
// Impulse (escapement) error: four routes
// ---------------------------------------------------------------------------

/// How the impulse error is computed (Feinstein's Table 2), cheapest first.
enum class ClockRoute { cycloid, circular_elliptic, cycloid_damped, circular_rk4 };

/// The name the output uses for a route.
inline const char* route_name(ClockRoute r) {
  switch (r) {
    case ClockRoute::cycloid: return "cycloid";
    case ClockRoute::circular_elliptic: return "circular_elliptic";
    case ClockRoute::cycloid_damped: return "cycloid_damped";
    case ClockRoute::circular_rk4: return "circular_rk4";
  }
  return "";
}

/// Which way the impulse pushes. Away from the position of equilibrium the
/// swing lengthens (the clock loses, error > 0); toward it the swing
/// shortens (error < 0). Feinstein Sec. VII cases B-E.
enum class ImpulseDirection { away, toward };

/// +1 away, -1 toward.
inline double direction_sign(ImpulseDirection d) { return d == ImpulseDirection::away ? 1.0 : -1.0; }

/// An impulse error and its rate of change, for an impulse away from the
/// position of equilibrium (multiply both by direction_sign for the other).
template <class T>
struct ImpulseEffect {
  T error;  ///< s/day
  T rate;   ///< d error / d(impulse location), s/day per rad (+inf at the end of the swing)
};

/// Undamped circular pendulum, exactly (Feinstein Eqs. D-1, D-2): the
/// swing differs from the free swing of its own turning amplitude by the
/// difference of the times from equilibrium to the impulse point theta at the
/// energies before and after the impulse,
///   dt = sqrt(l/g) [F(phi | k^2) - F(phi_i | k_i^2)],
///   sin phi = sin(theta/2)/k, k = sin(theta0/2), k_i^2 = (1 + pi/Q) k^2 (Eq. F-1).
/// In F's parts: sin^2 phi_i = s^2/k_i^2, cos^2 phi = (k^2 - s^2)/k^2 with
/// k^2 - s^2 = sin((theta0 - theta)/2) sin((theta0 + theta)/2) and
/// k_i^2 - s^2 = (k^2 - s^2) + (pi/Q) k^2, and Delta^2 = 1 - s^2 = cos^2(theta/2)
/// for both: nothing cancels but the final difference, which loses about
/// log10(F/dt) digits (4 at Q = 1e4; its absolute error stays near 1e-11
/// s/day, docs/clock.md).
/// The rate: d(sqrt(l/g) F)/d theta = 1/theta' = sqrt(l/g) / (2 sqrt(k^2 - s^2)),
/// Eq. (D-2) in closed form; +inf at theta = theta0.
/// \param theta0 semi-amplitude before the impulse (rad), 0 < theta0 < pi;
/// \param theta impulse location (rad), 0 <= theta <= theta0; \param q Q > 0.
template <class T>
ImpulseEffect<T> impulse_error_elliptic(const T& theta0, const T& theta, const T& q) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T k = sin(theta0 / 2.0), s = sin(theta / 2.0), c = cos(theta / 2.0);
  const T eps = kPi / q;  // Eq. (F-1): k_i^2 = (1 + eps) k^2
  const T k2 = k * k, ki2 = (1.0 + eps) * k2;
  const T d = sin((theta0 - theta) / 2.0) * sin((theta0 + theta) / 2.0);  // k^2 - s^2
  const T di = d + eps * k2;                                              // k_i^2 - s^2
  const T f = ellint_f_parts(s / k, d / k2, c * c);
  const T fi = ellint_f_parts(s / sqrt(ki2), di / ki2, c * c);
  // dt / (T/2) in s/day, dt in units of sqrt(l/g), T/2 = pi sqrt(l/g) (1 + circular error).
  const T per_swing = kSecondsPerDay / (kPi * (1.0 + finite_amplitude_agm(theta0)));
  const T rate = value_of(d) > 0.0 ? 1.0 / (2.0 * sqrt(d)) - 1.0 / (2.0 * sqrt(di))
                                   : T(HUGE_VAL);
  return {per_swing * (f - fi), per_swing * rate};  // Feinstein Eqs. (D-1), (D-2)
}

/// Undamped cycloidal pendulum in closed form (Feinstein Appendix H): the
/// arc s = 4a sin(beta) moves harmonically with omega0^2 = g/(4a), so the time
/// from equilibrium to beta is asin(sin(beta)/sin(beta0))/omega0 and
///   omega0 dt = asin(x) - asin(x/r) = asin((x/r) eps / (sqrt(r^2 - x^2) + sqrt(1 - x^2))),
/// x = sin(beta)/sin(beta0), r^2 = 1 + eps = 1 + pi/Q (sin^2 beta_i =
/// (1 + pi/Q) sin^2 beta0, Appendix F), written without cancellation.
/// Rate: cos(beta) [1/sqrt(sb0^2 - sb^2) - 1/sqrt(sb_i^2 - sb^2)] per rad of beta.
/// \param beta0 semi-amplitude as the cycloid's tangent angle (rad),
/// 0 < beta0 < pi/2; \param beta impulse location (rad), 0 <= beta <= beta0.
template <class T>
ImpulseEffect<T> impulse_error_cycloid(const T& beta0, const T& beta, const T& q) {
  using std::asin;
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T sb0 = sin(beta0), sb = sin(beta), cb = cos(beta);
  const T eps = kPi / q;
  const T d = sin(beta0 - beta) * sin(beta0 + beta);  // sb0^2 - sb^2
  const T di = d + eps * sb0 * sb0;                  // sb_i^2 - sb^2
  // 1 - x^2 = d/sb0^2, r^2 - x^2 = di/sb0^2, x/r = sb/sqrt(sb0^2 + eps sb0^2).
  const T x_over_r = sb / (sb0 * sqrt(1.0 + eps));
  const T dt = asin(x_over_r * eps * sb0 / (sqrt(di) + sqrt(d)));
  const double per_swing = kSecondsPerDay / kPi;
  const T rate = value_of(d) > 0.0 ? cb * (1.0 / sqrt(d) - 1.0 / sqrt(di)) : T(HUGE_VAL);
  return {per_swing * dt, per_swing * rate};
}

/// The cycloid's semi-amplitude (or impulse location) beta at the energy of a
/// circular swing theta (both rad), l = 4a: sin^2(beta) = 2 (1 - cos theta),
/// sin(beta) = 2 sin(theta/2). Feinstein Appendix H, last line.
/// Defined for theta <= 60 deg (sin beta <= 1).
template <class T>
T cycloid_angle_at_equal_energy(const T& theta) {
  using std::asin;
  using std::sin;
  return asin(2.0 * sin(theta / 2.0));  // Feinstein App. H: sin^2 beta0 = 2 (1 - cos theta0)
}

/// The period (s) of a clock pendulum on a circular path, impulsed once a
/// swing, undamped: T = T0 (2K(k)/pi) (1 + IE/86400), T0 = 2 pi sqrt(l/g),
/// IE the signed impulse error (s/day) of impulse_error_elliptic. A pure
/// function of (g, l, semi-amplitude, Q, impulse), for the period-model core.
/// \param g (m/s^2); \param length (m); \param theta0 semi-amplitude (rad);
/// \param q Q; \param location impulse location (rad), 0 <= location <= theta0.
/// Feinstein Eqs. (E-3), (D-1).
template <class T>
T clock_period(const T& g, const T& length, const T& theta0, const T& q, const T& location,
               ImpulseDirection direction) {
  const T free = ideal_period(length, g) * (1.0 + finite_amplitude_agm(theta0));  // Eq. (E-3)
  const T impulse = direction_sign(direction) * impulse_error_elliptic(theta0, location, q).error;
  return free * (1.0 + impulse / kSecondsPerDay);  // Eq. (D-1), one impulse a swing
}

namespace detail {

/// Time and speed at which the linearly damped oscillator x'' + x'/Q + x = 0
/// (time in 1/omega0), released from rest at x = 1, first reaches x = x1
/// (0 <= x1 <= 1): x(u) = e^{-u/2Q} (cos(w u) + sin(w u)/(2Q w)),
/// x'(u) = -e^{-u/2Q} sin(w u)/w, w = sqrt(1 - 1/(4Q^2)) (Feinstein
/// Appendix I, with A0 and delta for a release from rest). Newton's method
/// from the undamped time acos(x1).
template <class T>
std::array<T, 2> damped_oscillator_reach(const T& x1, const T& q) {
  using std::acos;
  using std::cos;
  using std::exp;
  using std::sin;
  using std::sqrt;
  const T w = sqrt(1.0 - 1.0 / (4.0 * q * q));
  T u = acos(x1);
  T v = T(0.0);
  for (int i = 0; i < 30; ++i) {
    const T e = exp(-u / (2.0 * q));
    const T x = e * (cos(w * u) + sin(w * u) / (2.0 * q * w));  // Feinstein App. I: s(t)
    v = e * sin(w * u) / w;                                      // -s'(t)
    if (value_of(v) <= 0.0) break;
    const T step = (x - x1) / v;
    u += step;
    if (std::fabs(value_of(step)) <= 1e-15 * std::fabs(value_of(u)) + 1e-300) break;  // quadratic: the next step is far below
  }
  return {u, v};
}

}  // namespace detail

/// Linearly damped cycloidal pendulum, in closed form (Feinstein Appendix I:
/// s'' + s'/tau + omega0^2 s = 0, 1/tau = omega0/Q). The swing toward
/// equilibrium is released from rest at beta0 (energy E) and, for the
/// impulsed swing, at beta_i (energy (1 + pi/Q) E, Appendix F); the impulse
/// error is the difference of their times from the impulse point beta to
/// equilibrium, the rate the difference of 1/(d beta/dt) there. Feinstein
/// reports it for one direction only; the same magnitude is used for both.
/// Differs from the undamped cycloid by O(1/Q) of the error.
/// \param beta0 (rad), 0 < beta0 < pi/2; \param beta (rad), 0 <= beta <= beta0; \param q Q > 1/2.
template <class T>
ImpulseEffect<T> impulse_error_cycloid_damped(const T& beta0, const T& beta, const T& q) {
  using std::atan;
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T sb0 = sin(beta0), sb = sin(beta), cb = cos(beta);
  const T sbi = sb0 * sqrt(1.0 + kPi / q);
  const T w = sqrt(1.0 - 1.0 / (4.0 * q * q));
  // Released from rest, x reaches 0 at w u = pi/2 + atan(1/(2 Q w)).
  const T u_zero = (kPi / 2.0 + atan(1.0 / (2.0 * q * w))) / w;
  const auto pre = detail::damped_oscillator_reach(sb / sb0, q);
  const auto post = detail::damped_oscillator_reach(sb / sbi, q);
  const T dt = (u_zero - pre[0]) - (u_zero - post[0]);
  // d beta/du = (ds/du)/(ds/d beta) = amplitude * v / cos(beta), s = l sin(beta).
  const bool at_end = value_of(pre[1]) <= 0.0;
  const T rate = at_end ? T(HUGE_VAL) : cb / (sb0 * pre[1]) - cb / (sbi * post[1]);
  const double per_swing = kSecondsPerDay / kPi;
  return {per_swing * dt, per_swing * rate};
}

namespace detail {

/// State of the damped circular pendulum theta'' + theta'/Q + sin(theta) = 0,
/// time in units of 1/omega0: theta (rad), alpha = d theta/du (rad).
template <class T>
struct SwingState {
  T theta, alpha;
};

/// One classic RK4 step of length z in Feinstein's Appendix G form,
/// f(theta, alpha) = -sin(theta) - alpha/Q:
/// theta += z alpha + (z/6)(n1 + n2 + n3), alpha += (n1 + 2 n2 + 2 n3 + n4)/6.
template <class T>
SwingState<T> rk4_swing_step(const SwingState<T>& x, const T& z, const T& q) {
  using std::sin;
  auto f = [&](const T& theta, const T& alpha) { return -sin(theta) - alpha / q; };
  const T n1 = z * f(x.theta, x.alpha);
  const T n2 = z * f(x.theta + z / 2.0 * x.alpha, x.alpha + n1 / 2.0);
  const T n3 = z * f(x.theta + z / 2.0 * x.alpha + z / 4.0 * n1, x.alpha + n2 / 2.0);
  const T n4 = z * f(x.theta + z * x.alpha + z / 2.0 * n2, x.alpha + n3);
  return {x.theta + z * x.alpha + z / 6.0 * (n1 + n2 + n3),  // Feinstein App. G
          x.alpha + (n1 + 2.0 * n2 + 2.0 * n3 + n4) / 6.0};
}

/// Released from rest at theta0 (rad), the damped swing toward equilibrium
/// by RK4 with `steps` steps a small-amplitude period: the times (1/omega0)
/// from the impulse point theta to theta = 0, and |alpha| at theta. The
/// crossing inside a step is found by Newton's method on the length of one
/// RK4 step from the step's start.
template <class T>
std::array<T, 2> rk4_time_to_equilibrium(const T& theta0, const T& theta, const T& q, int steps) {
  const T z = T(2.0 * kPi / steps);
  // The partial step h from `start` with theta(h) = target, from the
  // linear interpolation to `next`; d theta/dh ~ alpha.
  auto crossing = [&](const SwingState<T>& start, const SwingState<T>& next, const T& target) {
    T h = z * (start.theta - target) / (start.theta - next.theta);
    SwingState<T> end = rk4_swing_step(start, h, q);
    for (int i = 0; i < 20; ++i) {
      const T step = (end.theta - target) / end.alpha;
      h -= step;
      end = rk4_swing_step(start, h, q);
      if (std::fabs(value_of(step)) <= 1e-16 * value_of(z)) break;
    }
    return std::array<T, 2>{h, -end.alpha};
  };
  SwingState<T> x{theta0, T(0.0)};
  T u_theta = T(0.0), speed = T(0.0);
  bool passed = value_of(theta) >= value_of(theta0);  // an impulse at the turning point
  for (int i = 0; i < 8 * steps; ++i) {  // 8 small-amplitude periods
    const T u = double(i) * z;  // not summed: a sum of z would drift by i ulp
    const SwingState<T> next = rk4_swing_step(x, z, q);
    if (!passed && value_of(next.theta) <= value_of(theta)) {
      const auto c = crossing(x, next, theta);
      u_theta = u + c[0];
      speed = c[1];
      passed = true;
    }
    if (value_of(next.theta) <= 0.0) return {u + crossing(x, next, T(0.0))[0] - u_theta, speed};
    x = next;
  }
  throw std::domain_error("the damped swing did not reach equilibrium (Q too small)");
}

}  // namespace detail

/// Linearly damped circular pendulum by RK4 (Feinstein Appendix G:
/// theta'' + (omega0/Q) theta' + omega0^2 sin(theta) = 0), as
/// impulse_error_cycloid_damped: swings released from rest at theta0 and at
/// theta_i (Eq. F-1), the difference of their times from theta to
/// equilibrium and of 1/theta' at theta. `steps` RK4 steps a small-amplitude
/// period; the error falls as steps^-4 (docs/clock.md).
/// \param theta0 (rad), 0 < theta0 < pi; \param theta (rad), 0 <= theta <= theta0;
/// \param q Q > 1/2; \param steps >= 16.
template <class T>
ImpulseEffect<T> impulse_error_rk4(const T& theta0, const T& theta, const T& q, int steps) {
  const auto pre = detail::rk4_time_to_equilibrium(theta0, theta, q, steps);
  const auto post = detail::rk4_time_to_equilibrium(impulsed_amplitude(theta0, q), theta, q, steps);
  const T per_swing = kSecondsPerDay / (kPi * (1.0 + finite_amplitude_agm(theta0)));
  const T rate = value_of(pre[1]) > 0.0 ? 1.0 / pre[1] - 1.0 / post[1] : T(HUGE_VAL);
  return {per_swing * (pre[0] - post[0]), per_swing * rate};
}

// ---------------------------------------------------------------------------
// The clock: routes, their error bounds, the cheapest adequate route
// ---------------------------------------------------------------------------

/// The path of the bob: a circle (a plain pendulum) or a cycloid (Huygens'
/// cheeks; isochronous, no circular error).
enum class ClockPath { circular, cycloidal };

/// Does `route` model `path` (exactly or approximately)? The cycloid routes
/// approximate the circular path at equal energy; the circular routes do not
/// model a cycloid.
inline bool route_fits(ClockRoute route, ClockPath path) {
  return path == ClockPath::circular || route == ClockRoute::cycloid ||
         route == ClockRoute::cycloid_damped;
}

/// Impulse error of an impulse away from equilibrium at `location` (rad) on
/// a swing of semi-amplitude theta0 (rad) on `path`, by `route`. On the
/// circular path the cycloid routes take the cycloid of equal energy
/// (cycloid_angle_at_equal_energy) and their rate is converted to per rad of
/// theta by d beta/d theta = cos(theta/2)/cos(beta). On the cycloidal path
/// theta0 and location are the tangent angles beta0, beta.
/// \param rk4_steps RK4 steps a period (circular_rk4 only).
template <class T>
ImpulseEffect<T> impulse_error(ClockRoute route, ClockPath path, const T& theta0,
                               const T& location, const T& q, int rk4_steps) {
  using std::cos;
  if (!route_fits(route, path)) throw std::domain_error("a circular route does not model a cycloid");
  switch (route) {
    case ClockRoute::circular_elliptic: return impulse_error_elliptic(theta0, location, q);
    case ClockRoute::circular_rk4: return impulse_error_rk4(theta0, location, q, rk4_steps);
    case ClockRoute::cycloid:
    case ClockRoute::cycloid_damped: break;
  }
  auto by_cycloid = [&](const T& b0, const T& b) {
    return route == ClockRoute::cycloid ? impulse_error_cycloid(b0, b, q)
                                        : impulse_error_cycloid_damped(b0, b, q);
  };
  if (path == ClockPath::cycloidal) return by_cycloid(theta0, location);
  const T beta = cycloid_angle_at_equal_energy(location);
  ImpulseEffect<T> e = by_cycloid(cycloid_angle_at_equal_energy(theta0), beta);
  e.rate *= cos(location / 2.0) / cos(beta);
  return e;
}

/// Largest semi-amplitude (rad) at which the cycloid routes can stand for a
/// circular path: 2 sin(theta0/2) <= 1 (60 deg); the automatic choice uses
/// them up to 30 deg, the range where their bound is tested.
inline constexpr double kCycloidStandInMaxAmplitude = kPi / 6.0;

/// Relative and absolute parts of a route's error bound against the model
/// the scene asks for (path, damped or not): |error| <= relative |value| +
/// absolute, for the impulse error and its rate alike. Measured maxima over
/// semi-amplitudes to 30 deg, Q from 100 to 1e6 and the whole swing
/// (tests/test_clock.cpp asserts each on that grid):
///  - a cycloid for a circle: 0.26 m, m = sin^2(theta0/2) (the circular
///    error's 2K/pi - 1 ~ m/4 is the scale): bound 0.3 m;
///  - an undamped route for a damped scene: 0.79/Q (the damping's effect on
///    the difference of two damped swings): bound 1/Q;
///  - the closed forms' rounding, amplified by the final difference: below
///    1e-11 s/day: bound 1e-10 s/day absolute.
/// The RK4 route's bound is its step-doubling estimate (cheapest_clock_route).
struct RouteBound {
  double relative, absolute;  ///< (1), (s/day or s/day per rad)
};

inline RouteBound route_error_bound(ClockRoute route, ClockPath path, bool damped, double theta0,
                                    double q) {
  const double k = std::sin(theta0 / 2.0);
  double relative = 0.0;
  if (path == ClockPath::circular &&
      (route == ClockRoute::cycloid || route == ClockRoute::cycloid_damped)) {
    relative += 0.3 * k * k;
  }
  if (damped && (route == ClockRoute::cycloid || route == ClockRoute::circular_elliptic)) {
    relative += 1.0 / q;
  }
  return {relative, 1e-10};
}

/// A route with its result and bounds.
struct ClockChoice {
  ClockRoute route;
  int rk4_steps;                 ///< steps a period; 0 unless circular_rk4
  ImpulseEffect<double> effect;  ///< away from equilibrium
  double error_bound;            ///< bound on |error of effect.error| (s/day)
  double rate_bound;             ///< bound on |error of effect.rate| (s/day per rad)
};

/// Most RK4 steps a period the automatic choice tries (2^14).
inline constexpr int kMaxRk4Steps = 1 << 14;

/// The exact route of a scene's model.
inline ClockRoute exact_clock_route(ClockPath path, bool damped) {
  if (path == ClockPath::cycloidal) return damped ? ClockRoute::cycloid_damped : ClockRoute::cycloid;
  return damped ? ClockRoute::circular_rk4 : ClockRoute::circular_elliptic;
}

/// The impulse error by `route` with its bounds against the scene's model
/// (route_error_bound). RK4 doubles its steps a period from 64 until its
/// bound 2 |v(2N) - v(N)| + floor is within `tolerance` (s/day), or the
/// steps reach kMaxRk4Steps, or 1024 when tolerance <= 0; the bound says
/// what was reached. The error of the difference of two integrated swings
/// falls 10- to 100-fold a doubling down to 256 steps, then wanders below
/// the floor 1e-9 |v| + 1e-8 s/day (measured 3e-9 s/day at 8.9 s/day,
/// tests/test_clock.cpp).
/// \param theta0, location (rad); \param q Q.
inline ClockChoice run_clock_route(ClockRoute route, ClockPath path, bool damped, double theta0,
                                   double location, double q, double tolerance) {
  if (route != ClockRoute::circular_rk4) {
    const RouteBound b = route_error_bound(route, path, damped, theta0, q);
    const ImpulseEffect<double> e = impulse_error(route, path, theta0, location, q, 0);
    return {route, 0, e, b.relative * std::fabs(e.error) + b.absolute,
            b.relative * std::fabs(e.rate) + b.absolute};
  }
  int steps = 64;
  ImpulseEffect<double> coarse = impulse_error_rk4(theta0, location, q, steps);
  for (;;) {
    const ImpulseEffect<double> fine = impulse_error_rk4(theta0, location, q, 2 * steps);
    // Without damping in the scene, RK4 still integrates the damped model.
    const double model = damped ? 0.0 : 1.0 / q;
    const double bound = 2.0 * std::fabs(fine.error - coarse.error) +
                         (1e-9 + model) * std::fabs(fine.error) + 1e-8;
    const double rate_bound = std::isfinite(fine.rate)
                                  ? 2.0 * std::fabs(fine.rate - coarse.rate) +
                                        (1e-9 + model) * std::fabs(fine.rate) + 1e-8
                                  : HUGE_VAL;
    steps *= 2;
    if (bound <= tolerance || steps >= kMaxRk4Steps || (tolerance <= 0.0 && steps >= 1024)) {
      return {ClockRoute::circular_rk4, steps, fine, bound, rate_bound};
    }
    coarse = fine;
  }
}

/// The cheapest route (ClockRoute order: undamped cycloid, circular closed
/// form, damped cycloid, RK4) whose error bound on the impulse error is
/// within `tolerance` (s/day); the exact route of the scene's model when
/// none is, or when tolerance <= 0. The cycloid routes stand for a circle
/// only up to kCycloidStandInMaxAmplitude.
/// \param theta0, location (rad); \param q Q.
inline ClockChoice cheapest_clock_route(ClockPath path, bool damped, double theta0,
                                        double location, double q, double tolerance) {
  const ClockRoute exact = exact_clock_route(path, damped);
  for (ClockRoute r : {ClockRoute::cycloid, ClockRoute::circular_elliptic, ClockRoute::cycloid_damped,
                       ClockRoute::circular_rk4}) {
    if (!route_fits(r, path) || (tolerance <= 0.0 && r != exact)) continue;
    if (path == ClockPath::circular && (r == ClockRoute::cycloid || r == ClockRoute::cycloid_damped) &&
        theta0 > kCycloidStandInMaxAmplitude) {
      continue;
    }
    const ClockChoice c = run_clock_route(r, path, damped, theta0, location, q, tolerance);
    if (r == exact || c.error_bound <= tolerance) return c;
  }
  return run_clock_route(exact, path, damped, theta0, location, q, tolerance);
}

/// The semi-amplitude (rad) at which the rates of change of the circular
/// error (Eq. E-4) and of the impulse error (Eq. D-2) cancel: Feinstein
/// Sec. IX. The impulse stays at the location (rad) or at the fraction of
/// the semi-amplitude (`relative`) given. Only an impulse toward
/// equilibrium can cancel (its rate is negative, the circular error's
/// positive), only on a circular path. Undamped circular route; bisection
/// to 1e-15 relative on the semi-amplitudes where the impulsed swing stays
/// below 170 deg. \return nullopt when no semi-amplitude cancels.
inline std::optional<double> cancelling_semi_amplitude(ImpulseDirection direction, double location,
                                                       bool relative, double q) {
  if (direction != ImpulseDirection::toward) return std::nullopt;
  if (relative && !(location < 1.0)) return std::nullopt;  // the rate is infinite at the end
  auto total_rate = [&](double theta0) {
    const double theta = relative ? location * theta0 : location;
    return circular_error_rate(theta0) - impulse_error_elliptic(theta0, theta, q).rate;
  };
  // Upper end: the impulsed swing below 170 deg (Eq. F-1).
  const double hi_limit = 2.0 * std::asin(std::sin(radians(85.0)) / std::sqrt(1.0 + kPi / q));
  double lo = relative ? 1e-9 : location * (1.0 + 1e-12) + 1e-300;
  double hi = hi_limit;
  if (!(lo < hi) || total_rate(lo) >= 0.0 || total_rate(hi) <= 0.0) return std::nullopt;
  while (hi - lo > 1e-15 * hi) {
    const double mid = (lo + hi) / 2.0;
    (total_rate(mid) < 0.0 ? lo : hi) = mid;
  }
  return (lo + hi) / 2.0;
}

/// The semi-amplitude (rad) at which the clock's daily loss, circular plus
/// impulse error, does not change with the amplitude when the impulse stays
/// at a fixed location (rad) with a fixed Q:
/// d/d theta0 [CE(theta0) + IE(theta0, location)] = 0, the impulse error's
/// derivative by ceres::Jet of Eq. (D-1). Because IE depends on
/// location/theta0 almost alone, its derivative is about -(location/theta0)
/// times Feinstein's rate: positive for an impulse toward equilibrium (no
/// root), negative away from it. Bisection to 1e-15 relative between the
/// location and the semi-amplitude whose impulsed swing reaches 170 deg.
/// \return nullopt when none exists. Not in Feinstein (2005); see
/// docs/clock.md for why Sec. IX's rates do not measure this.
inline std::optional<double> amplitude_insensitive_semi_amplitude(ImpulseDirection direction,
                                                                  double location, double q) {
  using Jet = ceres::Jet<double, 1>;
  const double sign = direction_sign(direction);
  auto total_rate = [&](double theta0) {
    return circular_error_rate(theta0) +
           sign * impulse_error_elliptic(Jet(theta0, 0), Jet(location), Jet(q)).error.v[0];
  };
  const double hi = 2.0 * std::asin(std::sin(radians(85.0)) / std::sqrt(1.0 + kPi / q));
  double lo = location * (1.0 + 1e-9) + 1e-300;
  if (!(lo < hi) || !(total_rate(lo) < 0.0) || !(total_rate(hi) > 0.0)) return std::nullopt;
  double top = hi;
  while (top - lo > 1e-15 * top) {
    const double mid = (lo + top) / 2.0;
    (total_rate(mid) < 0.0 ? lo : top) = mid;
  }
  return (lo + top) / 2.0;
}

}  // namespace pendulum
