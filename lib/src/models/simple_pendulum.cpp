/// \file models/simple_pendulum.cpp
/// \brief The ball model's start and its results beside the fit: the
/// textbook line (docs/core.md, the period model).
#include "pendulum/models/simple_pendulum.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include <boost/math/special_functions/gamma.hpp>

#include "pendulum/analysis.hpp"
#include "pendulum/input_error.hpp"
#include "../fit_state.hpp"
#include "../json/writer.hpp"
#include "../plausibility.hpp"
#include "../text.hpp"
#include "pendulum/straight_line.hpp"

namespace pendulum {

namespace {

/// T^2 against L as a straight line, no corrections (through the origin
/// unless the length offset is fitted), weighted by the periods' and the
/// lengths' uncertainties.
StraightLine textbook_line(const ParsedScene& scene, const std::array<bool, SimplePendulum::kParameters>& fitted) {
  const std::size_t n = scene.observations.size();
  std::vector<double> x(n), y(n), sx(n), sy(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto& o = scene.observations[k];
    const auto& u = scene.observation_uncertainties[k];
    x[k] = o.length;
    y[k] = o.period * o.period;
    sx[k] = u.length;
    sy[k] = 2.0 * o.period * u.period;
  }
  const bool intercept = fitted[SimplePendulum::length_offset];
  StraightLine line = fit_straight_line(x, y, sx, sy, intercept);
  // Periods whose uncertainty is their scatter (ParsedScene): the line's own
  // scatter, chi2/(n - p) where above the floor, scales its variances.
  const double dof = static_cast<double>(n) - (intercept ? 2.0 : 1.0);
  if (scene.period_uncertainty_from_scatter && dof > 0.0) {
    double chi2 = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double r = y[k] - line.slope * x[k] - line.intercept;
      chi2 += r * r / (sy[k] * sy[k] + line.slope * line.slope * sx[k] * sx[k]);
    }
    const double s2 = std::max(chi2 / dof, 1.0);
    line.var_slope *= s2, line.var_intercept *= s2, line.cov *= s2;
  }
  return line;
}

/// The textbook line on the fit's scene with its length offset, none where
/// the lengths determine none (all equal, with the offset fitted); warns
/// where they are too close together to separate g from the offset.
std::optional<TextbookFit> textbook_fit(const FitState<SimplePendulum::kParameters>& fit,
                                        std::vector<std::string>& warnings) {
  // Through one length, T^2 against L is no line: an amplitude sweep's g is the fit's.
  const auto& obs = fit.scene.observations;
  if (obs.size() > 1 && std::all_of(obs.begin(), obs.end(), [&](const auto& o) { return o.length == obs.front().length; })) {
    return std::nullopt;
  }
  const StraightLine line = textbook_line(fit.scene, fit.fitted);
  const double g = gravity_for_slope(line.slope), sigma = g * std::sqrt(line.var_slope) / line.slope;
  if (!(g > 0.0 && std::isfinite(g) && std::isfinite(sigma))) return std::nullopt;
  TextbookFit t{{g, sigma}, {}};
  if (!fit.fitted[SimplePendulum::length_offset]) return t;
  const double a = line.slope, b = line.intercept;
  const double var = line.var_intercept / (a * a) + b * b * line.var_slope / (a * a * a * a) -
                     2.0 * b * line.cov / (a * a * a);
  t.length_offset = Estimate{b / a, std::sqrt(std::max(var, 0.0))};
  if (fit.singular) return t;
  // With the offset unknown, g's uncertainty grows by 1/sqrt(1 - rho^2).
  const double rho = fit.inverse(0, 1) / std::sqrt(fit.inverse(0, 0) * fit.inverse(1, 1));
  const double inflation = 1.0 / std::sqrt(std::max(1.0 - rho * rho, 0.0));
  if (inflation > 10.0) {
    const auto [lo, hi] = std::minmax_element(fit.scene.observations.begin(), fit.scene.observations.end(),
                                              [](const auto& x, const auto& y) { return x.length < y.length; });
    warnings.push_back("observations: the lengths span only " + format_number(lo->length, 5) + " m to " +
                       format_number(hi->length, 5) + " m, too close together to separate g from "
                       "length_offset (correlation " + format_number(rho, 6) + "), which makes g's uncertainty " +
                       format_number(inflation, 3) + " times what a known offset would give; swing at "
                       "lengths further apart");
  }
  return t;
}

}  // namespace

std::array<double, SimplePendulum::kParameters> SimplePendulum::start(const ParsedScene& scene,
                                                                      const std::array<bool, kParameters>&) {
  // From the textbook line through the origin, the offset at 0: close
  // enough at any amplitude for Levenberg-Marquardt, and finite however
  // close the lengths (the line with an intercept is not).
  std::array<double, kParameters> p = kDefaults;
  const std::size_t n = scene.observations.size();
  std::vector<double> x(n), y(n), zero(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    x[k] = scene.observations[k].length;
    y[k] = scene.observations[k].period * scene.observations[k].period;
  }
  p[g] = gravity_for_slope(fit_straight_line(x, y, zero, zero, false).slope);
  return p;
}

