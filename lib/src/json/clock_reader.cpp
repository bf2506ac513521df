// parse_clock_scene: a clock scene (docs/clock.md) on the JSON toolkit of
// reader.hpp.
#include <algorithm>
#include <cmath>
#include <optional>

#include "pendulum/argument_ranges.hpp"
#include "pendulum/clock_scene.hpp"
#include "pendulum/json/scene_json.hpp"
#include "reader.hpp"

namespace pendulum {

using namespace json_reader;

namespace {

/// One of `choices` under `key`, by name.
std::string choice(Object& o, const std::string& key, const std::vector<std::string>& choices) {
  const std::string v = o.text(key);
  if (std::find(choices.begin(), choices.end(), v) != choices.end()) return v;
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "\"" : ", \"") + c + "\"";
  throw InputError(o.path(key), "got " + shown(o.at(key)) + "; expected one of " + list);
}

/// A quantity in SI (reader.hpp) within [lo, hi], `what` naming that range.
/// A dimensionless one (Q: no `dim`) may be a bare number or an object whose
/// unit, if any, is "1".
ClockQuantity quantity(Object& parent, const std::string& key, std::optional<Dimension> dim, double lo, double hi,
                       const std::string& what) {
  const json& j = parent.at(key);
  if (dim) {
    const Measured m = json_reader::quantity(parent, key, *dim, Range::any);
    PENDULUM_FAIL_IF(!(m.value >= lo && m.value <= hi), parent.path(key) + ".value",
                     "got " + format_number(j.at("value").get<double>()) + " " + j.at("unit").get<std::string>() +
                         "; expected " + what);
    PENDULUM_FAIL_IF(m.value > 0.0 && m.sigma >= m.value, parent.path(key) + ".uncertainty",
                     uncertainty_not_below_value(shown(j.at("uncertainty")) + " " + j.at("unit").get<std::string>(),
                                                 shown(j.at("value")) + " " + j.at("unit").get<std::string>()));
    return {m.value, m.sigma};
  }
  if (j.is_number()) {
    const double x = finite_number(j, [&] { return parent.path(key); }, "a number");
    PENDULUM_FAIL_IF(!(x >= lo && x <= hi), parent.path(key), "got " + format_number(x) + "; expected " + what);
    return {x, 0.0};
  }
  Object q(j, parent.path(key), "a number or an object {\"value\": ...}");
  const double x = finite_number(q.at("value"), [&] { return q.path("value"); }, "a number");
  if (q.has("unit") && q.text("unit") != "1") {
    throw InputError(q.path("unit"), "got " + shown(q.at("unit")) + "; expected \"1\" (Q has no unit)");
  }
  const double u = q.has("uncertainty")
                       ? finite_number(q.at("uncertainty"), [&] { return q.path("uncertainty"); }, "a number")
                       : 0.0;
  PENDULUM_FAIL_IF(u < 0.0, q.path("uncertainty"), "got " + format_number(u) + "; expected a non-negative uncertainty");
  if (q.has("source")) q.text("source");
  q.finish();
  PENDULUM_FAIL_IF(!(x >= lo && x <= hi), q.path("value"), "got " + format_number(x) + "; expected " + what);
  PENDULUM_FAIL_IF(x > 0.0 && u >= x, q.path("uncertainty"),
                   uncertainty_not_below_value(format_number(u), format_number(x)));
  return {x, u};
}

}  // namespace

