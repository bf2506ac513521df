#pragma once
/// \file monte_carlo.hpp
/// \brief GUM Supplement 1 (JCGM 101:2008): g's distribution by drawing every
/// input from its own distribution and reducing each draw, its shortest 95 %
/// coverage interval, an adaptive number of draws, and the check of GUM's
/// linear interval against it (S1 8). docs/uncertainty.md.

#include <optional>
#include <utility>
#include <vector>

#include "pendulum/monte_carlo_result.hpp"

namespace pendulum {

struct ParsedScene;
struct Analysis;

/// "outside_domain", as the JSON keys say it.
const char* rejection_name(Rejection r);

/// g's distribution for a scene (`analysis` is its GUM result, analyse()'s).
/// Each input with a stated uncertainty is drawn as its InputEvaluation
/// says: normal, rectangular over +-sqrt(3)u, or the mean of n readings as
/// value + u t_{n-1} (S1 6.4.9); a decay fit's alpha and beta jointly from
/// their covariance; an input a series gives once, once for all its
/// observations. Each draw goes through every correction (the exact
/// amplitude factor) and, for a series, the fit: refitted with the
/// analysis's weights. Where a Birge ratio S scaled the fit's uncertainty,
/// the inputs are drawn at their own uncertainties and each observation's
/// period gets the scatter they do not explain, sqrt(S^2 - 1)/w_k (w_k its
/// fit weight), jointly as a multivariate t with the fit's n - p dof.
/// Seeded: the same seed gives the same draws. Empty where the analysis
/// has no uncertainty of g (a singular fit).
std::optional<MonteCarloResult> monte_carlo(const ParsedScene& scene, const Analysis& analysis,
                                            const MonteCarloOptions& options);

/// GUM's expanded uncertainty of g (m/s^2) with the budget rows `without`
/// held at their values: the rest's variance and Welch-Satterthwaite's
/// nu_eff formed as analyse() forms them (variance_components), the share a
/// Birge ratio added kept (the scatter it stands for is no input's). With
/// none held, the analysis's own g_expanded.
double expanded_without(const Analysis& a, const std::vector<std::string>& without);

/// The shortest interval holding `probability` of the sorted `values` (S1 7.7.2).
std::pair<double, double> shortest_interval(const std::vector<double>& sorted, double probability);

}  // namespace pendulum
