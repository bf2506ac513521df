// An amplitude sweep's T0 and law test in the result (docs/series.md,
// "Amplitude sweeps"): beside a series' g, or alone where the length was
// not measured.
#include <cstdio>
#include <sstream>

#include "pendulum/amplitude_sweep.hpp"
#include "pendulum/dispersion.hpp"
#include "pendulum/numeric.hpp"
#include "pendulum/json/output.hpp"
#include "pendulum/parsed_scene.hpp"
#include "writer.hpp"
#include "../grouping.hpp"
#include "../text.hpp"

namespace pendulum {

using json = nlohmann::ordered_json;

namespace {

/// The chi2 of the exact law judged, where the uncertainties are stated.
std::optional<std::string> sweep_dispersion_finding(const AmplitudeSweep& s) {
  if (s.sigma_from_scatter || s.scale == 1.0) return std::nullopt;
  return "amplitude sweep: " + dispersion_finding(dispersion(s.chi2, s.dof), "the periods scatter about the exact law") +
         ": T0's uncertainty is scaled by that ratio";
}

}  // namespace

std::vector<std::string> sweep_reasons(const ParsedScene& scene, const AmplitudeSweep& s) {
  std::vector<std::string> reasons = scene.suspicions;
  if (auto r = sweep_dispersion_finding(s)) reasons.push_back(std::move(*r));
  if (sweep_law_refuted(s)) reasons.push_back(sweep_law_finding(s));
  return reasons;
}

namespace writer {

json amplitude_sweep_json(const AmplitudeSweep& s) {
  json t0 = measured(s.t0, "s");
  t0["degrees_of_freedom"] = s.t0_dof <= 1e6 ? json(s.t0_dof) : json(nullptr);
  json quadratic = nullptr;
  if (s.coefficient) {
    quadratic = {{"equation", "T = a (1 + c theta0^2)"},
                 {"c", measured(*s.coefficient, "1/rad^2")},
                 {"c_law", s.coefficient_law},
                 {"c_small_amplitude", 1.0 / 16.0},
                 {"probability", optional_number(s.coefficient_probability)},
                 {"agrees_with_law", !sweep_law_refuted(s)}};
  }
  json points = json::array();
  for (std::size_t i = 0; i < s.law.size(); ++i) {
    points.push_back({{"law_s", s.law[i]},
                      {"effective_uncertainty_s", s.effective_sigma[i]},
                      {"residual_sigma", s.residual[i]}});
  }
  return {{"law", "T = T0 2K(sin^2(theta0/2))/pi, exact (Nelson & Olsson Eq. 8)"},
          {"small_amplitude_period", t0},
          {"amplitudes_deg", {degrees(s.low), degrees(s.high)}},
          {"period_uncertainty", s.sigma_from_scatter ? "scatter_about_fit" : "stated"},
          {"scale", s.scale},
          {"chi2", s.chi2},
          {"dof", s.dof},
          {"probability", optional_number(s.probability)},
          {"quadratic", quadratic},
          {"points", points}};
}

void amplitude_sweep_lines(const AmplitudeSweep& s, bool with_chi2, std::ostream& os) {
  char line[400];
  std::snprintf(line, sizeof line,
                "Amplitude sweep, %.3g to %.3g deg: small-amplitude period T0 = %s s (exact law T = T0 2K/pi%s)\n",
                degrees(s.low), degrees(s.high), rounded(s.t0.value, s.t0.uncertainty).c_str(),
                s.sigma_from_scatter ? ", the periods' sigma from its scatter" : "");
  os << line;
  if (s.probability && with_chi2) {
    std::snprintf(line, sizeof line, "  chi2/dof       = %.4g (probability of a larger chi2: %.3g)%s\n",
                  s.chi2 / s.dof, *s.probability, s.scale > 1.0 ? ", T0's uncertainty scaled by S" : "");
    os << line;
  }
  if (!s.coefficient) {
    os << "  law test       = none: fewer than three amplitudes\n";
    return;
  }
  std::snprintf(line, sizeof line,
                "  law test       = T = a (1 + c theta0^2): c = %.4g %s 1/rad^2, the exact law's %.4g at these amplitudes "
                "(1/16 at small ones): %s (probability %.3g)\n",
                s.coefficient->value, plus_minus(s.coefficient->uncertainty, "%.2g").c_str(), s.coefficient_law,
                sweep_law_refuted(s) ? "refuted" : "agrees", s.coefficient_probability.value_or(1.0));
  os << line;
}

}  // namespace writer

std::string sweep_result_json(const ParsedScene& scene, const AmplitudeSweep& s, const std::string& input) {
  const std::vector<std::string> reasons = sweep_reasons(scene, s);
  json observations = json::array();
  for (std::size_t k = 0; k < scene.observations.size(); ++k) {
    const auto& o = scene.observations[k];
    const auto& u = scene.observation_uncertainties[k];
    observations.push_back({{"index", k},
                            {"amplitude", {{"value", degrees(o.amplitude)}, {"uncertainty", degrees(u.amplitude)}, {"unit", "deg"}}},
                            {"period", {{"value", o.period}, {"uncertainty", u.period}, {"unit", "s"}}},
                            {"oscillations_per_trial", o.oscillations_per_trial}});
  }
  json out = {{"schema", "pendulum-g/result/1"},
              {"input", input},
              {"title", scene.title},
              {"status", reasons.empty() ? "ok" : "suspect"},
              {"status_reasons", reasons},
              {"kind", "amplitude_sweep"},
              {"g", nullptr},
              {"g_note", std::string("the length was not measured (\"length\": \"") + kLengthNotMeasured +
                             "\"): give it for g"},
              {"amplitude_sweep", writer::amplitude_sweep_json(s)},
              {"observations", observations},
              {"assumptions", scene.assumptions},
              {"warnings", scene.warnings}};
  return json_text(out, 2) + "\n";
}

std::string sweep_result_table(const ParsedScene& scene, const AmplitudeSweep& s) {
  std::ostringstream os;
  char line[200];
  if (!scene.title.empty()) os << one_line(scene.title, kShownTitleBytes, true) << "\n\n";
  std::snprintf(line, sizeof line, "%5s %12s %12s %10s %12s %10s\n", "obs", "theta0 (deg)", "T meas (s)", "+- (s)",
                "T law (s)", "resid (sd)");
  os << line;
  for (std::size_t k = 0; k < scene.observations.size(); ++k) {
    std::snprintf(line, sizeof line, "%5zu %12.2f %12.6f %10.6f %12.6f %+10.2f\n", k,
                  degrees(scene.observations[k].amplitude), scene.observations[k].period, s.effective_sigma[k],
                  s.law[k], s.residual[k]);
    os << line;
  }
  os << "\n";
  writer::amplitude_sweep_lines(s, true, os);
  os << "g                   = none: the length was not measured; give \"length\" for g\n";
  const std::vector<std::string> reasons = sweep_reasons(scene, s);
  os << "status              = " << (reasons.empty() ? "ok" : "suspect") << "\n";
  for (const auto& r : reasons) os << "  " << r << "\n";
  for (const auto& a : collapse_repeats(scene.assumptions)) os << "assumption: " << a << "\n";
  for (const auto& w : collapse_repeats(scene.warnings)) os << "warning: " << w << "\n";
  return os.str();
}

}  // namespace pendulum
