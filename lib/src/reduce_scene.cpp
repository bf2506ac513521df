#include "pendulum/reduce_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>

#include "pendulum/monte_carlo.hpp"
#include "pendulum/status.hpp"
#include "text.hpp"

namespace pendulum {

namespace {

/// S1 8: GUM's interval is not validated by the draws': which input bends
/// g, and the interval to quote instead.
std::string monte_carlo_finding(const MonteCarloResult& mc, const Analysis& a) {
  const double U = a.g_expanded->expanded;
  // To the tolerance's last decimal.
  const int decimals = std::max(0, 1 - static_cast<int>(std::floor(std::log10(mc.tolerance))));
  const auto fixed = [&](double x) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, x);
    return std::string(text);
  };
  const std::string why = mc.bending_input.empty()
                              ? "no single input's removal restores the agreement"
                              : "it comes from " + mc.bending_name + " (" + mc.bending_distribution + "): held at " +
                                    (mc.bending_input == mc.bending_name ? "its value" : "their values") + ", the two agree";
  return "uncertainty: GUM's 95 % interval [" + fixed(a.g.value - U) + ", " + fixed(a.g.value + U) +
         "] m/s^2 and the Monte Carlo's shortest one [" + fixed(mc.low) + ", " + fixed(mc.high) +
         "] differ by more than the numerical tolerance " + format_number(mc.tolerance, 2) +
         " m/s^2 (GUM Supplement 1, 8): " + why + "; quote the Monte Carlo interval";
}

/// Too few draws place the interval's ends no better than the tolerance:
/// GUM's interval is neither validated nor refuted by them.
std::string unjudged_finding(const MonteCarloResult& mc) {
  const double worst = std::max(mc.low_uncertainty, mc.high_uncertainty);
  // Infinite where too few draws were kept to form two batches.
  if (!std::isfinite(worst)) {
    return "uncertainty: " + std::to_string(mc.draws) +
           " Monte Carlo draws kept are too few to place the ends of their 95 % interval: GUM's interval is not judged";
  }
  return "uncertainty: " + std::to_string(mc.draws) + " Monte Carlo draws place the ends of their 95 % interval to +- " +
         format_number(worst, 2) + " m/s^2, more than the numerical tolerance " + format_number(mc.tolerance, 2) +
         " m/s^2: too few to judge GUM's interval (GUM Supplement 1, 7.9 and 8); about " +
         std::to_string(mc.draws_to_judge) + " draws would judge it, or leave their number out for the adaptive run";
}

/// Draws dropped cut g's distribution where they fell: said past 1 in 1000.
std::optional<std::string> rejection_finding(const MonteCarloResult& mc) {
  const long attempts = mc.draws + mc.rejected_draws;
  if (mc.rejected_draws * 1000 <= attempts) return std::nullopt;
  static constexpr const char* kWhy[kRejectionKinds] = {
      "outside the model's domain (an angle past 180 deg)", "whose refit found no optimum in 20 steps",
      "whose refit ran over 1000 uncertainties from the fit's", "with g <= 0"};
  std::string why;
  for (int i = 0; i < kRejectionKinds; ++i) {
    if (mc.rejected_by_reason[i] == 0) continue;
    why += (why.empty() ? "" : ", ") + std::to_string(mc.rejected_by_reason[i]) + " " + kWhy[i];
  }
  return "uncertainty: " + std::to_string(mc.rejected_draws) + " of " + std::to_string(attempts) +
         " Monte Carlo draws (" + format_number(100.0 * mc.rejected_draws / attempts, 2) + " %) gave no g and were "
         "dropped (" + why + "): g's distribution is cut where they fell, and its interval is of the rest";
}

}  // namespace

Analysis reduce_scene(const ParsedScene& given, const AnalysisOptions& options) {
  Analysis out = analyse(given, options);
  // The draws and the verdict see the scene the analysis reduced.
  const std::optional<ParsedScene> fitted = scene_with_fitted_decay(given, out.decay_fit);
  const ParsedScene& scene = fitted ? *fitted : given;
  if (const auto& asked = options.monte_carlo ? options.monte_carlo : scene.monte_carlo) {
    out.monte_carlo = monte_carlo(scene, out, *asked);
    if (!out.monte_carlo) {
      out.warnings.push_back("uncertainty: no Monte Carlo result: the draws start from GUM's budget, which this fit "
                             "does not give (singular), or fall outside the model's domain; the budget is GUM's "
                             "linear one");
    } else {
      if (auto w = rejection_finding(*out.monte_carlo)) out.warnings.push_back(std::move(*w));
      if (!out.monte_carlo->judged) {
        out.warnings.push_back(unjudged_finding(*out.monte_carlo));
      } else if (!out.monte_carlo->validated) {
        out.warnings.push_back(monte_carlo_finding(*out.monte_carlo, out));
      }
    }
  }
  Verdict verdict = judge(scene, out);
  out.status = verdict.status;
  out.status_reasons = std::move(verdict.reasons);
  return out;
}

}  // namespace pendulum
