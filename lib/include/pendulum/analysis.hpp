#pragma once
/// \file analysis.hpp
/// \brief A parsed scene reduced to g: the period model fitted to its
/// observations (in closed form for one observation), every input's
/// uncertainty propagated to the parameters and to each correction, and the
/// status of every correction: what `pendulum-g reduce` prints.

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "pendulum/amplitude_sweep.hpp"
#include "pendulum/analysis_options.hpp"
#include "pendulum/decay_fit.hpp"
#include "pendulum/drag.hpp"
#include "pendulum/estimate.hpp"
#include "pendulum/monte_carlo_result.hpp"
#include "pendulum/models/registry.hpp"
#include "pendulum/parsed_scene.hpp"
#include "pendulum/reduction.hpp"
#include "pendulum/uncertainty.hpp"

namespace pendulum {

enum class Status { applied, negligible, skipped };
const char* status_name(Status s);

/// The verdict on a result, which judge() gives (status.hpp). The names are
/// an API: "ok", "suspect", "failed".
enum class ResultStatus { ok, suspect, failed };
const char* result_status_name(ResultStatus s);

struct CorrectionRow {
  CorrectionInfo info;
  Status status = Status::skipped;
  std::string method;
  std::string reason;                 ///< why skipped or negligible
  std::optional<double> ratio;        ///< DeltaT/T0
  std::optional<double> delta_T;      ///< (s)
  std::optional<double> delta_g;      ///< (m/s^2), linearised: 2 g DeltaT/T0
  /// Standard uncertainty of delta_T from every input's (s); empty when the
  /// fit's covariance is singular.
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
  /// How `uncertainty` was evaluated: Type A or B, its distribution and
  /// degrees of freedom (infinite for Type B), GUM 4.2-4.3.
  InputEvaluation evaluation;
  /// contribution^2 / the combined variance from the stated uncertainties
  /// (g.uncertainty_unscaled^2); a correlated pair's may exceed 1.
  double variance_share;
};

/// GUM 6: the expanded uncertainty U = k u_c, k from Student's t at the
/// effective degrees of freedom (Welch-Satterthwaite, GUM G.4).
struct ExpandedUncertainty {
  double effective_dof;    ///< infinite where every input's is
  double coverage_factor;  ///< k
  double probability;      ///< the coverage probability, kCoverageProbability
  double expanded;         ///< U = k u_c (m/s^2)
};

/// A correlated pair of inputs (alpha and beta of a decay fit).
struct BudgetCorrelation {
  std::string first, second;
  double correlation;
  double variance;  ///< 2 dg/dfirst cov dg/dsecond (m^2/s^4), may be negative
};

/// One observation's measured and modelled period and its corrections.
struct ObservationResult {
  std::string path;  ///< "" or "observations[3]."
  double length;     ///< as measured (m)
  double amplitude;  ///< (rad), of `amplitude_of`
  AngleOf amplitude_of = AngleOf::pendulum;
  /// The pendulum's angle the corrections took (rad), where `amplitude` is the bob's.
  std::optional<double> amplitude_pendulum;
  int trials = 0;
  int oscillations_per_trial = 1;
  ValueWithUncertainty period_measured;  ///< (s)
  double period_model;                   ///< the fitted model's T (s)
  Estimate period_ideal;                 ///< T0 at the fitted parameters (s)
  /// (model - measured) / the effective uncertainty (the observation's
  /// period, length and amplitude uncertainties carried to its period, the
  /// fit's weight); empty for one observation.
  std::optional<double> residual;
  double effective_uncertainty = 0.0;  ///< (s), 1 / the fit's weight; 0 for one observation
  /// The 16 corrections, and the amplitude cross term where it is not negligible.
  std::vector<CorrectionRow> corrections;
  double cross_term_delta_T;  ///< (s), shown as a row only when not negligible
  double total_delta_T;       ///< T_model - T0 (s), every row and the cross term
  double total_delta_g;       ///< 2 g (T/T0 - 1) (m/s^2)
  double negligible_below;    ///< (s)
};

/// A fitted (or held) parameter of the period model.
struct ParameterResult {
  const char* name;
  const char* unit;
  double value;
  std::optional<double> uncertainty;  ///< from every input's; empty when singular or held
  /// From the observations' own uncertainties (period, length, amplitude):
  /// (J^T W J)^-1 of the fit's effective-variance weights, what
  /// ceres::Covariance or curve_fit with absolute sigma would give.
  std::optional<double> uncertainty_from_observations;
  bool fitted;
  /// `uncertainty` before the Birge ratio was applied (FitReport::scaled);
  /// equal to it otherwise.
  std::optional<double> uncertainty_unscaled;
  /// Effective degrees of freedom of `uncertainty` (Welch-Satterthwaite over
  /// the inputs; the share a Birge ratio adds has the fit's dof); infinite
  /// where every input's is, or the parameter has no uncertainty.
  double degrees_of_freedom = kInfiniteDof;
};

/// What the fit of a series adds.
struct FitReport {
  const char* model = "simple_pendulum";  ///< the period model's name (models/)
  std::vector<ParameterResult> parameters;
  /// Correlations of the fitted parameters (row-major, in `parameters`'
  /// order among those fitted); empty when singular.
  std::vector<double> correlation;
  double chi2;
  int dof;
  /// P(chi2 >= the one found) for `dof` degrees of freedom; empty at dof 0.
  std::optional<double> probability;
  /// S = sqrt(chi2/dof), the Birge ratio (PDG's scale factor); empty at dof 0.
  std::optional<double> birge_ratio;
  /// chi2 improbably large (dispersion.hpp): the result is suspect and the
  /// parameters' uncertainties carry S on the share the scatter tests.
  bool scaled = false;
  /// The lengths' scatter beyond their stated uncertainty, tau (m), where
  /// fitted (docs/series.md, "Lengths that scatter"): chi2 is then dof.
  std::optional<double> length_scatter;
  /// chi2 against the stated uncertainties alone, where tau was fitted.
  std::optional<double> chi2_stated;
  bool converged = true;
  std::string method;  ///< "closed_form" or "ceres_levenberg_marquardt"
  std::string termination;
  int iterations = 0;
  /// The model's own results beside the fit's (its Results, which its
  /// report() sets): none where it gives none, as the ball's where the
  /// lengths determine no textbook line (all equal, with the offset fitted).
  ModelResults results;

