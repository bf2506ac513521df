// The one place where the report code reads the analysis's own types (the
// decay fit's: decay_record.cpp).
#include "pendulum/report/scene_report.hpp"

#include <algorithm>
#include <cmath>

#include "pendulum/json/output.hpp"
#include "pendulum/report/recording_report.hpp"
#include "pendulum/report/svg_plot.hpp"
#include "../grouping.hpp"
#include "../text.hpp"

namespace pendulum::report {

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
  // A series of rods: each its own body, the textbook line in their equivalent lengths.
  const bool rod_series = !scene.observations.empty() && scene.observations.front().setting == Setting::rod_length;
  const PivotScan* rods = rod_series ? a.fit.results_of<PhysicalPendulum>() : nullptr;
  if (rods && rods->textbook) r.g_uncorrected = rods->textbook->g;
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
      // A rod's equivalent length is 2L/3 of its length and moves with it.
      const double equivalent = rods ? rods->conjugates[k].equivalent_length.value / o.length : 1.0;
      s.lengths.push_back(equivalent * o.length);
      s.length_uncertainties.push_back(equivalent * scene.observation_uncertainties[k].length);
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
    if (rods) s.length_words = "equivalent length 2L/3 of each rod";
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
