#pragma once
/// \file bodies.hpp
/// \brief A rigid pendulum built from parts: each part's mass, centre and
/// moment of inertia, the body's centre of mass and radius of gyration, its
/// moment of inertia about a pivot, its equivalent length and its period
/// (Kelley 1993, Sec. V c, Eqs. 53-56 and Fig. 9).
///
/// Frame: every part is centred on the body's axis, the line through the
/// pivot and the centre of mass. Positions are along that axis (m), from a
/// mark on the body, increasing downwards when the body hangs from a pivot
/// above its centre. The swing axis is horizontal and perpendicular to the
/// body's axis; every moment of inertia is about an axis parallel to it.
/// A hole is a part of negative mass (the material removed).
///
/// Pure functions, generic in the scalar (double, ceres::Jet).

#include <cmath>
#include <vector>

#include "pendulum/amplitude.hpp"
#include "pendulum/numeric.hpp"

namespace pendulum {

/// A shape's geometry, independent of its mass.
template <class T>
struct Shape {
  T volume;            ///< (m^3); 0 for the idealised shapes (point, thin rod), which need a mass
  T gyration_squared;  ///< I/m about the shape's centre, about the swing axis (m^2)
  T half_length;       ///< half its extent along the body's axis (m)
};

/// Point mass (Kelley's "dimensionless bob"): I = 0.
template <class T>
Shape<T> point_mass_shape() {
  return {T(0.0), T(0.0), T(0.0)};
}

/// Solid sphere of radius r (m), r >= 0: V = (4/3) pi r^3, I = (2/5) m r^2
/// (Kelley 1993, Fig. 9, "solid sphere about any diameter"; Eq. 57).
template <class T>
Shape<T> solid_sphere(const T& r) {
  return {4.0 / 3.0 * kPi * r * r * r, 0.4 * r * r, r};  // Fig. 9
}

/// Spherical shell of outer radius a and inner radius b (m), 0 <= b <= a:
/// V = (4/3) pi (a^3 - b^3), I = (2/5) m (a^5 - b^5)/(a^3 - b^3), written as
/// (2/5) m (a^4 + a^3 b + a^2 b^2 + a b^3 + b^4)/(a^2 + a b + b^2) so that
/// the thin shell b = a gives Fig. 9's (2/3) m a^2 without 0/0, and b = 0
/// the solid sphere.
template <class T>
Shape<T> spherical_shell(const T& a, const T& b) {
  const T a2 = a * a, b2 = b * b, ab = a * b;
  const T k2 = 0.4 * (a2 * a2 + a2 * ab + ab * ab + ab * b2 + b2 * b2) / (a2 + ab + b2);  // Fig. 9 (b = a)
  return {4.0 / 3.0 * kPi * (a * a2 - b * b2), k2, a};
}

/// Which way a cylinder's (or disk's, or ring's) own axis points.
enum class CylinderAxis {
  swing_axis,       ///< parallel to the swing axis: turns "about its axis" (a disk bob seen face on, a hole in a bar)
  body_axis,        ///< along the body's axis: turns "across" it (a rod, a hanging cylinder bob)
  swing_direction,  ///< horizontal in the plane of swing: across it too (a ring or disk seen edge on)
};

/// Hollow cylinder (tube) of outer radius a, inner radius b and length L
/// (m), 0 <= b <= a, L >= 0; b = 0 is the solid cylinder, L = 0 a flat
/// disk (b = 0) or ring (annulus). V = pi (a^2 - b^2) L, and
///   about its axis:  I = (m/2)(a^2 + b^2)                (Fig. 9, annular cylinder)
///   across its axis: I = m [(a^2 + b^2)/4 + L^2/12]      (Fig. 9, cylinder about a central diameter)
/// Its extent along the body's axis is 2a, or L when its axis is the body's.
template <class T>
Shape<T> cylinder(const T& a, const T& b, const T& length, CylinderAxis axis) {
  const T r2 = a * a + b * b;
  const T volume = kPi * (a * a - b * b) * length;
  if (axis == CylinderAxis::swing_axis) return {volume, 0.5 * r2, a};  // Fig. 9
  return {volume, 0.25 * r2 + length * length / 12.0,                  // Fig. 9
          axis == CylinderAxis::body_axis ? T(0.5 * length) : a};
}

/// Thin rod of length L (m) along the body's axis: I = m L^2/12 about its
/// centre (Kelley 1993, Fig. 9; m L^2/3 about its end, Eq. 45).
template <class T>
Shape<T> thin_rod(const T& length) {
  return {T(0.0), length * length / 12.0, 0.5 * length};  // Fig. 9
}

/// Rectangular box (a metre stick, a bar) with sides a along the body's
/// axis, b along the direction of swing and c along the swing axis (m):
/// V = a b c, I = m (a^2 + b^2)/12 (the plate's perpendicular-axis
/// theorem; c does not enter).
template <class T>
Shape<T> box(const T& a, const T& b, const T& c) {
  return {a * b * c, (a * a + b * b) / 12.0, 0.5 * a};
}

/// One part of a body: mass, centre and moment of inertia about its centre.
template <class T>
struct Part {
  T mass;     ///< (kg); negative for a hole
  T center;   ///< position of its centre along the body's axis (m)
  T inertia;  ///< about its own centre, about the swing axis (kg m^2)
};

/// A part of `shape` with mass m (kg, negative for a hole) centred at x (m).
template <class T>
Part<T> make_part(const Shape<T>& shape, const T& m, const T& x) {
  return {m, x, m * shape.gyration_squared};
}

/// What the swing of a rigid body depends on.
template <class T>
struct BodyProperties {
  T mass;               ///< M = sum m_i (kg)
  T center;             ///< x_c = sum m_i x_i / M (m)
  T inertia_center;     ///< I_c = sum [I_i + m_i (x_i - x_c)^2] (kg m^2), parallel axes
  T radius_of_gyration; ///< k = sqrt(I_c / M) (m)
};

/// The body of `parts` (at least one, total mass > 0). The inertia about
/// the centre of mass is summed about x_c directly, not as I_pivot - M h^2,
/// which would lose digits to cancellation when h >> k.
template <class T>
BodyProperties<T> body_properties(const std::vector<Part<T>>& parts) {
  using std::sqrt;
  T mass(0.0), moment(0.0);
  for (const auto& p : parts) {
    mass += p.mass;
    moment += p.mass * p.center;
  }
  const T center = moment / mass;
  T inertia(0.0);
  for (const auto& p : parts) {
    const T d = p.center - center;
    inertia += p.inertia + p.mass * d * d;  // parallel-axis theorem (Kelley 1993, before Eq. 57)
  }
  return {mass, center, inertia, sqrt(inertia / mass)};
}

/// Moment of inertia about a pivot at distance h (m) from the centre of
/// mass: I = I_c + M h^2 (kg m^2), the parallel-axis theorem.
template <class T>
T inertia_about_pivot(const BodyProperties<T>& body, const T& h) {
  return body.inertia_center + body.mass * h * h;
}

/// Equivalent length l = I/(M h) = (k^2 + h^2)/h (m): the simple pendulum
/// of the same period (Kelley 1993, Eq. 55, l_c = h the pivot to the centre
/// of mass). \param k radius of gyration about the centre of mass (m);
/// \param h pivot to centre of mass (m), > 0 (h = 0: no restoring torque).
template <class T>
T equivalent_length(const T& k, const T& h) {
  return (k * k + h * h) / h;  // Eq. (55)
}

/// Period of a rigid body swinging at amplitude theta0 (rad) about a pivot h
/// (m) from its centre of mass, radius of gyration k (m), in gravity g
/// (m/s^2): T = 4 sqrt(I/(g M h)) K(sin^2(theta0/2)) = 2 pi sqrt(l/g) 2K/pi
/// with l = (k^2 + h^2)/h (Kelley 1993, Eq. 56, K by the AGM).
/// Validity: h > 0, 0 <= theta0 < pi; a rigid body and a knife-edge pivot
/// (no air, no flexure).
template <class T>
T physical_pendulum_period(const T& g, const T& k, const T& h, const T& theta0) {
  const T t0 = ideal_period(equivalent_length(k, h), g);
  return t0 * (1.0 + finite_amplitude_agm(theta0));  // Eq. (56)
}

/// A length L0 at 0 degC of a material with linear expansion coefficient w
/// (1/K), at temperature C (degC): l = L0 (1 + w C) (Kelley 1993, Eq. 41).
/// Validity: Kelley's table holds for 10-90 degC.
template <class T>
T thermal_length(const T& length0, const T& w, const T& celsius) {
  return length0 * (1.0 + w * celsius);  // Eq. (41)
}

/// A material's linear expansion coefficient w (1/K), Eq. (41), with a
/// standard uncertainty and what it rests on.
struct ExpansionCoefficient {
  const char* material;
  double w;            ///< (1/K = 1/degC)
  double uncertainty;  ///< standard uncertainty of w (1/K)
  const char* basis;   ///< where the uncertainty comes from
};

/// sqrt(12): a value known only to lie in an interval of width d is uniform
/// there, with standard uncertainty d/sqrt(12) (GUM 4.3.7).
inline constexpr double kSqrt12 = 3.4641016151377546;

/// Kelley (1993) Sec. V a, the table after Eq. (41) (his Ref. 7, the
/// Handbook of Chemistry and Physics, 40th ed.): averages over grades and
/// alloys, for 10-90 degC. The uncertainties: for steel and wood the range
/// Kelley gives beside the table (steels 9.07e-6 to 1.21e-5, woods along the
/// grain 2.6e-6 beech to 9.5e-6 ash), for mercury the rounding of the
/// cubical 1.8e-4 it is a third of, for the others the rounding of the
/// printed value (half a unit of its last digit either way); each interval
/// taken as uniform. The rounding understates the spread between grades,
/// which Kelley gives only for steel and wood.
inline constexpr ExpansionCoefficient kExpansionCoefficients[] = {
    {"aluminum", 2.3e-5, 1e-6 / kSqrt12, "the printed 2.3e-5 rounded to 1e-6"},
    {"brass", 1.9e-5, 1e-6 / kSqrt12, "the printed 1.9e-5 rounded to 1e-6"},
    {"copper", 1.7e-5, 1e-6 / kSqrt12, "the printed 1.7e-5 rounded to 1e-6"},
    {"glass", 8.3e-6, 1e-7 / kSqrt12, "the printed 8.3e-6 rounded to 1e-7"},
    {"invar", 7e-7, 1e-7 / kSqrt12, "the printed 7e-7 rounded to 1e-7"},
    {"iron", 1.1e-5, 1e-6 / kSqrt12, "the printed 1.1e-5 rounded to 1e-6"},
    {"mercury", 6e-5, 1e-5 / 3.0 / kSqrt12, "a third of the cubical 1.8e-4 rounded to 1e-5"},
    {"steel", 1.1e-5, (1.21e-5 - 9.07e-6) / kSqrt12, "Kelley's range for typical steels, 9.07e-6 to 1.21e-5"},
    {"wood", 6e-6, (9.5e-6 - 2.6e-6) / kSqrt12, "Kelley's range along the grain, 2.6e-6 (beech) to 9.5e-6 (ash)"},
};

}  // namespace pendulum
