#pragma once
/// \file drag.hpp
/// \brief Theoretical damping constants of a sphere on a wire in air, and the
/// decay parameters alpha, beta they imply (Nelson & Olsson 1986, Sec. III.C.4).
///
/// The drag force on the pendulum is F = b |v| + c v^2 (Eq. 19) at the bob
/// centre. SI units: Pa s, kg/m^3, m, m/s, kg, rad/s; b in kg/s, c in kg/m.

#include <cmath>
#include <optional>

#include "pendulum/air.hpp"
#include "pendulum/apparatus.hpp"
#include "pendulum/numeric.hpp"
#include "pendulum/observation.hpp"

namespace pendulum {

/// Drag coefficient of a sphere, C_D = 24/R + 6/(1 + sqrt(R)) + 0.4, and its
/// part beyond Stokes's law, C'_D = 6/(1 + sqrt(R)) + 0.4.
/// \param reynolds R = rho V d / eta > 0. Validity: 0 < R < 2e5, about 10%
/// (White, Viscous Fluid Flow). Reference: Nelson & Olsson (1986) Eq. (63).
template <class T>
T sphere_drag_coefficient_beyond_stokes(const T& reynolds) {
  using std::sqrt;
  return 6.0 / (1.0 + sqrt(reynolds)) + 0.4;
}

/// Linear drag constant of the sphere, Stokes's law with the history term:
/// b = 6 pi eta a [1 + C_H a/delta].
/// \param eta viscosity (Pa s); \param a radius (m); \param c_h history
/// coefficient (Eq. 61b); \param delta penetration depth (m).
/// \return b (kg/s). Reference: Nelson & Olsson (1986) Eq. (64).
template <class T>
T sphere_linear_drag(const T& eta, const T& a, const T& c_h, const T& delta) {
  return 6.0 * kPi * eta * a * (1.0 + c_h * a / delta);
}

/// Quadratic drag constant of the sphere: c = (1/2) C'_D pi a^2 rho.
/// \param c_d_prime C'_D of Eq. (63); \param a radius (m); \param rho air
/// density (kg/m^3). \return c (kg/m). Reference: Nelson & Olsson (1986) Eq. (64).
template <class T>
T sphere_quadratic_drag(const T& c_d_prime, const T& a, const T& rho) {
  return 0.5 * c_d_prime * kPi * a * a * rho;
}

/// Linear drag constant of the wire, referred to the bob: b = (5/3) eta l,
/// from C_D = 10/R + 2 (Eq. 65) integrated along the wire (Eq. 67);
/// independent of the wire's diameter.
/// \param eta viscosity (Pa s); \param l length (m). \return b (kg/s).
/// Validity: 1 < R < 10 (wire Reynolds number). Reference: Eq. (67).
template <class T>
T wire_linear_drag(const T& eta, const T& l) {
  return 5.0 / 3.0 * eta * l;
}

/// Quadratic drag constant of the wire, referred to the bob: c = (1/4) rho D l.
/// \param rho air density (kg/m^3); \param d wire diameter (m); \param l
/// length (m). \return c (kg/m). Reference: Nelson & Olsson (1986) Eq. (67).
template <class T>
T wire_quadratic_drag(const T& rho, const T& d, const T& l) {
  return 0.25 * rho * d * l;
}

/// Linear decay rate from the linear drag constant: alpha = b / (2m).
/// \param b (kg/s); \param m bob mass (kg). \return alpha (1/s). Eq. (26).
template <class T>
T alpha_from_linear_drag(const T& b, const T& m) {
  return b / (2.0 * m);
}

/// Quadratic decay rate: beta = (4/3)(omega0/pi)(c l/m).
/// \param c (kg/m); \param omega0 (rad/s); \param l (m); \param m (kg).
/// \return beta (1/(s rad)). Reference: Nelson & Olsson (1986) Eq. (27).
template <class T>
T beta_from_quadratic_drag(const T& c, const T& omega0, const T& l, const T& m) {
  return 4.0 / 3.0 * omega0 / kPi * c * l / m;
}

/// The damping the air alone predicts for a scene (Nelson & Olsson 1986,
/// Sec. III.C.4), to set beside the fitted alpha and beta.
template <class T>
struct DragPrediction {
  T reynolds_sphere;   ///< at the bob's largest speed omega0 l theta0
  T c_d_prime;         ///< C'_D of Eq. (63) at the rms speed
  T b_sphere, c_sphere;              ///< (kg/s), (kg/m), Eq. (64)
  std::optional<T> b_wire, c_wire;   ///< (kg/s), (kg/m), Eq. (67)
  std::optional<T> reynolds_wire;    ///< at the bob's speed, on the wire diameter
  T b, c;                            ///< totals
  T alpha, beta;                     ///< Eqs. (26), (27)
};

/// Predicted drag constants of `app` swinging as observed in `o`; empty in
/// vacuum, without the bob's mass, or for a bob that is not a sphere. The wire's quadratic drag needs its
/// diameter; its linear drag does not (Eq. 67).
/// The velocity scale is the observation's amplitude, as in the paper (R = 1100).
template <class T>
std::optional<DragPrediction<T>> predict_drag(const Apparatus<T>& app, const Observation<T>& o) {
  using std::sqrt;
  if (!app.air || !app.bob || !app.bob->mass || app.bob->shape != BobShape::sphere) return std::nullopt;
  const auto& air = *app.air;
  const auto& bob = *app.bob;
  const T omega0 = 2.0 * kPi / o.period;
  const T rho = air_density(air.pressure, air.temperature, air.molar_mass);
  const T a = bob.diameter / 2.0;
  const T speed = omega0 * o.length * o.amplitude;
  DragPrediction<T> p;
  p.reynolds_sphere = rho * speed * bob.diameter / air.viscosity;
  p.c_d_prime = sphere_drag_coefficient_beyond_stokes(T(p.reynolds_sphere / sqrt(2.0)));
  const T x = inverse_acceleration_modulus(bob.diameter, o.length, o.amplitude);
  const T delta = penetration_depth(air.viscosity, omega0, rho);
  p.b_sphere = sphere_linear_drag(air.viscosity, a, history_coefficient(x), delta);
  p.c_sphere = sphere_quadratic_drag(p.c_d_prime, a, rho);
  p.b = p.b_sphere;
  p.c = p.c_sphere;
  if (app.wire) {
    p.b_wire = wire_linear_drag(air.viscosity, o.length);
    p.b += *p.b_wire;
    if (app.wire->diameter) {
      p.c_wire = wire_quadratic_drag(rho, *app.wire->diameter, o.length);
      p.c += *p.c_wire;
      p.reynolds_wire = rho * speed * *app.wire->diameter / air.viscosity;
    }
  }
  p.alpha = alpha_from_linear_drag(p.b, *bob.mass);
  p.beta = beta_from_quadratic_drag(p.c, omega0, o.length, *bob.mass);
  return p;
}

}  // namespace pendulum
