#include "reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

namespace pendulum {

InputError::InputError(std::string path, const std::string& message)
    : std::runtime_error((path.empty() ? std::string("(document)") : path) + ": " + message),
      path_(std::move(path)) {}

namespace json_reader {

std::string shown(const json& j) { return one_line(j.dump(-1, ' ', true), 60); }

namespace {
/// A key as a path component: as is if it is a plain name, else quoted.
std::string path_key(const std::string& key) {
  const bool plain = !key.empty() && key.size() <= 40 &&
                     std::all_of(key.begin(), key.end(), [](unsigned char c) {
                       return std::isalnum(c) || c == '_';
                     });
  return plain ? key : one_line(json(key).dump(-1, ' ', true), 40);
}

/// No scene nests deeper than 3 (air.pressure.value); the limit keeps the
/// recursive parts of the JSON library (dump, copy) off the end of the stack.
constexpr std::size_t kMaxNesting = 10;
}  // namespace

std::string join_path(const std::string& path, const std::string& key) {
  return path.empty() ? path_key(key) : path + "." + path_key(key);
}

/// Parses the text as JSON. The parser's callback tracks the path of the
/// value being read, to name it in syntax errors, refuses values nested too
/// deep, and refuses a key given twice in one object, which the JSON library
/// would silently resolve by keeping the last.
json parse_json(const std::string& text, std::size_t max_bytes) {
  if (text.size() > max_bytes) {
    throw InputError("", "got more than " + std::to_string(max_bytes) +
                             " bytes; expected a scene file of at most " + std::to_string(max_bytes >> 20) + " MiB");
  }
  struct Frame {
    bool array = false;
    std::size_t index = 0;       // arrays: the element being read
    std::string key;             // objects: the key being read
    std::set<std::string> keys;  // objects: the keys read so far
  };
  std::vector<Frame> frames;
  auto path = [&frames] {
    std::string p;
    for (const Frame& f : frames) {
      if (f.array) {
        p += "[" + std::to_string(f.index) + "]";
      } else if (!f.keys.empty()) {
        p = join_path(p, f.key);
      }
    }
    return p;
  };
  auto element_read = [&frames] {
    if (!frames.empty() && frames.back().array) ++frames.back().index;
  };
  const json::parser_callback_t callback = [&](int, json::parse_event_t event, json& parsed) {
    using Event = json::parse_event_t;
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        if (frames.size() >= kMaxNesting) {
          throw InputError(path(), "got values nested more than " + std::to_string(kMaxNesting) +
                                       " deep; expected a scene, whose values nest 3 deep");
        }
        frames.emplace_back();
        frames.back().array = event == Event::array_start;
        break;
      case Event::key:
        frames.back().key = parsed.get<std::string>();
        if (!frames.back().keys.insert(frames.back().key).second) {
          throw InputError(path(), "got this key twice in one object; expected each key once "
                                   "(a JSON reader would silently keep only the last)");
        }
        break;
      case Event::object_end:
      case Event::array_end:
        frames.pop_back();
        element_read();
        break;
      case Event::value:
        element_read();
        break;
    }
    return true;
  };
  try {
    return json::parse(text, callback);
  } catch (const json::exception& e) {
    const std::string why = e.what();  // "[json.exception.parse_error.101] parse error at ..."
    const auto bracket = why.find("] ");
    throw InputError(path(), "not valid JSON: " +
                                 one_line(bracket == std::string::npos ? why : why.substr(bracket + 2), 200));
  }
}

Object::Object(const json& j, std::string path, const char* what) : j_(j), path_(std::move(path)) {
  if (!j.is_object()) {
    throw InputError(path_, "got " + shown(j) + "; expected " + what);
  }
}

const json& Object::at(const std::string& key) {
  remember(key);
  const auto it = j_.find(key);
  if (it == j_.end()) throw InputError(path(key), "missing; it is required here");
  return *it;
}

std::string Object::text(const std::string& key) {
  const json& v = at(key);
  if (!v.is_string()) {
    throw InputError(path(key), "got " + shown(v) + "; expected a string");
  }
  return v.get<std::string>();
}

/// A value (SI) outside what a laboratory holds: a unit slip or a typo.
void within(double x, double lo, double hi, const std::string& path, const char* unit,
            const std::string& what) {
  PENDULUM_FAIL_IF(!(x >= lo && x <= hi), path, "got " + format_number(x) + " " + unit + "; expected " + what);
}

Measured quantity(Object& parent, const std::string& key, Dimension dim, Range range) {
  Object q(parent.at(key), parent.path(key),
           "an object {\"value\": ..., \"unit\": ...}");
  const double raw = finite_number(q.at("value"), [&] { return q.path("value"); }, "a number");
  const std::string unit_name = q.text("unit");
  const auto unit = find_unit(unit_name, dim);
  if (!unit) {
    throw InputError(q.path("unit"), "got " + shown(q.at("unit")) + "; expected a unit of " +
                                         dimension_name(dim) + ": " + unit_names(dim));
  }
  const double u = q.has("uncertainty")
                       ? finite_number(q.at("uncertainty"), [&] { return q.path("uncertainty"); }, "a number")
                       : 0.0;
  PENDULUM_FAIL_IF(u < 0.0, q.path("uncertainty"),
          "got " + format_number(u) + "; expected a non-negative uncertainty");
  const double sigma = u * unit->factor;
  if (q.has("source")) q.text("source");
  q.finish();
  const double si = raw * unit->factor + unit->offset;
  const bool ok = range == Range::any || (range == Range::positive ? si > 0.0 : si >= 0.0);
  if (!ok) {
    const std::string kind = range == Range::positive ? "a positive " : "a non-negative ";
    std::string what = dimension_name(dim);
    what = what.substr(what.find(' ') + 1);
    throw InputError(q.path("value"), "got " + format_number(raw) + " " + unit_name +
                                          "; expected " + kind + what);
  }
  // A positive quantity as uncertain as itself might be 0: it is unknown.
  PENDULUM_FAIL_IF(range == Range::positive && sigma >= si, q.path("uncertainty"),
          "got " + format_number(u) + " " + unit_name +
              "; expected an uncertainty smaller than the value (" + format_number(raw) + " " +
              unit_name + ")");
  return {si, sigma};
}

void put(Object& parent, const std::string& key, Dimension dim, Range range, double& value, double& sigma) {
  const Measured m = quantity(parent, key, dim, range);
  value = m.value;
  sigma = m.sigma;
}

void put(Object& parent, const std::string& key, Dimension dim, Range range, std::optional<double>& value,
         std::optional<double>& sigma) {
  if (!parent.has(key)) return;
  const Measured m = quantity(parent, key, dim, range);
  value = m.value;
  sigma = m.sigma;
}

/// A unit name under `key`, which must measure `dim`.
Unit unit_at(Object& o, const std::string& key, Dimension dim) {
  const std::string name = o.text(key);
  const auto unit = find_unit(name, dim);
  if (!unit) {
    throw InputError(o.path(key), "got \"" + name + "\"; expected a unit of " + dimension_name(dim) +
                                      ": " + unit_names(dim));
  }
  return *unit;
}

/// An array of finite numbers under `key`, each scaled by `factor`.
std::vector<double> number_array(Object& o, const std::string& key, double factor) {
  const json& a = o.at(key);
  if (!a.is_array()) {
    throw InputError(o.path(key), "got " + shown(a) + "; expected an array of numbers");
  }
  std::vector<double> out;
  out.reserve(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    out.push_back(factor * finite_number(a[i], [&] { return o.path(key) + "[" + std::to_string(i) + "]"; }, "a number"));
  }
  return out;
}

}  // namespace json_reader
}  // namespace pendulum
