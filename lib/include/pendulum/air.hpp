#pragma once
/// \file air.hpp
/// \brief The air: its density and viscosity, buoyancy and added mass (of a
/// sphere, and of a long bar swinging across its length).
///
/// SI units throughout: Pa, K, kg/mol, kg/m^3, Pa s, m, kg, rad/s.

#include <cmath>

#include "pendulum/numeric.hpp"

namespace pendulum {

/// Molar gas constant (J/(mol K)), exact in the 2019 SI.
inline constexpr double kGasConstant = 8.314462618;

/// Molar mass of dry air (kg/mol) used by Nelson & Olsson (1986) Sec. III.C.1.
inline constexpr double kDryAirMolarMass = 0.02896;

/// Ideal-gas density rho = p M / (R T).
/// \param p pressure (Pa) > 0; \param t absolute temperature (K) > 0;
/// \param molar_mass (kg/mol) > 0. \return density (kg/m^3).
/// Reference: Nelson & Olsson (1986) Sec. III.C.1 (1.171 kg/m^3 at
/// 100.44 kPa, 25.5 degC). Validity: dry air near ambient conditions, where
/// the ideal-gas law is good to about 1e-3.
template <class T>
T air_density(const T& p, const T& t, const T& molar_mass) {
  return p * molar_mass / (kGasConstant * t);
}

/// Dynamic viscosity of air by Sutherland's law,
/// eta = eta_0 (t/t_0)^{3/2} (t_0 + S)/(t + S), eta_0 = 1.716e-5 Pa s,
/// t_0 = 273.15 K, S = 110.4 K.
/// \param t absolute temperature (K) > 0. \return viscosity (Pa s).
/// Reference: F. M. White, Viscous Fluid Flow (Nelson & Olsson's Ref. 34).
/// Validity: about 2% from 170 K to 1900 K; at 25.5 degC it gives
/// 1.840e-5 Pa s where Nelson & Olsson quote 1.853e-5 (0.7% apart).
template <class T>
T air_viscosity(const T& t) {
  using std::sqrt;
  constexpr double eta0 = 1.716e-5, t0 = 273.15, s = 110.4;
  const T r = t / t0;
  return eta0 * r * sqrt(r) * (t0 + s) / (t + s);
}

/// Volume of a sphere of radius a (m): (4/3) pi a^3 (m^3).
template <class T>
T sphere_volume(const T& a) {
  return 4.0 / 3.0 * kPi * a * a * a;
}

/// Buoyancy: DeltaT/T0 = (1/2)(m_a/m).
/// \param m_a mass of the displaced air (kg); \param m bob mass (kg).
/// Reference: Nelson & Olsson (1986) Eq. (16).
template <class T>
T buoyancy(const T& m_a, const T& m) {
  return 0.5 * m_a / m;
}

/// Viscous penetration depth delta = sqrt(2 eta / (omega0 rho)).
/// \param eta viscosity (Pa s); \param omega0 angular frequency (rad/s);
/// \param rho density (kg/m^3). \return delta (m).
/// Reference: Nelson & Olsson (1986) text before Eq. (60).
template <class T>
T penetration_depth(const T& eta, const T& omega0, const T& rho) {
  using std::sqrt;
  return sqrt(2.0 * eta / (omega0 * rho));
}

/// Reciprocal of the acceleration modulus of a swinging sphere,
/// 1/M_A = l theta0 / (sqrt(2) d), where M_A = sqrt(2) d / (l theta0).
/// The reciprocal stays finite as theta0 -> 0 (M_A -> infinity).
/// \param d sphere diameter (m); \param l pivot to centre (m);
/// \param theta0 amplitude (rad). Reference: Nelson & Olsson (1986) after
/// Eq. (61) (M_A = 0.55 for their pendulum).
template <class T>
T inverse_acceleration_modulus(const T& d, const T& l, const T& theta0) {
  return l * theta0 / (1.4142135623730950488 * d);
}

/// Added-mass coefficient C_A = 2.10 - 0.132 M_A^2 / (1 + 0.12 M_A^2), written
/// in x = 1/M_A as 2.10 - 0.132 / (x^2 + 0.12) so that M_A -> infinity gives
/// the ideal-fluid limit C_A = 1.
/// \param x 1/M_A >= 0. Reference: Nelson & Olsson (1986) Eq. (61a), after
/// Odar & Hamilton (1964).
template <class T>
T added_mass_coefficient(const T& x) {
  return 2.10 - 0.132 / (x * x + 0.12);
}

/// History coefficient C_H = 0.48 + 0.52 M_A^3 / (1 + M_A)^3, written in
/// x = 1/M_A as 0.48 + 0.52 / (1 + x)^3 (C_H = 1 as M_A -> infinity).
/// \param x 1/M_A >= 0. Reference: Nelson & Olsson (1986) Eq. (61b), after
/// Odar & Hamilton (1964). The transcription prints (1 + M_A^3); the paper's
/// C_H = 0.50 needs (1 + M_A)^3 (docs/deviations.md).
template <class T>
T history_coefficient(const T& x) {
  const T y = 1.0 + x;
  return 0.48 + 0.52 / (y * y * y);
}

/// Added-mass factor kappa = C_A/2 + (9/4) C_H (delta/a), so that the
/// added mass is m' = kappa m_a.
/// \param c_a, c_h coefficients of Eq. (61); \param delta penetration depth
/// (m); \param a sphere radius (m). Reference: Nelson & Olsson (1986) Eq. (62).
template <class T>
T added_mass_factor(const T& c_a, const T& c_h, const T& delta, const T& a) {
  return 0.5 * c_a + 2.25 * c_h * delta / a;
}

/// Added mass: DeltaT/T0 = (1/2) kappa m_a / m.
/// \param kappa added-mass factor (Eq. 62); \param m_a mass of displaced air
/// (kg); \param m bob mass (kg). Reference: Nelson & Olsson (1986) Eq. (54).
template <class T>
T added_mass(const T& kappa, const T& m_a, const T& m) {
  return 0.5 * kappa * m_a / m;
}

/// Added moment of inertia (kg m^2) about the pivot of a long straight part
/// swinging across its length, in potential flow, by strips: the element ds
/// at distance s from the pivot moves across its axis at s dtheta/dt and
/// carries the two-dimensional added mass rho pi b^2 ds of a cylinder of
/// elliptic section whose semi-axis across the motion is b (Lamb 1932,
/// Hydrodynamics, 6th ed., Secs. 68 and 72), so
///   DeltaI = rho pi b^2 (s2^3 - s1^3)/3,
/// and DeltaT/T0 = (1/2) DeltaI/I for a body of moment of inertia I about the
/// pivot. b: a circular rod of radius a, b = a (the mass of the air it
/// displaces, Nelson & Olsson's Ref. 36: kappa = 1 against the sphere's 1/2
/// of Eq. 58); a flat strip of width w moving broadside, b = w/2.
/// \param rho air density (kg/m^3); \param b half the section's extent across
/// the motion (m); \param s1, s2 the part's ends along the body, signed
/// distances from the pivot (m), s1 <= s2.
/// Validity: inviscid attached flow, so the swing's excursion s theta0 << b
/// (Keulegan-Carpenter number pi s theta0 / b << 1) and the viscous
/// penetration depth (2 eta/(omega rho))^(1/2) << b; a part much longer than
/// b, away from walls. A pendulum's swing violates the first at its lower
/// end (docs/physical.md, "Added mass"), where the real added mass is larger
/// (Nelson & Olsson's sphere: kappa 1.18 against 1/2).
template <class T>
T strip_added_inertia(const T& rho, const T& b, const T& s1, const T& s2) {
  return kPi * rho * b * b * (s2 * s2 * s2 - s1 * s1 * s1) / 3.0;  // Lamb Secs. 68, 72
}

}  // namespace pendulum
