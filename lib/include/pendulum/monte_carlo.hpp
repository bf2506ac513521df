#pragma once
/// \file monte_carlo.hpp
/// \brief GUM Supplement 1 (JCGM 101:2008): g's distribution by drawing every
/// input from its own distribution and reducing each draw, its shortest 95 %
/// coverage interval, an adaptive number of draws, and the check of GUM's
/// linear interval against it (S1 8). docs/uncertainty.md.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pendulum {

struct ParsedScene;
struct Analysis;

/// What a scene's "uncertainty" or `--uncertainty monte-carlo` asks for.
struct MonteCarloOptions {
  std::uint64_t seed = 1;
  /// 0: adaptive (S1 7.9), batches of 10^4 until the mean, u(g) and the
  /// interval's ends are stable to the numerical tolerance.
  long draws = 0;
};

/// The adaptive run stops here whatever its tolerance (S1 7.9: a bound M).
inline constexpr long kMostDraws = 1000000;

struct MonteCarloResult {
  MonteCarloOptions options;
  long draws = 0;
  double mean = 0.0;                  ///< (m/s^2)
  double standard_uncertainty = 0.0;  ///< the draws' standard deviation (m/s^2)
  double low = 0.0, high = 0.0;       ///< the shortest 95 % coverage interval (S1 7.7.2) (m/s^2)
  /// delta of S1 7.9.2: half a unit in the last of u(g)'s two significant digits (m/s^2).
  double tolerance = 0.0;
  /// S1 8.2: |y - U - low| and |y + U - high|, GUM's interval y +- U against the draws'.
  double d_low = 0.0, d_high = 0.0;
  bool validated = false;  ///< both within the tolerance
  /// Where not validated: the input held at its value that restores the
  /// agreement (GUM's interval without it against the draws' without it);
  /// empty if none does. In a series, one field of every observation may be
  /// held together: "observations[].timing.period".
  std::string bending_input;
  /// How the table says it: the path, or "18 observations' timing.period",
  /// with the rows' distribution ("student_t").
  std::string bending_name, bending_distribution;
};

/// g's distribution for a scene (`analysis` is its GUM result, analyse()'s).
/// Each input with a stated uncertainty is drawn as its InputEvaluation
/// says: normal, rectangular over +-sqrt(3)u, or the mean of n readings as
/// value + u t_{n-1} (S1 6.4.9); a decay fit's alpha and beta jointly from
/// their covariance; an input a series gives once, once for all its
/// observations. Each draw goes through every correction (the exact
/// amplitude factor) and, for a series, the fit: refitted with the
/// analysis's weights, its observations' own inputs drawn S times wider as a
/// multivariate t where a Birge ratio S scaled the fit's uncertainty.
/// Seeded: the same seed gives the same draws. Empty where the analysis
/// has no uncertainty of g (a singular fit).
std::optional<MonteCarloResult> monte_carlo(const ParsedScene& scene, const Analysis& analysis,
                                            const MonteCarloOptions& options);

/// The shortest interval holding `probability` of the sorted `values` (S1 7.7.2).
std::pair<double, double> shortest_interval(const std::vector<double>& sorted, double probability);

}  // namespace pendulum
