// The one place where the report code reads the analysis's own types.
#include "pendulum/report/scene_report.hpp"

#include <algorithm>
#include <cmath>

#include <ceres/jet.h>

#include "pendulum/damping.hpp"
#include "pendulum/output.hpp"
#include "pendulum/report/recording_report.hpp"
#include "pendulum/report/svg_plot.hpp"
#include "../grouping.hpp"
#include "../text.hpp"

namespace pendulum::report {

namespace {

constexpr int kDecayGridPoints = 241;

/// theta0(t) of Eq. (25) at the fitted (alpha, beta, theta0m) and its
/// standard uncertainty sqrt(J C J^T), J by automatic differentiation.
Measured fitted_amplitude(const DecayFit& fit, double t) {
  using Jet = ceres::Jet<double, 3>;
  const Jet alpha(fit.alpha.value, 0), beta(fit.beta.value, 1), theta0m(fit.initial_amplitude.value, 2);
  const Jet theta = decayed_amplitude(theta0m, alpha, beta, Jet(t));
  double variance = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) variance += theta.v[i] * fit.covariance[3 * i + j] * theta.v[j];
  }
  return {theta.a, std::sqrt(std::max(variance, 0.0))};
}

}  // namespace

DecayRecord make_decay_record(const DecayData& data, const DecayFit& fit) {
  DecayRecord r;
  r.times = data.times;
  r.amplitudes = data.amplitudes;
  r.sigmas = data.sigmas;
  for (double t : data.times) r.fitted.push_back(fitted_amplitude(fit, t).value);
  // A fitted parameter without an uncertainty: the covariance is singular,
  // and the band unknown.
  bool covariance_known = true;
  for (const FittedParameter* p : {&fit.alpha, &fit.beta, &fit.initial_amplitude}) {
    covariance_known = covariance_known && (!p->fitted || p->uncertainty);
  }
  const double t0 = data.times.front(), t1 = data.times.back();
  for (int i = 0; i < kDecayGridPoints; ++i) {
    const double t = t0 + (t1 - t0) * i / (kDecayGridPoints - 1);
    const Measured m = fitted_amplitude(fit, t);
    r.grid.push_back(t);
    r.grid_fit.push_back(m.value);
    if (covariance_known) r.grid_uncertainty.push_back(m.uncertainty);
  }
  r.parameters = {{"alpha", "1/s", fit.alpha.value, fit.alpha.uncertainty, fit.alpha.fitted},
                  {"beta", "1/(s rad)", fit.beta.value, fit.beta.uncertainty, fit.beta.fitted},
                  {"theta0m", "rad", fit.initial_amplitude.value, fit.initial_amplitude.uncertainty,
                   fit.initial_amplitude.fitted}};
  switch (fit.model) {
    case DecayModel::both: r.model = "Eq. (25), alpha and beta fitted"; break;
    case DecayModel::linear_only: r.model = "Eq. (33), beta = 0"; break;
    case DecayModel::quadratic_only: r.model = "Eq. (46), alpha = 0"; break;
  }
  if (!fit.model_reason.empty()) r.model += " (" + fit.model_reason + ")";
  r.chi2 = fit.chi2;
  r.dof = fit.dof;
  r.uncertainty_scaling = fit.scaled ? "from the stated sigmas, scaled by the Birge ratio S = " +
                                           format_significant(*fit.birge_ratio, 3) +
                                           " (chi2 improbably large: the amplitudes scatter more than the sigmas allow)"
                         : fit.uncertainty_scaling == "sigma"
                             ? "from the stated sigmas (chi2/dof tells the fit's quality)"
                             : "scaled by the residual variance s^2 = SSR/dof (no sigmas stated)";
  return r;
}

namespace {

/// The budget as the page shows it: a series' rows of one field grouped
/// (issue 39, item 8), largest first.
std::vector<BudgetShare> budget_shares(const std::vector<BudgetEntry>& budget) {
  std::vector<std::string> paths;
  std::vector<double> contributions;
  for (const auto& b : budget) paths.push_back(b.input), contributions.push_back(b.contribution);
  std::vector<BudgetShare> shares;
  for (const BudgetGroup& group : group_budget(paths, contributions)) {
    const BudgetEntry& first = budget[group.rows.front()];
    const GroupEvaluation e = group_evaluation(group, budget, "\u221E");
    shares.push_back({group_name(group, paths), first.unit, first.value, first.uncertainty, group.together, e.type,
                      e.distribution, e.dof, e.variance_share, static_cast<int>(group.rows.size())});
  }
  return shares;
}

}  // namespace

