// parse_scene: the top level of a scene file (docs/scene.md): its
// observations, one at the top level or a series under "observations", the
// unknowns to fit, and the checks across parts and observations.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string_view>

#include "../plausibility.hpp"
#include "parts.hpp"
#include "recording_reader.hpp"
#include "table_reader.hpp"
#include "pendulum/amplitude_sweep.hpp"
#include "pendulum/argument_ranges.hpp"
#include "pendulum/dispersion.hpp"
#include "pendulum/models/registry.hpp"
#include "pendulum/json/scene_json.hpp"

namespace pendulum {

using namespace json_reader;

namespace {

/// Where an observation's `key` is read from: its own object, or the series'
/// top level where the key is given once for every observation.
Object& owner(Object& o, Object* shared, const char* key, ObservationSource& source) {
  if (o.has(key) || !shared || !shared->has(key)) return o;
  source.shared.push_back(key);
  return *shared;
}

/// The range a hand-released amplitude nobody wrote down is taken to lie in
/// (deg): below 3 deg a metre pendulum's bob moves under 5 cm to a side, too
/// little to see through ten swings as it decays; above 15 deg is past the
/// "small angle" every laboratory manual asks for (where theta0^2/16, the
/// period's first amplitude term, reaches 0.4 %). docs/scene.md, "An
/// amplitude not recorded".
constexpr double kHandReleaseDeg[2] = {3.0, 15.0};

/// What to write for an amplitude that is not known, for the messages.
constexpr const char* kUnrecordedAmplitude =
    "if the amplitude was not recorded, write \"amplitude\": \"not recorded\" (a hand release, taken as "
    "3 to 15 deg), or the range it was released in, \"amplitude\": {\"range\": [3, 10], \"unit\": \"deg\"} "
    "(docs/scene.md)";

/// "not recorded", or {"range": [a, b], "unit": u}: an amplitude known only to lie in a range.
bool unrecorded(const json& a) { return a.is_string() || (a.is_object() && a.contains("range")); }

/// The amplitude as a uniform distribution over its range (GUM 4.3.7): the
/// middle, and (b - a)/sqrt(12) as its standard uncertainty. `say`: once for
/// a shared one; the warning gives the effect on g, theta0 sigma/4 of it
/// (g goes as (T/T0)^2 and T/T0 = 1 + theta0^2/16 + ...).
Measured unrecorded_amplitude(Object& owner, ParsedScene& out, bool say) {
  const json& a = owner.at("amplitude");
  const std::string path = owner.path("amplitude");
  double lo = radians(kHandReleaseDeg[0]), hi = radians(kHandReleaseDeg[1]);
  std::string how = "not recorded; a hand release";
  if (a.is_string()) {
    PENDULUM_FAIL_IF(a != "not recorded", path,
                     "got " + shown(a) + "; expected \"not recorded\", a range ({\"range\": [3, 10], \"unit\": "
                     "\"deg\"}) or a quantity ({\"value\": 5, \"uncertainty\": 1, \"unit\": \"deg\"})");
  } else {
    Object r(a, path, "an object {\"range\": [low, high], \"unit\": ...}");
    const double factor = unit_at(r, "unit", Dimension::angle).factor;
    const json& range = r.at("range");
    PENDULUM_FAIL_IF(!range.is_array() || range.size() != 2, r.path("range"),
                     "got " + shown(range) + "; expected [low, high], the amplitudes it was released between");
    lo = factor * finite_number(range[0], [&] { return r.path("range") + "[0]"; }, "an angle (number)");
    hi = factor * finite_number(range[1], [&] { return r.path("range") + "[1]"; }, "an angle (number)");
    if (r.has("source")) r.text("source");
    r.finish();
    PENDULUM_FAIL_IF(!(lo >= 0.0 && hi > lo && hi < kPi), r.path("range"),
                     "got " + shown(range) + "; expected 0 <= low < high, below 180 deg");
    how = "released between " + format_number(degrees(lo), 4) + " and " + format_number(degrees(hi), 4) + " deg";
  }
  const double value = 0.5 * (lo + hi), sigma = (hi - lo) / std::sqrt(12.0);
  out.evaluations.push_back({path, 'B', Distribution::rectangular});
  if (say) {
    const double effect = value * sigma / 4.0;
    out.assumptions.push_back(path + ": " + how + ", taken as uniform over " + format_number(degrees(lo), 4) +
                              " to " + format_number(degrees(hi), 4) + " deg: " + format_number(degrees(value), 4) +
                              " +- " + format_number(degrees(sigma), 3) + " deg ((high - low)/sqrt(12))");
    out.warnings.push_back(path + ": " + how + ": its uncertainty, +- " + format_number(degrees(sigma), 3) +
                           " deg, moves g by about " + format_number(effect, 2) + " of itself (" +
                           format_number(effect * 9.80665, 2) + " m/s^2 near the Earth's g), its row " + path +
                           " in the budget; record the amplitude to remove it");
  }
  return {value, sigma};
}

/// Zero, and an uncertainty as large as the value ("5 +- 5 deg"), are what an
/// amplitude nobody knows gets written as: the message says what to write.
void refuse_unknown_amplitude(Object& owner) {
  const json& a = owner.at("amplitude");
  if (!a.is_object() || !a.contains("value") || !a["value"].is_number() || !a.contains("unit") || !a["unit"].is_string()) return;
  const std::string unit_name = a["unit"].get<std::string>();
  const auto unit = find_unit(unit_name, Dimension::angle);
  const double raw = a["value"].get<double>();
  if (!unit || !std::isfinite(raw)) return;  // quantity() says what is wrong
  const double v = std::isnormal(raw) ? raw : 0.0;
  const std::string path = owner.path("amplitude");
  PENDULUM_FAIL_IF(v <= 0.0, path + ".value",
                   "got " + format_number(v) + " " + unit_name + "; expected a positive angle: " + kUnrecordedAmplitude);
  if (!a.contains("uncertainty") || !a["uncertainty"].is_number()) return;
  const double u = a["uncertainty"].get<double>();
  PENDULUM_FAIL_IF(std::isfinite(u) && u >= v, path + ".uncertainty",
                   uncertainty_not_below_value(format_number(u) + " " + unit_name, format_number(v) + " " + unit_name) +
                       ": an amplitude known only to lie between " +
                       format_number(std::max(0.0, v - u)) + " and " + format_number(v + u) + " " + unit_name +
                       " is written \"amplitude\": {\"range\": [" + format_number(std::max(0.0, v - u)) + ", " +
                       format_number(v + u) + "], \"unit\": \"" + unit_name + "\"} (or \"not recorded\", docs/scene.md)");
}

/// Each registered kind's setting keys: "by length (simple_pendulum), or by
/// pivot_distance or pivot_position (physical_pendulum)".
/// The keys that set a kind's observations: "pivot_distance or pivot_position".
template <class M>
std::string settings_of() {
  std::string out;
  for (std::size_t i = 0; i < M::kSettings.size(); ++i) out += std::string(i == 0 ? "" : " or ") + setting_key(M::kSettings[i]);
  return out;
}

std::string settings_of_kinds() {
  std::string out;
  for_each_period_model([&](auto model) {
    using M = decltype(model);
    out += (out.empty() ? "by " : ", or by ") + settings_of<M>() + " (" + M::kName + ")";
  });
  return out;
}

/// The kind a scene names (its "kind": a registered model's kName, as
/// fit.model prints it).
PeriodModelKind kind_named(Object& top) {
  const std::string name = top.text("kind");
  std::optional<PeriodModelKind> kind;
  std::string names;
  for_each_period_model([&](auto model) {
    using M = decltype(model);
    if (name == M::kName) kind = kind_of<M>();
    names += std::string(names.empty() ? "\"" : ", \"") + M::kName + "\"";
  });
  PENDULUM_FAIL_IF(!kind, "kind", "got " + shown(top.at("kind")) + "; expected one of " + names);
  return *kind;
}

/// The keys of one observation, under `o` (the top level, or an item of
/// "observations") with `prefix` on every path; `shared`, in a series, holds
/// the length or amplitude given once for all.
void read_observation(Object& o, const std::string& prefix, ParsedScene& out, RecordingReader& recordings,
                      Object* shared = nullptr) {
  Observation<double> v, u;
  ObservationSource source;
  source.path = prefix;
  if (o.has("timing") && names_recording(o.at("timing"))) {
    read_recorded_timing(o, prefix, v, u, source, out, recordings);
  } else {
    read_timing(o, prefix, v, u, source, out);
  }
  // The setting is the one whose key the observation has (kSettingInfo); where none is there, the
  // kind's first: the ball's length, or the named or earlier observations' kind's (a pivot distance).
  v.setting = visit_period_model(out.model, [](auto model) { return decltype(model)::kSettings.front(); });
  for (const SettingInfo& setting : kSettingInfo) {
    if (!o.has(setting.key) || setting.setting == v.setting) continue;
    PENDULUM_FAIL_IF(o.has(setting_key(v.setting)), prefix + setting.key,
                     std::string("got both ") + setting_key(v.setting) + " and " + setting.key + "; expected one");
    v.setting = setting.setting;
  }
  u.setting = v.setting;
  const char* key = setting_key(v.setting);
  // The ball's length alone may be given once for a series (a top-level length).
  const bool physical = v.setting != Setting::length;
  Object& length_owner = physical ? o : owner(o, shared, "length", source);
  PENDULUM_FAIL_IF(physical && shared && shared->has("length"), "length",
                   std::string("got both length and ") + prefix + key + "; expected one");
  // The kind is the registered model's that reads this setting (models/registry.hpp).
  const PeriodModelKind kind = kind_of_setting(v.setting);
  PENDULUM_FAIL_IF(!out.observations.empty() && kind != out.model, prefix + key,
                   std::string("got ") + key + " after observations set by " +
                       setting_key(out.observations.back().setting) +
                       "; expected every observation set as one kind of pendulum: " + settings_of_kinds());
  out.model = kind;
  if (physical) {
    put(o, key, Dimension::length,
        setting_info(v.setting).signed_distance ? Range::any
        : v.setting == Setting::rod_length      ? Range::positive
                                                : Range::non_negative,
        v.length, u.length);
    within(std::abs(v.length), 0.0, 1e3, prefix + key + ".value", "m", "a laboratory body's pivot, within 1 km");
  } else if (length_owner.at("length").is_string() && &length_owner != &o) {
    // An amplitude sweep whose length nobody measured gives T0, not g (docs/series.md, "Amplitude sweeps").
    PENDULUM_FAIL_IF(length_owner.text("length") != kLengthNotMeasured, "length",
                     "got " + shown(length_owner.at("length")) + "; expected a length ({\"value\": 0.8, \"uncertainty\": "
                     "0.001, \"unit\": \"m\"}), or \"" + kLengthNotMeasured + "\" for an amplitude sweep whose "
                     "length nobody measured (its small-amplitude period, no g)");
    out.length_measured = false;
    v.length = u.length = 0.0;
  } else {
    const Measured length = quantity(length_owner, "length", Dimension::length, Range::positive, &source.measured_to);
    v.length = length.value;
    u.length = length.sigma;
    within(v.length, ranges::length.low, ranges::length.high, source.path_of("length.value"), ranges::length.unit,
           ranges::length.expected);
    // Left out, an uncertainty is unknown and said so; written as 0, it claims a perfect tape.
    const auto& written = length_owner.at("length");
    if (written.contains("uncertainty") && written.at("uncertainty") == 0) {
      out.suspicions.push_back(source.path_of("length.uncertainty") +
                               ": 0, but no tape reads a length exactly: give the tape's reading uncertainty "
                               "(about 1 mm read by eye, more where the ball's centre is judged), or leave it out");
    }
  }
  Object& amplitude_owner = owner(o, shared, "amplitude", source);
  if (!amplitude_owner.has("amplitude") && source.recording) {
    // The recording's amplitude where the timing starts (docs/recordings.md).
    const RecordingSummary& r = out.recordings[*source.recording].summary;
    const std::size_t with_amplitude = r.swings.decay.amplitudes.size();
    PENDULUM_FAIL_IF(!std::isfinite(r.swings.start_amplitude), prefix + "amplitude",
                     "missing, and the recording " + r.file +
                         (with_amplitude == 0
                              ? " gives no amplitudes (a photogate gives them with timing.bob_width)"
                              : " gives amplitudes for only " + std::to_string(with_amplitude) + " of the " +
                                    std::to_string(r.swings.swings.size()) +
                                    " swings from crossing to crossing it found, too few for the smooth curve that "
                                    "gives the one at the start, which needs 8 and half of them (a short record "
                                    "has few; knocks or a glitchy stretch lose theirs, which pendulum-g import " +
                                    r.file + " notes, and a \"range\" in timing cuts a stretch)") +
                         "; expected the amplitude at the start of the timing");
    v.amplitude = r.swings.start_amplitude;
    source.amplitude_from_recording = true;
    // A gyroscope or accelerometer turns with the bob it is in (docs/phone.md).
    if (sensor_in_bob(r.kind)) v.amplitude_of = u.amplitude_of = AngleOf::body;
    const bool known = std::isfinite(r.swings.start_amplitude_uncertainty);
    u.amplitude = known ? r.swings.start_amplitude_uncertainty : 0.0;
    source.amplitude_raw = degrees(v.amplitude);
    source.amplitude_unit = "deg";
    out.assumptions.push_back(
        prefix + "amplitude: " + format_number(source.amplitude_raw, 5) +
        " deg, the recording's at the start of its timing " +
        (known ? "(+- " + format_number(degrees(u.amplitude), 2) + " deg from its swings' scatter" +
                     (r.kind == SignalKind::position ? " and its circle's radius)" : ")")
               : std::string("(no uncertainty: a gyroscope's scale, g or a beam's width would set it)")));
  } else if (unrecorded(amplitude_owner.at("amplitude"))) {
    const bool shared = &amplitude_owner != &o;
    const Measured m = unrecorded_amplitude(amplitude_owner, out, !shared || out.observations.empty());
    v.amplitude = m.value;
    u.amplitude = m.sigma;
    source.amplitude_raw = degrees(v.amplitude);
    source.amplitude_unit = "deg";
  } else {
    refuse_unknown_amplitude(amplitude_owner);
    std::string of = "pendulum";
    const Measured m = quantity(amplitude_owner, "amplitude", Dimension::angle, Range::positive, &of, "of");
    v.amplitude = m.value;
    u.amplitude = m.sigma;
    PENDULUM_FAIL_IF(of != "pendulum" && of != "body", source.path_of("amplitude") + ".of",
                     "got \"" + one_line(of, 60, true) + "\"; expected \"pendulum\" (the line from the pivot to the bob's centre, "
                     "the default) or \"body\" (the bob's own tilt, what a sensor in it measures)");
    if (of == "body") v.amplitude_of = u.amplitude_of = AngleOf::body;
    const json& amplitude = amplitude_owner.at("amplitude");
    source.amplitude_raw = amplitude.at("value").get<double>();
    source.amplitude_unit = find_unit(amplitude.at("unit").get<std::string>(), Dimension::angle)->name;
  }
  PENDULUM_FAIL_IF(v.amplitude >= kPi, source.path_of("amplitude") + ".value",
                   "got " + format_number(degrees(v.amplitude)) +
                       " deg; expected an amplitude below 180 deg (at 180 deg and beyond "
                       "the pendulum goes over the top)");
  out.observations.push_back(v);
  out.observation_uncertainties.push_back(u);
  out.sources.push_back(std::move(source));
}

/// "observations": a non-empty array of objects with length, amplitude, timing.
/// A series timed by one hand and one stopwatch: the trials' scatter, in
/// seconds of a trial whatever the oscillations counted, pooled over every
/// observation timed more than once, unless Bartlett's test refutes that
/// they share it (p < 0.01). Each observation's own s from a few trials
/// would weigh the fit by 1/s^2, which overstates its weight where s came
/// out small (E[1/s^2] = nu/(nu - 2) sigma^-2): g's uncertainty then covered
/// 86 % for a nominal 95 % (docs/uncertainty.md, "A series' trials").
void pool_trial_scatter(ParsedScene& out) {
  std::vector<std::size_t> timed, tested;
  double nu = 0.0, squares = 0.0, logs = 0.0, inverses = 0.0, tested_nu = 0.0;
  for (std::size_t k = 0; k < out.observations.size(); ++k) {
    const auto& t = out.sources[k].trial_scatter;
    if (!t) continue;
    const double v = out.sources[k].trial_count - 1.0;
    timed.push_back(k);
    nu += v;
    squares += v * t->spread * t->spread;
    // Equal trials (their scatter below the resolution) add their
    // degrees of freedom and no square; Bartlett's test needs a logarithm.
    if (!(t->spread > 0.0)) continue;
    tested.push_back(k);
    logs += v * std::log(t->spread * t->spread);
    inverses += 1.0 / v;
    tested_nu += v;
  }
  if (timed.size() < 2 || !(squares > 0.0)) return;
  const double pooled = std::sqrt(squares / nu);
  // Bartlett (1937): M/C against chi2 with groups - 1 degrees of freedom,
  // over the observations that scatter; M is 0 where they scatter alike
  // (rounding may make it -1e-14).
  double probability = 1.0;
  if (tested.size() >= 2) {
    const double groups = static_cast<double>(tested.size());
    const double m = tested_nu * std::log(squares / tested_nu) - logs;
    const double c = 1.0 + (inverses - 1.0 / tested_nu) / (3.0 * (groups - 1.0));
    probability = dispersion(std::max(m / c, 0.0), static_cast<int>(tested.size()) - 1).probability.value_or(1.0);
  }
  const std::string p = format_number(probability, 2);
  if (probability < kOverDispersedProbability) {
    out.assumptions.push_back("observations: the trials' scatter differs from one observation to the next (Bartlett's "
                              "test p = " + p + "), so each period keeps its own");
    return;
  }
  for (const std::size_t k : timed) {
    const ObservationSource& source = out.sources[k];
    // A table's repeats arrive with their pooled scatter as the floor
    // (table_scene.cpp): the same number to rounding, and the pooled one.
    const double floor = source.trial_scatter->floor;
    const double sigma_trial = floor > pooled * (1.0 + 1e-9) ? floor : pooled, n = source.trial_count;
    out.observation_uncertainties[k].period = sigma_trial / std::sqrt(n) / out.observations[k].oscillations_per_trial;
    // A floor that wins is Type B, as for one observation (parts.cpp).
    const std::string path = source.path + "timing.period";
    const InputEvaluation evaluation =
        sigma_trial == pooled ? InputEvaluation{path, 'A', Distribution::student_t, nu, SharedVariance::pooled_trials}
        : source.trial_scatter->floor_is_resolution ? InputEvaluation{path, 'B', Distribution::rectangular}
                                                   : InputEvaluation{path};
    for (InputEvaluation& e : out.evaluations) {
      if (e.path == path) e = evaluation;
    }
  }
  out.assumptions.push_back("observations: the trials' scatter pooled over the " + std::to_string(timed.size()) +
                            " observations timed more than once (one hand, one stopwatch; Bartlett's test of equal "
                            "scatter p = " + p + "): " + format_number(pooled, 3) + " s a trial, " +
                            format_number(nu, 6) + " degrees of freedom; each period's uncertainty is it over "
                            "oscillations x sqrt(trials)");
}

void read_series(Object& top, ParsedScene& out, RecordingReader& recordings) {
  // A length or amplitude measured once is given once (shared); what
  // changes from one observation to the next is each observation's own.
  std::vector<const char*> own{"timing"};
  for (const SettingInfo& s : kSettingInfo) {
    if (s.setting != Setting::length) own.push_back(s.key);
  }
  for (const char* key : own) {
    PENDULUM_FAIL_IF(top.has(key), key,
                     "got both observations and a top-level " + std::string(key) +
                         "; expected each observation to hold its own " + key +
                         " (only a length or amplitude measured once for all may be given at the top level)");
  }
  const json& given = top.at("observations");
  // A table names its file: its rows become the observations (docs/series.md, "Tables").
  const json from_table = given.is_object() && given.contains("table") ? read_table_reference(top, out, recordings) : json();
  const json& list = from_table.is_null() ? given : from_table;
  PENDULUM_FAIL_IF(!list.is_array() || list.empty(), "observations",
                   "got " + shown(list) + "; expected a non-empty array of observations, each with length, "
                   "amplitude and timing, or a table of them, {\"table\": \"lengths.csv\"} (docs/series.md)");
  out.series = true;
  if (top.has("period_uncertainty")) {
    PENDULUM_FAIL_IF(top.text("period_uncertainty") != "scatter_about_fit", "period_uncertainty",
                     "got " + shown(top.at("period_uncertainty")) + "; expected \"scatter_about_fit\" (single timings "
                     "without an uncertainty: each period's is their scatter about the fit), or no key");
    out.period_uncertainty_from_scatter = true;
  }
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string path = "observations[" + std::to_string(k) + "]";
    Object o(list[k], path, "an object with length, amplitude and timing");
    for (const char* key : {"length", "amplitude"}) {
      PENDULUM_FAIL_IF(top.has(key) && o.has(key), path + "." + key,
                       "got both a top-level " + std::string(key) + " (shared by every observation) and this one; "
                       "expected one: give " + key + " once at the top level, or in every observation");
    }
    read_observation(o, path + ".", out, recordings, &top);
    if (o.has("source")) o.text("source");
    o.finish();
    PENDULUM_FAIL_IF(out.observation_uncertainties.back().period == 0.0, path + ".timing",
                     "got a period with no uncertainty (equal trials and no resolution); expected one: a series "
                     "weighs each period by its uncertainty, so state timing.resolution or timing.uncertainty");
  }
  pool_trial_scatter(out);
}

/// "uncertainty": {"method": "gum" | "monte-carlo", "draws": N, "seed": S}
/// (docs/uncertainty.md): Monte Carlo beside GUM's budget, N draws (or
/// adaptive without), seeded.
void read_uncertainty_method(Object& top, ParsedScene& out) {
  Object u(top.at("uncertainty"), "uncertainty");
  const std::string method = u.has("method") ? u.text("method") : "gum";
  PENDULUM_FAIL_IF(method != "gum" && method != "monte-carlo", u.path("method"),
                   "got " + shown(u.at("method")) + "; expected \"gum\" or \"monte-carlo\"");
  const auto whole = [&](const char* key, double least, double most) {
    const double x = finite_number(u.at(key), [&] { return u.path(key); }, "a whole number");
    PENDULUM_FAIL_IF(!(x >= least && x <= most && x == std::floor(x)), u.path(key),
                     "got " + format_number(x) + "; expected a whole number from " + format_number(least) + " to " +
                         format_number(most));
    return x;
  };
  MonteCarloOptions mc;
  if (u.has("draws")) mc.draws = static_cast<long>(whole("draws", 100, kMostDraws));
  if (u.has("seed")) mc.seed = static_cast<std::uint64_t>(whole("seed", 0, 9007199254740991.0));  // 2^53 - 1
  if (u.has("source")) u.text("source");
  u.finish();
  if (method == "monte-carlo") out.monte_carlo = mc;
}

/// "fit": the unknowns besides g, by the period model's parameter names.
template <class Model>
void read_fit(Object& top, ParsedScene& out) {
  const json& list = top.at("fit");
  std::string names;
  for (const auto& p : Model::kParameterInfo) names += (names.empty() ? "" : ", ") + std::string(p.name);
  PENDULUM_FAIL_IF(!list.is_array(), "fit", "got " + shown(list) + "; expected an array of unknowns from: " + names);
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string path = "fit[" + std::to_string(i) + "]";
    const json& name = list[i];
    const bool known = name.is_string() && std::any_of(Model::kParameterInfo.begin(), Model::kParameterInfo.end(),
                                                       [&](const ParameterInfo& p) { return name == p.name; });
    PENDULUM_FAIL_IF(!known, path, "got " + shown(name) + "; expected one of the unknowns: " + names);
    PENDULUM_FAIL_IF(std::find(out.fit.begin(), out.fit.end(), name.get<std::string>()) != out.fit.end(), path,
                     "got " + shown(name) + " twice; expected each unknown once");
    if (name != "g") out.fit.push_back(name.get<std::string>());  // g is always fitted
  }
}

