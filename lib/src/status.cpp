#include "pendulum/status.hpp"

#include <cmath>

#include "pendulum/air.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/numeric.hpp"
#include "text.hpp"

namespace pendulum {

const char* result_status_name(ResultStatus s) {
  switch (s) {
    case ResultStatus::ok: return "ok";
    case ResultStatus::suspect: return "suspect";
    case ResultStatus::failed: return "failed";
  }
  return "";
}

namespace {

/// A slip and the ratio it makes g / true g, from g = 4 pi^2 L / T^2.
struct Slip {
  double ratio;
  const char* text;
};
constexpr Slip kSlips[] = {
    // Period T/2: g x 4; period 2T: g / 4.
    {4.0, "the period is half the true one, as when half swings are counted as oscillations (an oscillation is "
          "a full swing, there and back): halve timing.oscillations_per_trial"},
    {0.25, "the period is twice the true one, as when timing.oscillations_per_trial is half the oscillations "
           "timed (an oscillation is a full swing, there and back): double it"},
    // Length x10: g x 10.
    {10.0, "the length is 10 times too long, as when a length in mm is written as cm: fix length.unit"},
    {0.1, "the length is 10 times too short, as when a length in cm is written as mm: fix length.unit"},
    // Length x100: g x 100; period T/10: g x 100.
    {100.0, "the length is 100 times too long, as when a length in cm is written as m (fix length.unit), or the "
            "period 10 times too short, as when one period per trial is typed with oscillations_per_trial 10 "
            "(fix timing.oscillations_per_trial)"},
    {0.01, "the length is 100 times too short, as when a length in m is written as cm (fix length.unit), or the "
           "period 10 times too long, as when trials of 10 oscillations are typed with oscillations_per_trial 1 "
           "(fix timing.oscillations_per_trial)"},
    {1e3, "the length is 1000 times too long, as when a length in mm is written as m: fix length.unit"},
    {1e-3, "the length is 1000 times too short, as when a length in m is written as mm: fix length.unit"},
    // Trials in min written as s: T/60, g x 3600; ms written as s: 1000 T, g / 1e6.
    {3600.0, "the period is 60 times too short, as when trials in min are written as s: fix timing.unit"},
    {1.0 / 3600.0, "the period is 60 times too long, as when trials in s are written as min: fix timing.unit"},
    {1e6, "the period is 1000 times too short, as when trials in s are written as ms: fix timing.unit"},
    {1e-6, "the period is 1000 times too long, as when trials in ms are written as s: fix timing.unit"},
};
/// A slip fits when g's ratio is within this factor of the slip's: hand
/// timing and the corrections move g by a few percent, no slip by less than x4.
constexpr double kSlipTolerance = 1.15;

/// Below this a bob is lighter than any solid ball a pendulum swings (a
/// ping-pong ball is about 80 kg/m^3, cork 240, wood 500).
constexpr double kLightestBob = 50.0;     // (kg/m^3)
constexpr double kDensestBob = 22590.0;   // osmium (kg/m^3)
constexpr double kLightestSolid = 500.0;  // wood (kg/m^3)
/// Sea level to the highest laboratories (Pa).
constexpr double kAtmosphereLow = 5e4, kAtmosphereHigh = 1.1e5;

std::string signed_number(double x, int digits) { return (x >= 0.0 ? "+" : "") + format_number(x, digits); }

/// `bob_slip`: the bob's density is implausible, which explains a g far off
/// through buoyancy and added mass.
/// `settings` names what sets the period besides the timing, for the hint.
void judge_g(const Analysis& a, bool bob_slip, const std::string& settings, std::vector<std::string>& reasons) {
  const std::string bob = ": the bob's implausible density (bob.mass, below) drives buoyancy and added mass";
  const double expected = a.expected_g ? a.expected_g->value : kStandardGravity;
  const std::string against = a.expected_g ? "the site's expected " + format_number(expected, 6) + " m/s^2"
                                           : "standard gravity (" + format_number(kStandardGravity) +
                                                 " m/s^2; the scene gives no site)";
  const double ratio = a.g.value / expected;
  const std::string g = "g = " + format_number(a.g.value, 5) + " m/s^2";
  if (const auto slip = name_slip(ratio)) {
    reasons.push_back(g + " is " + format_number(ratio, 3) + " times " + against + ": " + *slip);
    return;
  }
  if (a.expected_g && a.z_score) {
    if (std::abs(*a.z_score) <= kSuspectSigmas) return;
    reasons.push_back(g + " is " + format_number(std::abs(*a.z_score), 3) +
                      " combined standard uncertainties from " + against + " (difference " +
                      signed_number(a.g.value - expected, 4) +
                      " m/s^2)" +
                      (bob_slip ? bob
                                : ": an uncertainty stated too small, or a systematic error (the length's "
                                  "reference point, pivot to the bob's centre; the amplitude; a miscounted "
                                  "oscillation)"));
    return;
  }
  if (std::abs(ratio - 1.0) <= kSuspectFraction) return;
  reasons.push_back(g + " is " + format_percent(std::abs(ratio - 1.0)) + " " +
                    (ratio > 1.0 ? "above " : "below ") + against + ", more than 5%" +
                    (bob_slip ? bob
                              : "; no unit or counting slip makes this ratio: check " + settings +
                                    ", the trials and timing.oscillations_per_trial"));
}

}  // namespace

std::optional<std::string> bob_density_slip(const Apparatus<double>& app) {
  if (!app.bob || !app.bob->mass) return std::nullopt;
  const double density = *app.bob->mass / app.bob->volume();
  const bool sphere = app.bob->shape == BobShape::sphere;
  const double air = app.air ? air_density(app.air->pressure, app.air->temperature, app.air->molar_mass) : 0.0;
  if (density >= kLightestBob && density > air) return std::nullopt;
  std::string why = "bob.mass: a density of " + format_number(density, 3) +
                    " kg/m^3 (the mass over the " + (sphere ? "sphere of bob.diameter), " : "bob's volume), ");
  why += density <= air ? "less than the air's " + format_number(air, 3) + " kg/m^3: the bob would float"
                        : "lighter than any solid ball a pendulum swings (a ping-pong ball: about 80 kg/m^3), "
                          "which makes buoyancy and added mass implausibly large";
  const double thousandfold = density * 1000.0;
  if (thousandfold >= kLightestSolid && thousandfold <= kDensestBob) {
    why += "; a mass in kg written as g, or a diameter in mm written as cm? Either gives " +
           std::to_string(std::lround(thousandfold)) + " kg/m^3 (steel: 7850): fix bob.mass.unit or bob." +
           (sphere ? "diameter" : "width, height or depth") + ".unit";
  } else {
    why += std::string("; check bob.mass, bob.") + (sphere ? "diameter" : "width, height, depth") + " and their units";
  }
  return why;
}

namespace {

void judge_air(const ParsedScene& scene, std::vector<std::string>& reasons) {
  const auto& air = scene.apparatus.air;
  if (!air) return;
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
  constexpr double kOneDegree = kPi / 180.0, kSmallAngleLab = 20.0 * kOneDegree;
  for (std::size_t k = 0; k < scene.observations.size(); ++k) {
    const ObservationSource& s = scene.sources[k];
    const double raw = s.amplitude_raw;
    if (s.amplitude_unit != "deg" || raw < kOneDegree || raw > kSmallAngleLab) continue;
    const double arc_mm = scene.observations[k].length * raw * kOneDegree * 1e3;
    reasons.push_back(s.path_of("amplitude") + ": " + format_number(raw, 4) + " deg moves the bob by " +
                      format_number(arc_mm, 2) + " mm, too little to start and watch by hand, while " +
                      format_number(raw, 4) + " rad is " + format_number(raw / kOneDegree, 3) +
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
void judge_decay_record(const ParsedScene& scene, std::vector<std::string>& reasons) {
  constexpr double kUnitFactor = 20.0;  // far beyond any release, short of 57.3
  constexpr double kPeakToPeakTolerance = 0.15;  // a hand's release against a reading of the first swing
  if (!scene.decay_data || scene.series || scene.decay_data->amplitudes.empty()) return;
  const double first = scene.decay_data->amplitudes.front(), swing = scene.observations.front().amplitude;
  const double ratio = first / swing, degree = kPi / 180.0;
  const double swing_sigma = scene.observation_uncertainties.front().amplitude;
  if (std::abs(ratio / 2.0 - 1.0) <= kPeakToPeakTolerance && first - swing > 3.0 * swing_sigma) {
    reasons.push_back("decay.data.amplitudes[0]: the record starts at " + format_number(first / degree, 3) + " deg, " +
                      format_number(ratio, 3) + " times the scene's amplitude " + format_number(swing / degree, 3) +
                      " deg: peak-to-peak swings written as amplitudes? An amplitude is from the rest position to "
                      "one side: halve decay.data.amplitudes");
    return;
  }
  if (ratio > 1.0 / kUnitFactor && ratio < kUnitFactor) return;
  const bool tiny = ratio < 1.0;
  reasons.push_back("decay.data.amplitude_unit: the record starts at " + format_number(first / degree, 3) +
                    " deg, " + (tiny ? "1/" : "") + format_number(tiny ? 1.0 / ratio : ratio, 3) +
                    " times the scene's amplitude " + format_number(swing / degree, 3) + " deg: " +
                    (tiny ? "radians labelled deg? fix decay.data.amplitude_unit (\"rad\")"
                          : "degrees labelled rad? fix decay.data.amplitude_unit (\"deg\")"));
}

}  // namespace

std::optional<std::string> name_slip(double ratio) {
  if (!(ratio > 0.0) || !std::isfinite(ratio)) return std::nullopt;
  for (const Slip& s : kSlips) {
    if (ratio < s.ratio * kSlipTolerance && ratio > s.ratio / kSlipTolerance) return std::string(s.text);
  }
  return std::nullopt;
}

Verdict judge(const ParsedScene& scene, const Analysis& analysis) {
  Verdict v;
  auto bob = bob_density_slip(scene.apparatus);
  const bool rigid = scene.model == PeriodModelKind::physical_pendulum;
  const std::string settings =
      !rigid ? "the length (pivot to the bob's centre)"
      : scene.body_from_parts ? "the pivots, and the body's parts (masses, dimensions, positions and their units)"
                              : "the pivots, the radius of gyration and the centre of mass";
  judge_g(analysis, bob.has_value(), settings, v.reasons);
  if (!analysis.g.uncertainty) {
    v.reasons.push_back("g has no uncertainty: the observations cannot separate the unknowns (the fit's covariance "
                        "is singular); add observations at other settings, or fit fewer unknowns");
  }
  if (bob) v.reasons.push_back(std::move(*bob));
  v.reasons.insert(v.reasons.end(), scene.suspicions.begin(), scene.suspicions.end());
  judge_air(scene, v.reasons);
  judge_amplitudes(scene, v.reasons);
  judge_decay_record(scene, v.reasons);
  if (!v.reasons.empty()) v.status = ResultStatus::suspect;
  return v;
}

}  // namespace pendulum
