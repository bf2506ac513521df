#include "pendulum/status.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "pendulum/air.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/dispersion.hpp"
#include "pendulum/drag.hpp"
#include "pendulum/models/registry.hpp"
#include "pendulum/numeric.hpp"
#include "plausibility.hpp"
#include "text.hpp"

namespace pendulum {

namespace {

/// The words of the scene's model for what goes wrong with it.
const SuspectCauses& suspect_causes(const ParsedScene& scene) {
  return *visit_period_model(scene.model, [](auto model) { return &decltype(model)::kSuspectCauses; });
}

/// Sea level to the highest laboratories (Pa).
constexpr double kAtmosphereLow = 5e4, kAtmosphereHigh = 1.1e5;

std::string signed_number(double x, int digits) { return (x >= 0.0 ? "+" : "") + format_number(x, digits); }

/// Fractions of a period a late start (or an early stop) can take, and how
/// close to a whole number of periods an offset must be to be a miscount.
constexpr double kLateStartLow = 0.1, kLateStartHigh = 0.85, kMiscountTolerance = 0.15;

/// Which systematic error explains a g `z` combined standard uncertainties
/// from `expected`, for one observation: the length taped to the top of the
/// bob, on a string or a rod (adding the knot-to-centre distance, a ball's
/// radius or a box's or cylinder's half height, brings g within 3 sigma;
/// only where `top_of_ball`, with an uncertainty to judge by), or every
/// trial off by the same time, a fraction of a period (a stopwatch started
/// late or stopped early) or whole periods (oscillations miscounted), for
/// any body: at a fixed geometry g ~ 1/T^2, a physical pendulum's too. Not
/// for a series: a fitted length_offset takes up a length's offset, and a
/// time's changes each T^2 by its own amount. Empty when none fits.
std::optional<std::string> name_systematic(const ParsedScene& scene, const Analysis& a, double expected, double z,
                                           bool top_of_ball) {
  if (scene.series || scene.observations.size() != 1) return std::nullopt;
  const Observation<double>& o = scene.observations.front();
  const double sigma = std::abs(a.g.value - expected) / std::abs(z);  // the combined standard uncertainty
  const auto& bob = scene.apparatus.bob;
  if (top_of_ball && suspect_causes(scene).lengths_to_bob && bob &&
      scene.sources.front().measured_to == "center" && a.g.value < expected) {
    const double radius = bob->knot_to_center();
    const bool ball = bob->shape == BobShape::sphere;
    const double g_top = a.g.value * (o.length + radius) / o.length;  // g = 4 pi^2 L / T^2
    // Within 3 sigma, or two thirds of the way there (the trials' own scatter remains).
    if (std::abs(g_top - expected) <= std::max(kSuspectSigmas * sigma, std::abs(a.g.value - expected) / 3.0)) {
      return std::string("the length taped to the top of the ") + (ball ? "ball" : "bob") + "? Adding the " +
             (ball ? "ball's radius (" : "bob's half height (") + format_number(radius * 1e3, 3) +
             " mm) gives g = " + format_number(g_top, 5) + " m/s^2, " +
             format_number(std::abs(g_top - expected) / sigma, 2) +
             " combined standard uncertainties from it: if so, give length.measured_to \"top_of_bob\"";
    }
  }
  // The period the expected g gives, from T^2 g = const, and each trial's offset.
  const double period = o.period * std::sqrt(a.g.value / expected);
  const double offset = o.oscillations_per_trial * (o.period - period);  // (s), + for trials too long
  const double periods = std::abs(offset) / period, whole = std::round(periods);
  if (whole >= 1.0 && std::abs(periods - whole) <= kMiscountTolerance) {
    return "if the length is right, every trial is " + format_number(std::abs(offset), 3) + " s " + (offset > 0.0 ? "longer" : "shorter") +
           " than " + std::to_string(o.oscillations_per_trial) + " periods at the expected g, " +
           format_number(whole, 2) + (whole == 1.0 ? " period" : " periods") +
           ": oscillations miscounted in every trial? timing.oscillations_per_trial " +
           std::to_string(o.oscillations_per_trial) + " should then be " +
           std::to_string(o.oscillations_per_trial + static_cast<int>(offset > 0.0 ? whole : -whole));
  }
  if (periods >= kLateStartLow && periods <= kLateStartHigh) {
    // The same g comes from a length off by as much: both are named.
    return "if the length is right, every trial is " + format_number(std::abs(offset), 2) + " s " + (offset > 0.0 ? "longer" : "shorter") +
           " than " + std::to_string(o.oscillations_per_trial) + " periods at the expected g, " +
           format_number(periods, 2) + " of a period, too little for a miscounted oscillation: a stopwatch " +
           (offset > 0.0 ? "started early or stopped late" : "started late or stopped early") + " by about " +
           format_number(std::abs(offset), 2) +
           " s? Start and stop the watch as the ball passes the same point, and time the trials again";
  }
  return std::nullopt;
}

/// Without a site: g beyond the range of g on the Earth's surface (no
/// laboratory has a g outside it) by more than kSuspectSigmas of its own
/// standard uncertainties. A g 2% low, where a ball's radius is left out of
/// the length, or 4% high, from a stopwatch started 0.7 s late over 20
/// periods, stays within standard gravity's 5% but not within the range.
/// (Beyond 5%, judge_g's own message names what to check.)
void judge_against_earth_range(const ParsedScene& scene, const Analysis& a, bool bob_slip, const std::string& bob,
                               const std::string& settings, const SuspectCauses& causes,
                               std::vector<std::string>& reasons) {
  if (a.expected_g || !a.surface_g || !a.surface_g->range || !a.g.uncertainty || !(*a.g.uncertainty > 0.0)) return;
  const auto [low, high] = *a.surface_g->range;
  const double sigma = *a.g.uncertainty;
  const bool below = a.g.value < low;
  const double outside = below ? low - a.g.value : a.g.value - high;
  if (!(outside > kSuspectSigmas * sigma)) return;
  const auto systematic = bob_slip ? std::nullopt
                                   : name_systematic(scene, a, kStandardGravity,
                                                     (a.g.value - kStandardGravity) / sigma, true);
  reasons.push_back("g = " + format_number(a.g.value, 5) + " m/s^2 is " + format_number(outside / sigma, 3) +
                    " of its standard uncertainties " + (below ? "below the lowest" : "above the highest") +
                    " g on the Earth's surface (" + format_number(below ? low : high, 5) +
                    " m/s^2; the scene gives no site)" +
                    (bob_slip     ? bob
                     : systematic ? ": " + *systematic
                                  : ": an uncertainty stated too small, or a systematic error: check " + settings +
                                        ", " + causes.reference + ", the trials and timing.oscillations_per_trial"));
}

/// `bob_slip`: the bob's density is implausible, which explains a g far off
/// through buoyancy and added mass.
/// `settings` names what sets the period besides the timing, for the hint;
/// `causes`, the model's words for the rest.
void judge_g(const ParsedScene& scene, const Analysis& a, bool bob_slip, const std::string& settings,
             const SuspectCauses& causes, std::vector<std::string>& reasons) {
  const std::string bob = ": the bob's implausible density (bob.mass, below) drives buoyancy and added mass";
  const double expected = a.expected_g ? a.expected_g->value : kStandardGravity;
  const std::string against = a.expected_g ? "the site's expected " + format_number(expected, 6) + " m/s^2"
                                           : "standard gravity (" + format_number(kStandardGravity) +
                                                 " m/s^2; the scene gives no site)";
  const double ratio = a.g.value / expected;
  const std::string g = "g = " + format_number(a.g.value, 5) + " m/s^2";
  if (const auto slip = name_slip(ratio)) {
    // A cause the reader named for the trials as a whole (a frequency typed
    // as trials) explains the ratio; a slip matching it would be chance.
    const bool explained = std::any_of(scene.suspicions.begin(), scene.suspicions.end(), [](const std::string& s) {
      return s.find(kFrequencyTyped) != std::string::npos;
    });
    reasons.push_back(g + " is " + format_number(ratio, 3) + " times " + against + ": " +
                      (explained ? std::string("from the trials (the reason above)") : *slip));
    return;
  }
  if (a.expected_g && a.z_score) {
    if (std::abs(*a.z_score) <= kSuspectSigmas) return;
    const auto systematic = bob_slip ? std::nullopt : name_systematic(scene, a, expected, *a.z_score, true);
    reasons.push_back(g + " is " + format_number(std::abs(*a.z_score), 3) +
                      " combined standard uncertainties from " + against + " (difference " +
                      signed_number(a.g.value - expected, 4) +
                      " m/s^2)" +
                      (bob_slip     ? bob
                       : systematic ? ": " + *systematic
                                    : std::string(": an uncertainty stated too small, or a systematic error (") +
                                          causes.systematic + ")"));
    return;
  }
  if (std::abs(ratio - 1.0) <= kSuspectFraction) {
    judge_against_earth_range(scene, a, bob_slip, bob, settings, causes, reasons);
    return;
  }
  // Without a stated uncertainty of the expected g, 5% stands for 3 sigma.
  const auto systematic =
      bob_slip ? std::nullopt : name_systematic(scene, a, expected, (ratio - 1.0) / kSuspectFraction * kSuspectSigmas, false);
  reasons.push_back(g + " is " + format_percent(std::abs(ratio - 1.0)) + " " +
                    (ratio > 1.0 ? "above " : "below ") + against + ", more than 5%" +
                    (bob_slip ? bob
                              : "; no unit or counting slip makes this ratio: check " + settings +
                                    ", the trials and timing.oscillations_per_trial" +
                                    (systematic ? "; " + *systematic : "")));
}


/// A laboratory's air (degC): no one times a pendulum below or above these.
constexpr double kLabColdest = 5.0, kLabHottest = 40.0;

void judge_air(const ParsedScene& scene, std::vector<std::string>& reasons) {
  const auto& air = scene.apparatus.air;
  if (!air) return;
  const double celsius = air->temperature - 273.15;
  if (celsius < kLabColdest || celsius > kLabHottest) {
    const double from_fahrenheit = (celsius - 32.0) * 5.0 / 9.0, from_kelvin = celsius - 273.15;
    auto in_lab = [](double c) { return c >= kLabColdest && c <= kLabHottest; };
    const std::string as_typed = format_number(celsius, 4);
    reasons.push_back("air.temperature: " + as_typed + " degC is no laboratory's air (" + format_number(kLabColdest) +
                      " to " + format_number(kLabHottest) + " degC)" +
                      (in_lab(from_fahrenheit)
                           ? "; " + as_typed + " degF is " + format_number(from_fahrenheit, 3) +
                                 " degC: a thermometer's degF written as degC? fix air.temperature.unit (\"degF\")"
                       : in_lab(from_kelvin)
                           ? "; " + as_typed + " K is " + format_number(from_kelvin, 3) +
                                 " degC: kelvin written as degC? fix air.temperature.unit (\"K\")"
                           : ": check air.temperature and its unit"));
  }
  const double p = air->pressure;
  for (const auto& [factor, unit] : {std::pair{100.0, "hPa"}, std::pair{1000.0, "kPa"}}) {
    if (p * factor < kAtmosphereLow || p * factor > kAtmosphereHigh) continue;
    reasons.push_back("air.pressure: " + format_number(p, 4) + " Pa is 1/" + format_number(factor) +
                      " of a room's air (50 to 110 kPa), the air of a vacuum chamber: a barometer's " +
                      format_number(p, 4) + " " + unit + " written as Pa? fix air.pressure.unit (\"" + unit +
                      "\")");
  }
}

void judge_amplitudes(const ParsedScene& scene, std::vector<std::string>& reasons) {
  constexpr double kSmallAngleLab = radians(20.0);
  for (std::size_t k = 0; k < scene.observations.size(); ++k) {
    const ObservationSource& s = scene.sources[k];
    const double raw = s.amplitude_raw;
    if (s.amplitude_unit != "deg" || raw < kRadiansPerDegree || raw > kSmallAngleLab) continue;
    const double arc_mm = scene.observations[k].length * radians(raw) * 1e3;
    reasons.push_back(s.path_of("amplitude") + ": " + format_number(raw, 4) + " deg moves the bob by " +
                      format_number(arc_mm, 2) + " mm, too little to start and watch by hand, while " +
                      format_number(raw, 4) + " rad is " + format_number(degrees(raw), 3) +
                      " deg, a small-angle lab's amplitude: radians written as deg? fix " + s.path_of("amplitude.unit") +
                      " (\"rad\")");
  }
}

/// A decay record whose amplitudes are 57 times the scene's, or 1/57 of
/// them, is in the other angular unit; one that starts at twice the scene's
/// amplitude, more than 3 of its standard uncertainties above it, holds
/// peak-to-peak swings. Nothing finer: a record may well start from a larger
/// release than the timing (Nelson & Olsson's starts at 17 deg, their trials
/// at 3 deg).
/// The fitted damping against the air's drag theory (Eqs. 26, 27, 63-67;
/// drag.hpp): a record whose times are minutes labelled s damps about 60
/// times faster than the air can make it, one in s labelled min 60 times
/// slower. A pivot's friction adds damping of its own, so only a factor
/// beyond kDragUnitFactor counts.
void judge_decay_against_drag(const ParsedScene& scene, const Analysis& a, std::vector<std::string>& reasons) {
  constexpr double kDragUnitFactor = 20.0;
  if (!scene.decay_data || !a.decay_fit || scene.series || scene.observations.empty()) return;
  const auto drag = predict_drag(scene.apparatus, scene.observations.front());
  if (!drag) return;
  const DecayFit& f = *a.decay_fit;
  // The larger of the fitted constants against its prediction: the one the record determines.
  double ratio = 0.0;
  std::string which;
  for (const auto& [p, predicted, name] : {std::tuple{&f.alpha, drag->alpha, "alpha"}, std::tuple{&f.beta, drag->beta, "beta"}}) {
    if (!p->fitted || !(predicted > 0.0) || !(p->value > 0.0)) continue;
    if (p->value / predicted > ratio) ratio = p->value / predicted, which = name;
  }
  if (ratio <= kDragUnitFactor) return;
  reasons.push_back("decay.data.time_unit: the record damps " + format_number(ratio, 3) + " times faster (" + which +
                    ") than the air's drag predicts for this ball (fit-decay prints both): times in min labelled s? "
                    "fix decay.data.time_unit (\"min\"); else check the bob's mass and the pivot's friction");
}

void judge_decay_record(const ParsedScene& scene, std::vector<std::string>& reasons) {
  constexpr double kUnitFactor = 20.0;  // far beyond any release, short of 57.3
  constexpr double kPeakToPeakTolerance = 0.15;  // a hand's release against a reading of the first swing
  if (!scene.decay_data || scene.series || scene.decay_data->amplitudes.empty()) return;
  const double first = scene.decay_data->amplitudes.front(), swing = scene.observations.front().amplitude;
  const double ratio = first / swing;
  const double swing_sigma = scene.observation_uncertainties.front().amplitude;
  if (std::abs(ratio / 2.0 - 1.0) <= kPeakToPeakTolerance && first - swing > 3.0 * swing_sigma) {
    reasons.push_back("decay.data.amplitudes[0]: the record starts at " + format_number(degrees(first), 3) + " deg, " +
                      format_number(ratio, 3) + " times the scene's amplitude " + format_number(degrees(swing), 3) +
                      " deg: peak-to-peak swings written as amplitudes? An amplitude is from the rest position to "
                      "one side: halve decay.data.amplitudes");
    return;
  }
  if (ratio > 1.0 / kUnitFactor && ratio < kUnitFactor) return;
  const bool tiny = ratio < 1.0;
  reasons.push_back("decay.data.amplitude_unit: the record starts at " + format_number(degrees(first), 3) +
                    " deg, " + (tiny ? "1/" : "") + format_number(tiny ? 1.0 / ratio : ratio, 3) +
                    " times the scene's amplitude " + format_number(degrees(swing), 3) + " deg: " +
                    (tiny ? "radians labelled deg? fix decay.data.amplitude_unit (\"rad\")"
                          : "degrees labelled rad? fix decay.data.amplitude_unit (\"deg\")"));
}

/// Every observation at one length: no offset can be told from g there.
bool one_length(const ParsedScene& scene) {
  const auto& obs = scene.observations;
  return std::all_of(obs.begin(), obs.end(), [&](const auto& o) { return o.length == obs.front().length; });
}

bool offset_fitted(const Analysis& a) {
  return std::any_of(a.fit.parameters.begin(), a.fit.parameters.end(),
                     [](const ParameterResult& p) { return p.fitted && std::string(p.name) == "length_offset"; });
}

/// Fits whose chi2 is improbably large (dispersion.hpp): what scatters, by
/// how much, what it means, and the uncertainty the scatter supports.
void judge_dispersion(const ParsedScene& scene, const Analysis& a, std::vector<std::string>& reasons) {
  if (a.fit.scaled && a.g.uncertainty && a.g_uncertainty_unscaled && !scene.period_uncertainty_from_scatter) {
    const SuspectCauses& causes = suspect_causes(scene);
    reasons.push_back(
        "fit: " + dispersion_finding(dispersion(a.fit.chi2, a.fit.dof), "the observations scatter about the fit") +
        ": uncertainties understated, or something the model misses (" +
        causes.scatter + ")?" +
        (!causes.lengths_to_bob || offset_fitted(a) || one_length(scene) ? std::string()
                                                    : " Lengths measured to another point than the bob's centre (its "
                                                      "top, the knot) are fitted out by \"fit\": [\"length_offset\"].") +
        " g's uncertainty is the one the scatter supports, " + format_number(*a.g.uncertainty, 3) +
        " m/s^2: the share of the observations' own uncertainties scaled by the Birge ratio S = " +
        format_number(*a.fit.birge_ratio, 3) + " (from the stated uncertainties alone " +
        format_number(*a.g_uncertainty_unscaled, 3) + " m/s^2)");
  }
  if (a.decay_fit && a.decay_fit->scaled) {
    const DecayFit& f = *a.decay_fit;
    reasons.push_back("decay.data: " + dispersion_finding(dispersion(f.chi2, f.dof), "the amplitudes scatter about Eq. (25)") +
                      ": decay.data.sigmas understated, or damping the law misses (a pivot's friction, a swing "
                      "that is not planar)? alpha's and beta's uncertainties, and g's through them, are scaled by "
                      "the Birge ratio S = " + format_number(*f.birge_ratio, 3));
  }
}

}  // namespace

Verdict judge(const ParsedScene& scene, const Analysis& analysis) {
  Verdict v;
  auto bob = bob_density_slip(scene.apparatus);
  const SuspectCauses& causes = suspect_causes(scene);
  const std::string settings = scene.body_from_parts ? causes.settings_from_parts : causes.settings;
  // What the reader and the plausibility checks found first: they name a
  // cause where the ratio of g only matches a slip by chance (a frequency
  // typed as trials gives g (T^2)^2 times too large).
  v.reasons = scene.suspicions;
  judge_g(scene, analysis, bob.has_value(), settings, causes, v.reasons);
  if (!analysis.g.uncertainty) {
    v.reasons.push_back("g has no uncertainty: the observations cannot separate the unknowns (the fit's covariance "
                        "is singular); add observations at other settings, or fit fewer unknowns");
  }
  judge_dispersion(scene, analysis, v.reasons);
  if (analysis.amplitude_sweep && sweep_law_refuted(*analysis.amplitude_sweep)) {
    v.reasons.push_back(sweep_law_finding(*analysis.amplitude_sweep));
  }
  if (bob) v.reasons.push_back(std::move(*bob));
  judge_air(scene, v.reasons);
  judge_amplitudes(scene, v.reasons);
  judge_decay_record(scene, v.reasons);
  judge_decay_against_drag(scene, analysis, v.reasons);
  if (!v.reasons.empty()) v.status = ResultStatus::suspect;
  return v;
}

namespace {

/// The text up to the first of the separators that end a reason's first
/// clause (": ", "; ", " (", "?"), from `from` on.
std::string first_clause(const std::string& text, std::size_t from = 0) {
  std::size_t end = text.size();
  for (const char* sep : {": ", "; ", " (", "?", ", as when"}) end = std::min(end, text.find(sep, from));
  return text.substr(0, end);
}

std::size_t code_points(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

/// `s` cut at a space to at most kBriefReasonLength code points, "..." added;
/// before a parenthesis the cut would leave open (a reader would look for its close).
std::string shortened(std::string s) {
  if (code_points(s) <= kBriefReasonLength) return s;
  std::size_t cut = 0, open_at = 0;
  int depth = 0;
  for (std::size_t i = 0, n = 0; i < s.size(); ++i) {
    if ((static_cast<unsigned char>(s[i]) & 0xC0) != 0x80 && ++n > kBriefReasonLength - 3) break;
    if (s[i] == ' ' && depth == 0) cut = i;
    if (s[i] == '(' && depth++ == 0) open_at = i;
    if (s[i] == ')' && depth > 0) --depth;
  }
  if (depth > 0 && open_at < cut) cut = open_at;
  while (cut > 0 && s[cut - 1] == ' ') --cut;
  return s.substr(0, cut) + "...";
}

/// The likely slip in a reason's text: the question it asks ("... pasted?"),
/// else the slip after ", as when", else its first clause.
std::string guess(const std::string& text) {
  const std::size_t q = text.find('?');
  if (q != std::string::npos) {
    const std::size_t colon = text.rfind(": ", q), semicolon = text.rfind("; ", q);
    std::size_t start = 0;
    for (std::size_t at : {colon, semicolon}) {
      if (at != std::string::npos) start = std::max(start, at + 2);
    }
    return text.substr(start, q + 1 - start);
  }
  const std::string as_when = ", as when ";
  const std::size_t a = text.find(as_when);
  if (a != std::string::npos) return first_clause(text.substr(a + as_when.size()));
  return first_clause(text);
}

}  // namespace

std::string brief_reason(const std::string& reason) {
  // "g = 39.377 m/s^2 is 4.01 times the site's expected 9.81 m/s^2: the
  // period is half the true one, as when ...": the ratio and the slip.
  const std::string g_is = " m/s^2 is ";
  const std::size_t is = reason.find(g_is);
  if (reason.compare(0, 4, "g = ") != 0 || is == std::string::npos) {
    // "air.pressure: 1013 Pa is 1/100 of ...: a barometer's 1013 hPa written as Pa? fix ...": the subject and its guess.
    const std::size_t subject = reason.find(": ");
    if (subject == std::string::npos || reason.find(' ') < subject) return shortened(guess(reason));
    return shortened(reason.substr(0, subject + 2) + guess(reason.substr(subject + 2)));
  }
  const std::string rest = reason.substr(is + g_is.size());
  const std::string number = rest.substr(0, rest.find(' '));
  const std::string after = rest.substr(number.size());
  const std::string expected = after.find("standard gravity") < after.find(": ") ? "standard gravity" : "the expected g";
  // What follows the comparison: the slip named, a systematic error guessed, or none.
  const std::size_t colon = rest.find(": ");
  const std::string then = colon == std::string::npos ? "" : rest.substr(colon + 2);
  if (after.compare(0, 7, " times ") == 0) {
    return shortened("g " + number + " times " + expected + (then.empty() ? "" : ": " + guess(then)));
  }
  const bool asks = then.find('?') != std::string::npos;
  if (after.compare(0, 32, " combined standard uncertainties") == 0) {
    return shortened("g " + number + " sigma from " + expected + (asks ? ": " + guess(then) : ""));
  }
  const std::string own = " of its standard uncertainties ";
  if (after.compare(0, own.size(), own) == 0) {
    return shortened("g " + number + " sigma " + after.substr(own.size(), 5) + " the Earth's range" +
                     (asks ? ": " + guess(then) : ""));
  }
  if (after.compare(0, 7, " above ") == 0 || after.compare(0, 7, " below ") == 0) {
    return shortened("g " + number + after.substr(0, 7) + expected + (asks ? ": " + guess(then) : ""));
  }
  return shortened(first_clause(reason));
}

}  // namespace pendulum
