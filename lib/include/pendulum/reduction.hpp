#pragma once
/// \file reduction.hpp
/// \brief Scene -> period corrections -> ideal period -> g, generic in the
/// scalar type (double, ceres::Jet).
///
/// The corrections add linearly (Nelson & Olsson 1986, Eqs. 6-7):
/// T = T0 (1 + sum_i r_i) with r_i = DeltaT_i/T0, so T0 = T / (1 + sum r_i),
/// DeltaT_i = r_i T0 and g = 4 pi^2 l / T0^2 (Eq. 3).
///
/// Corrections that need the pendulum's own frequency or g (damping, added
/// mass, stretch, support) use the working values omega0 = 2 pi / T and
/// g = omega0^2 l from the measured period: they are second-order terms, and
/// the difference from T0 changes them by about DeltaT/T (1e-4 of their size).

#include <array>
#include <optional>

#include "pendulum/air.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/damping.hpp"
#include "pendulum/elastic.hpp"
#include "pendulum/mass.hpp"
#include "pendulum/numeric.hpp"
#include "pendulum/scene.hpp"

namespace pendulum {

/// The corrections, in the order of Nelson & Olsson's Table II.
enum class CorrectionId {
  finite_amplitude,
  bob_radius,
  ring,
  cap,
  cap_screw,
  wire_mass,
  wire_flexibility,
  bob_rotation,
  double_pendulum,
  buoyancy,
  linear_damping,
  quadratic_damping,
  amplitude_decay,
  added_mass,
  wire_stretch,
  support_motion,
};
inline constexpr int kCorrectionCount = 16;

/// What the output says about a correction besides its size.
struct CorrectionInfo {
  const char* id;        ///< stable JSON id
  const char* title;     ///< Table II's row name
  const char* equation;  ///< where the formula comes from
};

/// The table of corrections, indexed by CorrectionId.
inline constexpr std::array<CorrectionInfo, kCorrectionCount> kCorrections{{
    {"finite_amplitude", "Finite amplitude", "Nelson & Olsson (1986) Eq. (8)"},
    {"bob_radius", "Finite radius of bob", "Nelson & Olsson (1986) Eq. (10)"},
    {"ring", "Mass of ring", "Nelson & Olsson (1986) Eq. (11)"},
    {"cap", "Mass of cap", "Nelson & Olsson (1986) Eq. (12)"},
    {"cap_screw", "Mass of cap screw", "Nelson & Olsson (1986) Eq. (12), Sec. III.B.2"},
    {"wire_mass", "Mass of wire", "Nelson & Olsson (1986) Eq. (13)"},
    {"wire_flexibility", "Flexibility of wire", "Nelson & Olsson (1986) Sec. III.B.3, (71-55)/1440 (m_w/m)^2"},
    {"bob_rotation", "Rotation of bob", "Nelson & Olsson (1986) Sec. III.B.3, Eq. (10) x (2/5)(a/l)"},
    {"double_pendulum", "Double pendulum", "Nelson & Olsson (1986) Eq. (15), third term"},
    {"buoyancy", "Buoyancy", "Nelson & Olsson (1986) Eq. (16)"},
    {"linear_damping", "Linear damping", "Nelson & Olsson (1986) Eq. (34)"},
    {"quadratic_damping", "Quadratic damping", "Nelson & Olsson (1986) Eq. (48)"},
    {"amplitude_decay", "Decay of finite amplitude", "Nelson & Olsson (1986) Eqs. (50a), (50b)"},
    {"added_mass", "Added mass", "Nelson & Olsson (1986) Eqs. (54), (61), (62)"},
    {"wire_stretch", "Stretching of wire", "Nelson & Olsson (1986) Eq. (79)"},
    {"support_motion", "Motion of support", "Nelson & Olsson (1986) Eqs. (83), (87), (88)"},
}};

/// Choices the user may make about the reduction.
struct ReductionOptions {
  /// `automatic` takes the cheapest method whose error bound is below
  /// amplitude_tolerance; the others are forced.
  AmplitudeMethod amplitude_method = AmplitudeMethod::automatic;
  int series_terms = 4;  ///< for AmplitudeMethod::series
  /// Largest error of DeltaT/T0 (dimensionless) the automatic choice may
  /// make; 0 takes the exact method.
  double amplitude_tolerance = 0.0;
};

/// One correction's outcome: its relative size, or why it was skipped.
template <class T>
struct Term {
  std::optional<T> ratio;      ///< DeltaT/T0; empty when skipped
  const char* method = "";     ///< formula variant used
  const char* skip_reason = "";
  std::optional<double> error_bound;  ///< bound on |error| of ratio, where proven
  int series_terms = 0;        ///< terms of a truncated series, 0 otherwise
};

/// Everything the reduction computes, in SI units.
template <class T>
struct Reduction {
  std::array<Term<T>, kCorrectionCount> terms;
  T total_ratio;   ///< sum of the applied DeltaT/T0
  T period_ideal;  ///< T0 (s)
  T g;             ///< 4 pi^2 l / T0^2 (m/s^2)
  T g_uncorrected;  ///< 4 pi^2 l / T^2 (m/s^2), Eq. (5)
};

/// Reduces a scene to g. Pure: no I/O, no state.
template <class T>
Reduction<T> reduce(const Scene<T>& s, const ReductionOptions& options = {}) {
  Reduction<T> out;
  auto set = [&](CorrectionId id, const T& ratio, const char* method) {
    auto& term = out.terms[static_cast<int>(id)];
    term.ratio = ratio;
    term.method = method;
  };
  auto skip = [&](CorrectionId id, const char* reason) {
    out.terms[static_cast<int>(id)].skip_reason = reason;
  };
  using Id = CorrectionId;

  const T& l = s.length;
  const T& theta0 = s.amplitude;
  const T& m = s.bob.mass;
  const T a = s.bob.diameter / 2.0;
  const T omega0 = 2.0 * kPi / s.period;
  const T g_work = omega0 * omega0 * l;

  const AmplitudeChoice amp =
      options.amplitude_method == AmplitudeMethod::automatic
          ? cheapest_amplitude_method(value_of(theta0), options.amplitude_tolerance)
          : AmplitudeChoice{options.amplitude_method, options.series_terms,
                            amplitude_error_bound(options.amplitude_method,
                                                  value_of(theta0), options.series_terms)};
  set(Id::finite_amplitude, finite_amplitude(amp.method, theta0, amp.terms),
      method_name(amp.method));
  auto& amplitude_term = out.terms[static_cast<int>(Id::finite_amplitude)];
  amplitude_term.error_bound = amp.bound;
  if (amp.method == AmplitudeMethod::series) amplitude_term.series_terms = amp.terms;
  set(Id::bob_radius, bob_radius(a, l), "eq10");
  set(Id::bob_rotation, bob_rotation(a, l), "eq10_rotation");

  if (s.ring) {
    const auto& r = *s.ring;
    const T i_r = ring_moment_of_inertia(r.mass, r.pivot_distance,
                                         r.inner_radius, r.outer_radius);
    set(Id::ring, ring(r.mass, i_r, r.pivot_distance, m, l), "eq11");
    set(Id::double_pendulum,
        double_pendulum(r.mass, r.pivot_distance, r.outer_radius, m, l),
        "eq15");
  } else {
    skip(Id::ring, "the scene has no ring");
    skip(Id::double_pendulum, "the scene has no ring");
  }

  if (s.cap) {
    set(Id::cap, point_mass_on_bob(s.cap->mass, s.cap->center_distance, m, l),
        "eq12");
  } else {
    skip(Id::cap, "the scene has no cap");
  }
  if (s.cap_screw) {
    set(Id::cap_screw,
        point_mass_on_bob(T(-s.cap_screw->mass_deficit),
                          s.cap_screw->center_distance, m, l),
        "eq12");
  } else {
    skip(Id::cap_screw, "the scene has no cap_screw");
  }

  if (s.wire) {
    set(Id::wire_mass, wire_mass(s.wire->mass, m), "eq13");
    set(Id::wire_flexibility, wire_flexibility(s.wire->mass, m),
        "second_order_flexible_minus_rigid");
    if (s.wire->diameter && s.wire->youngs_modulus) {
      const T& d = *s.wire->diameter;
      const T area = kPi * d * d / 4.0;
      set(Id::wire_stretch,
          wire_stretch(m, g_work, *s.wire->youngs_modulus, area, theta0),
          "eq79");
    } else {
      skip(Id::wire_stretch,
           "the wire needs both diameter and youngs_modulus");
    }
  } else {
    skip(Id::wire_mass, "the scene has no wire");
    skip(Id::wire_flexibility, "the scene has no wire");
    skip(Id::wire_stretch, "the scene has no wire");
  }

  if (s.air) {
    const auto& air = *s.air;
    const T rho = air_density(air.pressure, air.temperature, air.molar_mass);
    T volume = sphere_volume(a);
    if (s.cap && s.cap->volume) volume += *s.cap->volume;
    const T m_air = rho * volume;
    set(Id::buoyancy, buoyancy(m_air, m), "eq16");
    const T x = inverse_acceleration_modulus(s.bob.diameter, l, theta0);
    const T delta = penetration_depth(air.viscosity, omega0, rho);
    const T kappa = added_mass_factor(added_mass_coefficient(x),
                                      history_coefficient(x), delta, a);
    set(Id::added_mass, added_mass(kappa, m_air, m), "eq54_eq62");
  } else {
    skip(Id::buoyancy, "the scene is in vacuum");
    skip(Id::added_mass, "the scene is in vacuum");
  }

  if (s.decay) {
    const auto& d = *s.decay;
    set(Id::linear_damping, linear_damping(d.alpha, omega0), "eq34");
    set(Id::quadratic_damping, quadratic_damping(d.beta, omega0, theta0),
        "eq48");
    const T t_f = double(s.oscillations_per_trial) * s.period;
    set(Id::amplitude_decay, amplitude_decay(theta0, d.alpha, d.beta, t_f),
        "eq50");
  } else {
    const char* why = "the scene gives no decay (alpha, beta)";
    skip(Id::linear_damping, why);
    skip(Id::quadratic_damping, why);
    skip(Id::amplitude_decay, why);
  }

  if (s.support) {
    const auto& sup = *s.support;
    if (sup.stiffness && sup.mass) {
      set(Id::support_motion,
          support_coupled(m, *sup.mass, *sup.stiffness, omega0), "eq83");
    } else if (sup.stiffness) {
      set(Id::support_motion, support_elastic(m, g_work, *sup.stiffness, l),
          "eq87");
    } else {
      set(Id::support_motion, support_inertial(m, *sup.mass), "eq88");
    }
  } else {
    skip(Id::support_motion, "the scene has no support (taken as rigid)");
  }

  out.total_ratio = T(0.0);
  for (const auto& term : out.terms) {
    if (term.ratio) out.total_ratio += *term.ratio;
  }
  out.period_ideal = s.period / (1.0 + out.total_ratio);  // Eqs. (6)-(7)
  out.g = 4.0 * kPi * kPi * l / (out.period_ideal * out.period_ideal);  // Eq. (3)
  out.g_uncorrected = 4.0 * kPi * kPi * l / (s.period * s.period);     // Eq. (5)
  return out;
}

}  // namespace pendulum