  /// `Model`'s results; null where it gave none or the fit is another model's.
  template <class Model>
  const typename Model::Results* results_of() const {
    return std::get_if<kind_of<Model>().index + 1>(&results);
  }
  template <class Model>
  void set_results(typename Model::Results r) {
    results.template emplace<kind_of<Model>().index + 1>(std::move(r));
  }
};

struct Analysis {
  std::vector<ObservationResult> observations;
  FitReport fit;
  Estimate g;                            ///< (m/s^2)
  /// g's uncertainty before the Birge ratio was applied (fit.scaled); equal
  /// to g.uncertainty otherwise.
  std::optional<double> g_uncertainty_unscaled;
  /// The uncertainty of g from the observations' periods and lengths alone,
  /// as in Nelson & Olsson's Eq. (91) (m/s^2).
  std::optional<double> g_period_and_length_uncertainty;
  /// Every input with a stated uncertainty, largest contribution first.
  /// Their squares and budget_correlation's variance add to g.uncertainty^2.
  std::vector<BudgetEntry> budget;
  std::optional<BudgetCorrelation> budget_correlation;
  /// g's expanded uncertainty for 95 % coverage; empty without an uncertainty.
  std::optional<ExpandedUncertainty> g_expanded;
  /// GUM Supplement 1's g where asked for (monte_carlo.hpp; reduce_scene()
  /// runs it).
  std::optional<MonteCarloResult> monte_carlo;
  /// JSON paths of the inputs stated without an uncertainty.
  std::vector<std::string> inputs_without_uncertainty;
  /// A series at one length and three amplitudes or more: T0 and the law
  /// tested (amplitude_sweep_of).
  std::optional<AmplitudeSweep> amplitude_sweep;
  /// The fit of alpha and beta when the scene gives a decay record.
  std::optional<DecayFit> decay_fit;
  /// alpha and beta given beside a decay record, for comparison.
  std::optional<Decay<double>> decay_given;
  /// The air's predicted damping, for one observation with air and decay.
  std::optional<DragPrediction<double>> drag;
  /// The g expected at the site, when the scene gives one, and how far the
  /// measurement is from it: (g - expected) / sqrt(sigma_g^2 + sigma_expected^2).
  std::optional<ExpectedGravity> expected_g;
  std::optional<double> z_score;
  /// Without a site: standard gravity with the range of g over the Earth's
  /// surface as its uncertainty (earth_surface_gravity()), and z against it.
  /// The status judges g against the range itself (status.hpp).
  std::optional<ExpectedGravity> surface_g;
  std::optional<double> surface_z;
  /// Findings of the analysis itself (the scene's own are in ParsedScene),
  /// among them the corrections skipped for a part not described that
  /// typical values would not leave negligible.
  std::vector<std::string> warnings;
  /// ok or suspect, and why suspect: the likely slip and the input to fix
  /// (judge(), status.hpp; reduce_scene() sets them, analyse() leaves them ok).
  ResultStatus status = ResultStatus::ok;
  std::vector<std::string> status_reasons;
};

/// What a decay fit's user should know: non-convergence, a chi2/dof that
/// the stated sigmas cannot explain, a term that is not significant.
std::vector<std::string> review_decay_fit(const DecayFit& fit);

/// The apparatus with alpha and beta taken from the fit of the decay
/// record (their uncertainties from the fit's covariance).
void use_fitted_decay(ParsedScene& scene, const DecayFit& fit);

/// The scene an analysis reduces: `given` with alpha and beta from `fit`
/// (use_fitted_decay); empty where there is no fit, and `given` is that scene.
std::optional<ParsedScene> scene_with_fitted_decay(const ParsedScene& given, const std::optional<DecayFit>& fit);

/// A physical pendulum's starting parameters (g, k, centre) for the fit:
/// T^2 h = (4 pi^2/g)(k^2 + h^2) is a straight line in h^2 (Kelley Eq. 55),
/// whose slope gives g and intercept k^2; an unknown centre is the one, on a
/// grid of 600 across the pivots and a span beyond, whose line fits best
/// (relative residuals), refined by golden-section search within a grid
/// step. A k the body gives holds the line through the origin in k^2 + h^2.
/// `fitted` in PhysicalPendulum's parameter order.
std::array<double, 3> physical_start(const ParsedScene& scene, const std::array<bool, 3>& fitted);

/// The scene's observations as an amplitude sweep: a series (not a
/// recording's swing-by-swing groups) of a ball at one length, measured or
/// not, with three amplitudes or more (two where the length is not
/// measured); none otherwise. Each period with its stated uncertainty, each
/// amplitude as given.
std::optional<AmplitudeSweep> amplitude_sweep_of(const ParsedScene& scene);

/// Fits the scene's period model to its observations and propagates every
/// input's uncertainty (and the decay fit's alpha-beta covariance) by
/// automatic differentiation: implicit-function sensitivities of the fit.
/// A scene whose length is not measured is refused (InputError at "length").
/// Neither the Monte Carlo nor the verdict: reduce_scene() adds them.
Analysis analyse(const ParsedScene& scene, const AnalysisOptions& options = {});

}  // namespace pendulum