/// Each length to the bob's centre: the radius (a box's or cylinder's half
/// height) added to a length measured to the top of the bob, subtracted from
/// one to its bottom. The radius's uncertainty is not the length's: it is
/// the bob's, common to every such length and to the bob's own corrections,
/// and the analysis propagates it so (ObservationSource::knot_to_center_sign).
void refer_lengths_to_centre(ParsedScene& out) {
  for (std::size_t k = 0; k < out.observations.size(); ++k) {
    const std::string& to = out.sources[k].measured_to;
    const std::string path = out.sources[k].path_of("length.measured_to");
    const double sign = to == "top_of_bob" ? 1.0 : to == "bottom_of_bob" ? -1.0 : 0.0;
    PENDULUM_FAIL_IF(sign == 0.0 && to != "center" && to != "centre", path,
                     "got \"" + one_line(to, 60, true) + "\"; expected \"center\", \"top_of_bob\" or \"bottom_of_bob\"");
    if (sign == 0.0) continue;
    const auto& bob = out.apparatus.bob;
    PENDULUM_FAIL_IF(!bob, path,
                     "got \"" + to + "\" but no bob; expected bob.diameter, whose half is " +
                         (sign > 0 ? "added to" : "subtracted from") + " the length");
    const double radius = bob->knot_to_center();
    out.observations[k].length += sign * radius;
    out.sources[k].knot_to_center_sign = sign;
    if (k > 0 && out.sources[k].is_shared("length")) continue;  // said once
    out.assumptions.push_back(out.sources[k].path_of("length") + ": measured to the " +
                              (sign > 0 ? "top" : "bottom") + " of the bob; its " +
                              (bob->shape == BobShape::sphere ? "radius " : "half height ") +
                              format_number(radius * 1e3, 4) + " mm is " + (sign > 0 ? "added" : "subtracted"));
  }
}

