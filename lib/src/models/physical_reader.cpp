// The keys of a physical pendulum (PhysicalPendulum::read_keys; docs/physical.md): a measured centre of
// mass, a body given in parts, the temperature; and the checks of a scene
// whose observations hang a rigid body at pivots.
#include <algorithm>
#include <cmath>

#include "../json/parts.hpp"
#include "pendulum/bodies.hpp"
#include "pendulum/models/physical_pendulum.hpp"

namespace pendulum::json_reader {

namespace {

const char* const kShapes =
    "point_mass, solid_sphere, spherical_shell, cylinder, disk, ring, thin_rod, box";

/// A length under `key` that must be positive (a dimension of a part), into
/// the part's field and its uncertainty.
void dimension(Object& o, const std::string& key, std::optional<double>& value, std::optional<double>& sigma) {
  const Measured m = quantity(o, key, Dimension::length, Range::positive);
  value = m.value;
  sigma = m.sigma;
}

/// A radius below the part's radius (a hole through a cylinder or a sphere), when present.
void inner_radius(Object& o, BodyPart<double>& v, BodyPart<double>& u) {
  if (!o.has("inner_radius")) return;
  const Measured inner = quantity(o, "inner_radius", Dimension::length, Range::non_negative);
  PENDULUM_FAIL_IF(inner.value > *v.radius, o.path("inner_radius") + ".value",
                   "got " + format_number(inner.value) + " m; expected at most the radius, " +
                       format_number(*v.radius) + " m");
  v.inner_radius = inner.value;
  u.inner_radius = inner.sigma;
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

/// One part as written (values and their uncertainties, the same fields).
struct ReadPart {
  BodyPart<double> value, sigma;
};

ReadPart read_part(const json& j, const std::string& path) {
  Object o(j, path, "an object with shape, its dimensions, mass or density, and position");
  const std::string shape = o.text("shape");
  BodyPart<double> v, u;
  if (shape == "point_mass") {
    v.shape = PartShape::point_mass;
  } else if (shape == "solid_sphere") {
    v.shape = PartShape::solid_sphere;
    dimension(o, "radius", v.radius, u.radius);
  } else if (shape == "spherical_shell") {
    v.shape = PartShape::spherical_shell;
    dimension(o, "radius", v.radius, u.radius);
    inner_radius(o, v, u);
  } else if (shape == "cylinder") {
    v.shape = PartShape::cylinder;
    dimension(o, "radius", v.radius, u.radius);
    inner_radius(o, v, u);
    dimension(o, "length", v.length, u.length);
    v.axis = orientation(o, "axis", CylinderAxis::body_axis);
  } else if (shape == "disk" || shape == "ring") {
    v.shape = shape == "ring" ? PartShape::ring : PartShape::disk;
    dimension(o, "radius", v.radius, u.radius);
    if (shape == "ring") inner_radius(o, v, u);
    if (o.has("thickness")) dimension(o, "thickness", v.thickness, u.thickness);
    v.axis = orientation(o, "plane", CylinderAxis::swing_axis);
  } else if (shape == "thin_rod") {
    v.shape = PartShape::thin_rod;
    dimension(o, "length", v.length, u.length);
  } else if (shape == "box") {
    v.shape = PartShape::box;
    dimension(o, "length", v.length, u.length);
    dimension(o, "width", v.width, u.width);
    dimension(o, "thickness", v.thickness, u.thickness);
  } else {
    throw InputError(o.path("shape"), "got " + shown(o.at("shape")) + "; expected one of: " + kShapes);
  }
  const Shape<double> s = shape_of(v);
  const bool has_mass = o.has("mass"), has_density = o.has("density");
  PENDULUM_FAIL_IF(has_mass == has_density, path,
                   std::string(has_mass ? "got both mass and density" : "got neither mass nor density") +
                       "; expected one of them");
  if (has_mass) {
    const Measured m = quantity(o, "mass", Dimension::mass, Range::positive);
    v.mass = m.value;
    u.mass = m.sigma;
  } else {
    PENDULUM_FAIL_IF(!(s.volume > 0.0), o.path("density"),
                     "a " + shape + " has no volume (or a zero dimension); expected its mass instead");
    const Measured rho = quantity(o, "density", Dimension::density, Range::positive);
    within(rho.value, 1e-3, kMaxDensity, o.path("density") + ".value", "kg/m^3",
           "a solid's or a liquid's density, up to osmium's 22590 kg/m^3");
    v.density = rho.value;
    u.density = rho.sigma;
  }
  v.hole = o.has("hole") && o.at("hole").is_boolean() && o.at("hole").get<bool>();
  PENDULUM_FAIL_IF(o.has("hole") && !o.at("hole").is_boolean(), o.path("hole"),
                   "got " + shown(o.at("hole")) + "; expected true or false");
  const Measured position = quantity(o, "position", Dimension::length, Range::any);
  v.position = position.value;
  u.position = position.sigma;
  if (o.has("source")) o.text("source");
  o.finish();
  u.shape = v.shape, u.axis = v.axis, u.hole = v.hole;
  return {v, u};
}

/// "body": {"parts": [...]}: the parts (values and uncertainties), checked
/// to make a body; k, the centre, the mass and (when every part has one) the
/// volume follow from them (derive_from_parts).
void read_body(Object& top, RigidBody<double>& v, RigidBody<double>& u) {
  Object body(top.at("body"), "body", "an object with parts");
  const json& list = body.at("parts");
  PENDULUM_FAIL_IF(!list.is_array() || list.empty(), "body.parts",
                   "got " + shown(list) + "; expected a non-empty array of parts");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const ReadPart r = read_part(list[i], "body.parts[" + std::to_string(i) + "]");
    v.parts.push_back(r.value);
    u.parts.push_back(r.sigma);
  }
  if (body.has("source")) body.text("source");
  body.finish();
  // The body's extent is the solid parts'; a hole must lie within it.
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const auto& p : v.parts) {
    if (p.hole) continue;
    const double half = shape_of(p).half_length;
    lo = std::min(lo, p.position - half);
    hi = std::max(hi, p.position + half);
  }
  PENDULUM_FAIL_IF(!(hi >= lo), "body.parts", "every part is a hole; expected at least one solid part");
  for (std::size_t i = 0; i < v.parts.size(); ++i) {
    const auto& p = v.parts[i];
    const double half = shape_of(p).half_length, from = p.position - half, to = p.position + half;
    PENDULUM_FAIL_IF(p.hole && (from < lo || to > hi), "body.parts[" + std::to_string(i) + "].position",
                     "the hole spans " + format_number(from) + " m to " + format_number(to) +
                         " m; expected it inside the body, which spans " + format_number(lo) + " m to " +
                         format_number(hi) + " m");
  }
  const BodyProperties<double> b = sum_parts(v.parts).body;
  PENDULUM_FAIL_IF(!(b.mass > 0.0) || !(b.inertia_center > 0.0), "body.parts",
                   "the holes outweigh the solid parts (total mass " + format_number(b.mass) +
                       " kg); expected a body of positive mass and moment of inertia");
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
      u.expansion_coefficient = m.uncertainty;
      out.assumptions.push_back("expansion_coefficient: " + name + ", " + format_number(m.w) + " +- " +
                                format_number(m.uncertainty, 2) +
                                " /K (Kelley 1993, table after Eq. 41: an average over grades, 10-90 degC; "
                                "the uncertainty from " + m.basis + ", as a uniform interval)");
      return;
    }
    names += (names.empty() ? "" : ", ") + std::string(m.material);
  }
  throw InputError("material", "got " + shown(top.at("material")) + "; expected one of: " + names +
                                   " (or expansion_coefficient)");
}

}  // namespace

}  // namespace pendulum::json_reader

