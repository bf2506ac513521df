#pragma once
/// \file monte_carlo_result.hpp
/// \brief What a Monte Carlo of g (GUM Supplement 1, monte_carlo.hpp) is
/// asked for and what it gives: types alone, so that the scene that asks for
/// it and the analysis that carries its result need not know how it runs.

#include <array>
#include <cstdint>
#include <string>

namespace pendulum {

/// What a scene's "uncertainty" or `--uncertainty monte-carlo` asks for.
struct MonteCarloOptions {
  std::uint64_t seed = 1;
  /// 0: adaptive (S1 7.9), batches of 10^4 until the mean, u(g) and the
  /// interval's ends are stable to the numerical tolerance.
  long draws = 0;
};

/// The adaptive run stops here whatever its tolerance (S1 7.9: a bound M).
inline constexpr long kMostDraws = 1000000;

/// Why a draw gives no g; each is counted, as dropping draws truncates g's
/// distribution.
enum class Rejection {
  outside_domain,  ///< an input the model cannot take (an angle past 180 deg)
  no_convergence,  ///< a series' refit found no optimum in 20 steps
  run_away,        ///< ... or one over 1000 uncertainties from the fit's
  g_not_positive,
};
inline constexpr int kRejectionKinds = 4;

struct MonteCarloResult {
  MonteCarloOptions options;
  long draws = 0;
  /// Draws that gave no g, not among `draws`, and why (by Rejection).
  long rejected_draws = 0;
  std::array<long, kRejectionKinds> rejected_by_reason{};
  double mean = 0.0;                  ///< (m/s^2)
  double standard_uncertainty = 0.0;  ///< the draws' standard deviation (m/s^2)
  double low = 0.0, high = 0.0;       ///< the shortest 95 % coverage interval (S1 7.7.2) (m/s^2)
  /// delta of S1 7.9.2: half a unit in the last of u(g)'s two significant digits (m/s^2).
  double tolerance = 0.0;
  /// S1 8.2: |y - U - low| and |y + U - high|, GUM's interval y +- U against the draws'.
  double d_low = 0.0, d_high = 0.0;
  /// The standard uncertainty of `low` and `high` from the draws' own
  /// sampling (m/s^2): the spread of their batches' ends, carried to all
  /// the draws at the rate M^(-1/3) at which a shortest interval's ends
  /// settle (docs/uncertainty.md).
  double low_uncertainty = 0.0, high_uncertainty = 0.0;
  /// Both within the tolerance: too few draws place the ends no better than
  /// the tolerance, and their d_low and d_high say nothing of GUM's interval.
  bool judged = false;
  /// Where not judged: about how many draws would judge it; 0 where the
  /// ends' uncertainty is unknown (fewer than two batches of draws kept).
  long draws_to_judge = 0;
  bool validated = false;  ///< judged, and d_low and d_high within the tolerance
  /// Where judged and not validated: the input held at its value that restores the
  /// agreement (GUM's interval without it against the draws' without it);
  /// empty if none does. In a series, one field of every observation may be
  /// held together: "observations[].timing.period".
  std::string bending_input;
  /// How the table says it: the path, or "18 observations' timing.period",
  /// with the rows' distribution ("student_t").
  std::string bending_name, bending_distribution;
};

}  // namespace pendulum