/// Says, for each amplitude that is the bob's (a sensor in it, or "of":
/// "body"), what the corrections take instead: the pendulum's angle, the slow
/// mode's ratio times it at the measured length, and on a string the finite
/// amplitude the mode's series in the bob's own (docs/phone.md).
void note_body_amplitudes(ParsedScene& out) {
  for (std::size_t k = 0; k < out.observations.size(); ++k) {
    const Observation<double>& o = out.observations[k];
    if (o.amplitude_of != AngleOf::body || (k > 0 && (out.swing_by_swing || out.sources[k].is_shared("amplitude")))) continue;
    const double c = pendulum_over_body_angle(out.apparatus, o.length);
    out.assumptions.push_back(out.sources[k].path_of("amplitude") + ": the bob's own angle; the corrections take " +
                              "the pendulum's (pivot to the bob's centre), " + format_number(c, 6) + " times it" +
                              (c == 1.0 ? (out.apparatus.bob || out.apparatus.body ? " (rigid: the bob turns with the line)" : " (no bob: a point)")
                                        : std::string(" (the slow mode on the string); the finite amplitude takes the "
                                                      "mode's own series in the bob's angle (method slow_mode_...)")));
  }
}

/// Per row of kCorrections, whether `M` uses some correction of that row's
/// part (its kCorrectionUse): fixed per model, so found at compile time.
template <class M>
constexpr std::array<bool, kCorrectionCount> parts_used() {
  std::array<bool, kCorrectionCount> used{};
  for (int i = 0; i < kCorrectionCount; ++i) {
    for (const CorrectionInfo& other : kCorrections) {
      used[i] = used[i] || (std::string_view(kCorrections[i].part) == other.part &&
                            M::kCorrectionUse[static_cast<int>(other.correction)] != CorrectionUse::not_applicable);
    }
  }
  return used;
}