ClockScene parse_clock_scene(const std::string& text) {
  const json doc = parse_json(text, kSceneInput);
  Object top(doc, "", "a JSON object (the clock scene)");
  ClockScene s;
  PENDULUM_FAIL_IF(!top.has("schema"), "schema",
                   std::string("missing; a clock scene names itself: \"schema\": \"") + kClockSceneSchema + "\"");
  const std::string schema = top.text("schema");
  if (schema != kClockSceneSchema) {
    throw InputError("schema", "got " + shown(top.at("schema")) + "; expected \"" + kClockSceneSchema + "\"" +
                                   (schema == kSceneSchema ? " (a pendulum-g/scene/1 file is for pendulum-g reduce)" : ""));
  }
  if (top.has("title")) s.title = top.text("title");
  if (top.has("source")) s.source = top.text("source");
  if (top.has("notes")) top.text("notes");
  s.path = top.has("path") && choice(top, "path", {"circular", "cycloidal"}) == "cycloidal"
               ? ClockPath::cycloidal
               : ClockPath::circular;
  if (top.has("damped")) {
    if (!top.at("damped").is_boolean()) {
      throw InputError("damped", "got " + shown(top.at("damped")) + "; expected true or false");
    }
    s.damped = top.at("damped").get<bool>();
  }
  s.g = quantity(top, "g", Dimension::acceleration, 0.1, 1000.0, "a surface gravity from 0.1 to 1000 m/s^2");
  const bool has_length = top.has("length"), has_period = top.has("nominal_period");
  if (has_length == has_period) {
    throw InputError(has_length ? "nominal_period" : "length",
                     has_length ? "given beside length; expected one of length and nominal_period"
                                : "missing; expected length or nominal_period");
  }
  if (has_length) {
    s.length = quantity(top, "length", Dimension::length, 1e-3, 1e3, "a length from 1 mm to 1 km");
  } else {
    const ClockQuantity p =
        quantity(top, "nominal_period", Dimension::time, 1e-2, 1e3, "a period from 0.01 to 1000 s");
    s.nominal_period = p.value;
    s.length = {length_for_period(p.value, s.g.value), 0.0};  // Feinstein Eq. (B-1)
  }
  const bool cycloid = s.path == ClockPath::cycloidal;
  const double top_angle = cycloid ? kPi / 2.0 : kPi;
  // From ranges::semi_amplitude's low end to below the top (the cycloid's cusp at 90 deg).
  const ArgumentRange& a = ranges::semi_amplitude;
  const std::string range = cycloid ? "an angle from 1e-9 rad to below 90 deg (the cycloid's cusp)" : a.expected;
  s.semi_amplitude = quantity(top, "semi_amplitude", Dimension::angle, a.low, top_angle, range);
  if (!(s.semi_amplitude.value < top_angle)) {
    throw InputError("semi_amplitude.value", "got " + format_number(s.semi_amplitude.value) + " rad; expected " + range);
  }
  // A damped swing of Q >= 1 reaches equilibrium within 0.4 of a
  // small-amplitude period.
  s.q = quantity(top, "Q", std::nullopt, ranges::quality.low, ranges::quality.high, ranges::quality.expected);
  const std::string over_top = impulse_over_top(s.semi_amplitude.value, s.q.value, s.path);
  if (!over_top.empty()) throw InputError("Q", over_top);
  Object impulse(top.at("impulse"), "impulse");
  const bool has_location = impulse.has("location"), has_relative = impulse.has("relative_location");
  if (has_location == has_relative) {
    throw InputError(has_location ? "impulse.relative_location" : "impulse.location",
                     has_location ? "given beside location; expected one of location and relative_location"
                                  : "missing; expected location (an angle) or relative_location (0 to 1)");
  }
  if (has_location) {
    s.location = quantity(impulse, "location", Dimension::angle, 0.0, s.semi_amplitude.value,
                          "an angle from 0 to the semi-amplitude (" + format_number(s.semi_amplitude.value) + " rad)");
  } else {
    s.location = quantity(impulse, "relative_location", std::nullopt, 0.0, 1.0,
                          "a fraction of the semi-amplitude from 0 to 1");
    s.relative_location = true;
  }
  s.direction = choice(impulse, "direction", {"away", "toward"}) == "toward" ? ImpulseDirection::toward
                                                                              : ImpulseDirection::away;
  impulse.finish();
  if (top.has("accuracy")) {
    s.accuracy = quantity(top, "accuracy", Dimension::daily_rate, 0.0, 1e6,
                          "a non-negative daily rate (0: the exact route)").value;
  }
  top.finish();
  return s;
}

}  // namespace pendulum
