#include "plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "pendulum/air.hpp"
#include "pendulum/mass.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/models/registry.hpp"
#include "pendulum/reduction.hpp"
#include "pendulum/slips.hpp"
#include "pendulum/units.hpp"
#include "text.hpp"

namespace pendulum {

namespace {

/// A measured period this far from the expected one draws a warning...
constexpr double kPeriodWarning = 0.05;
/// ...this factor off, an error: no laboratory's g is 100 times off.
constexpr double kPeriodFactor = 10.0;
/// The other reading of an amplitude's unit fits when it brings the period
/// this close to the expected one.
constexpr double kPeriodFit = 0.01;
constexpr double kSmallAngleLab = 20.0;  // (deg)

/// What the scene's model expects of observation o (Expectation).
std::optional<Expectation> expectation(const ParsedScene& scene, const Observation<double>& o) {
  return visit_period_model(scene.model, [&](auto model) { return decltype(model)::expectation(scene, o); });
}

/// Where the period came from a recording, the recording as a likely cause:
/// its file, family and the columns analysed (issue 19: a counter read as
/// time, the frame interval taken for a period); empty otherwise.
std::string recording_cause(const ParsedScene& scene, const ObservationSource& source) {
  if (!source.recording || *source.recording >= scene.recordings.size()) return {};
  const RecordingSummary& r = scene.recordings[*source.recording].summary;
  std::string columns;
  for (const RecordingColumn& c : r.columns) {
    if (c.role == "unused") continue;
    columns += (columns.empty() ? "" : ", ") + std::to_string(c.index) + (c.name.empty() ? "" : " \"" + c.name + "\"") +
               " as " + c.role;
  }
  return "; or the recording " + r.file + (r.set.empty() ? "" : "/" + r.set) + " (read as " +
         recording_format_name(r.format) + (columns.empty() ? "" : ", columns " + columns) +
         ") timed something other than the swing: check its columns and run pendulum-g import on it";
}

/// "5.3% longer"
std::string off_by(double ratio) {
  return format_percent(std::abs(ratio - 1.0)) + " " + (ratio > 1.0 ? "longer" : "shorter");
}

/// `expected_or_none`: the expectation of observation k.
void check_observation(ParsedScene& scene, std::size_t k, const std::optional<Expectation>& expected_or_none) {
  const Apparatus<double>& app = scene.apparatus;
  const Observation<double>& o = scene.observations[k];
  const ObservationSource& source = scene.sources[k];
  const std::string& at = source.path;
  if (!expected_or_none) return;  // a body whose k or centre the fit finds
  const double expected = expected_or_none->period;
  const double ratio = o.period / expected;
  const std::string standard = "standard gravity (" + format_number(kStandardGravity) + " m/s^2)";
  const std::string at_g = "this pendulum has at " + standard;

  // Degrees and radians mixed up: the period fits the other reading.
  const std::string& unit = source.amplitude_unit;
  if (!(std::abs(ratio - 1.0) <= kPeriodWarning) && (unit == "deg" || unit == "rad")) {
    const std::string other = unit == "deg" ? "rad" : "deg";
    const double raw = source.amplitude_raw;
    Observation<double> alt = o;
    alt.amplitude = raw * find_unit(other, Dimension::angle)->factor;
    const double alt_ratio = alt.amplitude < kPi ? o.period / expectation(scene, alt)->period : 0.0;
    if (std::abs(alt_ratio - 1.0) <= kPeriodFit) {
      throw InputError(source.path_of("amplitude.unit"), "got \"" + unit + "\": at " + format_number(raw) + " " + unit +
                                                  " the measured period is " + off_by(ratio) + " than the one " +
                                                  at_g + "; expected \"" + other + "\": at " + format_number(raw) +
                                                  " " + other + " it is " + off_by(alt_ratio));
    }
  }

  // Against the model's slip check (a ball's finite amplitude alone), so that
  // a wrong unit is named as such before it drives a correction out of its range.
  const double swing = expected_or_none->slip_check;
  // A frequency (1/s) typed where the trial times belong: its inverse is the
  // pendulum's period. Not where the trial's time and that inverse lie
  // within twice the warning's band of each other (N T^2 near 1 s^2, N
  // oscillations a trial): a frequency typed is then no further off than a
  // reading off by that band (a class's 0.958 s for 1.02 s at 25.9 cm was
  // named a frequency).
  const double trial = o.period * o.oscillations_per_trial;  // (s) the mean trial, as typed
  if (std::abs(1.0 / (trial * expected) - 1.0) <= kPeriodWarning && std::abs(ratio - 1.0) > kPeriodWarning &&
      std::abs(o.oscillations_per_trial * expected * expected - 1.0) > 2.0 * kPeriodWarning) {
    const std::string why = "the mean trial " + format_number(trial, 4) + " s is 1/" +
                            format_number(1.0 / trial, 4) + ", and " + format_number(1.0 / trial, 4) +
                            " s is the period this pendulum has at " + standard +
                            ": " + kFrequencyTyped + " Give the time of " +
                            std::to_string(o.oscillations_per_trial) +
                            (o.oscillations_per_trial == 1 ? " oscillation" : " oscillations") +
                            " in s in each trial (the period is 1/frequency)";
    if (!(o.period / swing > 1.0 / kPeriodFactor && o.period / swing < kPeriodFactor)) throw InputError(at + "timing.trials", why);
    scene.suspicions.push_back(at + "timing.trials: " + why);
  }
  if (!(o.period / swing > 1.0 / kPeriodFactor && o.period / swing < kPeriodFactor)) {
    // g = 4 pi^2 l / T^2 would be (swing / period)^2 times standard gravity.
    const auto slip = name_slip((swing / o.period) * (swing / o.period));
    throw InputError(at + "timing.trials",
                     "got a period of " + format_number(o.period, 5) + " s, but this pendulum swings in " +
                         format_number(swing, 5) + " s at " + standard + "; expected them within a factor of " +
                         format_number(kPeriodFactor) +
                         (slip ? ": " + *slip : " (is a unit or oscillations_per_trial wrong?)") +
                         recording_cause(scene, source));
  }

  visit_period_model(scene.model, [&](auto model) { decltype(model)::check_rows(scene, o); });

  if (std::abs(ratio - 1.0) > kPeriodWarning) {
    scene.warnings.push_back(at + "timing.trials: the measured period " + format_number(o.period, 5) + " s is " +
                             off_by(ratio) + " than the " + format_number(expected, 5) + " s " + at_g +
                             (bob_density_slip(app) ? std::string("; check bob.mass and its unit: the bob's density is implausible")
                                                    : "; check the " + std::string(setting_key(o.setting)) +
                                                          "'s unit and oscillations_per_trial" +
                                                          (scene.body_from_parts ? ", and the body's parts" : "")) +
                             recording_cause(scene, source));
  }
  const double deg = degrees(o.amplitude);
  // A series may sweep the amplitude on purpose.
  if (deg > kSmallAngleLab && !scene.series) {
    // As given, to 15 digits: 4 made 179.99999 deg "180 deg".
    scene.warnings.push_back(at + "amplitude.value: " + format_number(deg, 15) +
                             " deg is over the 20 deg of a small-angle lab; the finite-amplitude "
                             "correction is exact at any amplitude, but check the amplitude and its unit");
  }
}

/// For a body on a flexible string at its own amplitude: the slow mode's
/// psi0^4 coefficient beyond a simple pendulum's, kappa4 - (11/3072)(4
/// sqrt kappa2)^4 (mass.hpp, slow_mode_amplitude_series), its term in
/// DeltaT/T, and the fast mode's frequency over the slow one's, from
/// lambda = omega^2/g solving s k^2 lambda^2 - (d l + k^2) lambda + d = 0.
struct SlowModeRest {
  double coefficient, term, frequency_ratio;
};

std::optional<SlowModeRest> slow_mode_rest(const Apparatus<double>& app, const Observation<double>& o) {
  if (!app.bob || app.bob->suspension != Suspension::flexible || o.amplitude_of != AngleOf::body) return std::nullopt;
  const double k2 = app.bob->gyration_squared(), d = app.bob->knot_to_center(), l = o.length;
  const auto [kappa2, kappa4] = slow_mode_amplitude_series(k2, d, l);
  const double ratio2 = 16.0 * kappa2, coefficient = kappa4 - 11.0 / 3072.0 * ratio2 * ratio2;
  const double psi2 = o.amplitude * o.amplitude;
  const double s = l - d, b = d * l + k2, root = std::sqrt(b * b - 4.0 * s * d * k2);
  return SlowModeRest{coefficient, coefficient * psi2 * psi2, std::sqrt((b + root) * (b + root) / (4.0 * s * d * k2))};
}

/// The largest |kappa4 - (11/3072)(4 sqrt kappa2)^4| the nonlinear check
/// covered (the phone on 0.1-1 m, tests/tools/phone_nonlinear_check.py):
/// 6.4e-3 at 0.1 m; twice that is beyond it, near the modes' 3:1 resonance.
constexpr double kCheckedCoefficient = 1.3e-2;

}  // namespace

void check_first_order(const Apparatus<double>& app, const Observation<double>& o) {
  // At the modes' 3:1 resonance kappa4 has a pole: a term of 1e-2 of T, 20
  // times the largest the nonlinear check covered (4.8e-4: the phone on 0.1 m
  // at 30 deg), is no series' any more.
  constexpr double kSeriesLimit = 1e-2;
  if (const auto rest = slow_mode_rest(app, o);
      rest && !(std::fabs(rest->coefficient) <= kCheckedCoefficient || std::fabs(rest->term) < kSeriesLimit)) {
    throw InputError("amplitude", "got a body on a string whose fast mode runs at " +
                                      format_number(rest->frequency_ratio, 5) + " times its slow one's frequency, "
                                      "near 3:1, where the slow mode's psi0^4 term is " + format_number(rest->term, 2) + " of T; expected it below " +
                                      format_number(kSeriesLimit) + " (docs/phone.md): change the string's length "
                                      "by a few cm, or swing smaller");
  }
  const Reduction<double> r = reduce(app, o);
  for (int i = 0; i < kCorrectionCount; ++i) {
    const std::optional<double>& x = r.terms[i].ratio;
    const CorrectionInfo& info = kCorrections[i];
    if (!x || std::abs(*x) < info.max_ratio) continue;
    // A bob light as a balloon is most often a unit slip: say which.
    const auto bob = bob_density_slip(app);
    throw InputError(info.part, "got DeltaT/T0 = " + format_number(*x) + " for \"" + info.title + "\" (" +
                                    info.equation + "); expected |DeltaT/T0| below " +
                                    format_number(info.max_ratio) + ", where its first-order formula holds" +
                                    (bob ? "; " + *bob : ""));
  }
}

void check_first_order(const ParsedScene& scene) {
  for (const auto& o : scene.observations) check_first_order(scene.apparatus, o);
}

namespace {

/// Buoyancy and added mass in room air (20 degC, 101.325 kPa) of a 25.4 mm
/// ball of `density` (kg/m^3) on observation k (s): they hardly depend on
/// the diameter, on the density as rho_air / rho_bob (Eqs. 54, 61, 62).
double air_share(const ParsedScene& scene, std::size_t k, double density) {
  Apparatus<double> typical = scene.apparatus;
  const double temperature = 293.15, diameter = 0.0254;
  typical.air = Air<double>{101325.0, temperature, kDryAirMolarMass, air_viscosity(temperature)};
  typical.bob = Bob<double>{diameter, density * sphere_volume(diameter / 2.0)};
  const Reduction<double> r = reduce(typical, scene.observations[k]);
  return (*r.terms[static_cast<int>(CorrectionId::buoyancy)].ratio +
          *r.terms[static_cast<int>(CorrectionId::added_mass)].ratio) * r.period_ideal;
}

/// A scene with neither bob nor air: the air's share for a steel ball and
/// for a wooden one (700 kg/m^3), when the wooden one's is not negligible.
std::optional<std::string> warn_about_unknown_ball(const ParsedScene& scene, double negligible_fraction) {
  double steel = 0.0, wood = 0.0, threshold = 0.0;
  for (std::size_t k = 0; k < scene.observations.size(); ++k) {
    const double w = air_share(scene, k, 700.0), t = negligible_fraction * scene.observation_uncertainties[k].period;
    if (k == 0 || std::abs(w) / t > std::abs(wood) / threshold) wood = w, steel = air_share(scene, k, 7850.0), threshold = t;
  }
  if (!(std::abs(wood) > threshold)) return std::nullopt;
  return "air and bob: not given, so buoyancy and added mass are skipped; in room air (20 degC, 101.325 kPa) they "
         "would change the period by " + format_number(steel * 1e6, 3) + " us for a steel ball, " +
         format_number(wood * 1e6, 3) + " us for a wooden one (700 kg/m^3), against the " +
         format_number(threshold * 1e6, 3) + " us below which a correction is negligible; give the bob's diameter "
         "and mass and the air's pressure and temperature, or \"air\": \"vacuum\"";
}

}  // namespace

std::vector<std::string> warn_about_skipped_ball_parts(const ParsedScene& scene, double negligible_fraction) {
  const Apparatus<double>& app = scene.apparatus;
  std::vector<std::string> warnings;
  if (!app.bob) {
    if (!app.air && !app.vacuum) {
      if (auto w = warn_about_unknown_ball(scene, negligible_fraction)) warnings.push_back(std::move(*w));
    }
    return warnings;
  }
  const bool no_air = !app.air && !app.vacuum;
  const bool no_mass = app.air && !app.bob->mass;
  if (!no_air && !no_mass) return warnings;
  // Room air: ISO 554's 20 degC and the standard atmosphere's 101.325 kPa,
  // dry; steel at 7850 kg/m^3 (a typical carbon steel's density).
  Apparatus<double> typical = app;
  if (no_air) {
    const double temperature = 293.15;
    typical.air = Air<double>{101325.0, temperature, kDryAirMolarMass, air_viscosity(temperature)};
  }
  if (!typical.bob->mass) typical.bob->mass = 7850.0 * typical.bob->volume();
  double worst = 0.0, worst_delta = 0.0, worst_threshold = 0.0;
  for (std::size_t k = 0; k < scene.observations.size(); ++k) {
    const Observation<double>& o = scene.observations[k];
    const Reduction<double> r = reduce(typical, o);
    const double delta = (*r.terms[static_cast<int>(CorrectionId::buoyancy)].ratio +
                          *r.terms[static_cast<int>(CorrectionId::added_mass)].ratio) * r.period_ideal;
    const double threshold = negligible_fraction * scene.observation_uncertainties[k].period;
    const double size = threshold > 0.0 ? std::abs(delta) / threshold : HUGE_VAL;
    if (size > worst) worst = size, worst_delta = delta, worst_threshold = threshold;
  }
  if (worst < 1.0) return warnings;
  const std::string change = format_number(worst_delta * 1e6, 3) + " us, over the " +
                             format_number(worst_threshold * 1e6, 3) + " us below which a correction is negligible";
  if (no_air) {
    warnings.push_back("air: not given, so buoyancy and added mass are skipped; room air (20 degC, 101.325 kPa) "
                       "would change the period by " + change + "; give the air's pressure and temperature, or "
                       "\"vacuum\"");
  } else {
    warnings.push_back("bob.mass: not given, so buoyancy and added mass are skipped; a steel bob (7850 kg/m^3) of "
                       "this diameter would change the period by " + change + "; give the bob's mass");
  }
  return warnings;
}

namespace {

/// The added mass (kg) of a box or upright cylinder swinging broadside in air
/// of density rho (kg/m^3): rho pi (a/2)^2 b, the potential flow's about an
/// elliptic cylinder moving along an axis, pi rho q^2 per unit length with q
/// the semi-axis across the motion whatever the other (Lamb, Hydrodynamics,
/// Ch. IV), for a section a wide across the swing and b long: a box's depth
/// and height (a, b the shorter and the longer), a cylinder's diameter and
/// height. An estimate: a rectangle's section carries somewhat more than its
/// inscribed ellipse's, finite ends less, and the boundary layer adds to it.
double unmodelled_added_mass(const Bob<double>& bob, double rho) {
  const double across = bob.shape == BobShape::box ? bob.depth : bob.diameter;
  const double a = std::min(across, bob.height), b = std::max(across, bob.height);
  return rho * kPi * a * a / 4.0 * b;
}

}  // namespace

std::optional<std::string> warn_about_unmodelled_added_mass(const ParsedScene& scene, double negligible_fraction) {
  const Apparatus<double>& app = scene.apparatus;
  if (!app.bob || app.bob->shape == BobShape::sphere || !app.air || !app.bob->mass) return std::nullopt;
  const double rho = air_density(app.air->pressure, app.air->temperature, app.air->molar_mass);
  const double added = unmodelled_added_mass(*app.bob, rho);
  const double ratio = added / (2.0 * *app.bob->mass);  // DeltaT/T, a point bob's
  double worst = 0.0, worst_delta = 0.0, worst_threshold = 0.0;
  for (std::size_t k = 0; k < scene.observations.size(); ++k) {
    const double delta = ratio * scene.observations[k].period;
    const double threshold = negligible_fraction * scene.observation_uncertainties[k].period;
    const double size = threshold > 0.0 ? delta / threshold : HUGE_VAL;
    if (size > worst) worst = size, worst_delta = delta, worst_threshold = threshold;
  }
  if (worst < 1.0) return std::nullopt;
  const Bob<double>& bob = *app.bob;
  std::string text = std::string("bob: a ") + (bob.shape == BobShape::box ? "box" : "cylinder") +
                     "'s added mass in air is not modelled (Eqs. (54)-(62) are a sphere's); estimated as the "
                     "potential flow's about its section across the swing, " +
                     format_number(added * 1e3, 2) + " g, it would lengthen the period by " +
                     format_number(ratio, 2) + " of itself (" + format_number(worst_delta * 1e6, 3) + " us, over the " +
                     format_number(worst_threshold * 1e6, 3) + " us below which a correction is negligible), and g "
                     "comes out low by about " + format_number(2.0 * ratio, 2) + " of itself";
  if (bob.shape == BobShape::box && bob.depth > bob.width) {
    Bob<double> turned = bob;
    std::swap(turned.width, turned.depth);
    text += "; swung a quarter turn about the vertical (bob.width " + format_number(bob.depth * 100.0, 3) +
            " cm along the swing, its face in the swing's plane) it would carry " +
            format_number(added / unmodelled_added_mass(turned, rho), 2) + " times less";
  }
  return text;
}

std::optional<std::string> warn_about_mode_resonance(const ParsedScene& scene, double negligible_fraction) {
  for (std::size_t k = 0; k < scene.observations.size(); ++k) {
    const auto rest = slow_mode_rest(scene.apparatus, scene.observations[k]);
    const double threshold =
        negligible_fraction * scene.observation_uncertainties[k].period / scene.observations[k].period;
    if (!rest || !(std::fabs(rest->coefficient) > kCheckedCoefficient && std::fabs(rest->term) > threshold)) continue;
    return scene.sources[k].path_of("amplitude") + ": the bob's two modes on the string are near 3:1 (the fast " +
           "one at " + format_number(rest->frequency_ratio, 4) + " times the slow one's frequency), where the " +
           "slow mode's psi0^4 coefficient grows without bound: here " + format_number(rest->coefficient, 2) +
           " beyond a simple pendulum's, where the check against the full equations of motion went to 6.4e-3 " +
           "(docs/phone.md); its term in the finite-amplitude row, " + format_number(rest->term, 2) +
           " of T, is not to be trusted: change the string's length by a few cm, or swing smaller";
  }
  return std::nullopt;
}

/// A slip's text (status.cpp) with the keys it names as this observation's paths.
std::string in_observation(std::string text, const ObservationSource& source) {
  for (const auto& [key, path] : {std::pair<std::string, std::string>{"length.unit", source.path_of("length.unit")},
                                  {"timing.", source.path_of("timing.")}}) {
    for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + path.size())) {
      text.replace(at, key.size(), path);
    }
  }
  return text;
}

