// The keys of a physical pendulum (docs/physical.md): a measured centre of
// mass, a body given in parts, the temperature; and the checks of a scene
// whose observations hang a rigid body at pivots.
#include <algorithm>
#include <cmath>

#include "parts.hpp"
#include "pendulum/bodies.hpp"
#include "pendulum/models/physical_pendulum.hpp"

namespace pendulum::json_reader {

namespace {

const char* const kShapes =
    "point_mass, solid_sphere, spherical_shell, cylinder, disk, ring, thin_rod, box";

/// A length under `key` that must be positive (a dimension of a part).
double dimension(Object& o, const std::string& key) {
  const Measured m = quantity(o, key, Dimension::length, Range::positive);
  return m.value;
}

/// A radius below `radius` (a hole through a cylinder or a sphere), 0 when absent.
double inner_radius(Object& o, double radius) {
  if (!o.has("inner_radius")) return 0.0;
  const double inner = quantity(o, "inner_radius", Dimension::length, Range::non_negative).value;
  PENDULUM_FAIL_IF(inner > radius, o.path("inner_radius") + ".value",
                   "got " + format_number(inner) + " m; expected at most the radius, " + format_number(radius) + " m");
  return inner;
}

/// "axis" of a cylinder, or "plane" of a disk or ring.
CylinderAxis orientation(Object& o, const std::string& key, CylinderAxis otherwise) {
  if (!o.has(key)) return otherwise;
  const std::string v = o.text(key);
  if (key == "axis") {
    if (v == "swing") return CylinderAxis::swing_axis;
    if (v == "body") return CylinderAxis::body_axis;
    if (v == "swing_direction") return CylinderAxis::swing_direction;
    throw InputError(o.path(key), "got " + shown(o.at(key)) +
                                      "; expected \"swing\" (its axis along the swing axis), \"body\" (along the "
                                      "body) or \"swing_direction\"");
  }
  if (v == "swing") return CylinderAxis::swing_axis;
  if (v == "edge_on") return CylinderAxis::swing_direction;
  throw InputError(o.path(key), "got " + shown(o.at(key)) +
                                    "; expected \"swing\" (face on in the plane of swing) or \"edge_on\"");
}

/// One part: its shape, mass (or density), position and whether it is a hole.
struct ReadPart {
  Shape<double> shape;
  Part<double> part;
};

ReadPart read_part(const json& j, const std::string& path) {
  Object o(j, path, "an object with shape, its dimensions, mass or density, and position");
  const std::string shape = o.text("shape");
  Shape<double> s;
  if (shape == "point_mass") {
    s = point_mass_shape<double>();
  } else if (shape == "solid_sphere") {
    s = solid_sphere(dimension(o, "radius"));
  } else if (shape == "spherical_shell") {
    const double r = dimension(o, "radius");
    s = spherical_shell(r, inner_radius(o, r));
  } else if (shape == "cylinder") {
    const double r = dimension(o, "radius");
    s = cylinder(r, inner_radius(o, r), dimension(o, "length"), orientation(o, "axis", CylinderAxis::body_axis));
  } else if (shape == "disk" || shape == "ring") {
    const double r = dimension(o, "radius");
    const double inner = shape == "ring" ? inner_radius(o, r) : 0.0;
    const double thickness = o.has("thickness") ? dimension(o, "thickness") : 0.0;
    s = cylinder(r, inner, thickness, orientation(o, "plane", CylinderAxis::swing_axis));
  } else if (shape == "thin_rod") {
    s = thin_rod(dimension(o, "length"));
  } else if (shape == "box") {
    s = box(dimension(o, "length"), dimension(o, "width"), dimension(o, "thickness"));
  } else {
    throw InputError(o.path("shape"), "got " + shown(o.at("shape")) + "; expected one of: " + kShapes);
  }
  const bool has_mass = o.has("mass"), has_density = o.has("density");
  PENDULUM_FAIL_IF(has_mass == has_density, path,
                   std::string(has_mass ? "got both mass and density" : "got neither mass nor density") +
                       "; expected one of them");
  double mass;
  if (has_mass) {
    mass = quantity(o, "mass", Dimension::mass, Range::positive).value;
  } else {
    PENDULUM_FAIL_IF(!(s.volume > 0.0), o.path("density"),
                     "a " + shape + " has no volume (or a zero dimension); expected its mass instead");
    const double rho = quantity(o, "density", Dimension::density, Range::positive).value;
    within(rho, 1e-3, kMaxDensity, o.path("density") + ".value", "kg/m^3",
           "a solid's or a liquid's density, up to osmium's 22590 kg/m^3");
    mass = rho * s.volume;
  }
  const bool hole = o.has("hole") && o.at("hole").is_boolean() && o.at("hole").get<bool>();
  PENDULUM_FAIL_IF(o.has("hole") && !o.at("hole").is_boolean(), o.path("hole"),
                   "got " + shown(o.at("hole")) + "; expected true or false");
  const double position = quantity(o, "position", Dimension::length, Range::any).value;
  if (o.has("source")) o.text("source");
  o.finish();
  return {s, make_part(s, hole ? -mass : mass, position)};
}

/// "body": {"parts": [...]}: k, the centre, the mass and (when every part
/// has one) the volume.
RigidBody<double> read_body(Object& top) {
  Object body(top.at("body"), "body", "an object with parts");
  const json& list = body.at("parts");
  PENDULUM_FAIL_IF(!list.is_array() || list.empty(), "body.parts",
                   "got " + shown(list) + "; expected a non-empty array of parts");
  std::vector<ReadPart> read;
  for (std::size_t i = 0; i < list.size(); ++i) read.push_back(read_part(list[i], "body.parts[" + std::to_string(i) + "]"));
  if (body.has("source")) body.text("source");
  body.finish();
  // The body's extent is the solid parts'; a hole must lie within it.
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const auto& r : read) {
    if (r.part.mass < 0.0) continue;
    lo = std::min(lo, r.part.center - r.shape.half_length);
    hi = std::max(hi, r.part.center + r.shape.half_length);
  }
  PENDULUM_FAIL_IF(!(hi >= lo), "body.parts", "every part is a hole; expected at least one solid part");
  std::vector<Part<double>> parts;
  double volume = 0.0;
  bool volumes = true;
  for (std::size_t i = 0; i < read.size(); ++i) {
    const auto& r = read[i];
    const double from = r.part.center - r.shape.half_length, to = r.part.center + r.shape.half_length;
    PENDULUM_FAIL_IF(r.part.mass < 0.0 && (from < lo || to > hi), "body.parts[" + std::to_string(i) + "].position",
                     "the hole spans " + format_number(from) + " m to " + format_number(to) +
                         " m; expected it inside the body, which spans " + format_number(lo) + " m to " +
                         format_number(hi) + " m");
    parts.push_back(r.part);
    volumes = volumes && r.shape.volume > 0.0;
    volume += (r.part.mass < 0.0 ? -1.0 : 1.0) * r.shape.volume;
  }
  const BodyProperties<double> b = body_properties(parts);
  PENDULUM_FAIL_IF(!(b.mass > 0.0) || !(b.inertia_center > 0.0), "body.parts",
                   "the holes outweigh the solid parts (total mass " + format_number(b.mass) +
                       " kg); expected a body of positive mass and moment of inertia");
  RigidBody<double> out;
  out.center_of_mass_position = b.center;
  out.radius_of_gyration = b.radius_of_gyration;
  out.mass = b.mass;
  if (volumes) out.volume = volume;
  return out;
}

/// temperature, reference_temperature, and expansion_coefficient or material.
void read_temperature(Object& top, RigidBody<double>& v, RigidBody<double>& u, ParsedScene& out) {
  const Measured t = quantity(top, "temperature", Dimension::temperature, Range::positive);
  within(t.value, 150.0, 500.0, "temperature.value", "K", "a laboratory's temperature, 150 K to 500 K");
  v.temperature = t.value;
  u.temperature = t.sigma;
  if (top.has("reference_temperature")) {
    const Measured r = quantity(top, "reference_temperature", Dimension::temperature, Range::positive);
    within(r.value, 150.0, 500.0, "reference_temperature.value", "K", "a laboratory's temperature, 150 K to 500 K");
    v.reference_temperature = r.value;
    u.reference_temperature = r.sigma;
  } else {
    v.reference_temperature = 293.15;
    u.reference_temperature = 0.0;
    out.assumptions.push_back("reference_temperature: not given; the body's lengths were measured at 20 degC");
  }
  const bool coefficient = top.has("expansion_coefficient"), material = top.has("material");
  PENDULUM_FAIL_IF(coefficient == material, "temperature",
                   std::string(coefficient ? "got both expansion_coefficient and material"
                                           : "got a temperature but neither expansion_coefficient nor material") +
                       "; expected one of them");
  if (coefficient) {
    const Measured w = quantity(top, "expansion_coefficient", Dimension::expansion, Range::any);
    within(std::abs(w.value), 0.0, 1e-3, "expansion_coefficient.value", "1/K",
           "a solid's linear expansion, below 1e-3 /K (steel 1.1e-5)");
    v.expansion_coefficient = w.value;
    u.expansion_coefficient = w.sigma;
    return;
  }
  const std::string name = top.text("material");
  std::string names;
  for (const auto& m : kExpansionCoefficients) {
    if (name == m.material) {
      v.expansion_coefficient = m.w;
      u.expansion_coefficient = 0.0;
      out.assumptions.push_back("expansion_coefficient: " + name + ", " + format_number(m.w) +
                                " /K (Kelley 1993, table after Eq. 41: an average over grades, 10-90 degC)");
      return;
    }
    names += (names.empty() ? "" : ", ") + std::string(m.material);
  }
  throw InputError("material", "got " + shown(top.at("material")) + "; expected one of: " + names +
                                   " (or expansion_coefficient)");
}

}  // namespace

