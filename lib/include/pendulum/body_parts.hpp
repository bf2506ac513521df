#pragma once
/// \file body_parts.hpp
/// \brief A body's parts as the scene gives them (`body.parts[j]`): shape,
/// dimensions, mass or density, position, each scalar a field with its JSON
/// path, so that their uncertainties are inputs of the propagation like any
/// other; and what the parts give the body (bodies.hpp), generic in the
/// scalar so that a dual number seeded on one dimension carries it to k, the
/// centre, the mass and the volume.

#include <optional>
#include <type_traits>
#include <vector>

#include "pendulum/bodies.hpp"
#include "pendulum/fields.hpp"

namespace pendulum {

/// The shapes of docs/physical.md; a disk and a ring are cylinders whose
/// length is their thickness.
enum class PartShape { point_mass, solid_sphere, spherical_shell, cylinder, disk, ring, thin_rod, box };

/// One part as written: the dimensions its shape has (m), its mass (kg) or
/// density (kg/m^3), the position of its centre along the body (m).
template <class T>
struct BodyPart {
  PartShape shape = PartShape::point_mass;
  CylinderAxis axis = CylinderAxis::body_axis;  ///< a cylinder's axis, a disk's or ring's plane
  bool hole = false;                            ///< material removed: a part of negative mass
  std::optional<T> radius, inner_radius, length, width, thickness;
  std::optional<T> mass, density;  ///< one of them
  T position{};
  template <class A, class B, class F>
  static void zip(A& a, B& b, F& f) {
    if constexpr (!std::is_const_v<B>) b.shape = a.shape, b.axis = a.axis, b.hole = a.hole;
    f({"body.parts[].radius", "m"}, a.radius, b.radius);
    f({"body.parts[].inner_radius", "m"}, a.inner_radius, b.inner_radius);
    f({"body.parts[].length", "m"}, a.length, b.length);
    f({"body.parts[].width", "m"}, a.width, b.width);
    f({"body.parts[].thickness", "m"}, a.thickness, b.thickness);
    f({"body.parts[].mass", "kg"}, a.mass, b.mass);
    f({"body.parts[].density", "kg/m^3"}, a.density, b.density);
    f({"body.parts[].position", "m"}, a.position, b.position);
  }
};

/// The part's geometry (bodies.hpp); an absent inner radius or thickness is 0.
template <class T>
Shape<T> shape_of(const BodyPart<T>& p) {
  const T zero(0.0);
  const T inner = p.inner_radius.value_or(zero), thickness = p.thickness.value_or(zero);
  switch (p.shape) {
    case PartShape::point_mass: return point_mass_shape<T>();
    case PartShape::solid_sphere: return solid_sphere(*p.radius);
    case PartShape::spherical_shell: return spherical_shell(*p.radius, inner);
    case PartShape::cylinder: return cylinder(*p.radius, inner, *p.length, p.axis);
    case PartShape::disk: return cylinder(*p.radius, zero, thickness, p.axis);
    case PartShape::ring: return cylinder(*p.radius, inner, thickness, p.axis);
    case PartShape::thin_rod: return thin_rod(*p.length);
    case PartShape::box: return box(*p.length, *p.width, *p.thickness);
  }
  return point_mass_shape<T>();
}

/// Its mass (kg): the given one, or density times volume; negative for a hole.
template <class T>
T signed_mass(const BodyPart<T>& p, const Shape<T>& s) {
  const T m = p.mass ? *p.mass : T(*p.density * s.volume);
  return p.hole ? T(-m) : m;
}

/// What the parts give the body: M, x_c, I_c, k (body_properties), and the
/// volume when every part has one (m^3; a hole's counts negative).
template <class T>
struct PartsSum {
  BodyProperties<T> body;
  std::optional<T> volume;
};

/// The sums over `parts` (at least one).
template <class T>
PartsSum<T> sum_parts(const std::vector<BodyPart<T>>& parts) {
  std::vector<Part<T>> list;
  T volume(0.0);
  bool volumes = true;
  for (const auto& p : parts) {
    const Shape<T> s = shape_of(p);
    list.push_back(make_part(s, signed_mass(p, s), p.position));
    volumes = volumes && s.volume > 0.0;
    volume += p.hole ? T(-s.volume) : s.volume;
  }
  PartsSum<T> out{body_properties(list), std::nullopt};
  if (volumes) out.volume = volume;
  return out;
}

}  // namespace pendulum
