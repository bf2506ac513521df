#pragma once
/// \file apparatus.hpp
/// \brief What stays the same during an experiment: the bob, the suspension,
/// the air, the support and the decay of the amplitude, as plain data in SI
/// units, generic in the scalar type so that the same reduction runs on
/// `double` and on dual numbers.
///
/// A part that the experiment lacks is an empty std::optional, and the
/// corrections for it are skipped. Every scalar field is visited by
/// `zip_apparatus` with its JSON path and SI unit (docs/scene.md), in one
/// place, so that conversions (double -> Jet, values -> uncertainties) list
/// no field twice.

#include <optional>
#include <type_traits>
#include <vector>

#include "pendulum/body_parts.hpp"
#include "pendulum/fields.hpp"
#include "pendulum/air.hpp"
#include "pendulum/numeric.hpp"
#include "pendulum/observation.hpp"

namespace pendulum {

/// The bob's shape (docs/phone.md): a sphere (Nelson & Olsson's), or a box
/// or an upright cylinder such as a phone or a plumb bob.
enum class BobShape { sphere, box, cylinder };

/// How the bob hangs: from a string or wire about which it turns (the double
/// pendulum's slow mode), or clamped to a rigid rod (a physical pendulum).
enum class Suspension { flexible, rigid };

/// A uniform bob hanging at the end of the suspension, its top at the knot.
///
/// A sphere has its diameter; a box its width (along the swing), height
/// (vertical) and depth (along the axis of rotation); a cylinder hangs with
/// its axis vertical and has its diameter and height. Only a shape's own
/// fields are visited (a box's diameter is 0 and no field).
template <class T>
struct Bob {
  T diameter{};           ///< sphere, cylinder (m)
  std::optional<T> mass;  ///< (kg); the corrections of the other parts need it
  BobShape shape = BobShape::sphere;
  Suspension suspension = Suspension::flexible;
  T width{};   ///< box: along the swing (m)
  T height{};  ///< box, cylinder: vertical (m)
  T depth{};   ///< box: along the axis of rotation (m)

  /// The knot (the bob's top, where the suspension holds it) to its centre (m).
  T knot_to_center() const { return shape == BobShape::sphere ? T(diameter / 2.0) : T(height / 2.0); }
  /// k^2 (m^2): the bob's moment of inertia about the horizontal axis through
  /// its centre along the swing's axis, over its mass. Sphere (2/5) a^2; box
  /// (w^2 + h^2)/12; upright cylinder a^2/4 + h^2/12 (a = diameter/2).
  T gyration_squared() const {
    switch (shape) {
      case BobShape::box: return (width * width + height * height) / 12.0;
      case BobShape::cylinder: return diameter * diameter / 16.0 + height * height / 12.0;
      case BobShape::sphere: break;
    }
    return 0.1 * diameter * diameter;  // (2/5) (d/2)^2
  }
  /// The volume (m^3): what displaces the air.
  T volume() const {
    switch (shape) {
      case BobShape::box: return width * height * depth;
      case BobShape::cylinder: return kPi / 4.0 * diameter * diameter * height;
      case BobShape::sphere: break;
    }
    return sphere_volume(T(diameter / 2.0));
  }

  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    if constexpr (!std::is_const_v<B>) b.shape = a.shape, b.suspension = a.suspension;
    if (a.shape != BobShape::box) f({"bob.diameter", "m"}, a.diameter, b.diameter);
    if (a.shape == BobShape::box) f({"bob.width", "m"}, a.width, b.width);
    if (a.shape != BobShape::sphere) f({"bob.height", "m"}, a.height, b.height);
    if (a.shape == BobShape::box) f({"bob.depth", "m"}, a.depth, b.depth);
    f({"bob.mass", "kg"}, a.mass, b.mass);
  }
};

/// Suspension ring (annulus) with the pivot inside it, above the wire.
template <class T>
struct Ring {
  T mass;            ///< (kg)
  T inner_radius;    ///< (m)
  T outer_radius;    ///< (m)
  T pivot_distance;  ///< pivot to ring centre (m)
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    f({"ring.mass", "kg"}, a.mass, b.mass);
    f({"ring.inner_radius", "m"}, a.inner_radius, b.inner_radius);
    f({"ring.outer_radius", "m"}, a.outer_radius, b.outer_radius);
    f({"ring.pivot_distance", "m"}, a.pivot_distance, b.pivot_distance);
  }
};