namespace pendulum {

namespace json_reader {
namespace {

/// A series of rods (Setting::rod_length): every observation one, and none
/// of the keys of one body hung at its pivots, which each rod's length replaces.
void check_rods(Object& top, const ParsedScene& out) {
  for (std::size_t k = 0; k < out.observations.size(); ++k) {
    const Setting s = out.observations[k].setting;
    PENDULUM_FAIL_IF(s != Setting::rod_length, out.sources[k].path + setting_key(s),
                     std::string("got ") + setting_key(s) + " beside rod_length; expected every observation a rod "
                     "pivoted at its end (rod_length), or one body at its pivots (pivot_distance or pivot_position)");
  }
  for (const char* key : {"body", "center_of_mass_position"}) {
    PENDULUM_FAIL_IF(top.has(key), key,
                     std::string("given with rod_length; expected none: each rod is its own uniform body, its "
                                 "radius of gyration and centre following from its length"));
  }
  PENDULUM_FAIL_IF(!out.fit.empty(), "fit",
                   "got " + out.fit.front() + " with rod_length; expected no unknowns besides g: each rod's radius "
                   "of gyration and centre follow from its length");
}

}  // namespace
}  // namespace json_reader

void PhysicalPendulum::read_keys(json_reader::Object& top, ParsedScene& out) {
  using namespace json_reader;
  const bool rods = std::any_of(out.observations.begin(), out.observations.end(),
                                [](const auto& o) { return o.setting == Setting::rod_length; });
  if (rods) check_rods(top, out);
  RigidBody<double> v, u;
  if (top.has("body")) read_body(top, v, u);
  const bool fit_k = std::find(out.fit.begin(), out.fit.end(), "radius_of_gyration") != out.fit.end();
  const bool fit_center = std::find(out.fit.begin(), out.fit.end(), "center_of_mass_position") != out.fit.end();
  if (!v.parts.empty()) {
    // What the parts give, also where the fit replaces it (the fit is checked against it).
    RigidBody<double> parts = v;
    parts.gyration_from_parts = parts.center_from_parts = true;
    derive_from_parts(parts);
    out.body_from_parts = parts;
    // The fit replaces what the parts give, and so does a measured centre.
    v.gyration_from_parts = u.gyration_from_parts = !fit_k;
    v.center_from_parts = u.center_from_parts = !fit_center && !top.has("center_of_mass_position");
    derive_from_parts(v);
  }
  if (top.has("center_of_mass_position")) {
    PENDULUM_FAIL_IF(fit_center, "center_of_mass_position",
                     "given and also in fit; expected one: a measured centre is held, a fitted one is not given");
    const Measured c = quantity(top, "center_of_mass_position", Dimension::length, Range::any);
    v.center_of_mass_position = c.value;
    u.center_of_mass_position = c.sigma;
  }
  if (top.has("temperature")) read_temperature(top, v, u, out);
  if (!rods && !fit_k && !v.radius_of_gyration) {
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
    if (o.setting == Setting::pivot_position && !v.center_of_mass_position) continue;
    const double p[kParameters] = {kStandardGravity, 0.0, v.center_of_mass_position.value_or(0.0)};
    const double h = pivot_distance(p, o, out.apparatus);
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

}  // namespace pendulum
