#include "pendulum/clock_scene.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include <ceres/jet.h>
#include <nlohmann/json.hpp>

#include "pendulum/scene_json.hpp"
#include "pendulum/units.hpp"

namespace pendulum {
namespace {

using nlohmann::json;

constexpr const char* kClockSceneSchema = "pendulum-g/clock-scene/1";

std::string shown(const json& j) {
  std::string s = j.dump(-1, ' ', true, json::error_handler_t::replace);
  return s.size() > 60 ? s.substr(0, 57) + "..." : s;
}

std::string number(double x) {
  std::ostringstream out;
  out.precision(10);
  out << x;
  return out.str();
}

std::string join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

/// JSON text -> document; a key given twice in one object is refused (the
/// JSON library would keep the last silently), syntax errors name the byte.
json parse_document(const std::string& text) {
  if (text.size() > kMaxSceneBytes) {
    throw InputError("", "got more than " + std::to_string(kMaxSceneBytes) +
                             " bytes; expected a clock scene of at most 1 MiB");
  }
  std::vector<std::set<std::string>> keys;
  std::string duplicate;
  const json::parser_callback_t callback = [&](int depth, json::parse_event_t event, json& parsed) {
    using Event = json::parse_event_t;
    if (depth > 8) throw InputError("", "got values nested more than 8 deep; expected a clock scene");
    if (event == Event::object_start) keys.emplace_back();
    if (event == Event::object_end) keys.pop_back();
    if (event == Event::key && !keys.back().insert(parsed.get<std::string>()).second) {
      throw InputError(parsed.get<std::string>(), "got this key twice in one object; expected each key once");
    }
    return true;
  };
  try {
    return json::parse(text, callback);
  } catch (const json::exception& e) {
    const std::string why = e.what();
    const auto bracket = why.find("] ");
    throw InputError("", "not valid JSON: " + (bracket == std::string::npos ? why : why.substr(bracket + 2)));
  }
}

/// An object being read: the keys asked for are known; finish() refuses the rest.
class Fields {
 public:
  Fields(const json& j, std::string path) : j_(j), path_(std::move(path)) {
    if (!j.is_object()) throw InputError(path_, "got " + shown(j) + "; expected an object");
  }
  bool has(const std::string& key) {
    known_.insert(key);
    return j_.contains(key);
  }
  const json& at(const std::string& key) {
    if (!has(key)) throw InputError(path(key), "missing; it is required here");
    return j_.at(key);
  }
  std::string path(const std::string& key) const { return join(path_, key); }
  std::string text(const std::string& key) {
    const json& v = at(key);
    if (!v.is_string()) throw InputError(path(key), "got " + shown(v) + "; expected a string");
    return v.get<std::string>();
  }
  /// One of `choices`, by name.
  std::string choice(const std::string& key, const std::vector<std::string>& choices) {
    const std::string v = text(key);
    if (std::find(choices.begin(), choices.end(), v) != choices.end()) return v;
    std::string list;
    for (const auto& c : choices) list += (list.empty() ? "\"" : ", \"") + c + "\"";
    throw InputError(path(key), "got " + shown(at(key)) + "; expected one of " + list);
  }
  double finite(const std::string& key, const std::string& expected) {
    const json& v = at(key);
    if (!v.is_number() || !std::isfinite(v.get<double>())) {
      throw InputError(path(key), "got " + shown(v) + "; expected " + expected);
    }
    return v.get<double>();
  }
  void finish() const {
    for (const auto& item : j_.items()) {
      if (known_.count(item.key())) continue;
      std::string list;
      for (const auto& k : known_) list += (list.empty() ? "" : ", ") + k;
      throw InputError(path(item.key()), "unknown key; this object takes: " + list);
    }
  }

