#include "pendulum/scene_json.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "pendulum/air.hpp"
#include "pendulum/decay_fit.hpp"
#include "pendulum/numeric.hpp"
#include "pendulum/reduction.hpp"
#include "pendulum/units.hpp"

namespace pendulum {

InputError::InputError(std::string path, const std::string& message)
    : std::runtime_error((path.empty() ? std::string("(document)") : path) +
                         ": " + message),
      path_(std::move(path)) {}

namespace {

using nlohmann::json;

constexpr const char* kSceneSchema = "pendulum-g/scene/1";

constexpr double kMaxDensity = 22590.0;       // osmium (kg/m^3)
constexpr double kMaxYoungsModulus = 1.2e12;  // diamond (Pa)
/// Beyond this |DeltaT/T0|, a correction is outside the first-order theory
/// it comes from: the terms it neglects, of order (DeltaT/T0)^2, would reach
/// 1% of the period.
constexpr double kMaxFirstOrder = 0.1;
/// A measured period this far from the expected one draws a warning...
constexpr double kPeriodWarning = 0.05;
/// ...this factor off, an error: no laboratory's g is 100 times off.
constexpr double kPeriodFactor = 10.0;
/// The other reading of an amplitude's unit fits when it brings the period
/// this close to the expected one.
constexpr double kPeriodFit = 0.01;
constexpr double kSmallAngleLab = 20.0;  // (deg)

/// `s` fit for a one-line message: ASCII only, control and non-ASCII bytes
/// as \xNN, cut to `max` characters.
std::string one_line(const std::string& s, std::size_t max) {
  std::string out;
  for (const unsigned char c : s) {
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static const char hex[] = "0123456789abcdef";
      out += {'\\', 'x', hex[c >> 4], hex[c & 15]};
    }
  }
  return out.size() > max ? out.substr(0, max - 3) + "..." : out;
}

std::string shown(const json& j) { return one_line(j.dump(-1, ' ', true), 60); }

std::string format_number(double x, int digits = 10) {
  std::ostringstream os;
  os.precision(digits);
  os << x;
  return os.str();
}

/// A key as a path component: as is if it is a plain name, else quoted.
std::string path_key(const std::string& key) {
  const bool plain = !key.empty() && key.size() <= 40 &&
                     std::all_of(key.begin(), key.end(), [](unsigned char c) {
                       return std::isalnum(c) || c == '_';
                     });
  return plain ? key : one_line(json(key).dump(-1, ' ', true), 40);
}

std::string join_path(const std::string& path, const std::string& key) {
  return path.empty() ? path_key(key) : path + "." + path_key(key);
}

/// No scene nests deeper than 3 (air.pressure.value); the limit keeps the
/// recursive parts of the JSON library (dump, copy) off the end of the stack.
constexpr std::size_t kMaxNesting = 10;

/// Parses the text as JSON. The parser's callback tracks the path of the
/// value being read, to name it in syntax errors, refuses values nested too
/// deep, and refuses a key given twice in one object, which the JSON library
/// would silently resolve by keeping the last.
json parse_json(const std::string& text) {
  if (text.size() > kMaxSceneBytes) {
    throw InputError("", "got more than " + std::to_string(kMaxSceneBytes) +
                             " bytes; expected a scene file of at most 1 MiB");
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

/// A JSON object being read: remembers which keys were asked for, so that
/// finish() can refuse the others by name.
class Object {
 public:
  Object(const json& j, std::string path, const char* what = "an object")
      : j_(j), path_(std::move(path)) {
    if (!j.is_object()) {
      throw InputError(path_, "got " + shown(j) + "; expected " + what);
    }
  }

  bool has(const std::string& key) {
    remember(key);
    return j_.contains(key);
  }

  const json& at(const std::string& key) {
    remember(key);
    const auto it = j_.find(key);
    if (it == j_.end()) throw InputError(path(key), "missing; it is required here");
    return *it;
  }

  std::string path(const std::string& key) const { return join_path(path_, key); }
  const std::string& path() const { return path_; }

  std::string text(const std::string& key) {
    const json& v = at(key);
    if (!v.is_string()) {
      throw InputError(path(key), "got " + shown(v) + "; expected a string");
    }
    return v.get<std::string>();
  }

  /// Refuses every key that was not asked for.
  void finish() const {
    for (const auto& item : j_.items()) {
      if (std::find(known_.begin(), known_.end(), item.key()) != known_.end()) continue;
      std::vector<std::string> keys = known_;
      std::sort(keys.begin(), keys.end());
      std::string list;
      for (const auto& k : keys) list += (list.empty() ? "" : ", ") + k;
      throw InputError(path(item.key()),
                       "unknown key; this object takes: " + list);
    }
  }

 private:
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
            const std::string& what) {
  PENDULUM_FAIL_IF(!(x >= lo && x <= hi), path, "got " + format_number(x) + " " + unit + "; expected " + what);
}

enum class Range { positive, non_negative, any };

struct Measured {
  double value;  ///< SI
  double sigma;  ///< SI
};

/// Reads the scene's quantities into `value` and `uncertainty` and records
/// the SI unit of each path.
class SceneReader {
 public:
  explicit SceneReader(ParsedScene& out) : out_(out) {}

  /// {"value": x, "unit": "cm", "uncertainty": u, "source": "..."}
  Measured quantity(Object& parent, const std::string& key, Dimension dim,
                    Range range) {
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
    out_.si_unit[q.path()] = si_unit(dim);
    return {si, sigma};
  }

  void put(Object& parent, const std::string& key, Dimension dim, Range range,
           double& value, double& sigma) {
    const Measured m = quantity(parent, key, dim, range);
    value = m.value;
    sigma = m.sigma;
  }

  /// An optional field: read only when present.
  void put(Object& parent, const std::string& key, Dimension dim, Range range,
           std::optional<double>& value, std::optional<double>& sigma) {
    if (!parent.has(key)) return;
    const Measured m = quantity(parent, key, dim, range);
    value = m.value;
    sigma = m.sigma;
  }

 private:
  ParsedScene& out_;
};

/// Warns about trials (in `unit`) that disagree more than they should: one
/// far from the others (a miscounted oscillation, a typo), or a scatter far
/// beyond the stated one-trial uncertainty. A scatter beyond the resolution
/// alone is normal: a hand on a stopwatch scatters more than its last digit.
void warn_about_trials(const std::vector<double>& times, double spread, std::optional<double> resolution,
                       std::optional<double> trial_sigma, const std::string& unit,
                       std::vector<std::string>& warnings) {
  auto in_unit = [&](double x) { return format_number(x, 4) + " " + unit; };
  if (trial_sigma && spread > 3.0 * *trial_sigma) {
    warnings.push_back("timing.uncertainty: the trials scatter by " + in_unit(spread) +
                       " (standard deviation), over 3 times the stated one-trial uncertainty " +
                       in_unit(*trial_sigma) + "; the period's uncertainty uses the scatter");
  }
  if (times.size() < 3) return;  // two trials: no telling which one is off
  // The median and the median absolute deviation (MAD), which one bad trial
  // cannot drag; 1.4826 MAD estimates the standard deviation of the others.
  auto median = [](std::vector<double> x) {
    const auto mid = x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2);
    std::nth_element(x.begin(), mid, x.end());
    const double upper = *mid;
    if (x.size() % 2) return upper;
    return (*std::max_element(x.begin(), mid) + upper) / 2.0;
  };
  const double centre = median(times);
  std::vector<double> deviation(times.size());
  for (std::size_t i = 0; i < times.size(); ++i) deviation[i] = std::abs(times[i] - centre);
  const double scatter = 1.4826 * median(deviation);
  const double allowed =
      5.0 * std::max({scatter, resolution.value_or(0.0), trial_sigma.value_or(0.0)});
  const auto worst = std::max_element(deviation.begin(), deviation.end());
  if (allowed == 0.0 || *worst <= allowed) return;
  std::vector<std::string> allowance{"the trials' scatter (" + in_unit(scatter) + ")"};
  if (resolution) allowance.push_back("the resolution (" + in_unit(*resolution) + ")");
  if (trial_sigma) allowance.push_back("the stated uncertainty (" + in_unit(*trial_sigma) + ")");
  std::string largest = allowance.size() > 1 ? "the largest of " : "";
  for (std::size_t k = 0; k < allowance.size(); ++k) {
    largest += (k == 0 ? "" : k + 1 == allowance.size() ? " and " : ", ") + allowance[k];
  }
  const auto i = static_cast<std::size_t>(worst - deviation.begin());
  warnings.push_back("timing.trials[" + std::to_string(i) + "]: " + format_number(times[i]) + " " +
                     unit + " is " + in_unit(*worst) + " from the median trial " +
                     format_number(centre) + " " + unit + ", over 5 times " + largest +
                     "; a miscounted oscillation or a typo?");
}

void read_timing(Object& top, ParsedScene& out) {
  Object t(top.at("timing"), "timing");
  const json& n_json = t.at("oscillations_per_trial");
  if (!n_json.is_number_integer() || n_json.get<long long>() < 1 ||
      n_json.get<long long>() > 1000000000) {
    throw InputError(t.path("oscillations_per_trial"),
                     "got " + shown(n_json) + "; expected a positive whole number");
  }
  const int n_osc = static_cast<int>(n_json.get<long long>());
  const std::string unit_name = t.text("unit");
  const auto unit = find_unit(unit_name, Dimension::time);
  if (!unit) {
    throw InputError(t.path("unit"), "got " + shown(t.at("unit")) + "; expected a unit of a time: " +
                                         unit_names(Dimension::time));
  }
  const json& trials = t.at("trials");
  if (!trials.is_array() || trials.empty()) {
    throw InputError(t.path("trials"), "got " + shown(trials) +
                                           "; expected a non-empty array of trial times");
  }
  std::vector<double> times;  // in `unit`
  for (std::size_t i = 0; i < trials.size(); ++i) {
    const auto p = [&] { return t.path("trials") + "[" + std::to_string(i) + "]"; };
    const double x = finite_number(trials[i], p, "a time (number)");
    if (x <= 0.0) {
      throw InputError(p(), "got " + format_number(x) + " " + unit_name +
                                "; expected a positive time");
    }
    times.push_back(x);
  }
  auto optional_time = [&](const char* key) -> std::optional<double> {
    if (!t.has(key)) return std::nullopt;
    const double x = finite_number(t.at(key), [&] { return t.path(key); }, "a number");
    if (x <= 0.0) {
      throw InputError(t.path(key), "got " + format_number(x) + " " + unit_name +
                                        "; expected a positive time");
    }
    return x;
  };
  const std::optional<double> resolution = optional_time("resolution");
  const std::optional<double> trial_sigma = optional_time("uncertainty");
  if (t.has("source")) t.text("source");
  t.finish();

  // In the file's unit, and relative to the mean so that no sum overflows.
  auto in_unit = [&](double x) { return format_number(x) + " " + unit_name; };
  const double n = static_cast<double>(times.size());
  double mean = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i) mean += (times[i] - mean) / (i + 1.0);
  // Beyond a third of the mean, a one-trial uncertainty leaves a mean +-
  // standard error (N&O Eq. 4) that means nothing: trials of different
  // oscillation counts or units, or a wrong resolution.
  PENDULUM_FAIL_IF(resolution && *resolution >= mean, t.path("resolution"),
          "got " + in_unit(resolution.value_or(0.0)) +
              "; expected a resolution finer than the mean trial (" + in_unit(mean) + ")");
  PENDULUM_FAIL_IF(trial_sigma && *trial_sigma > mean / 3.0, t.path("uncertainty"),
          "got " + in_unit(trial_sigma.value_or(0.0)) +
              "; expected a one-trial uncertainty below a third of the mean trial (" +
              in_unit(mean) + ")");
  double sigma_trial = 0.0;
  if (times.size() >= 2) {
    double ss = 0.0;
    for (double x : times) ss += (x / mean - 1.0) * (x / mean - 1.0);
    const double spread = std::sqrt(ss / (n - 1.0)) * mean;
    const auto [lo, hi] = std::minmax_element(times.begin(), times.end());
    PENDULUM_FAIL_IF(spread > mean / 3.0, t.path("trials"),
            "got trials from " + format_number(*lo) + " to " + in_unit(*hi) +
                ", a standard deviation over a third of their mean " + in_unit(mean) +
                "; expected repeated timings of the same oscillations (a mean of these means nothing)");
    // The resolution and a stated uncertainty are floors: a scatter below
    // them is luck.
    sigma_trial = std::max({spread, resolution.value_or(0.0) / std::sqrt(12.0),
                            trial_sigma.value_or(0.0)});
    if (sigma_trial == 0.0) {
      out.warnings.push_back(
          "timing.trials: all trials are equal and no resolution is given, so "
          "the period's uncertainty is 0; state timing.resolution");
    }
    warn_about_trials(times, spread, resolution, trial_sigma, unit_name, out.warnings);
  } else if (trial_sigma) {
    sigma_trial = *trial_sigma;
    out.assumptions.push_back(
        "timing: a single trial; its uncertainty is timing.uncertainty");
  } else if (resolution) {
    sigma_trial = *resolution / std::sqrt(12.0);
    out.assumptions.push_back(
        "timing: a single trial; its uncertainty is timing.resolution/sqrt(12)");
  } else {
    throw InputError(t.path("trials"),
                     "got a single trial; expected two or more, or a single one "
                     "with timing.uncertainty or timing.resolution");
  }
  out.trial_count = static_cast<int>(times.size());
  out.value.oscillations_per_trial = n_osc;
  out.uncertainty.oscillations_per_trial = n_osc;
  out.value.period = mean * unit->factor / n_osc;
  out.uncertainty.period = sigma_trial * unit->factor / std::sqrt(n) / n_osc;
  out.si_unit["timing.trials"] = "s";
}

/// The scene part a correction comes from, named in its errors.
const char* part_of(CorrectionId id) {
  using Id = CorrectionId;
  switch (id) {
    case Id::finite_amplitude: return "amplitude";
    case Id::bob_radius: case Id::bob_rotation: return "bob";
    case Id::ring: case Id::double_pendulum: return "ring";
    case Id::cap: return "cap";
    case Id::cap_screw: return "cap_screw";
    case Id::wire_mass: case Id::wire_flexibility: case Id::wire_stretch: return "wire";
    case Id::buoyancy: case Id::added_mass: return "air";
    case Id::linear_damping: case Id::quadratic_damping: case Id::amplitude_decay: return "decay";
    case Id::support_motion: return "support";
  }
  return "";
}

/// The period this pendulum has at standard gravity, with every correction:
/// 2 pi sqrt(l/g) T/T0 (Eqs. 3, 6).
double expected_period(const Scene<double>& s) {
  return 2.0 * kPi * std::sqrt(s.length / kStandardGravity) * (s.period / reduce(s).period_ideal);
}

/// "5.3% longer"
std::string off_by(double ratio) {
  return format_number(100.0 * std::abs(ratio - 1.0), 2) + "% " + (ratio > 1.0 ? "longer" : "shorter");
}

/// Checks that need the reduction: every first-order correction small, the
/// period within reach of the expected one, and warns about what is legal but
/// suspicious (docs/robustness.md).
void check_plausibility(const json& doc, ParsedScene& out) {
  const Scene<double>& s = out.value;
  const double expected = expected_period(s);
  const double ratio = s.period / expected;
  const std::string standard = "standard gravity (" + format_number(kStandardGravity) + " m/s^2)";
  const std::string at_g = "this pendulum has at " + standard;

  // Degrees and radians mixed up: the period fits the other reading.
  const json& amplitude = doc.at("amplitude");
  const std::string unit = amplitude.at("unit").get<std::string>();
  if (!(std::abs(ratio - 1.0) <= kPeriodWarning) && (unit == "deg" || unit == "rad")) {
    const std::string other = unit == "deg" ? "rad" : "deg";
    const double raw = amplitude.at("value").get<double>();
    Scene<double> alt = s;
    alt.amplitude = raw * find_unit(other, Dimension::angle)->factor;
    const double alt_ratio = alt.amplitude < kPi ? s.period / expected_period(alt) : 0.0;
    PENDULUM_FAIL_IF(std::abs(alt_ratio - 1.0) <= kPeriodFit, "amplitude.unit",
            "got \"" + unit + "\": at " + format_number(raw) + " " + unit + " the measured period is " +
                off_by(ratio) + " than the one " + at_g + "; expected \"" + other + "\": at " +
                format_number(raw) + " " + other + " it is " + off_by(alt_ratio));
  }

  // Against the finite-amplitude correction alone, so that a wrong unit is
  // named as such before it drives a correction out of its range.
  const double swing = 2.0 * kPi * std::sqrt(s.length / kStandardGravity) *
                       (1.0 + finite_amplitude_agm(s.amplitude));
  PENDULUM_FAIL_IF(!(s.period / swing > 1.0 / kPeriodFactor && s.period / swing < kPeriodFactor),
          "timing.trials",
          "got a period of " + format_number(s.period, 5) + " s, but this pendulum swings in " +
              format_number(swing, 5) + " s at " + standard + "; expected them within a factor of " +
              format_number(kPeriodFactor) + " (is a unit or oscillations_per_trial wrong?)");

  const Reduction<double> r = reduce(s);
  for (int i = 0; i < kCorrectionCount; ++i) {
    const auto id = static_cast<CorrectionId>(i);
    const std::optional<double>& x = r.terms[i].ratio;
    if (id == CorrectionId::finite_amplitude || !x) continue;  // exact at any amplitude
    PENDULUM_FAIL_IF(!(std::abs(*x) < kMaxFirstOrder), part_of(id),
            "got DeltaT/T0 = " + format_number(*x) + " for \"" + kCorrections[i].title + "\" (" +
                kCorrections[i].equation + "); expected |DeltaT/T0| below " +
                format_number(kMaxFirstOrder) + ", where its first-order formula holds");
  }

  if (std::abs(ratio - 1.0) > kPeriodWarning) {
    out.warnings.push_back("timing.trials: the measured period " + format_number(s.period, 5) +
                           " s is " + off_by(ratio) + " than the " + format_number(expected, 5) +
                           " s " + at_g + "; check the length's unit and oscillations_per_trial");
  }
  const double degrees = s.amplitude * 180.0 / kPi;
  if (degrees > kSmallAngleLab) {
    out.warnings.push_back("amplitude.value: " + format_number(degrees, 4) +
                           " deg is over the 20 deg of a small-angle lab; the finite-amplitude "
                           "correction is exact at any amplitude, but check the amplitude and its unit");
  }
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

/// site: a measured reference g, or latitude and height for normal gravity.
void read_site(Object& top, SceneReader& r, ParsedScene& out) {
  Object o(top.at("site"), "site");
  Site site;
  if (o.has("latitude")) {
    const Measured lat = r.quantity(o, "latitude", Dimension::angle, Range::any);
    const double deg = lat.value * 180.0 / kPi;
    if (!(std::abs(deg) <= 90.0)) {
      throw InputError("site.latitude.value", "got " + format_number(deg) +
                                                  " deg; expected a latitude from -90 to 90 deg");
    }
    site.latitude_deg = deg;
  }
  if (o.has("height")) {
    const double h = r.quantity(o, "height", Dimension::length, Range::any).value;
    if (!(h > -12000.0 && h < 100000.0)) {
      throw InputError("site.height.value", "got " + format_number(h) +
                                                " m; expected a height on Earth (-12 km to 100 km)");
    }
    site.height = h;
    const std::string reference = o.text("height_reference");
    if (reference != "ellipsoid" && reference != "sea_level") {
      throw InputError(o.path("height_reference"),
                       "got \"" + reference + "\"; expected \"ellipsoid\" or \"sea_level\"");
    }
    site.height_above_ellipsoid = reference == "ellipsoid";
  }
  if (o.has("reference_g")) {
    const Measured g = r.quantity(o, "reference_g", Dimension::acceleration, Range::positive);
    // Any planet's surface, with room to spare; beyond, a unit slip or a typo.
    within(g.value, 0.1, 1000.0, "site.reference_g.value", "m/s^2", "a surface gravity from 0.1 to 1000 m/s^2");
    site.reference_g = g.value;
    site.reference_g_uncertainty = g.sigma;
    const json& q = o.at("reference_g");
    if (q.contains("source") && q.at("source").is_string()) site.reference_source = q.at("source").get<std::string>();
  }
  o.finish();
  if (!site.reference_g && (!site.latitude_deg || !site.height)) {
    throw InputError("site", "expected reference_g, or latitude and height");
  }
  out.site = site;
}

/// decay: alpha and beta as measured, and/or a record to fit them from
/// (docs/scene.md); the record is validated here, fitted by the analysis.
void read_decay(Object& top, SceneReader& r, ParsedScene& out) {
  Object o(top.at("decay"), "decay");
  const bool given = o.has("alpha") || o.has("beta");
  const bool has_data = o.has("data");
  PENDULUM_FAIL_IF(!given && !has_data, "decay", "got neither alpha and beta nor data; expected one of them");
  if (given) {
    auto& pv = out.value.decay.emplace();
    auto& pu = out.uncertainty.decay.emplace();
    r.put(o, "alpha", Dimension::rate, Range::non_negative, pv.alpha, pu.alpha);
    r.put(o, "beta", Dimension::rate_per_angle, Range::non_negative, pv.beta, pu.beta);
  }
  if (has_data) {
    Object d(o.at("data"), "decay.data");
    const Unit time_unit = unit_at(d, "time_unit", Dimension::time);
    const Unit angle_unit = unit_at(d, "amplitude_unit", Dimension::angle);
    DecayData data;
    data.times = number_array(d, "times", time_unit.factor);
    data.amplitudes = number_array(d, "amplitudes", angle_unit.factor);
    PENDULUM_FAIL_IF(d.has("sigma") && d.has("sigmas"), d.path("sigmas"),
            "got both sigma and sigmas; expected one of them");
    if (d.has("sigma")) {
      const double sigma = finite_number(d.at("sigma"), [&] { return d.path("sigma"); }, "a number");
      PENDULUM_FAIL_IF(!(sigma > 0.0), d.path("sigma"),
              "got " + format_number(sigma) + "; expected a positive uncertainty");
      data.sigmas.assign(data.times.size(), sigma * angle_unit.factor);
    } else if (d.has("sigmas")) {
      data.sigmas = number_array(d, "sigmas", angle_unit.factor);
    }
    if (d.has("initial_amplitude")) {
      data.initial_amplitude =
          r.quantity(d, "initial_amplitude", Dimension::angle, Range::positive).value;
    }
    if (d.has("source")) d.text("source");
    if (d.has("generator")) d.at("generator");  // free-form metadata
    d.finish();
    validate_decay_data(data, "decay.data");
    out.decay_data = std::move(data);
  }
  o.finish();
}

}  // namespace

ParsedScene parse_scene(const std::string& text) {
  const json doc = parse_json(text);
  ParsedScene out;
  SceneReader r(out);
  Scene<double>& v = out.value;
  Scene<double>& u = out.uncertainty;
  Object top(doc, "", "a JSON object (the scene)");

  if (top.has("schema")) {
    PENDULUM_FAIL_IF(top.text("schema") != kSceneSchema, "schema",
            "got " + shown(top.at("schema")) + "; expected \"" + kSceneSchema + "\"");
  }
  if (top.has("title")) {
    // The table prints the title as is: no control character may reach the terminal.
    out.title = top.text("title");
    PENDULUM_FAIL_IF(std::any_of(out.title.begin(), out.title.end(),
                        [](unsigned char c) { return c < 0x20 || c == 0x7f; }),
            "title", "got " + shown(top.at("title")) + "; expected one line of printable text");
  }
  if (top.has("source")) out.source = top.text("source");
  if (top.has("notes")) top.text("notes");

  read_timing(top, out);
  r.put(top, "length", Dimension::length, Range::positive, v.length, u.length);
  within(v.length, 1e-3, 1e3, "length.value", "m", "a laboratory pendulum, 1 mm to 1 km long");
  r.put(top, "amplitude", Dimension::angle, Range::positive, v.amplitude, u.amplitude);
  PENDULUM_FAIL_IF(v.amplitude >= kPi, "amplitude.value",
          "got " + format_number(v.amplitude * 180.0 / kPi) +
              " deg; expected an amplitude below 180 deg (at 180 deg and beyond "
              "the pendulum goes over the top)");

  {
    Object bob(top.at("bob"), "bob");
    r.put(bob, "diameter", Dimension::length, Range::positive, v.bob.diameter, u.bob.diameter);
    r.put(bob, "mass", Dimension::mass, Range::positive, v.bob.mass, u.bob.mass);
    bob.finish();
    PENDULUM_FAIL_IF(v.bob.diameter / 2.0 >= v.length, "length.value",
            "got " + format_number(v.length) + " m; expected more than the bob radius " +
                format_number(v.bob.diameter / 2.0) + " m");
    const double density = v.bob.mass / sphere_volume(v.bob.diameter / 2.0);
    PENDULUM_FAIL_IF(density > kMaxDensity, "bob.mass.value",
            "got " + format_number(v.bob.mass) + " kg, a density of " + format_number(density) +
                " kg/m^3 for this diameter; expected at most " + format_number(kMaxDensity) +
                " kg/m^3 (osmium, the densest element)");
  }
  // A part's fields are read into `pv` (values) and `pu` (uncertainties); its
  // consistency is checked once no unknown key is left.
  auto part = [&](const char* key, auto& value, auto& sigma, auto&& read, auto&& check) {
    if (!top.has(key)) return;
    Object o(top.at(key), key);
    read(o, value.emplace(), sigma.emplace());
    o.finish();
    check(*value);
  };
  auto lighter_than_bob = [&](double mass, const std::string& path, const char* what) {
    PENDULUM_FAIL_IF(mass >= v.bob.mass, path,
            "got " + format_number(mass) + " kg; expected " + what + " lighter than the bob (" +
                format_number(v.bob.mass) + " kg): the corrections are first order in its mass ratio");
  };
  part("ring", v.ring, u.ring, [&](Object& o, Ring<double>& pv, Ring<double>& pu) {
    r.put(o, "mass", Dimension::mass, Range::positive, pv.mass, pu.mass);
    r.put(o, "inner_radius", Dimension::length, Range::non_negative, pv.inner_radius, pu.inner_radius);
    r.put(o, "outer_radius", Dimension::length, Range::positive, pv.outer_radius, pu.outer_radius);
    r.put(o, "pivot_distance", Dimension::length, Range::non_negative, pv.pivot_distance, pu.pivot_distance);
  }, [&](const Ring<double>& pv) {
    PENDULUM_FAIL_IF(pv.inner_radius >= pv.outer_radius, "ring.inner_radius.value",
            "got " + format_number(pv.inner_radius) + " m; expected less than ring.outer_radius (" +
                format_number(pv.outer_radius) + " m)");
    PENDULUM_FAIL_IF(pv.pivot_distance + pv.outer_radius >= v.length - v.bob.diameter / 2.0,
            "ring.outer_radius.value",
            "the ring reaches " + format_number(pv.pivot_distance + pv.outer_radius) +
                " m below the pivot; expected it to end above the bob, which starts at " +
                format_number(v.length - v.bob.diameter / 2.0) + " m");
    lighter_than_bob(pv.mass, "ring.mass.value", "a ring");
  });
  part("cap", v.cap, u.cap, [&](Object& o, Cap<double>& pv, Cap<double>& pu) {
    r.put(o, "mass", Dimension::mass, Range::non_negative, pv.mass, pu.mass);
    r.put(o, "center_distance", Dimension::length, Range::non_negative, pv.center_distance,
          pu.center_distance);
    r.put(o, "volume", Dimension::volume, Range::non_negative, pv.volume, pu.volume);
  }, [&](const Cap<double>& pv) {
    lighter_than_bob(pv.mass, "cap.mass.value", "a cap");
    PENDULUM_FAIL_IF(pv.center_distance >= v.length, "cap.center_distance.value",
            "got " + format_number(pv.center_distance) + " m; expected less than the length (" +
                format_number(v.length) + " m): the cap hangs between the pivot and the bob");
  });
  part("cap_screw", v.cap_screw, u.cap_screw,
       [&](Object& o, CapScrew<double>& pv, CapScrew<double>& pu) {
         r.put(o, "mass_deficit", Dimension::mass, Range::any, pv.mass_deficit, pu.mass_deficit);
         r.put(o, "center_distance", Dimension::length, Range::non_negative, pv.center_distance,
               pu.center_distance);
       },
       [&](const CapScrew<double>& pv) {
         lighter_than_bob(std::abs(pv.mass_deficit), "cap_screw.mass_deficit.value",
                          "a mass deficit");
         PENDULUM_FAIL_IF(pv.center_distance >= v.bob.diameter / 2.0, "cap_screw.center_distance.value",
                 "got " + format_number(pv.center_distance) +
                     " m; expected less than the bob radius (" +
                     format_number(v.bob.diameter / 2.0) + " m): the screw is inside the bob");
       });
  part("wire", v.wire, u.wire, [&](Object& o, Wire<double>& pv, Wire<double>& pu) {
    r.put(o, "mass", Dimension::mass, Range::positive, pv.mass, pu.mass);
    r.put(o, "diameter", Dimension::length, Range::positive, pv.diameter, pu.diameter);
    r.put(o, "youngs_modulus", Dimension::modulus, Range::positive, pv.youngs_modulus,
          pu.youngs_modulus);
  }, [&](const Wire<double>& pv) {
    lighter_than_bob(pv.mass, "wire.mass.value", "a wire");
    if (pv.diameter) {
      PENDULUM_FAIL_IF(*pv.diameter >= v.bob.diameter, "wire.diameter.value",
              "got " + format_number(*pv.diameter) + " m; expected a wire thinner than the bob (" +
                  format_number(v.bob.diameter) + " m)");
    }
    if (!pv.youngs_modulus) return;
    within(*pv.youngs_modulus, 0.0, kMaxYoungsModulus, "wire.youngs_modulus.value", "Pa",
           "at most " + format_number(kMaxYoungsModulus) + " Pa (diamond, the stiffest material)");
    if (!pv.diameter) return;
    // Eq. (79) is the stretch of a stiff wire; the bob's weight over E S is
    // the wire's static strain.
    const double strain = v.bob.mass * kStandardGravity /
                          (*pv.youngs_modulus * kPi * *pv.diameter * *pv.diameter / 4.0);
    PENDULUM_FAIL_IF(!(strain < 0.1), "wire",
            "got a wire that the bob stretches by " + format_number(100.0 * strain, 3) +
                "% (weight / (youngs_modulus x cross-section)); expected a stiff wire, "
                "stretched by less than 10%");
  });
  if (top.has("air")) {
    const json& air = top.at("air");
    if (air.is_string()) {
      PENDULUM_FAIL_IF(air.get<std::string>() != "vacuum", "air",
              "got " + shown(air) + "; expected \"vacuum\" or an object with pressure and temperature");
    } else {
      Object o(air, "air", "\"vacuum\" or an object with pressure and temperature");
      auto& pv = v.air.emplace();
      auto& pu = u.air.emplace();
      r.put(o, "pressure", Dimension::pressure, Range::positive, pv.pressure, pu.pressure);
      r.put(o, "temperature", Dimension::temperature, Range::positive, pv.temperature,
            pu.temperature);
      // A laboratory's gas: 25 "K" meant degC, 28.96 "kg/mol" meant g/mol.
      within(pv.temperature, 150.0, 500.0, "air.temperature.value", "K",
             "the temperature of a laboratory's air, 150 K to 500 K (-123 degC to 227 degC)");
      // Thinner air is a vacuum; and its density would near a double's underflow.
      within(pv.pressure, 1e-12, HUGE_VAL, "air.pressure.value", "Pa",
             "at least 1e-12 Pa, an ultra-high vacuum (for less, \"air\": \"vacuum\")");
      if (o.has("molar_mass")) {
        r.put(o, "molar_mass", Dimension::molar_mass, Range::positive, pv.molar_mass, pu.molar_mass);
        within(pv.molar_mass, 1e-3, 1.0, "air.molar_mass.value", "kg/mol",
               "the molar mass of a gas, 0.001 to 1 kg/mol (air 0.02896)");
      } else {
        pv.molar_mass = kDryAirMolarMass;
        pu.molar_mass = 0.0;
        out.si_unit["air.molar_mass"] = "kg/mol";
        out.assumptions.push_back("air.molar_mass: not given; dry air, 0.02896 kg/mol");
      }
      if (o.has("viscosity")) {
        r.put(o, "viscosity", Dimension::viscosity, Range::positive, pv.viscosity, pu.viscosity);
        within(pv.viscosity, 1e-6, 1e-4, "air.viscosity.value", "Pa s",
               "the viscosity of a gas, 1e-6 to 1e-4 Pa s (air 1.8e-5)");
      } else {
        pv.viscosity = air_viscosity(pv.temperature);
        pu.viscosity = 0.0;
        out.si_unit["air.viscosity"] = "Pa s";
        out.assumptions.push_back("air.viscosity: not given; Sutherland's law gives " +
                                  format_number(pv.viscosity) + " Pa s");
      }
      o.finish();
      const double rho = air_density(pv.pressure, pv.temperature, pv.molar_mass);
      PENDULUM_FAIL_IF(rho > 100.0, "air",
              "density " + format_number(rho) +
                  " kg/m^3 from this pressure, temperature and molar mass; expected a gas (below 100 kg/m^3)");
      if (v.cap && !v.cap->volume) {
        out.warnings.push_back(
            "cap.volume: not given; buoyancy and added mass count the bob's volume only");
      }
    }
  } else {
    throw InputError("air", "missing; give the air's pressure and temperature, or \"vacuum\"");
  }
  part("support", v.support, u.support, [&](Object& o, Support<double>& pv, Support<double>& pu) {
    r.put(o, "stiffness", Dimension::stiffness, Range::positive, pv.stiffness, pu.stiffness);
    r.put(o, "mass", Dimension::mass, Range::positive, pv.mass, pu.mass);
  }, [&](const Support<double>& pv) {
    PENDULUM_FAIL_IF(!pv.stiffness && !pv.mass, "support",
            "got neither stiffness nor mass; expected at least one");
    // Bounds that keep Eq. (83)'s discriminant, (K/M)^2, a finite number.
    if (pv.stiffness) {
      within(*pv.stiffness, 0.0, kMaxYoungsModulus, "support.stiffness.value", "N/m",
             "at most " + format_number(kMaxYoungsModulus) + " N/m (a cubic metre of diamond)");
    }
    if (pv.mass) within(*pv.mass, 1e-6, HUGE_VAL, "support.mass.value", "kg", "at least 1 mg");
  });
  if (top.has("decay")) read_decay(top, r, out);
  if (top.has("site")) read_site(top, r, out);
  top.finish();
  check_plausibility(doc, out);
  return out;
}

}  // namespace pendulum