void read_physical(Object& top, ParsedScene& out) {
  RigidBody<double> v, u;
  if (top.has("body")) {
    out.body_from_parts = read_body(top);
    v = *out.body_from_parts;
  }
  const bool fit_k = std::find(out.fit.begin(), out.fit.end(), "radius_of_gyration") != out.fit.end();
  const bool fit_center = std::find(out.fit.begin(), out.fit.end(), "center_of_mass_position") != out.fit.end();
  // The fit replaces what the parts give; the parts' values stay for the check.
  if (fit_k) v.radius_of_gyration.reset();
  if (fit_center) v.center_of_mass_position.reset();
  // What the parts give carries no uncertainty of its own (their
  // dimensions' uncertainties are not propagated).
  if (v.radius_of_gyration) u.radius_of_gyration = 0.0;
  if (v.center_of_mass_position) u.center_of_mass_position = 0.0;
  if (v.mass) u.mass = 0.0;
  if (v.volume) u.volume = 0.0;
  if (top.has("center_of_mass_position")) {
    PENDULUM_FAIL_IF(fit_center, "center_of_mass_position",
                     "given and also in fit; expected one: a measured centre is held, a fitted one is not given");
    const Measured c = quantity(top, "center_of_mass_position", Dimension::length, Range::any);
    v.center_of_mass_position = c.value;
    u.center_of_mass_position = c.sigma;
  }
  if (top.has("temperature")) read_temperature(top, v, u, out);
  if (!fit_k && !v.radius_of_gyration) {
    throw InputError("fit", "the radius of gyration is neither fitted nor given; expected \"radius_of_gyration\" in "
                            "fit, or the body in parts (body.parts)");
  }
  const bool positions = std::any_of(out.observations.begin(), out.observations.end(),
                                     [](const auto& o) { return o.setting == Setting::pivot_position; });
  PENDULUM_FAIL_IF(positions && !fit_center && !v.center_of_mass_position, "center_of_mass_position",
                   "not given; expected the centre's position (balanced on an edge), \"center_of_mass_position\" "
                   "in fit, or the body in parts: the observations give pivot_position");
  // A pivot at a known centre: no restoring torque, an infinite period.
  for (std::size_t k = 0; k < out.observations.size(); ++k) {
    const auto& o = out.observations[k];
    const std::string at = out.sources[k].path + setting_key(o.setting) + ".value";
    const double h = o.setting == Setting::pivot_position && v.center_of_mass_position
                         ? std::abs(o.length - *v.center_of_mass_position)
                         : o.length;
    if (o.setting == Setting::pivot_position && !v.center_of_mass_position) continue;
    PENDULUM_FAIL_IF(!(h > 1e-9 * std::max(1.0, std::abs(o.length))), at,
                     "got a pivot " + format_number(h) + " m from the centre of mass; expected a pivot away from "
                     "it (at the centre the body has no restoring torque and its period is infinite)");
  }
  // With k fitted, the pivots must lie at more than one distance from the
  // centre: at one distance every period is the same one, which tells g
  // from k no better than a single observation.
  if (fit_k && !fit_center && out.observations.size() > 1) {
    auto distance = [&](const Observation<double>& o) {
      return o.setting == Setting::pivot_position ? std::abs(o.length - *v.center_of_mass_position) : o.length;
    };
    const double h0 = distance(out.observations.front());
    const bool one_distance = std::all_of(out.observations.begin(), out.observations.end(), [&](const auto& o) {
      return std::abs(distance(o) - h0) <= 1e-6 * h0;
    });
    const auto& last = out.observations.back();
    PENDULUM_FAIL_IF(one_distance, out.sources.back().path + setting_key(last.setting) + ".value",
                     "got every pivot " + format_number(h0) + " m from the centre of mass; expected pivots at "
                     "different distances: with radius_of_gyration fitted, one distance gives one period, which "
                     "cannot tell g from k");
  }
  out.apparatus.body = v;
  out.apparatus_uncertainty.body = u;
}

}  // namespace pendulum::json_reader