/// Refuses a part none of whose corrections the scene's kind uses (its
/// kCorrectionUse, models/registry.hpp): a ball's ring or wire on a rigid body.
void check_parts_apply(Object& top, const ParsedScene& out) {
  visit_period_model(out.model, [&](auto model) {
    using M = decltype(model);
    static constexpr std::array<bool, kCorrectionCount> used = parts_used<M>();
    for (int i = 0; i < kCorrectionCount; ++i) {
      if (used[i]) continue;
      const std::string part = kCorrections[i].part;
      PENDULUM_FAIL_IF(top.has(part) && top.at(part).is_object(), part,
                       "got a " + part + " in a scene of a " + M::kName + "; expected none: no correction of a " +
                           M::kName + " uses it (docs/core.md)");
    }
  });
}

/// ", a and b" or " and a": the unknowns besides g, for a message.
std::string unknown_names(const std::vector<std::string>& fit) {
  std::string out;
  for (std::size_t i = 0; i < fit.size(); ++i) out += (i + 1 == fit.size() ? " and " : ", ") + fit[i];
  return out;
}

/// Unknowns besides g need observations at more than one setting: at one,
/// every period is the same one, which tells g from them no better than one
/// observation does (issue 42: a series of equal lengths fitting
/// length_offset gave g 9.5225 +- null).
void refuse_one_setting_fit(const ParsedScene& out) {
  const auto& observations = out.observations;
  if (out.fit.empty() || observations.size() < 2) return;
  const Observation<double>& first = observations.front();
  const bool one = std::all_of(observations.begin(), observations.end(), [&](const Observation<double>& o) {
    return o.setting == first.setting && std::abs(o.length - first.length) <= 1e-6 * std::abs(first.length);
  });
  std::string fitted;
  for (const auto& name : out.fit) fitted += (fitted.empty() ? "" : ", ") + name;
  const std::string key = setting_key(first.setting);
  PENDULUM_FAIL_IF(one, out.sources.back().path + key + ".value",
                   "got every observation at the " + key + " " + format_number(first.length) +
                       " m; expected observations at different ones: with " + fitted + " fitted, one " + key +
                       " gives one period, which cannot tell g from " + fitted);
}

