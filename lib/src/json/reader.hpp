#pragma once
// The JSON reading toolkit of the scene reader: parsing with paths in the
// errors, objects that refuse unknown keys, numbers, quantities with units.
// Private to lib/src/json: no public header includes the JSON parser.

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pendulum/files.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/units.hpp"
#include "../text.hpp"

namespace pendulum::json_reader {

/// The documents' "schema": a scene (pendulum-g reduce) and a clock scene
/// (pendulum-g clock); each reader names the other's in its refusal.
inline constexpr const char* kSceneSchema = "pendulum-g/scene/1";
inline constexpr const char* kClockSceneSchema = "pendulum-g/clock-scene/1";

using nlohmann::json;

/// A JSON value fit for a one-line message (at most 60 characters).
std::string shown(const json& j);

/// `key` appended to `path` as a path component, quoted unless a plain name.
std::string join_path(const std::string& path, const std::string& key);

/// Parses the text as JSON. The parser's callback tracks the path of the
/// value being read, to name it in syntax errors, refuses values nested too
/// deep, and refuses a key given twice in one object, which the JSON library
/// would silently resolve by keeping the last.
json parse_json(const std::string& text, const InputLimits& limits);

/// A JSON object being read: remembers which keys were asked for, so that
/// finish() can refuse the others by name.
class Object {
 public:
  Object(const json& j, std::string path, const char* what = "an object");

  bool has(const std::string& key) {
    remember(key);
    return j_.contains(key);
  }

  const json& at(const std::string& key);

  std::string path(const std::string& key) const { return join_path(path_, key); }
  const std::string& path() const { return path_; }

  std::string text(const std::string& key);

  /// Refuses every key that was not asked for, suggesting the key it is a
  /// misspelling of when one is near (issue 14: "lenght").
  void finish() const;

 private:
  /// The key asked for but absent that `unknown` misspells, if any.
  std::optional<std::string> misspelt(const std::string& unknown) const;

  // A handful of keys an object: a vector beats a set here.
  void remember(const std::string& key) {
    if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.push_back(key);
  }

  const json& j_;
  std::string path_;
  std::vector<std::string> known_;
};

/// A finite JSON number; `path()` names it in the error, built only then.
template <class Path>
double finite_number(const json& j, Path&& path, const std::string& expected) {
  if (!j.is_number()) {
    throw InputError(path(), "got " + shown(j) + "; expected " + expected);
  }
  const double x = j.get<double>();
  if (!std::isfinite(x)) {
    throw InputError(path(), "got " + shown(j) + "; expected a finite number");
  }
  // -0 and subnormal numbers (below 2.2e-308; 1e-400 the JSON parser already
  // reads as 0) are 0: they carry no physics, only traps (no "-0" in a
  // result; 1/5e-324 overflows, so derivatives through them became NaN).
  return std::isnormal(x) ? x : 0.0;
}

/// Throws InputError(path, message) when `bad`; a macro, so that the message
/// (often several formatted numbers) is built only for a bad input.
#define PENDULUM_FAIL_IF(bad, path, message)    \
  do {                                            \
    if (bad) throw InputError((path), (message)); \
  } while (false)

/// A value (SI) outside what a laboratory holds: a unit slip or a typo.
void within(double x, double lo, double hi, const std::string& path, const char* unit,
            const std::string& what);

enum class Range { positive, non_negative, any };

struct Measured {
  double value;  ///< SI
  double sigma;  ///< SI
};

/// {"value": x, "unit": "cm", "uncertainty": u, "source": "..."} under `key`.
/// With `qualifier`, the quantity may also hold the text `qualifier_key`
/// ("measured_to", a length's reference point; "of", whose angle an
/// amplitude is), read into it.
Measured quantity(Object& parent, const std::string& key, Dimension dim, Range range,
                  std::string* qualifier = nullptr, const char* qualifier_key = "measured_to");

/// A required quantity into a field and its uncertainty.
void put(Object& parent, const std::string& key, Dimension dim, Range range, double& value, double& sigma);

/// An optional quantity: read only when present.
void put(Object& parent, const std::string& key, Dimension dim, Range range, std::optional<double>& value,
         std::optional<double>& sigma);

/// A unit name under `key`, which must measure `dim`.
Unit unit_at(Object& o, const std::string& key, Dimension dim);

/// An array of finite numbers under `key`, each scaled by `factor`.
std::vector<double> number_array(Object& o, const std::string& key, double factor);

}  // namespace pendulum::json_reader