/// Cap joining the wire to the bob.
template <class T>
struct Cap {
  T mass;             ///< without its screw (kg)
  T center_distance;  ///< cap centre of mass above the bob centre (m)
  std::optional<T> volume;  ///< (m^3), displaces air with the bob
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    f({"cap.mass", "kg"}, a.mass, b.mass);
    f({"cap.center_distance", "m"}, a.center_distance, b.center_distance);
    f({"cap.volume", "m^3"}, a.volume, b.volume);
  }
};

/// Screw of the cap, lighter than the bob material it replaces.
template <class T>
struct CapScrew {
  T mass_deficit;     ///< mass missing from the bob (kg); negative for a heavier screw
  T center_distance;  ///< deficit's centre above the bob centre (m)
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    f({"cap_screw.mass_deficit", "kg"}, a.mass_deficit, b.mass_deficit);
    f({"cap_screw.center_distance", "m"}, a.center_distance, b.center_distance);
  }
};

/// Suspension wire from the ring (or pivot) to the cap (or bob).
template <class T>
struct Wire {
  T mass;                           ///< (kg)
  std::optional<T> diameter;        ///< (m)
  std::optional<T> youngs_modulus;  ///< (Pa)
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    f({"wire.mass", "kg"}, a.mass, b.mass);
    f({"wire.diameter", "m"}, a.diameter, b.diameter);
    f({"wire.youngs_modulus", "Pa"}, a.youngs_modulus, b.youngs_modulus);
  }
};

/// Still air around the pendulum (absent for a vacuum).
template <class T>
struct Air {
  T pressure;     ///< (Pa)
  T temperature;  ///< (K)
  T molar_mass;   ///< (kg/mol)
  T viscosity;    ///< (Pa s)
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    f({"air.pressure", "Pa"}, a.pressure, b.pressure);
    f({"air.temperature", "K"}, a.temperature, b.temperature);
    f({"air.molar_mass", "kg/mol"}, a.molar_mass, b.molar_mass);
    f({"air.viscosity", "Pa s"}, a.viscosity, b.viscosity);
  }
};

/// The support, as a mass on a spring (Nelson & Olsson Fig. 3); at least one
/// of the two is given.
template <class T>
struct Support {
  std::optional<T> stiffness;  ///< (N/m)
  std::optional<T> mass;       ///< (kg)
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    f({"support.stiffness", "N/m"}, a.stiffness, b.stiffness);
    f({"support.mass", "kg"}, a.mass, b.mass);
  }
};

/// Amplitude decay d theta0/dt = -alpha theta0 - beta theta0^2 (Eq. 24).
template <class T>
struct Decay {
  T alpha;  ///< (1/s)
  T beta;   ///< (1/(s rad)), of the angle `angle_of`
  AngleOf angle_of = AngleOf::pendulum;  ///< whose angle the decay record followed
  /// Eq. (50) follows the amplitude over each timing; false where every
  /// observation is a group of a recording's swings already at its own
  /// amplitude (a long decay reduced swing by swing, recordings/swing_series.hpp).
  bool over_timing = true;
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    if constexpr (!std::is_const_v<B>) b.angle_of = a.angle_of, b.over_timing = a.over_timing;
    f({"decay.alpha", "1/s"}, a.alpha, b.alpha);
    f({"decay.beta", "1/(s rad)"}, a.beta, b.beta);
  }
};