void SimplePendulum::report(const FitState<kParameters>& fit, Analysis& out) {
  const std::size_t k = fit.scene.observations.size();
  if (const auto textbook = textbook_fit(fit, out.warnings)) out.fit.set_results<SimplePendulum>(*textbook);
  // Too large a chi2 makes the result suspect (status.cpp); too small a one is only said.
  if (k > 1 && out.fit.probability && !fit.scene.period_uncertainty_from_scatter) {
    const double lower = boost::math::gamma_p(out.fit.dof / 2.0, out.fit.chi2 / 2.0);
    if (lower < 1e-3) {
      out.warnings.push_back("fit: chi2 = " + format_number(out.fit.chi2, 4) + " for " +
                              std::to_string(out.fit.dof) + " degrees of freedom (chi2/dof = " +
                              format_number(out.fit.chi2 / out.fit.dof, 4) + "); so small a chi2 has probability " +
                              format_number(lower, 2) + ": the periods' uncertainties are too large");
    }
  }
}

std::optional<Expectation> SimplePendulum::expectation(const ParsedScene& scene, const Observation<double>& o) {
  const double ideal = ideal_period(o.length, kStandardGravity);  // Eq. (3)
  return Expectation{ideal * (1.0 + reduce(scene.apparatus, o).total_ratio),
                     ideal * (1.0 + finite_amplitude_agm(o.amplitude))};
}

void SimplePendulum::check_rows(const ParsedScene& scene, const Observation<double>& o) {
  check_first_order(scene.apparatus, o);
}

std::vector<std::string> SimplePendulum::skipped_part_warnings(const ParsedScene& scene, double negligible_fraction) {
  std::vector<std::string> warnings = warn_about_skipped_ball_parts(scene, negligible_fraction);
  if (auto w = warn_about_unmodelled_added_mass(scene, negligible_fraction)) warnings.push_back(std::move(*w));
  if (auto w = warn_about_mode_resonance(scene, negligible_fraction)) warnings.push_back(std::move(*w));
  return warnings;
}

void SimplePendulum::put_fit_results(const Results* textbook, JsonOut& fit) {
  nlohmann::ordered_json line = nullptr;
  if (textbook) {
    line = {{"equation", textbook->length_offset ? "T^2 = (4 pi^2 / g) (L + length_offset), no corrections"
                                                 : "T^2 = (4 pi^2 / g) L, no corrections"},
            {"g", writer::measured(textbook->g, "m/s^2")}};
    if (textbook->length_offset) line["length_offset"] = writer::measured(*textbook->length_offset, "m");
  }
  fit.json["textbook"] = line;
}

void SimplePendulum::put_observation_results(const Results* textbook, JsonOut& observation) {
  if (textbook) observation.json["g_uncorrected"] = writer::measured(textbook->g, "m/s^2");
}

void SimplePendulum::fit_results_lines(const Results* textbook, std::ostream& os) {
  if (!textbook) {
    os << "Textbook line T^2 = (4 pi^2/g)(L + offset): none, the lengths are all equal\n";
    return;
  }
  char line[160];
  const TextbookFit& t = *textbook;
  std::snprintf(line, sizeof line, "Textbook line T^2 = (4 pi^2/g)%s, no corrections: g = %.5f %s m/s^2",
                t.length_offset ? "(L + offset)" : " L", t.g.value,
                writer::plus_minus(t.g.uncertainty, "%.5f").c_str());
  os << line;
  if (t.length_offset) {
    std::snprintf(line, sizeof line, ", offset = %.5f %s m", t.length_offset->value,
                  writer::plus_minus(t.length_offset->uncertainty, "%.5f").c_str());
    os << line;
  }
  os << "\n";
}

void SimplePendulum::observation_results_lines(const Results* textbook, std::ostream& os) {
  if (textbook) os << "g (uncorrected)     = " << writer::rounded(textbook->g.value, textbook->g.uncertainty) << " m/s^2\n";
}

// The ball model's parts against its lengths (period_model.hpp, check_scene).
void SimplePendulum::check_scene(const ParsedScene& out) {
  const Apparatus<double>& v = out.apparatus;
  for (std::size_t k = 0; k < out.observations.size(); ++k) {
    const double length = out.observations[k].length;
    const std::string at = out.sources[k].path_of("length") + ".value";
    if (!v.bob) continue;
    const double radius = v.bob->knot_to_center();
    if (radius >= length) {
      throw InputError(at, "got " + format_number(length) + " m; expected more than the bob " +
                               (v.bob->shape == BobShape::sphere ? "radius " : "half height ") +
                               format_number(radius) + " m");
    }
    if (v.ring && v.ring->pivot_distance + v.ring->outer_radius >= length - radius) {
      throw InputError("ring.outer_radius.value",
                       "the ring reaches " + format_number(v.ring->pivot_distance + v.ring->outer_radius) +
                           " m below the pivot; expected it to end above the bob, which starts at " +
                           format_number(length - radius) + " m");
    }
    if (v.cap && v.cap->center_distance >= length) {
      throw InputError("cap.center_distance.value",
                       "got " + format_number(v.cap->center_distance) + " m; expected less than the length (" +
                           format_number(length) + " m): the cap hangs between the pivot and the bob");
    }
  }
}

}  // namespace pendulum
