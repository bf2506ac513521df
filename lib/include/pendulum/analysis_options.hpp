#pragma once
/// \file analysis_options.hpp
/// \brief What the user asks of an analysis (analysis.hpp): the reduction's
/// choices, the thresholds of its findings and the Monte Carlo beside the
/// budget; what a period model's results read of them too (fit_state.hpp).

#include <optional>

#include "pendulum/monte_carlo_result.hpp"
#include "pendulum/reduction.hpp"

namespace pendulum {

struct AnalysisOptions {
  ReductionOptions reduction;
  /// A correction smaller than this fraction of the period's uncertainty is
  /// flagged negligible (it is still applied).
  double negligible_fraction = 0.1;
  /// With the automatic amplitude method, the chosen method's error bound
  /// stays below this fraction of the period's uncertainty.
  double amplitude_fraction = 0.01;
  /// `--uncertainty monte-carlo`: GUM Supplement 1 beside the budget (a
  /// scene's "uncertainty" asks the same; these options win).
  std::optional<MonteCarloOptions> monte_carlo;
};

}  // namespace pendulum