/// A sweep without its length: T0 alone is asked of it, so nothing is fitted
/// but T0, and the amplitudes must differ.
void check_sweep_without_length(const ParsedScene& out) {
  PENDULUM_FAIL_IF(!out.fit.empty(), "fit",
                   "got unknowns beside g with \"length\": \"" + std::string(kLengthNotMeasured) +
                       "\"; expected none: a sweep without its length gives its small-amplitude period alone");
  PENDULUM_FAIL_IF(out.recordings.size() > 0 || out.decay_data, "length",
                   "got \"" + std::string(kLengthNotMeasured) + "\" in a scene with a recording or a decay record; "
                   "expected the length: a recording's corrections need it");
  std::vector<double> amplitudes;
  for (const auto& o : out.observations) amplitudes.push_back(o.amplitude);
  PENDULUM_FAIL_IF(distinct_amplitudes(amplitudes) < 2, "length",
                   "got \"" + std::string(kLengthNotMeasured) + "\" and every observation at one amplitude; expected "
                   "the length (g needs it), or observations at different amplitudes (an amplitude sweep's "
                   "small-amplitude period)");
}

/// schema, title, source, notes: what every document may say about itself.
void read_header(Object& top, ParsedScene& out) {
  if (top.has("schema")) {
    const std::string schema = top.text("schema");
    PENDULUM_FAIL_IF(schema != kSceneSchema, "schema",
                     "got " + shown(top.at("schema")) + "; expected \"" + kSceneSchema + "\"" +
                         (schema == kClockSceneSchema ? " (a clock scene is for pendulum-g clock)" : ""));
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
}

}  // namespace