/// In a series, each observation whose period alone gives a g that a slip
/// explains, unless every observation gives the same: that slip shows in
/// the fitted g itself (status.cpp), while one slipped observation only
/// drags the fit somewhere no slip names. `expected`: each observation's
/// expectation.
void name_observation_slips(ParsedScene& scene, const std::vector<std::optional<Expectation>>& expected) {
  const std::size_t n = scene.observations.size();
  if (n < 2) return;
  std::vector<std::optional<std::string>> slips(n);
  std::vector<double> ratios(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (!expected[k]) return;  // a body whose k or centre the fit finds
    const double ratio = expected[k]->period / scene.observations[k].period;
    ratios[k] = ratio * ratio;  // g = 4 pi^2 l / T^2
    slips[k] = name_slip(ratios[k]);
  }
  if (std::all_of(slips.begin(), slips.end(), [&](const auto& s) { return s == slips.front(); })) return;
  for (std::size_t k = 0; k < n; ++k) {
    if (!slips[k]) continue;
    const ObservationSource& source = scene.sources[k];
    scene.suspicions.push_back(source.path + "timing: this observation alone gives g = " +
                               format_number(ratios[k], 3) + " times standard gravity, unlike the others: " +
                               in_observation(*slips[k], source));
  }
}

void check_plausibility(ParsedScene& scene) {
  std::vector<std::optional<Expectation>> expected;
  for (const auto& o : scene.observations) expected.push_back(expectation(scene, o));
  for (std::size_t k = 0; k < scene.observations.size(); ++k) check_observation(scene, k, expected[k]);
  name_observation_slips(scene, expected);
}

}  // namespace pendulum
