#include "reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <set>

#include "pendulum/files.hpp"
#include "pendulum/recordings/table.hpp"

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
namespace {

/// UTF-16 text (after its byte order mark) as UTF-8: what Windows Notepad
/// saves as "Unicode".
std::string utf16_to_utf8(const std::string& bytes, bool little_endian) {
  auto fail = [](std::size_t at, const char* what) {
    throw InputError("", std::string("got UTF-16 text with ") + what + " at byte " + std::to_string(at) +
                             "; expected a scene file in UTF-8: save it as UTF-8");
  };
  if (bytes.size() % 2) fail(bytes.size() - 1, "an odd number of bytes");
  auto unit = [&](std::size_t i) {
    const auto lo = static_cast<unsigned char>(bytes[i + (little_endian ? 0 : 1)]);
    const auto hi = static_cast<unsigned char>(bytes[i + (little_endian ? 1 : 0)]);
    return static_cast<std::uint32_t>(hi << 8 | lo);
  };
  std::string out;
  for (std::size_t i = 2; i < bytes.size(); i += 2) {
    std::uint32_t c = unit(i);
    if (c >= 0xdc00 && c < 0xe000) fail(i, "a lone low surrogate");
    if (c >= 0xd800 && c < 0xdc00) {
      if (i + 3 >= bytes.size() || unit(i + 2) < 0xdc00 || unit(i + 2) >= 0xe000) fail(i, "a lone high surrogate");
      c = 0x10000 + ((c - 0xd800) << 10) + (unit(i + 2) - 0xdc00);
      i += 2;
    }
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else if (c < 0x800) {
      out += {static_cast<char>(0xc0 | c >> 6), static_cast<char>(0x80 | (c & 0x3f))};
    } else if (c < 0x10000) {
      out += {static_cast<char>(0xe0 | c >> 12), static_cast<char>(0x80 | (c >> 6 & 0x3f)),
              static_cast<char>(0x80 | (c & 0x3f))};
    } else {
      out += {static_cast<char>(0xf0 | c >> 18), static_cast<char>(0x80 | (c >> 12 & 0x3f)),
              static_cast<char>(0x80 | (c >> 6 & 0x3f)), static_cast<char>(0x80 | (c & 0x3f))};
    }
  }
  return out;
}

/// "line 3, column 20" of the first comma that only white space separates
/// from a closing } or ], outside strings; empty when there is none.
std::optional<std::string> trailing_comma(const std::string& text) {
  bool in_string = false, escaped = false;
  std::size_t line = 1, column = 0, comma_line = 0, comma_column = 0;
  bool comma = false;
  for (const char c : text) {
    ++column;
    if (c == '\n') ++line, column = 0;
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') continue;
    if (comma && (c == '}' || c == ']')) {
      return "line " + std::to_string(comma_line) + ", column " + std::to_string(comma_column);
    }
    comma = c == ',';
    if (comma) comma_line = line, comma_column = column;
    if (c == '"') in_string = true;
  }
  return std::nullopt;
}

}  // namespace