std::string scene_directory(const std::string& path) {
  if (path == "-") return ".";
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

std::vector<std::string> scene_file_names(const std::string& text, const SceneFiles& files) {
  std::vector<std::string> out;
  json doc;
  try {
    doc = parse_json(text, files.limits.applied_to(kSceneInput));  // nested at most 10 deep: the walk below is bounded
  } catch (const InputError&) {
    return out;
  }
  if (!files.directory) return out;
  const auto add = [&](const json& o, const char* key) {
    if (o.is_object() && o.contains(key) && o.at(key).is_string()) {
      out.push_back(scene_file(*files.directory, o.at(key).get<std::string>()));
    }
  };
  // A recording may be named in a timing, a decay's data or a series' observation.
  const auto walk = [&](const json& j, const auto& self) -> void {
    add(j, "recording");
    if (j.is_structured()) {
      for (const auto& item : j) self(item, self);
    }
  };
  walk(doc, walk);
  if (doc.is_object() && doc.contains("observations")) add(doc.at("observations"), "table");
  return out;
}

ParsedScene parse_scene(const std::string& text, const SceneFiles& files) {
  const json doc = parse_json(text, files.limits.applied_to(kSceneInput));
  RecordingReader recordings(files);
  ParsedScene out;
  Object top(doc, "", "a JSON object (the scene)");
  read_header(top, out);
  const std::optional<PeriodModelKind> named = top.has("kind") ? std::optional(kind_named(top)) : std::nullopt;
  if (named) out.model = *named;
  (void)top.has("import");  // import's report of a table's columns (docs/series.md): free-form, not read

  if (top.has("observations")) {
    read_series(top, out, recordings);
  } else {
    read_observation(top, "", out, recordings);
  }
  // The kind the observations' keys set must be the one the scene names.
  if (named && *named != out.model) {
    const std::string set = visit_period_model(out.model, [](auto model) { return decltype(model)::kName; });
    const std::string keys = visit_period_model(*named, [](auto model) { return settings_of<decltype(model)>(); });
    throw InputError("kind", "got " + shown(top.at("kind")) + " for observations set by " +
                                 setting_key(out.observations.front().setting) + ", which make a " + set +
                                 "; expected \"" + set + "\", or observations set by " + keys);
  }
  read_parts(top, out);
  if (top.has("decay")) read_decay(top, out, recordings);
  reduce_swing_by_swing(out);
  if (top.has("site")) read_site(top, out);
  if (top.has("uncertainty")) read_uncertainty_method(top, out);
  visit_period_model(out.model, [&](auto model) {
    if (top.has("fit")) read_fit<decltype(model)>(top, out);
    decltype(model)::read_keys(top, out);
  });
  check_parts_apply(top, out);
  top.finish();
  const std::size_t unknowns = out.fit.size() + 1;
  PENDULUM_FAIL_IF(out.observations.size() < unknowns, out.series ? "observations" : "fit",
                   "got " + std::to_string(out.observations.size()) + " observation" +
                       (out.observations.size() == 1 ? "" : "s") + " for " + std::to_string(unknowns) +
                       " unknowns (g" + unknown_names(out.fit) + "); expected at least as many observations "
                       "as unknowns");
  if (!out.length_measured) {
    check_sweep_without_length(out);
    return out;  // every other check weighs a period against its length
  }
  refuse_one_setting_fit(out);
  refer_lengths_to_centre(out);
  visit_period_model(out.model, [&](auto model) { decltype(model)::check_scene(out); });
  note_body_amplitudes(out);
  check_plausibility(out);
  return out;
}

ParsedScene parse_decay_document(const std::string& text, const SceneFiles& files) {
  const json doc = parse_json(text, files.limits.applied_to(kSceneInput));
  Object top(doc, "", "a JSON object (the scene)");
  for (const char* key : {"observations", "timing", "length", "amplitude"}) {
    if (top.has(key)) return parse_scene(text, files);
  }
  RecordingReader recordings(files);
  ParsedScene out;
  read_header(top, out);
  PENDULUM_FAIL_IF(!top.has("decay"), "decay",
                   "missing; expected a decay record (decay.data), alone or in a whole scene");
  read_decay(top, out, recordings);
  top.finish();
  return out;
}

}  // namespace pendulum
