#pragma once
/// \file numeric.hpp
/// \brief Small helpers that let the physics run on `double` and on
/// automatic-differentiation scalars (ceres::Jet) alike.

#include <cmath>
#include <type_traits>

namespace pendulum {

/// The plain value of a scalar: `x` for arithmetic types, the value part
/// (`x.a`, recursively) for ceres::Jet and other dual numbers. Used only for
/// control flow (series cut-offs, convergence tests), never in a result.
template <class T>
double value_of(const T& x) {
  if constexpr (std::is_arithmetic_v<T>) {
    return static_cast<double>(x);
  } else {
    return value_of(x.a);
  }
}

/// pi to double precision.
inline constexpr double kPi = 3.14159265358979323846;

/// One degree in radians, and one radian in degrees: a name for each
/// direction, so that a constant called "degree" cannot mean either.
inline constexpr double kRadiansPerDegree = kPi / 180.0;
inline constexpr double kDegreesPerRadian = 180.0 / kPi;

/// An angle x (rad) in degrees, and d (deg) in radians. As x * 180 / pi and
/// d * pi / 180, which round differently in the last bit from a product
/// with the constants above: the JSON prints every bit, and was made so.
/// The recordings' amplitudes (recording_writer.cpp, the Python module)
/// were made by the product, and keep it.
template <class T>
constexpr T degrees(const T& x) {
  return x * 180.0 / kPi;
}
template <class T>
constexpr T radians(const T& d) {
  return d * kPi / 180.0;
}

/// Standard gravity (m/s^2), used only to judge plausibility, never in g.
inline constexpr double kStandardGravity = 9.80665;

/// T0 = 2 pi sqrt(l/g) (s): the small-amplitude period of the ideal
/// pendulum of length l (m; a rigid body's equivalent length) in gravity g
/// (m/s^2). Nelson & Olsson (1986) Eq. (3); Kelley (1993) Eq. (56) without
/// K. g may be a plain number where the scalar T is a dual number (the fit
/// evaluates at g = 1).
template <class T, class G>
T ideal_period(const T& l, const G& g) {
  using std::sqrt;
  return 2.0 * kPi * sqrt(l / g);  // Eq. (3)
}

/// g = 4 pi^2 l / T^2 (m/s^2): the gravity in which the ideal pendulum of
/// length l (m) swings in period T (s), Eq. (3) solved for g.
template <class T>
T gravity_for_period(const T& l, const T& period) {
  return 4.0 * kPi * kPi * l / (period * period);
}

/// g = 4 pi^2 / s (m/s^2) from the slope s (s^2/m) of T^2 against l, the
/// textbook line T^2 = (4 pi^2/g) l (Eq. 3 squared); read backwards, the
/// slope (s^2/m) for a g (m/s^2).
template <class T>
T gravity_for_slope(const T& slope) {
  return 4.0 * kPi * kPi / slope;
}

/// l = p^2 g / (4 pi^2) (m): the length of the ideal pendulum of period p
/// (s) in gravity g (m/s^2). Feinstein (2005) Eq. (B-1).
template <class T>
T length_for_period(const T& p, const T& g) {
  return p * p * g / (4.0 * kPi * kPi);  // Feinstein Eq. (B-1)
}

}  // namespace pendulum
