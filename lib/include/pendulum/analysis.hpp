#pragma once
/// \file analysis.hpp
/// \brief The reduction of a parsed scene with its uncertainties and the
/// status of every correction: what `pendulum-g reduce` prints.

#include <optional>
#include <string>
#include <vector>

#include "pendulum/decay_fit.hpp"
#include "pendulum/drag.hpp"
#include "pendulum/reduction.hpp"
#include "pendulum/scene_json.hpp"

namespace pendulum {

struct AnalysisOptions {
  ReductionOptions reduction;
  /// A correction smaller than this fraction of the period's uncertainty is
  /// flagged negligible (it is still applied).
  double negligible_fraction = 0.1;
  /// With the automatic amplitude method, the chosen method's error bound
  /// stays below this fraction of the period's uncertainty.
  double amplitude_fraction = 0.01;
};

enum class Status { applied, negligible, skipped };
const char* status_name(Status s);

struct CorrectionRow {
  CorrectionInfo info;
  Status status = Status::skipped;
  std::string method;
  std::string reason;                 ///< why skipped or negligible
  std::optional<double> ratio;        ///< DeltaT/T0
  std::optional<double> delta_T;      ///< (s)
  std::optional<double> delta_g;      ///< (m/s^2), linearised: 2 g DeltaT/T0
  /// Standard uncertainty of delta_T from every input's (s).
  std::optional<double> delta_T_uncertainty;
  std::optional<double> error_bound_delta_T;  ///< (s), bound on the formula's error
  int series_terms = 0;               ///< terms of a truncated series, 0 otherwise
};

/// One input's share of the uncertainty of g.
struct BudgetEntry {
  std::string input;   ///< JSON path
  std::string unit;    ///< SI unit of value and uncertainty
  double value;
  double uncertainty;
  double sensitivity;   ///< dg/d(input) (m/s^2 per unit)
  double contribution;  ///< |sensitivity| x uncertainty (m/s^2)
};

/// The one correlated pair of inputs: alpha and beta of a decay fit.
struct BudgetCorrelation {
  std::string first, second;
  double correlation;
  double variance;  ///< 2 dg/dfirst cov dg/dsecond (m^2/s^4), may be negative
};

struct ValueWithUncertainty {
  double value;
  double uncertainty;
};

struct Analysis {
  std::vector<CorrectionRow> corrections;
  ValueWithUncertainty period_measured;  ///< (s)
  ValueWithUncertainty period_ideal;     ///< (s)
  ValueWithUncertainty g;                ///< (m/s^2)
  ValueWithUncertainty g_uncorrected;    ///< (m/s^2), Eq. (5)
  double total_delta_T;                  ///< (s)
  double total_delta_g;                  ///< (m/s^2)
  double negligible_below;               ///< (s)
  /// Every input with a stated uncertainty, largest contribution first.
  /// Their squares and budget_correlation's variance add to g.uncertainty^2.
  std::vector<BudgetEntry> budget;
  std::optional<BudgetCorrelation> budget_correlation;
  /// The uncertainty of g from the period and the length alone, as in
  /// Nelson & Olsson's Eq. (91) (m/s^2).
  double g_period_and_length_uncertainty = 0.0;
  /// JSON paths of the inputs stated without an uncertainty.
  std::vector<std::string> inputs_without_uncertainty;
  /// The fit of alpha and beta when the scene gives a decay record.
  std::optional<DecayFit> decay_fit;
  /// alpha and beta given beside a decay record, for comparison.
  std::optional<Decay<double>> decay_given;
  /// The air's predicted damping, when the scene has air and decay.
  std::optional<DragPrediction<double>> drag;
  /// The g expected at the site, when the scene gives one, and how far the
  /// measurement is from it: (g - expected) / sqrt(sigma_g^2 + sigma_expected^2).
  std::optional<ExpectedGravity> expected_g;
  std::optional<double> z_score;
  /// Findings of the analysis itself (the scene's own are in ParsedScene).
  std::vector<std::string> warnings;
};

/// What a decay fit's user should know: non-convergence, a chi2/dof that
/// the stated sigmas cannot explain, a term that is not significant.
std::vector<std::string> review_decay_fit(const DecayFit& fit);

/// The scene with alpha and beta taken from the fit of its decay record,
/// if it has one (its uncertainties from the fit's covariance).
ParsedScene with_fitted_decay(const ParsedScene& scene, const DecayFit& fit);

/// Reduces the scene and propagates every input's uncertainty (and the
/// decay fit's alpha-beta covariance) by automatic differentiation through
/// the whole reduction.
Analysis analyse(const ParsedScene& scene, const AnalysisOptions& options = {});

}  // namespace pendulum