 private:
  const json& j_;
  std::string path_;
  std::set<std::string> known_;
};

/// {"value": x, "unit": "...", "uncertainty": u, "source": "..."} in SI,
/// the value within [lo, hi] (SI) with `what` naming that range. A
/// dimensionless quantity (Q) takes no unit, or "1", and may be a bare number.
ClockQuantity quantity(Fields& parent, const std::string& key, std::optional<Dimension> dim, double lo,
                       double hi, const std::string& what) {
  const std::string path = parent.path(key);
  const json& j = parent.at(key);
  if (!dim && j.is_number()) {
    const double x = parent.finite(key, "a number");
    if (!(x >= lo && x <= hi)) throw InputError(path, "got " + number(x) + "; expected " + what);
    return {x, 0.0};
  }
  Fields q(j, path);
  const double raw = q.finite("value", "a number");
  double factor = 1.0;
  std::string unit_name = "1";
  if (dim) {
    unit_name = q.text("unit");
    const auto unit = find_unit(unit_name, *dim);
    if (!unit) {
      throw InputError(q.path("unit"), "got " + shown(q.at("unit")) + "; expected a unit of " +
                                           dimension_name(*dim) + ": " + unit_names(*dim));
    }
    factor = unit->factor;
  } else if (q.has("unit") && q.text("unit") != "1") {
    throw InputError(q.path("unit"), "got " + shown(q.at("unit")) + "; expected \"1\" (Q has no unit)");
  }
  const double u = q.has("uncertainty") ? q.finite("uncertainty", "a number") : 0.0;
  if (u < 0.0) throw InputError(q.path("uncertainty"), "got " + number(u) + "; expected a non-negative uncertainty");
  if (q.has("source")) q.text("source");
  q.finish();
  const double si = raw * factor;
  if (!(si >= lo && si <= hi)) {
    throw InputError(q.path("value"), "got " + number(raw) + " " + unit_name + "; expected " + what);
  }
  if (si > 0.0 && u * factor >= si) {
    throw InputError(q.path("uncertainty"), "got " + number(u) + " " + unit_name +
                                                "; expected an uncertainty smaller than the value");
  }
  return {si, u * factor};
}

}  // namespace

ClockScene parse_clock_scene(const std::string& text) {
  const json doc = parse_document(text);
  Fields top(doc, "");
  ClockScene s;
  const std::string schema = top.text("schema");
  if (schema != kClockSceneSchema) {
    throw InputError("schema", "got " + shown(top.at("schema")) + "; expected \"" + kClockSceneSchema + "\"");
  }
  if (top.has("title")) s.title = top.text("title");
  if (top.has("source")) s.source = top.text("source");
  if (top.has("notes")) top.text("notes");
  s.path = top.has("path") && top.choice("path", {"circular", "cycloidal"}) == "cycloidal"
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
  // From 1e-9 rad (2e-4 arc seconds, far below any clock's swing; k^2 stays
  // far from underflow) to below the top (the cycloid's cusp at 90 deg).
  const std::string range = cycloid ? "an angle from 1e-9 rad to below 90 deg (the cycloid's cusp)"
                                    : "an angle from 1e-9 rad to below 180 deg";
  s.semi_amplitude = quantity(top, "semi_amplitude", Dimension::angle, 1e-9, top_angle, range);
  if (!(s.semi_amplitude.value < top_angle)) {
    throw InputError("semi_amplitude.value", "got " + number(s.semi_amplitude.value) + " rad; expected " + range);
  }
  // Q >= 1: a clock's pendulum swings many times before it stops (Feinstein:
  // 100 to 1e6); a damped swing then reaches equilibrium within 0.4 of a
  // small-amplitude period.
  s.q = quantity(top, "Q", std::nullopt, 1.0, 1e15, "a quality factor from 1 to 1e15");
  // The impulse adds pi E/Q: the swing after it must stay below the top (Eq. F-1).
  const double k_i = std::sqrt(1.0 + kPi / s.q.value) *
                     (cycloid ? std::sin(s.semi_amplitude.value) : std::sin(s.semi_amplitude.value / 2.0));
  if (!(k_i < 1.0)) {
    throw InputError("Q", "got " + number(s.q.value) + "; expected a Q large enough that the impulse (pi/Q of "
                          "the energy, Eq. F-1) keeps the swing below " + (cycloid ? "90 deg" : "180 deg"));
  }
  Fields impulse(top.at("impulse"), "impulse");
  const bool has_location = impulse.has("location"), has_relative = impulse.has("relative_location");
  if (has_location == has_relative) {
    throw InputError(has_location ? "impulse.relative_location" : "impulse.location",
                     has_location ? "given beside location; expected one of location and relative_location"
                                  : "missing; expected location (an angle) or relative_location (0 to 1)");
  }
  if (has_location) {
    s.location = quantity(impulse, "location", Dimension::angle, 0.0, s.semi_amplitude.value,
                          "an angle from 0 to the semi-amplitude (" + number(s.semi_amplitude.value) + " rad)");
  } else {
    s.location = quantity(impulse, "relative_location", std::nullopt, 0.0, 1.0,
                          "a fraction of the semi-amplitude from 0 to 1");
    s.relative_location = true;
  }
  s.direction = impulse.choice("direction", {"away", "toward"}) == "toward" ? ImpulseDirection::toward
                                                                              : ImpulseDirection::away;
  impulse.finish();
  if (top.has("accuracy")) {
    s.accuracy = quantity(top, "accuracy", Dimension::daily_rate, 0.0, 1e6,
                          "a non-negative daily rate (0: the exact route)").value;
  }
  top.finish();
  return s;
}

ClockAnalysis analyse_clock(const ClockScene& s, std::optional<ClockRoute> route) try {
  ClockAnalysis a{};
  const bool circular = s.path == ClockPath::circular;
  const double theta0 = s.semi_amplitude.value, q = s.q.value;
  a.location = s.relative_location ? s.location.value * theta0 : s.location.value;
  a.small_amplitude_period = s.nominal_period ? *s.nominal_period : small_amplitude_period(s.length.value, s.g.value);
  a.circular_error_rate = circular ? circular_error_rate(theta0) : 0.0;
  a.circular_error = {circular ? circular_error(theta0) : 0.0, a.circular_error_rate * s.semi_amplitude.sigma};
  a.impulsed_amplitude = circular ? impulsed_amplitude(theta0, q)
                                  : std::asin(std::sqrt(1.0 + kPi / q) * std::sin(theta0));  // App. F

  if (route) {
    if (!route_fits(*route, s.path)) {
      throw InputError("--route", std::string("got ") + route_name(*route) +
                                      "; a circular route cannot model a cycloidal path");
    }
    const bool stand_in = circular && (*route == ClockRoute::cycloid || *route == ClockRoute::cycloid_damped);
    if (stand_in && !(a.impulsed_amplitude <= kPi / 3.0)) {
      throw InputError("--route", std::string("got ") + route_name(*route) +
                                      "; a cycloid of equal energy exists for a circular swing up to 60 deg");
    }
    a.choice = run_clock_route(*route, s.path, s.damped, theta0, a.location, q, s.accuracy);
  } else {
    a.choice = cheapest_clock_route(s.path, s.damped, theta0, a.location, q, s.accuracy);
  }
  const double sign = direction_sign(s.direction);
  a.impulse_error = sign * a.choice.effect.error;
  a.impulse_error_rate = sign * a.choice.effect.rate;
  if (s.accuracy > 0.0 && a.choice.error_bound > s.accuracy) {
    a.warnings.push_back("the accuracy asked (" + number(s.accuracy) + " s/day) was not reached: the bound of " +
                         route_name(a.choice.route) + " is " + number(a.choice.error_bound) + " s/day");
  }

  // First-order uncertainty from the amplitude, the location and Q, with
  // the derivatives of the path's closed-form route.
  using Jet = ceres::Jet<double, 3>;
  const Jet t0(theta0, 0), loc(s.location.value, 1), qq(q, 2);
  const Jet theta = s.relative_location ? loc * t0 : loc;
  const Jet e = circular ? impulse_error_elliptic(t0, theta, qq).error : impulse_error_cycloid(t0, theta, qq).error;
  const double sigmas[3] = {s.semi_amplitude.sigma, s.location.sigma, s.q.sigma};
  double variance = 0.0;
  for (int i = 0; i < 3; ++i) {
    if (sigmas[i] > 0.0) variance += std::pow(e.v[i] * sigmas[i], 2);
  }
  if (std::isfinite(variance)) a.impulse_error_sigma = std::sqrt(variance);
  {
    using Jet1 = ceres::Jet<double, 1>;
    const Jet1 t(theta0, 0), fixed(a.location), qd(q);
    a.impulse_error_amplitude_rate =
        sign * (circular ? impulse_error_elliptic(t, fixed, qd).error : impulse_error_cycloid(t, fixed, qd).error).v[0];
  }

  const double ratio = circular ? finite_amplitude_agm(theta0) : 0.0;
  a.free_period = a.small_amplitude_period * (1.0 + ratio);
  a.impulsed_period = a.free_period * (1.0 + a.impulse_error / kSecondsPerDay);
  const double relative = s.nominal_period ? 0.0 : 0.5 * std::hypot(s.length.sigma / s.length.value, s.g.sigma / s.g.value);
  a.period_sigma = std::hypot(a.free_period * relative,
                              a.small_amplitude_period * a.circular_error.sigma / kSecondsPerDay);

  if (circular) a.insensitive_semi_amplitude = amplitude_insensitive_semi_amplitude(s.direction, a.location, q);
  if (!circular) {
    a.cancelling_note = "a cycloid has no circular error to cancel";
  } else if (s.direction == ImpulseDirection::away) {
    a.cancelling_note = "an impulse away from equilibrium adds its rate to the circular error's";
  } else {
    a.cancelling_semi_amplitude = cancelling_semi_amplitude(s.direction, s.location.value, s.relative_location, q);
    a.cancelling_note = a.cancelling_semi_amplitude
                            ? (s.relative_location ? "relative impulse location held fixed"
                                                   : "impulse location held fixed")
                            : "no semi-amplitude below 170 deg cancels";
  }
  return a;
} catch (const std::domain_error& e) {
  // A scene the validation let through but a route cannot model.
  throw InputError("", std::string("the clock cannot be modelled: ") + e.what());
}

}  // namespace pendulum
