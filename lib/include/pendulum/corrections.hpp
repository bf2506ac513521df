#pragma once
/// \file corrections.hpp
/// \brief The period corrections of Nelson & Olsson (1986) for an apparatus
/// and one swing, their metadata in one table, and how they compose into
/// the period's ratio T/T0. Generic in the scalar type (double, ceres::Jet).

#include <array>
#include <iterator>
#include <limits>
#include <optional>

#include "pendulum/air.hpp"
#include "pendulum/amplitude.hpp"
#include "pendulum/apparatus.hpp"
#include "pendulum/damping.hpp"
#include "pendulum/elastic.hpp"
#include "pendulum/mass.hpp"
#include "pendulum/numeric.hpp"
#include "pendulum/observation.hpp"

namespace pendulum {

/// The corrections, in the order of Nelson & Olsson's Table II, one row
/// each: X(id, title, equation, part, max_ratio, reads_length), the fields
/// of CorrectionInfo. Both CorrectionId (its enumerators) and kCorrections
/// (its rows, id also the stable JSON id) are made from it, so a new
/// correction is its row here, its function and its call in
/// visit_corrections.
#define PENDULUM_CORRECTIONS(X) \
  X(finite_amplitude, "Finite amplitude", "Nelson & Olsson (1986) Eq. (8)", "amplitude", kNoLimit, false) \
  X(bob_radius, "Finite radius of bob", "Nelson & Olsson (1986) Eq. (10)", "bob", kFirstOrderLimit, true) \
  X(ring, "Mass of ring", "Nelson & Olsson (1986) Eq. (11)", "ring", kFirstOrderLimit, true) \
  X(cap, "Mass of cap", "Nelson & Olsson (1986) Eq. (12)", "cap", kFirstOrderLimit, true) \
  X(cap_screw, "Mass of cap screw", "Nelson & Olsson (1986) Eq. (12), Sec. III.B.2", \
      "cap_screw", kFirstOrderLimit, true) \
  X(wire_mass, "Mass of wire", "Nelson & Olsson (1986) Eq. (13)", "wire", kFirstOrderLimit, false) \
  X(wire_flexibility, "Flexibility of wire", "Nelson & Olsson (1986) Sec. III.B.3, (71-55)/1440 (m_w/m)^2", \
      "wire", kFirstOrderLimit, false) \
  X(bob_rotation, "Rotation of bob", "Nelson & Olsson (1986) Sec. III.B.3, Eq. (10) x (2/5)(a/l)", \
      "bob", kFirstOrderLimit, true) \
  X(double_pendulum, "Double pendulum", "Nelson & Olsson (1986) Eq. (15), third term", "ring", kFirstOrderLimit, true) \
  X(buoyancy, "Buoyancy", "Nelson & Olsson (1986) Eq. (16)", "air", kFirstOrderLimit, false) \
  X(linear_damping, "Linear damping", "Nelson & Olsson (1986) Eq. (34)", "decay", kFirstOrderLimit, false) \
  X(quadratic_damping, "Quadratic damping", "Nelson & Olsson (1986) Eq. (48)", "decay", kFirstOrderLimit, false) \
  X(amplitude_decay, "Decay of finite amplitude", "Nelson & Olsson (1986) Eqs. (50a), (50b)", \
      "decay", kFirstOrderLimit, false) \
  X(added_mass, "Added mass", "Nelson & Olsson (1986) Eqs. (54), (61), (62)", "air", kFirstOrderLimit, true) \
  X(wire_stretch, "Stretching of wire", "Nelson & Olsson (1986) Eq. (79)", "wire", kFirstOrderLimit, true) \
  X(support_motion, "Motion of support", "Nelson & Olsson (1986) Eqs. (83), (87), (88)", \
      "support", kFirstOrderLimit, true)

/// A correction's place in kCorrections.
enum class CorrectionId {
#define PENDULUM_CORRECTION_ENUMERATOR(id, ...) id,
  PENDULUM_CORRECTIONS(PENDULUM_CORRECTION_ENUMERATOR)
#undef PENDULUM_CORRECTION_ENUMERATOR
};

/// First-order theories hold while |DeltaT/T0| stays below this: the terms
/// they neglect, of order (DeltaT/T0)^2, would reach 1% of the period.
inline constexpr double kFirstOrderLimit = 0.1;
/// The limit of a correction that is exact at any size.
inline constexpr double kNoLimit = std::numeric_limits<double>::infinity();

/// What the output says about a correction besides its size.
struct CorrectionInfo {
  CorrectionId correction;  ///< its place in the table
  const char* id;           ///< stable JSON id
  const char* title;        ///< Table II's row name
  const char* equation;     ///< where the formula comes from
  const char* part;         ///< the scene part it corrects for, named in its errors
  double max_ratio;         ///< validity: |DeltaT/T0| below this
  /// Whether its ratio reads the swing's length (directly, or through the
  /// working g = omega^2 l or the added mass's x): only these change with a
  /// fit's parameters, which reach the corrections through the length alone.
  /// A body's angle (a sensor in the bob) makes the amplitude and damping rows
  /// read it too, through theta = c psi; only beside the bob's rows, which do.
  bool reads_length;
};

/// The table of corrections, indexed by CorrectionId.
inline constexpr CorrectionInfo kCorrections[] = {
#define PENDULUM_CORRECTION_ROW(id, title, equation, part, max_ratio, reads_length) \
  {CorrectionId::id, #id, title, equation, part, max_ratio, reads_length},
    PENDULUM_CORRECTIONS(PENDULUM_CORRECTION_ROW)
#undef PENDULUM_CORRECTION_ROW
};
#undef PENDULUM_CORRECTIONS
/// The number of corrections: kCorrections's rows.
inline constexpr int kCorrectionCount = static_cast<int>(std::size(kCorrections));

/// The row that composition adds: the finite-amplitude factor times the sum
/// of the other corrections (see compose()).
inline constexpr CorrectionInfo kAmplitudeCrossTerm{
    CorrectionId::finite_amplitude, "amplitude_cross_term", "Finite amplitude x other corrections",
    "(1 + r_amplitude)(1 + sum of the other r_i): Kelley (1993) Eq. (16) on the corrected pendulum",
    "amplitude", kNoLimit, false};

/// One correction's outcome: its relative size, or why it was skipped.
template <class T>
struct Term {
  std::optional<T> ratio;      ///< DeltaT/T0; empty when skipped
  const char* method = "";     ///< formula variant used
  const char* skip_reason = "";
  std::optional<double> error_bound;  ///< bound on |error| of ratio, where proven
  int series_terms = 0;        ///< terms of a truncated series, 0 otherwise
};

template <class T>
using Terms = std::array<Term<T>, kCorrectionCount>;

/// The pendulum's angle (the line from the pivot to the bob's centre) over
/// the bob's own, for `app` at length l (m): the slow mode's ratio on a
/// flexible suspension (mass.hpp, slow_mode_line_over_body), 1 on a rigid
/// one (the bob turns with the line) or without a bob (a point).
template <class T>
T pendulum_over_body_angle(const Apparatus<T>& app, const T& l) {
  if (!app.bob || app.bob->suspension == Suspension::rigid) return T(1.0);
  return slow_mode_line_over_body(app.bob->gyration_squared(), app.bob->knot_to_center(), l);
}

/// Whether the finite-amplitude row is the slow mode's series: a body on a
/// flexible string, timed at its own amplitude (a sensor in it, or "of":
/// "body").
template <class T>
bool slow_mode_amplitude(const Apparatus<T>& app, const Swing<T>& s) {
  return s.amplitude_of == AngleOf::body && app.bob && app.bob->suspension == Suspension::flexible;
}

/// DeltaT/T_slow of a body on a flexible string at its own amplitude psi0
/// (rad), checked to 30 deg: the slow mode's series 1 + kappa2 psi0^2 +
/// kappa4 psi0^4 (mass.hpp, slow_mode_amplitude_series) as a simple
/// pendulum's factor F by `amplitude`'s method at theta_e = 4 sqrt(kappa2)
/// psi0, which holds the psi0^2 term, times 1 + R with the rest of the psi0^4
/// one, R = (kappa4 - q (theta_e/psi0)^4) psi0^4, q the theta^4 coefficient F
/// holds (11/3072 exactly, -1/192 for Eq. 8's first term alone, 0 for
/// theta^2/16): F + R + F R. Against the full equations of motion, for a
/// phone on 0.1-1 m of string, it errs at most 1.75e-7 of T at 10 deg,
/// 1.0e-5 at 20 deg and 9.7e-5 at 30 deg, where the factor at c psi0 alone
/// erred 1.2e-5, 5.1e-5 and 2.4e-4 (tests/tools/phone_nonlinear_check.py,
/// docs/phone.md). Near the modes' 3:1 resonance kappa4 grows without bound
/// and the series fails (warn_about_mode_resonance, plausibility.cpp).
template <class T>
T slow_mode_finite_amplitude(const Apparatus<T>& app, const T& l, const T& psi0, const AmplitudeChoice& amplitude) {
  using std::sqrt;
  const auto [kappa2, kappa4] = slow_mode_amplitude_series(app.bob->gyration_squared(), app.bob->knot_to_center(), l);
  const T ratio = 4.0 * sqrt(kappa2);  // theta_e/psi0
  const T factor = finite_amplitude(amplitude.method, T(ratio * psi0), amplitude.terms);
  const double q = amplitude.method == AmplitudeMethod::small_angle                      ? 0.0
                   : amplitude.method == AmplitudeMethod::series && amplitude.terms < 2 ? -1.0 / 192.0
                                                                                          : 11.0 / 3072.0;
  const T psi2 = psi0 * psi0, ratio2 = ratio * ratio;
  const T rest = (kappa4 - q * ratio2 * ratio2) * psi2 * psi2;
  return factor + rest + factor * rest;
}

/// Every correction for `app` swinging as `s`, handed to `sink` as
/// sink.set(id, ratio, method) or sink.skip({ids...}, reason): a correction
/// whose part the apparatus lacks is skipped with the reason. The
/// finite-amplitude factor by `amplitude`. Pure: no I/O, no state.
template <class T, class Sink>
void visit_corrections(const Apparatus<T>& app, const Swing<T>& s, const AmplitudeChoice& amplitude, Sink& sink) {
  using Id = CorrectionId;
  auto set = [&](Id id, const T& ratio, const char* method) { sink.set(id, ratio, method); };
  auto skip = [&](std::initializer_list<Id> ids, const char* reason) { sink.skip(ids, reason); };

  const T& l = s.length;
  const T& omega0 = s.omega;
  // The corrections take the pendulum's angle; a sensor in the bob saw the bob's.
  const bool body_decay = app.decay && app.decay->angle_of == AngleOf::body;
  const T c = s.amplitude_of == AngleOf::body || body_decay ? pendulum_over_body_angle(app, l) : T(1.0);
  const T theta0 = s.amplitude_of == AngleOf::body ? T(c * s.amplitude) : s.amplitude;

  if (slow_mode_amplitude(app, s)) {
    set(Id::finite_amplitude, slow_mode_finite_amplitude(app, l, s.amplitude, amplitude),
        method_name(amplitude.method, true));
  } else {
    set(Id::finite_amplitude, finite_amplitude(amplitude.method, theta0, amplitude.terms),
        method_name(amplitude.method));
  }

  if (!app.bob) {
    skip({Id::bob_radius, Id::bob_rotation}, "the scene has no bob");
  } else if (app.bob->shape == BobShape::sphere) {
    // The slow mode's first orders in a/l (mass.hpp, slow_mode): Nelson & Olsson's rows.
    const T a = app.bob->diameter / 2.0;
    set(Id::bob_radius, bob_radius(a, l), "eq10");
    if (app.bob->suspension == Suspension::rigid) {
      skip({Id::bob_rotation}, "a rigid suspension turns with the bob");
    } else {
      set(Id::bob_rotation, bob_rotation(a, l), "eq10_rotation");
    }
  } else {
    // Exact at any size: the rigid body, and the flexible suspension's slow mode beyond it.
    const T k2 = app.bob->gyration_squared();
    const T rigid = rigid_bob(k2, l);
    set(Id::bob_radius, rigid, "eq9_rigid_body");
    if (app.bob->suspension == Suspension::rigid) {
      skip({Id::bob_rotation}, "a rigid suspension turns with the bob");
    } else {
      set(Id::bob_rotation, T(slow_mode(k2, app.bob->knot_to_center(), l) - rigid), "slow_mode");
    }
  }
  // The other parts' corrections are their mass (or the air's) relative to the bob's.
  const T* m = app.bob && app.bob->mass ? &*app.bob->mass : nullptr;
  const char* no_bob_mass = "needs the bob's mass (bob.mass)";

  if (!app.ring) {
    skip({Id::ring, Id::double_pendulum}, "the scene has no ring");
  } else if (!m) {
    skip({Id::ring, Id::double_pendulum}, no_bob_mass);
  } else {
    const auto& r = *app.ring;
    const T i_r = ring_moment_of_inertia(r.mass, r.pivot_distance, r.inner_radius, r.outer_radius);
    set(Id::ring, ring(r.mass, i_r, r.pivot_distance, *m, l), "eq11");
    set(Id::double_pendulum, double_pendulum(r.mass, r.pivot_distance, r.outer_radius, *m, l), "eq15");
  }

  if (!app.cap) {
    skip({Id::cap}, "the scene has no cap");
  } else if (!m) {
    skip({Id::cap}, no_bob_mass);
  } else {
    set(Id::cap, point_mass_on_bob(app.cap->mass, app.cap->center_distance, *m, l), "eq12");
  }
  if (!app.cap_screw) {
    skip({Id::cap_screw}, "the scene has no cap_screw");
  } else if (!m) {
    skip({Id::cap_screw}, no_bob_mass);
  } else {
    set(Id::cap_screw,
        point_mass_on_bob(T(-app.cap_screw->mass_deficit), app.cap_screw->center_distance, *m, l), "eq12");
  }

  const std::initializer_list<Id> wire_ids{Id::wire_mass, Id::wire_flexibility, Id::wire_stretch};
  if (!app.wire) {
    skip(wire_ids, "the scene has no wire");
  } else if (!m) {
    skip(wire_ids, no_bob_mass);
  } else {
    const auto& w = *app.wire;
    set(Id::wire_mass, wire_mass(w.mass, *m), "eq13");
    if (app.bob->suspension == Suspension::rigid) {
      skip({Id::wire_flexibility}, "a rigid suspension does not bend");
    } else {
      set(Id::wire_flexibility, wire_flexibility(w.mass, *m), "second_order_flexible_minus_rigid");
    }
    if (w.diameter && w.youngs_modulus) {
      const T& d = *w.diameter;
      const T area = kPi * d * d / 4.0;
      set(Id::wire_stretch, wire_stretch(*m, s.working_g(), *w.youngs_modulus, area, theta0), "eq79");
    } else {
      skip({Id::wire_stretch}, "the wire needs both diameter and youngs_modulus");
    }
  }

  if (!app.air) {
    skip({Id::buoyancy, Id::added_mass}, app.vacuum ? "the scene is in vacuum" : "the scene gives no air");
  } else if (!m) {
    skip({Id::buoyancy, Id::added_mass}, "needs the bob's diameter and mass (bob)");
  } else {
    const auto& air = *app.air;
    const T rho = air_density(air.pressure, air.temperature, air.molar_mass);
    T volume = app.bob->volume();
    if (app.cap && app.cap->volume) volume += *app.cap->volume;
    const T m_air = rho * volume;
    set(Id::buoyancy, buoyancy(m_air, *m), "eq16");
    if (app.bob->shape != BobShape::sphere) {
      skip({Id::added_mass}, "Eqs. (54)-(62) are for a sphere; a box's or cylinder's added mass is not modelled "
                             "(docs/phone.md)");
    } else {
      const T a = app.bob->diameter / 2.0;
      const T x = inverse_acceleration_modulus(app.bob->diameter, l, theta0);
      const T delta = penetration_depth(air.viscosity, omega0, rho);
      const T kappa = added_mass_factor(added_mass_coefficient(x), history_coefficient(x), delta, a);
      set(Id::added_mass, added_mass(kappa, m_air, *m), "eq54_eq62");
    }
  }

  if (!app.decay) {
    skip({Id::linear_damping, Id::quadratic_damping, Id::amplitude_decay},
         "the scene gives no decay (alpha, beta)");
  } else {
    const auto& d = *app.decay;
    // d theta/dt = -beta theta^2 with theta = c psi: the line's beta is the bob's over c (alpha is either's).
    const T beta = body_decay ? T(d.beta / c) : d.beta;
    set(Id::linear_damping, linear_damping(d.alpha, omega0), "eq34");
    set(Id::quadratic_damping, quadratic_damping(beta, omega0, theta0), "eq48");
    if (d.over_timing) {
      set(Id::amplitude_decay, amplitude_decay(theta0, d.alpha, beta, s.trial_duration), "eq50");
    } else {
      skip({Id::amplitude_decay}, "reduced swing by swing: each group of swings is corrected at its own amplitude");
    }
  }

  if (!app.support) {
    skip({Id::support_motion}, "the scene has no support (taken as rigid)");
  } else if (!m) {
    skip({Id::support_motion}, no_bob_mass);
  } else {
    const auto& sup = *app.support;
    if (sup.stiffness && sup.mass) {
      set(Id::support_motion, support_coupled(*m, *sup.mass, *sup.stiffness, omega0), "eq83");
    } else if (sup.stiffness) {
      set(Id::support_motion, support_elastic(*m, s.working_g(), *sup.stiffness, l), "eq87");
    } else {
      set(Id::support_motion, support_inertial(*m, *sup.mass), "eq88");
    }
  }
}

/// The rows a pass over the corrections gives: visit(sink) hands each row to
/// sink as visit_corrections does; the finite amplitude's bound and terms
/// from `amplitude`.
template <class T, class Visit>
Terms<T> rows_of(const Visit& visit, const AmplitudeChoice& amplitude) {
  struct Rows {
    Terms<T> out;
    void set(CorrectionId id, const T& ratio, const char* method) {
      auto& term = out[static_cast<int>(id)];
      term.ratio = ratio;
      term.method = method;
    }
    void skip(std::initializer_list<CorrectionId> ids, const char* reason) {
      for (CorrectionId id : ids) out[static_cast<int>(id)].skip_reason = reason;
    }
  } rows;
  visit(rows);
  auto& amplitude_term = rows.out[static_cast<int>(CorrectionId::finite_amplitude)];
  amplitude_term.error_bound = amplitude.bound;
  if (amplitude.method == AmplitudeMethod::series) amplitude_term.series_terms = amplitude.terms;
  return rows.out;
}

/// Every correction as a row: its ratio and method, or why it was skipped.
template <class T>
Terms<T> correction_terms(const Apparatus<T>& app, const Swing<T>& s, const AmplitudeChoice& amplitude) {
  return rows_of<T>([&](auto& sink) { visit_corrections(app, s, amplitude, sink); }, amplitude);
}

/// T/T0 from the corrections' ratios r_i = DeltaT_i/T0.
///
/// Eqs. (6)-(7) of Nelson & Olsson add the ratios, but the exact amplitude
/// factor 2K(k)/pi (Kelley 1993, Eq. 16) multiplies the period of the
/// pendulum it acts on, the one the other corrections describe:
///   T/T0 = (1 + r_amplitude)(1 + sum of the other r_i).
/// The product exceeds the sum by the cross term r_amplitude x (sum of the
/// others), which the output shows as its own row where it is not negligible
/// (3e-5 of T at 90 deg in room air; 1e-8 at Nelson & Olsson's 3 deg).
template <class T>
struct Composition {
  T amplitude;  ///< r_amplitude
  T others;     ///< sum of the other applied r_i
  T cross;      ///< r_amplitude x others
  T total;      ///< T/T0 - 1 = amplitude + others + cross

  /// The composition of r_amplitude and the sum of the others.
  static Composition of(const T& amplitude, const T& others) {
    const T cross = amplitude * others;
    return {amplitude, others, cross, amplitude + others + cross};
  }
};

/// The composition of the ratios a pass over the corrections gives (visit as
/// in rows_of), without their rows: what a fit needs at every step.
template <class T, class Visit>
Composition<T> composition_of(const Visit& visit) {
  struct Sums {
    T amplitude{0.0}, others{0.0};
    void set(CorrectionId id, const T& ratio, const char*) {
      (id == CorrectionId::finite_amplitude ? amplitude : others) += ratio;
    }
    void skip(std::initializer_list<CorrectionId>, const char*) {}
  } sums;
  visit(sums);
  return Composition<T>::of(sums.amplitude, sums.others);
}

/// The composition straight from the corrections, without their rows.
template <class T>
Composition<T> compose(const Apparatus<T>& app, const Swing<T>& s, const AmplitudeChoice& amplitude) {
  return composition_of<T>([&](auto& sink) { visit_corrections(app, s, amplitude, sink); });
}

/// Whether any row a pass over the corrections applies (visit as in rows_of)
/// reads the swing's length (CorrectionInfo::reads_length). Which ones apply
/// depends on the apparatus's parts alone, so a fit asks once: when none
/// does, an observation's T/T0 is the same at every step and is composed once.
template <class T, class Visit>
bool reads_length_of(const Visit& visit) {
  struct Applied {
    bool reads_length = false;
    void set(CorrectionId id, const T&, const char*) {
      reads_length |= kCorrections[static_cast<int>(id)].reads_length;
    }
    void skip(std::initializer_list<CorrectionId>, const char*) {}
  } applied;
  visit(applied);
  return applied.reads_length;
}

/// Whether any correction `app` applies reads the swing's length (reads_length_of).
template <class T>
bool corrections_read_length(const Apparatus<T>& app, const Swing<T>& s, const AmplitudeChoice& amplitude) {
  return reads_length_of<T>([&](auto& sink) { visit_corrections(app, s, amplitude, sink); });
}

/// The composition of the ratios in the table's order: ratio(i) is row i's
/// ratio, or null where it was skipped.
template <class T, class Ratio>
Composition<T> compose_rows(const Ratio& ratio) {
  T amplitude(0.0), others(0.0);
  for (int i = 0; i < kCorrectionCount; ++i) {
    const T* r = ratio(i);
    if (!r) continue;
    if (i == static_cast<int>(CorrectionId::finite_amplitude)) {
      amplitude = *r;
    } else {
      others += *r;
    }
  }
  return Composition<T>::of(amplitude, others);
}

template <class T>
Composition<T> compose(const Terms<T>& terms) {
  return compose_rows<T>([&](int i) { return terms[i].ratio ? &*terms[i].ratio : nullptr; });
}

/// compose(rows_of<T>(visit, ...)) bit for bit (the same sum in the
/// table's order, not composition_of()'s in the visit's), without building
/// the rows: their copies were most of a Monte Carlo draw's closed form.
template <class T, class Visit>
Composition<T> composition_in_table_order_of(const Visit& visit) {
  struct Ratios {
    std::array<T, kCorrectionCount> value;
    std::array<bool, kCorrectionCount> applied{};
    void set(CorrectionId id, const T& ratio, const char*) {
      value[static_cast<int>(id)] = ratio;
      applied[static_cast<int>(id)] = true;
    }
    void skip(std::initializer_list<CorrectionId>, const char*) {}
  } ratios;
  visit(ratios);
  return compose_rows<T>([&](int i) { return ratios.applied[i] ? &ratios.value[i] : nullptr; });
}

/// compose(correction_terms(app, s, amplitude)) bit for bit, without the rows.
template <class T>
Composition<T> compose_in_table_order(const Apparatus<T>& app, const Swing<T>& s, const AmplitudeChoice& amplitude) {
  return composition_in_table_order_of<T>([&](auto& sink) { visit_corrections(app, s, amplitude, sink); });
}

}  // namespace pendulum