SceneReport make_scene_report(const std::string& input, const ParsedScene& scene, const Analysis& a,
                              const std::vector<Recording>& samples) {
  const ObservationResult& first = a.observations.front();
  SceneReport r;
  r.input = input;
  r.title = scene.title;
  r.source = scene.source;
  r.status = result_status_name(a.status);
  r.status_reasons = a.status_reasons;
  r.g = a.g;
  const TextbookFit* textbook = a.fit.results_of<SimplePendulum>();
  if (textbook) r.g_uncorrected = textbook->g;
  if (a.fit.scaled) r.birge_ratio = a.fit.birge_ratio, r.g_uncertainty_unscaled = a.g_uncertainty_unscaled;
  r.period_measured = {first.period_measured.value, first.period_measured.uncertainty};
  r.period_ideal = first.period_ideal;
  r.trials = first.trials;
  r.oscillations_per_trial = first.oscillations_per_trial;
  // With a site, its g; without, standard gravity and the Earth's range.
  if (const auto& expected = a.expected_g ? a.expected_g : a.surface_g) {
    r.expected_g = Measured{expected->value, expected->uncertainty};
    r.expected_source = expected->source;
    r.expected_note = expected->note;
  }
  r.z = a.expected_g ? a.z_score : a.surface_z;
  r.negligible_below = first.negligible_below;
  for (const auto& row : first.corrections) {
    r.corrections.push_back({row.info.id, row.info.title, status_name(row.status), row.method, row.reason,
                             row.info.equation, row.delta_T, row.delta_T_uncertainty, row.delta_g});
  }
  r.budget = budget_shares(a.budget);
  if (a.g_expanded) r.g_expanded = expanded_result(a.g.value, *a.g_expanded, true);
  if (a.budget_correlation) r.budget_correlation_variance = a.budget_correlation->variance;
  r.inputs_without_uncertainty = a.inputs_without_uncertainty;
  if (scene.decay_data && a.decay_fit) r.decay = make_decay_record(*scene.decay_data, *a.decay_fit);
  if (scene.series) {
    SeriesRecord s;
    for (std::size_t k = 0; k < a.observations.size(); ++k) {
      const ObservationResult& o = a.observations[k];
      s.lengths.push_back(o.length);
      s.length_uncertainties.push_back(scene.observation_uncertainties[k].length);
      s.periods.push_back(o.period_measured.value);
      s.period_uncertainties.push_back(o.period_measured.uncertainty);
      s.effective_uncertainties.push_back(o.effective_uncertainty > 0.0 ? o.effective_uncertainty
                                                                        : o.period_measured.uncertainty);
      s.periods_model.push_back(o.period_model);
      s.amplitudes.push_back(o.amplitude);
    }
    s.sweep = a.amplitude_sweep;
    for (const auto& p : a.fit.parameters) s.parameters.push_back({p.name, p.unit, p.value, p.uncertainty, p.fitted});
    s.chi2 = a.fit.chi2;
    s.dof = a.fit.dof;
    s.probability = a.fit.probability;
    if (r.g_uncorrected) s.textbook_g = r.g_uncorrected->value;
    if (textbook && textbook->length_offset) s.textbook_length_offset = textbook->length_offset->value;
    r.series = s;
  }
  r.pivot_scan = pivot_scan_record(scene, a);
  // Each recording the scene names, once however often it is named
  // (timing and decay.data); the signal plot where its samples are given.
  for (std::size_t i = 0; i < scene.recordings.size(); ++i) {
    const RecordingSummary& summary = scene.recordings[i].summary;
    const bool named_before = std::any_of(scene.recordings.begin(), scene.recordings.begin() + i, [&](const auto& o) {
      return o.summary.file == summary.file && o.summary.set == summary.set;
    });
    if (!named_before) r.recordings.push_back(make_recording_record(summary, i < samples.size() ? &samples[i] : nullptr));
  }
  r.warnings = scene.warnings;
  r.warnings.insert(r.warnings.end(), a.warnings.begin(), a.warnings.end());
  return r;
}

}  // namespace pendulum::report