json parse_json(const std::string& given, const InputLimits& limits) {
  const bool utf16_le = given.size() >= 2 && given[0] == '\xff' && given[1] == '\xfe';
  const bool utf16_be = given.size() >= 2 && given[0] == '\xfe' && given[1] == '\xff';
  const std::string text = utf16_le || utf16_be ? utf16_to_utf8(given, utf16_le) : given;
  if (text.size() > limits.bytes) {
    throw InputError("", over_limit(limits, Limit::bytes));  // as the files' reader says it
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
    PENDULUM_FAIL_IF(looks_like_settings_table(text), "",
                     "a table of settings and periods, not a scene (JSON); expected a scene: make one with "
                     "pendulum-g import TABLE > scene.json, or name the table in a scene, \"observations\": "
                     "{\"table\": \"lengths.csv\"} (docs/series.md, Tables)");
    if (const auto at = trailing_comma(text)) {
      throw InputError(path(), "not valid JSON: a trailing comma at " + *at +
                               " (JSON allows no comma before } or ]): remove it");
    }
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

namespace {

/// Optimal string alignment distance: insertions, deletions, substitutions
/// and transpositions of neighbours ("lenght" is 1 from "length").
std::size_t edit_distance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                                       std::tolower(static_cast<unsigned char>(b[j - 1]))
                                   ? 0
                                   : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[n][m];
}

/// Keys longer than this are no misspelling of a scene's keys.
constexpr std::size_t kLongestKey = 64;

}  // namespace

std::optional<std::string> Object::misspelt(const std::string& unknown) const {
  if (unknown.size() > kLongestKey) return std::nullopt;
  std::optional<std::string> best;
  std::size_t best_distance = 0;
  for (const auto& k : known_) {
    if (j_.contains(k)) continue;
    // Two edits, and fewer than half the key's letters: "mass" is no
    // misspelling of "unit".
    const std::size_t d = edit_distance(unknown, k);
    if (d > 2 || 2 * d >= k.size()) continue;
    if (!best || d < best_distance) best = k, best_distance = d;
  }
  return best;
}

void Object::finish() const {
  for (const auto& item : j_.items()) {
    if (std::find(known_.begin(), known_.end(), item.key()) != known_.end()) continue;
    if (const auto key = misspelt(item.key())) {
      throw InputError(path(item.key()), "unknown key; did you mean " + *key + "?");
    }
    std::vector<std::string> keys = known_;
    std::sort(keys.begin(), keys.end());
    std::string list;
    for (const auto& k : keys) list += (list.empty() ? "" : ", ") + k;
    throw InputError(path(item.key()), "unknown key; this object takes: " + list);
  }
}

namespace {

/// What a missing required key takes: its unit and an example, the values
/// allowed where they are few, and when its part may be left out instead.
/// By the key's path without an observation's prefix ("observations[2].").
std::string missing_hint(std::string path) {
  if (path.compare(0, 13, "observations[") == 0) path = path.substr(path.find("].") + 2);
  struct Hint {
    const char* path;
    const char* text;
  };
  static const Hint hints[] = {
      {"timing", "the trials, e.g. \"timing\": {\"oscillations_per_trial\": 10, \"unit\": \"s\", \"resolution\": "
                 "0.01, \"trials\": [20.09, 20.03, 20.12]} (pendulum-g template prints a whole scene)"},
      {"timing.oscillations_per_trial", "the full oscillations (there and back) timed in each trial, e.g. 10"},
      {"timing.trials", "the times read off the stopwatch, one per trial, in timing.unit, e.g. [20.09, 20.03, 20.12]"},
      {"length", "the length from the pivot to the ball's centre, e.g. {\"value\": 100.0, \"uncertainty\": 0.2, "
                 "\"unit\": \"cm\"}"},
      {"amplitude", "the angle the ball was pulled aside at the start, e.g. {\"value\": 5, \"uncertainty\": 1, "
                    "\"unit\": \"deg\"}, or \"not recorded\" when nobody wrote it down (docs/scene.md)"},
      {"bob.diameter", "the ball's diameter, e.g. {\"value\": 25.4, \"uncertainty\": 0.1, \"unit\": \"mm\"}; bob may "
                       "be left out (then the corrections that need the ball are skipped)"},
      {"air.pressure", "a pressure, e.g. {\"value\": 1013, \"unit\": \"hPa\"} (hPa, kPa, Pa, mbar, mmHg, ...); air may be "
                       "left out (buoyancy and added mass are then skipped), or be \"vacuum\""},
      {"air.temperature", "a temperature, e.g. {\"value\": 21, \"unit\": \"degC\"} (degC, K, degF); air may be left "
                          "out (buoyancy and added mass are then skipped), or be \"vacuum\""},
      {"site.latitude", "the latitude, e.g. {\"value\": 51.0, \"unit\": \"deg\"}; site may be left out (then g is "
                        "compared with standard gravity alone)"},
      {"site.height_reference", "what site.height is measured from: \"sea_level\" or \"ellipsoid\" (a GPS height)"},
  };
  for (const Hint& h : hints) {
    if (path == h.path) return std::string("; expected ") + h.text;
  }
  const std::size_t dot = path.rfind('.');
  const std::string last = dot == std::string::npos ? path : path.substr(dot + 1);
  if (last == "value") return "; expected the number, e.g. \"value\": 25.4, beside its \"unit\"";
  if (last == "unit") return "; expected the value's unit as a string, e.g. \"unit\": \"mm\"";
  return "";
}

}  // namespace

const json& Object::at(const std::string& key) {
  remember(key);
  const auto it = j_.find(key);
  if (it == j_.end()) {
    // A misspelt required key is reported as such, not as a missing one.
    for (const auto& item : j_.items()) {
      if (std::find(known_.begin(), known_.end(), item.key()) != known_.end()) continue;
      if (misspelt(item.key()) == key) throw InputError(path(item.key()), "unknown key; did you mean " + key + "?");
    }
    throw InputError(path(key), "missing; it is required here" + missing_hint(path(key)));
  }
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

Measured quantity(Object& parent, const std::string& key, Dimension dim, Range range, std::string* qualifier,
                  const char* qualifier_key) {
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
  if (qualifier && q.has(qualifier_key)) *qualifier = q.text(qualifier_key);
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
          uncertainty_not_below_value(format_number(u) + " " + unit_name, format_number(raw) + " " + unit_name));
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
    throw InputError(o.path(key), "got \"" + one_line(name, 60, true) + "\"; expected a unit of " + dimension_name(dim) +
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