/// A rigid body swinging about pivots along its axis (a physical pendulum,
/// models/physical_pendulum.hpp): what the scene states or its parts give
/// (bodies.hpp), each held in the fit. Positions are in the frame of the
/// observations' pivot_position: along the body from a mark on it.
///
/// A body in parts has its parts' scalars as fields (`body.parts[j].mass`),
/// and its k, centre, mass and volume are what the parts give
/// (derive_from_parts, run by convert_apparatus), not fields of their own:
/// a part's dimension moves them wherever it moves.
template <class T>
struct RigidBody {
  std::optional<T> center_of_mass_position;  ///< measured (balanced on an edge) or from the parts (m)
  std::optional<T> radius_of_gyration;       ///< about the centre of mass, from the parts (m)
  std::optional<T> mass;                     ///< from the parts (kg); buoyancy needs it
  std::optional<T> volume;                   ///< from the parts (m^3); buoyancy needs it
  std::optional<T> temperature;              ///< of the body during the swings (K)
  std::optional<T> reference_temperature;    ///< at which its lengths were measured (K)
  std::optional<T> expansion_coefficient;    ///< linear, w of Kelley Eq. (41) (1/K)
  std::vector<BodyPart<T>> parts;            ///< as the scene gives them (body.parts)
  bool gyration_from_parts = false;          ///< k held at the parts' (not fitted)
  bool center_from_parts = false;            ///< the centre held at the parts' (not fitted, not measured)
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    if constexpr (!std::is_const_v<B>) b.gyration_from_parts = a.gyration_from_parts, b.center_from_parts = a.center_from_parts;
    if (!a.center_from_parts) f({"center_of_mass_position", "m"}, a.center_of_mass_position, b.center_of_mass_position);
    if (a.parts.empty()) {
      f({"body.radius_of_gyration", "m"}, a.radius_of_gyration, b.radius_of_gyration);
      f({"body.mass", "kg"}, a.mass, b.mass);
      f({"body.volume", "m^3"}, a.volume, b.volume);
    }
    detail::zip_list(a.parts, b.parts, f);
    f({"temperature", "K"}, a.temperature, b.temperature);
    f({"reference_temperature", "K"}, a.reference_temperature, b.reference_temperature);
    f({"expansion_coefficient", "1/K"}, a.expansion_coefficient, b.expansion_coefficient);
  }
};

/// Sets what a body's parts give it: its mass and volume, and its k and
/// centre where they are held at the parts'. Only a body of values (positive
/// mass) has them: an apparatus of uncertainties keeps none.
template <class T>
void derive_from_parts(RigidBody<T>& b) {
  if (b.parts.empty()) return;
  const PartsSum<T> sum = sum_parts(b.parts);
  if (!(sum.body.mass > 0.0)) return;
  b.mass = sum.body.mass;
  b.volume = sum.volume;
  if (b.gyration_from_parts) b.radius_of_gyration = sum.body.radius_of_gyration;
  if (b.center_from_parts) b.center_of_mass_position = sum.body.center;
}

/// The apparatus of one experiment: the parts it has.
template <class T>
struct Apparatus {
  std::optional<Bob<T>> bob;
  std::optional<Ring<T>> ring;
  std::optional<Cap<T>> cap;
  std::optional<CapScrew<T>> cap_screw;
  std::optional<Wire<T>> wire;
  std::optional<Air<T>> air;
  std::optional<Support<T>> support;
  /// Shared by every observation: what the file states, or the fit of its
  /// decay record.
  std::optional<Decay<T>> decay;
  /// A physical pendulum's body (models/physical_pendulum.hpp).
  std::optional<RigidBody<T>> body;
  /// No air by statement ("air": "vacuum"), as opposed to air not described.
  bool vacuum = false;
};

/// Visits every scalar field that `a` has, paired with the same field of
/// `b`: f(Field, a_field, b_field). Parts and optional fields present in `a`
/// are created in `b` when `b` is writable; a read-only `b` must have the
/// shape of `a` (pass `a` twice to visit one apparatus).
template <class A, class B, class F>
void zip_apparatus(A& a, B& b, F&& f) {
  detail::FieldZipper<F> z{f};
  if constexpr (!std::is_const_v<B>) b.vacuum = a.vacuum;
  detail::zip_part(a.bob, b.bob, z);
  detail::zip_part(a.ring, b.ring, z);
  detail::zip_part(a.cap, b.cap, z);
  detail::zip_part(a.cap_screw, b.cap_screw, z);
  detail::zip_part(a.wire, b.wire, z);
  detail::zip_part(a.air, b.air, z);
  detail::zip_part(a.support, b.support, z);
  detail::zip_part(a.decay, b.decay, z);
  detail::zip_part(a.body, b.body, z);
}

/// The same apparatus with every scalar mapped by f(field, value) -> U, and
/// what a body's parts give derived again from the mapped parts.
template <class U, class T, class F>
Apparatus<U> convert_apparatus(const Apparatus<T>& a, F&& f) {
  Apparatus<U> out;
  zip_apparatus(a, out, [&](const Field& field, const T& x, U& y) { y = f(field, x); });
  if (out.body) derive_from_parts(*out.body);
  return out;
}

}  // namespace pendulum
