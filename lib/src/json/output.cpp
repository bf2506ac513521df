#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pendulum/interrupt.hpp"
#include "pendulum/models/registry.hpp"
#include "pendulum/monte_carlo.hpp"
#include "pendulum/json/output.hpp"
#include "pendulum/status.hpp"
#include "writer.hpp"
#include "../grouping.hpp"
#include "../text.hpp"

namespace pendulum {

namespace {
/// Throws std::logic_error at a number that is not finite: the JSON library
/// would print it as null, where the API promises a number.
void require_finite(const nlohmann::ordered_json& j, const std::string& path) {
  if (j.is_structured()) {
    for (const auto& item : j.items()) require_finite(item.value(), path + "/" + item.key());
  } else if (j.is_number_float() && !std::isfinite(j.get<double>())) {
    throw std::logic_error("non-finite number in the output at " + path);
  }
}

}  // namespace

/// JSON text as every command prints it, after the check above. A file name
/// that is not UTF-8 prints its bad bytes as U+FFFD instead of failing.
std::string json_text(const nlohmann::ordered_json& j, int indent) {
  require_finite(j, "");
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

namespace writer {

using json = nlohmann::ordered_json;

json optional_number(const std::optional<double>& x) { return x ? json(*x) : json(nullptr); }

json finite_or_null(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

json measured(const ValueWithUncertainty& x, const char* unit) {
  return {{"value", x.value}, {"uncertainty", x.uncertainty}, {"unit", unit}};
}

json measured(const Estimate& x, const char* unit) {
  return {{"value", x.value}, {"uncertainty", optional_number(x.uncertainty)}, {"unit", unit}};
}

std::string format_fixed(double x, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, x);
  return text;
}

std::string plus_minus(const std::optional<double>& u, const char* format) {
  if (!u) return "+- ? (singular fit)";
  char text[64];
  std::snprintf(text, sizeof text, format, *u);
  return std::string("+- ") + text;
}

std::string rounded(double value, const std::optional<double>& u) {
  if (!u) return plus_minus(u, "%.5f").insert(0, format_fixed(value, 5) + " ");
  const int d = decimals_for_uncertainty(*u, 12);
  return format_fixed(value, d) + " +- " + format_fixed(*u, d);
}

}  // namespace writer

namespace {

constexpr const char* kResultSchema = "pendulum-g/result/1";

using json = nlohmann::ordered_json;

using writer::finite_or_null;
using writer::format_fixed;
using writer::measured;
using writer::optional_number;
using writer::plus_minus;
using writer::rounded;

json parameter(const FittedParameter& q, const char* unit) {
  return {{"value", q.value},
          {"uncertainty", optional_number(q.uncertainty)},
          {"unit", unit},
          {"fitted", q.fitted},
          {"at_bound", q.at_bound},
          {"significant", q.significant},
          {"uncertainty_unscaled", optional_number(q.uncertainty_unscaled)}};
}

/// `of`: whose angle the record followed, and so the angle beta is of.
json decay_fit_to_json(const DecayFit& f, const std::optional<Decay<double>>& given, AngleOf of) {
  json out = {{"equation", "Nelson & Olsson (1986) Eq. (25)"},
              {"angle_of", angle_of_name(of)},
              {"model", decay_model_name(f.model)},
              {"model_reason", f.model_reason},
              {"alpha", parameter(f.alpha, "1/s")},
              {"beta", parameter(f.beta, "1/(s rad)")},
              {"initial_amplitude", parameter(f.initial_amplitude, "rad")},
              {"correlation_alpha_beta", f.correlation_alpha_beta},
              {"alpha_beta_separable", f.separable},
              {"chi2", f.chi2},
              {"dof", f.dof},
              {"reduced_chi2", f.dof > 0 ? json(f.chi2 / f.dof) : json(nullptr)},
              {"residual_standard_error_rad", f.residual_standard_error},
              {"residual_variance_rad2", f.residual_standard_error * f.residual_standard_error},
              {"uncertainty_scaling", f.uncertainty_scaling},
              {"probability", optional_number(f.probability)},
              {"birge_ratio", optional_number(f.birge_ratio)},
              {"uncertainties_scaled", f.scaled},
              {"points", f.points},
              {"converged", f.converged},
              {"termination", f.termination},
              {"iterations", f.iterations}};
  if (given) out["given"] = {{"alpha_1_s", given->alpha}, {"beta_1_s_rad", given->beta}};
  return out;
}

json drag_to_json(const DragPrediction<double>& d, const Decay<double>& decay) {
  auto optional = [](const std::optional<double>& x) { return x ? json(*x) : json(nullptr); };
  return {{"equation", "Nelson & Olsson (1986) Eqs. (26), (27), (63)-(67)"},
          {"reynolds_sphere", d.reynolds_sphere},
          {"reynolds_wire", optional(d.reynolds_wire)},
          {"c_d_prime", d.c_d_prime},
          {"b_kg_s", {{"sphere", d.b_sphere}, {"wire", optional(d.b_wire)}, {"total", d.b}}},
          {"c_kg_m", {{"sphere", d.c_sphere}, {"wire", optional(d.c_wire)}, {"total", d.c}}},
          {"alpha_1_s", d.alpha},
          {"beta_1_s_rad", d.beta},
          {"measured_over_predicted", {{"alpha", decay.alpha / d.alpha}, {"beta", decay.beta / d.beta}}}};
}

// RFC 4180: quote a field that holds a comma, quote or line break. Text
// (a file name, a title) never starts a formula; numbers are not text.
std::string csv_field(const json& v) {
  if (v.is_null()) return "";
  std::string text = v.is_string() ? spreadsheet_text(v.get<std::string>()) : v.dump();
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}
// New columns go at the end: scripts may read the columns by position.
constexpr const char* kCsvColumns[] = {"input", "ok", "g_m_s2", "g_uncertainty_m_s2", "largest_budget_input",
                                       "largest_budget_m_s2", "expected_g_m_s2", "z", "warnings", "error",
                                       "status", "status_reasons", "title", "warning_count"};
/// A list of messages in one CSV field.
constexpr const char* kCsvSeparator = "; ";

json joined(const json& messages) {
  std::string text;
  for (const auto& m : messages) text += (text.empty() ? "" : kCsvSeparator) + m.get<std::string>();
  return text;
}

std::string csv_row(const json& summary) {
  std::string line;
  bool first = true;
  for (const char* c : kCsvColumns) {
    if (!first) line += ",";
    first = false;
    if (!summary.contains(c)) continue;
    const json& v = summary.at(c);
    line += csv_field(v.is_array() ? joined(v) : v);
  }
  return line + "\n";
}

json correction_json(const CorrectionRow& row) {
  json c = {{"id", row.info.id},
            {"title", row.info.title},
            {"status", status_name(row.status)},
            {"delta_T_s", optional_number(row.delta_T)},
            {"delta_T_uncertainty_s", optional_number(row.delta_T_uncertainty)},
            {"delta_T_over_T0", optional_number(row.ratio)},
            {"delta_g_m_s2", optional_number(row.delta_g)},
            {"equation", row.info.equation},
            {"method", row.method.empty() ? json(nullptr) : json(row.method)},
            {"error_bound_delta_T_s", optional_number(row.error_bound_delta_T)}};
  if (row.series_terms > 0) c["series_terms"] = row.series_terms;
  if (!row.reason.empty()) c["reason"] = row.reason;
  return c;
}

/// Where the amplitude is the bob's (a sensor in it): whose it is, and the
/// pendulum's that the corrections took (docs/phone.md).
void amplitude_of_json(const ObservationResult& o, json& out) {
  out["amplitude_of"] = angle_of_name(o.amplitude_of);
  out["amplitude_pendulum_rad"] = *o.amplitude_pendulum;
}

json corrections_json(const ObservationResult& o) {
  json corrections = json::array();
  for (const auto& row : o.corrections) corrections.push_back(correction_json(row));
  return corrections;
}

/// Degrees of freedom, null where infinite (docs/output.md).
json dof_json(double dof) { return std::isfinite(dof) ? json(dof) : json(nullptr); }

json expanded_json(const Analysis& a) {
  if (!a.g_expanded) return nullptr;
  const ExpandedUncertainty& e = *a.g_expanded;
  return {{"uncertainty", e.expanded},
          {"unit", "m/s^2"},
          {"coverage_factor", e.coverage_factor},
          {"coverage_probability", e.probability},
          {"effective_degrees_of_freedom", dof_json(e.effective_dof)},
          {"result", "g = " + expanded_result(a.g.value, e, true)}};
}

json g_json(const Analysis& a) {
  json budget = json::array();
  for (const auto& b : a.budget) {
    budget.push_back({{"input", b.input},
                      {"value", b.value},
                      {"uncertainty", b.uncertainty},
                      {"unit", b.unit},
                      {"sensitivity", b.sensitivity},
                      {"contribution_m_s2", b.contribution},
                      {"type", std::string(1, b.evaluation.type)},
                      {"distribution", distribution_name(b.evaluation.distribution)},
                      {"degrees_of_freedom", dof_json(b.evaluation.dof)},
                      {"variance_share_percent", 100.0 * b.variance_share}});
  }
  json g = measured(a.g, "m/s^2");
  g["uncertainty_unscaled"] = optional_number(a.g_uncertainty_unscaled);
  g["scale_factor"] = a.fit.scaled ? *a.fit.birge_ratio : 1.0;
  g["uncertainty_period_and_length"] = optional_number(a.g_period_and_length_uncertainty);
  g["budget"] = budget;
  if (a.budget_correlation) {
    g["budget_correlation"] = {{"inputs", {a.budget_correlation->first, a.budget_correlation->second}},
                               {"correlation", a.budget_correlation->correlation},
                               {"variance_m2_s4", a.budget_correlation->variance}};
  }
  g["inputs_without_uncertainty"] = a.inputs_without_uncertainty;
  g["effective_degrees_of_freedom"] = dof_json(a.fit.parameters.front().degrees_of_freedom);
  g["expanded"] = expanded_json(a);
  if (const auto& mc = a.monte_carlo) {
    g["monte_carlo"] = {{"method", "monte-carlo"},
                        {"draws", mc->draws},
                        {"seed", mc->options.seed},
                        {"adaptive", mc->options.draws == 0},
                        {"mean", mc->mean},
                        {"uncertainty", mc->standard_uncertainty},
                        {"unit", "m/s^2"},
                        {"coverage_interval", {mc->low, mc->high}},
                        {"coverage_probability", kCoverageProbability},
                        {"tolerance", mc->tolerance},
                        {"d_low", mc->d_low},
                        {"d_high", mc->d_high},
                        {"validated", mc->validated},
                        {"bending_input", mc->bending_input.empty() ? json(nullptr) : json(mc->bending_input)},
                        {"judged", mc->judged},
                        {"coverage_interval_uncertainty_m_s2", {finite_or_null(mc->low_uncertainty), finite_or_null(mc->high_uncertainty)}},
                        {"draws_to_judge", mc->judged || mc->draws_to_judge == 0 ? json(nullptr) : json(mc->draws_to_judge)},
                        {"rejected_draws", mc->rejected_draws}};
    json& reasons = g["monte_carlo"]["rejected_draws_by_reason"] = json::object();
    for (int i = 0; i < kRejectionKinds; ++i) reasons[rejection_name(static_cast<Rejection>(i))] = mc->rejected_by_reason[i];
  }
  return g;
}

json fit_json(const ParsedScene& scene, const Analysis& a) {
  const FitReport& f = a.fit;
  json parameters = json::array();
  json names = json::array();
  for (const auto& p : f.parameters) {
    parameters.push_back({{"name", p.name},
                          {"value", p.value},
                          {"uncertainty", optional_number(p.uncertainty)},
                          {"uncertainty_from_observations", optional_number(p.uncertainty_from_observations)},
                          {"unit", p.unit},
                          {"fitted", p.fitted},
                          {"uncertainty_unscaled", optional_number(p.uncertainty_unscaled)},
                          {"degrees_of_freedom", p.uncertainty ? dof_json(p.degrees_of_freedom) : json(nullptr)}});
    if (p.fitted) names.push_back(p.name);
  }
  json matrix = json::array();
  const std::size_t n = names.size();
  for (std::size_t i = 0; i < n && !f.correlation.empty(); ++i) {
    matrix.push_back(std::vector<double>(f.correlation.begin() + i * n, f.correlation.begin() + (i + 1) * n));
  }
  json observations = json::array();
  for (std::size_t k = 0; k < a.observations.size(); ++k) {
    check_interrupt();
    const ObservationResult& o = a.observations[k];
    const auto& u = scene.observation_uncertainties[k];
    observations.push_back(
        {{"index", k},
         {setting_key(scene.observations[k].setting), measured(ValueWithUncertainty{o.length, u.length}, "m")},
         {"amplitude", measured(ValueWithUncertainty{o.amplitude, u.amplitude}, "rad")},
         {"period",
          {{"measured", measured(o.period_measured, "s")},
           {"model_s", o.period_model},
           {"ideal", measured(o.period_ideal, "s")},
           {"trials", o.trials},
           {"oscillations_per_trial", o.oscillations_per_trial}}},
         {"effective_uncertainty_s", o.effective_uncertainty},
         {"residual_sigma", optional_number(o.residual)},
         {"total_delta_T_s", o.total_delta_T},
         {"negligible_threshold_delta_T_s", o.negligible_below},
         {"corrections", corrections_json(o)}});
    if (o.amplitude_pendulum) amplitude_of_json(o, observations.back());
  }
  json out = {{"model", f.model},
              {"method", f.method},
              {"parameters", parameters},
              {"correlation", {{"parameters", names}, {"matrix", matrix.empty() ? json(nullptr) : matrix}}},
              {"chi2", f.chi2},
              {"dof", f.dof},
              {"reduced_chi2", f.dof > 0 ? json(f.chi2 / f.dof) : json(nullptr)},
              {"probability", optional_number(f.probability)},
              {"birge_ratio", optional_number(f.birge_ratio)},
              {"uncertainties_scaled", f.scaled},
              {"length_scatter_m", optional_number(f.length_scatter)},
              {"chi2_stated", optional_number(f.chi2_stated)},
              {"period_uncertainty", scene.period_uncertainty_from_scatter ? "scatter_about_fit" : "stated"},
              {"converged", f.converged},
              {"termination", f.termination},
              {"iterations", f.iterations},
              {"observations", observations}};
  visit_period_model(scene.model, [&](auto model) {
    using Model = decltype(model);
    JsonOut fit{out};
    Model::put_fit_results(f.results_of<Model>(), fit);
  });
  return out;
}

/// How a timing's recording was reduced (docs/recordings.md, "A long decay,
/// swing by swing"); a timing's only, not a decay record's.
json reduction_json(const RecordingReduction& reduction) {
  const RecordingReduction* r = &reduction;
  json out = {{"requested", r->requested},
              {"mode", r->swing_by_swing ? "swing_by_swing" : "mean_period"},
              {"shift_of", "exact_beyond_theta0_squared_over_16"},
              {"decay_corrected", r->decay_corrected},
              {"threshold_sigmas", kSwingBySwingShift}};
  // Only what there is: no amplitudes, no shift; one mean period, no groups.
  if (std::isfinite(r->shift_sigmas)) out["amplitude_shift_sigmas"] = r->shift_sigmas;
  if (r->swing_by_swing) {
    out["groups"] = r->groups.size();
    out["periods_per_group"] = r->groups.front().periods;
  }
  return out;
}

/// Where the timing and decay records came from when the scene names
/// recordings (docs/recordings.md, "In a scene").
json recordings_json(const ParsedScene& scene) {
  json list = json::array();
  for (const SceneRecording& r : scene.recordings) {
    const PeriodEstimate& p = r.summary.swings.period;
    list.push_back({{"path", r.path},
                    {"recording", r.name},
                    {"file", r.summary.file},
                    {"format", recording_format_name(r.summary.format)},
                    {"set", r.summary.set.empty() ? json(nullptr) : json(r.summary.set)},
                    {"rows", r.summary.rows},
                    {"skipped_rows", r.summary.dropped},
                    {"periods", p.periods},
                    {"period", {{"value", p.value}, {"uncertainty", p.uncertainty}, {"unit", "s"}}},
                    // No stated sigma per crossing: the covariance is the residuals' own,
                    // chi2/dof 1 by construction (docs/output.md).
                    {"period_fit",
                     {{"uncertainty_scaling", "residual_variance"},
                      {"residual_rms_s", p.residual_rms},
                      {"lag1_correlation", p.lag1_correlation},
                      {"autocorrelation_inflation", p.inflation}}},
                    {"swing_amplitudes", r.summary.swings.decay.amplitudes.size()}});
    if (r.reduction) list.back()["reduction"] = reduction_json(*r.reduction);
  }
  return list;
}

json warnings_json(const ParsedScene& scene, const Analysis& a) {
  json warnings = scene.warnings;
  for (const auto& w : a.warnings) warnings.push_back(w);
  return warnings;
}

}  // namespace

std::string result_json(const ParsedScene& scene, const Analysis& a, const AnalysisOptions& options,
                        const std::string& input, int indent) {
  json out = {{"schema", kResultSchema},
              {"input", input},
              {"title", scene.title},
              {"status", result_status_name(a.status)},
              {"status_reasons", a.status_reasons}};
  if (scene.series) {
    out["kind"] = "series";
    out["g"] = g_json(a);
    out["fit"] = fit_json(scene, a);
    if (a.amplitude_sweep) out["amplitude_sweep"] = writer::amplitude_sweep_json(*a.amplitude_sweep);
    out["negligible_threshold"] = {{"fraction_of_period_uncertainty", options.negligible_fraction}};
  } else {
    const ObservationResult& o = a.observations.front();
    out["g"] = g_json(a);
    visit_period_model(scene.model, [&](auto model) {
      using Model = decltype(model);
      JsonOut observation{out};
      Model::put_observation_results(a.fit.results_of<Model>(), observation);
    });
    out["period"] = {{"measured", measured(o.period_measured, "s")},
                     {"ideal", measured(o.period_ideal, "s")},
                     {"trials", o.trials},
                     {"oscillations_per_trial", o.oscillations_per_trial}};
    out["total_delta_T_s"] = o.total_delta_T;
    out["total_delta_g_m_s2"] = o.total_delta_g;
    out["negligible_threshold"] = {{"fraction_of_period_uncertainty", options.negligible_fraction},
                                   {"delta_T_s", o.negligible_below}};
    out["corrections"] = corrections_json(o);
    if (o.amplitude_pendulum) amplitude_of_json(o, out);
  }
  out["assumptions"] = scene.assumptions;
  out["warnings"] = warnings_json(scene, a);
  // With a site, its g; without, standard gravity and the Earth's range.
  if (const auto& expected = a.expected_g ? a.expected_g : a.surface_g) {
    out["expected_g"] = {{"value", expected->value},
                         {"uncertainty", expected->uncertainty},
                         {"unit", "m/s^2"},
                         {"source", expected->source},
                         {"note", expected->note}};
    if (expected->range) out["expected_g"]["range_m_s2"] = {expected->range->first, expected->range->second};
    out["comparison"] = {{"difference_m_s2", a.g.value - expected->value},
                         {"z", optional_number(a.expected_g ? a.z_score : a.surface_z)}};
  }
  if (a.decay_fit) out["decay_fit"] = decay_fit_to_json(*a.decay_fit, a.decay_given, decay_angle_of(scene));
  if (!scene.recordings.empty()) out["recordings"] = recordings_json(scene);
  if (a.drag) {
    const Decay<double> used = a.decay_fit ? Decay<double>{a.decay_fit->alpha.value, a.decay_fit->beta.value}
                                           : *scene.apparatus.decay;
    out["drag_theory"] = drag_to_json(*a.drag, used);
  }
  return json_text(out, indent);
}

std::string decay_fit_json(const std::string& input, const ParsedScene& scene, const DecayFit& fit,
                           const std::vector<std::string>& warnings) {
  json out = {{"schema", "pendulum-g/decay-fit/1"}, {"input", input}};
  out.update(decay_fit_to_json(fit, scene.apparatus.decay, decay_angle_of(scene)));
  if (!scene.recordings.empty()) out["recordings"] = recordings_json(scene);
  ParsedScene fitted = scene;
  use_fitted_decay(fitted, fit);
  // A decay-only document has no pendulum to predict the air's damping of.
  if (!fitted.observations.empty()) {
    if (const auto drag = predict_drag(fitted.apparatus, fitted.observations.front())) {
      out["drag_theory"] = drag_to_json(*drag, *fitted.apparatus.decay);
    }
  }
  out["warnings"] = warnings;
  return json_text(out, 2);
}

namespace {

/// Decimals that show `u` to two significant digits (5 for none, at most 12).
int decimals_of(double u) { return decimals_for_uncertainty(u, 12); }

/// Degrees of freedom as the table and the result line print them: whole
/// (GUM G.4.1 truncates nu_eff), "∞" where infinite or beyond 1e6 (the
/// table prints no "inf": it reads as a number gone wrong).
std::string dof_text(double dof) {
  if (!(dof <= 1e6)) return "\u221E";
  return format_fixed(std::floor(dof), 0);
}

}  // namespace

std::string expanded_result(double g, const ExpandedUncertainty& e, bool unicode) {
  const int d = decimals_of(e.expanded);
  return format_fixed(g, d) + (unicode ? " ± " : " +- ") + format_fixed(e.expanded, d) +
         (unicode ? " m/s² (k = " : " m/s^2 (k = ") + format_fixed(e.coverage_factor, 2) + ", " +
         format_fixed(100.0 * e.probability, 0) + (unicode ? " %, ν_eff = " : " %, nu_eff = ") +
         dof_text(e.effective_dof) + ")";
}

namespace {

/// A batch's table row after the file column: status, g rounded to its
/// uncertainty, z, and the first reason (or the error) in brief.
std::string table_row(const std::string& status, const std::optional<double>& g, const std::optional<double>& u,
                      const std::optional<double>& z, const std::string& reason) {
  char line[256];
  std::snprintf(line, sizeof line, "%-8s %-22s %8s  ", status.c_str(), g ? rounded(*g, u).c_str() : "-",
                z ? format_fixed(*z, 1).insert(0, *z >= 0.0 ? "+" : "").c_str() : "-");
  std::string row = line + (reason.empty() ? std::string() : brief_reason(reason));
  while (!row.empty() && row.back() == ' ') row.pop_back();
  return row;
}

/// The CSV row of a summary line: its warnings counted, the first given
/// (the rest are in the JSON line).
std::string csv_of(json line) {
  if (line.contains("warnings")) {
    const json w = line["warnings"];
    line["warning_count"] = w.size();
    line["warnings"] = w.empty() ? json("") : w.front();
  }
  return csv_row(line);
}

/// A line's text in `format`: the JSON line, its CSV row, or its table row.
std::string batch_text(const json& line, BatchFormat format, const std::function<std::string()>& table) {
  switch (format) {
    case BatchFormat::jsonl: return json_text(line, -1);
    case BatchFormat::csv: return csv_of(line);
    case BatchFormat::table: return table();
  }
  return {};
}

}  // namespace

BatchLine batch_line(const std::string& input, const ParsedScene& scene, const Analysis& a, BatchFormat format) {
  const json line = {{"input", input},
                     {"ok", true},
                     {"status", result_status_name(a.status)},
                     {"status_reasons", a.status_reasons},
                     {"title", scene.title},
                     {"g_m_s2", a.g.value},
                     {"g_uncertainty_m_s2", optional_number(a.g.uncertainty)},
                     {"largest_budget_input", a.budget.empty() ? json(nullptr) : json(a.budget.front().input)},
                     {"largest_budget_m_s2", a.budget.empty() ? json(nullptr) : json(a.budget.front().contribution)},
                     {"expected_g_m_s2", a.expected_g ? json(a.expected_g->value) : json(nullptr)},
                     {"z", optional_number(a.z_score)},
                     {"warnings", warnings_json(scene, a)}};
  return {true, a.status, a.g.value, batch_text(line, format, [&] {
            return table_row(result_status_name(a.status), a.g.value, a.g.uncertainty,
                             a.expected_g ? a.z_score : a.surface_z,
                             a.status_reasons.empty() ? "" : a.status_reasons.front());
          })};
}

BatchLine batch_failure(const std::string& input, const std::string& error, BatchFormat format) {
  const json line = {{"input", input},
                     {"ok", false},
                     {"status", result_status_name(ResultStatus::failed)},
                     {"status_reasons", json::array()},
                     {"error", error}};
  return {false, ResultStatus::failed, std::nullopt, batch_text(line, format, [&] {
            return table_row(result_status_name(ResultStatus::failed), std::nullopt, std::nullopt, std::nullopt, error);
          })};
}

ClassSummary summarise_class(const std::vector<BatchLine>& lines) {
  std::vector<std::pair<ResultStatus, std::optional<double>>> results;
  for (const BatchLine& l : lines) results.emplace_back(l.status, l.g);
  return summarise_class(results);
}

ClassSummary summarise_class(const std::vector<std::pair<ResultStatus, std::optional<double>>>& results) {
  ClassSummary c;
  double mean = 0.0, m2 = 0.0;  // Welford's running mean and sum of squares
  for (const auto& [status, g] : results) {
    ++c.count[static_cast<int>(status)];
    if (status != ResultStatus::ok || !g) continue;
    ++c.ok_g_count;
    const double d = *g - mean;
    mean += d / c.ok_g_count;
    m2 += d * (*g - mean);
  }
  if (c.ok_g_count > 0) c.ok_g_mean = mean;
  if (c.ok_g_count > 1) c.ok_g_standard_deviation = std::sqrt(m2 / (c.ok_g_count - 1));
  return c;
}

std::string batch_class_json(const ClassSummary& c) {
  const json line = {{"class", true},
                     {"scenes", c.count[0] + c.count[1] + c.count[2]},
                     {"counts", {{"ok", c.count[0]}, {"suspect", c.count[1]}, {"failed", c.count[2]}}},
                     {"g_of_ok",
                      {{"count", c.ok_g_count},
                       {"mean_m_s2", optional_number(c.ok_g_mean)},
                       {"standard_deviation_m_s2", optional_number(c.ok_g_standard_deviation)}}}};
  return json_text(line, -1);
}

std::string batch_class_csv(const ClassSummary& c) {
  std::string line = "# class: " + std::to_string(c.count[0]) + " ok, " + std::to_string(c.count[1]) +
                     " suspect, " + std::to_string(c.count[2]) + " failed; g of the ok scenes: ";
  if (!c.ok_g_mean) return line + "none\n";
  char numbers[160];
  std::snprintf(numbers, sizeof numbers, "mean %.5f m/s^2", *c.ok_g_mean);
  line += numbers;
  if (c.ok_g_standard_deviation) {
    std::snprintf(numbers, sizeof numbers, ", standard deviation %.5f m/s^2", *c.ok_g_standard_deviation);
    line += numbers;
  }
  return line + " (" + std::to_string(c.ok_g_count) + (c.ok_g_count == 1 ? " scene)\n" : " scenes)\n");
}

std::string batch_class_table(const ClassSummary& c) { return batch_class_csv(c).substr(2); }

std::string batch_table_header(std::size_t file_width) {
  char line[128];
  std::snprintf(line, sizeof line, "%-8s %-22s %8s  %s", "status", "g (m/s^2)", "z", "reason (in brief; in full in the JSON lines)");
  return std::string("file").append(file_width + 2 - 4, ' ') + line + "\n";
}

std::string batch_csv_header() {
  std::string line;
  for (const char* c : kCsvColumns) line += (line.empty() ? "" : ",") + std::string(c);
  return line + "\n";
}

namespace {

void correction_table(std::ostringstream& os, const ObservationResult& o) {
  char line[320];
  std::snprintf(line, sizeof line, "%-26s %12s %10s %16s  %-10s %s\n", "Correction", "dT (us)", "+- (us)",
                "dg (mGal)", "status", "method");
  os << line;
  for (const auto& row : o.corrections) {
    if (row.delta_T) {
      // Rounded to the row's uncertainty, as the pages' table (correction_decimals).
      const CorrectionDecimals d = correction_decimals(*row.delta_T, row.delta_T_uncertainty, *row.delta_g);
      char sigma[32] = "?";
      if (row.delta_T_uncertainty) std::snprintf(sigma, sizeof sigma, "%10.*f", d.delta_T, *row.delta_T_uncertainty * 1e6);
      std::snprintf(line, sizeof line, "%-26s %+12.*f %10s %+16.*f  %-10s %s\n", row.info.title, d.delta_T,
                    *row.delta_T * 1e6, sigma, d.delta_g, *row.delta_g * 1e5, status_name(row.status),
                    row.method.c_str());
    } else {
      std::snprintf(line, sizeof line, "%-26s %12s %10s %16s  %-10s %s\n", row.info.title, "-", "", "-",
                    status_name(row.status), row.reason.c_str());
    }
    os << line;
  }
  std::snprintf(line, sizeof line, "%-26s %+12.4f %10s %+16.4f\n", "Total", o.total_delta_T * 1e6, "",
                o.total_delta_g * 1e5);
  os << line << "(dT: the correction to the period, in microseconds; dg: to g, in mGal, 1 mGal = 1e-5 m/s^2)\n";
}

/// "alpha = 2.49e-04 +- 1.1e-05 1/s (fitted)" for the tables.
std::string decay_parameter_line(const char* name, const FittedParameter& q, const char* unit) {
  char line[200];
  if (!q.fitted) {
    std::snprintf(line, sizeof line, "  %-17s = %.4g %s (held%s)\n", name, q.value, unit,
                  q.value == 0.0 ? ": not in the model" : "");
  } else if (!q.uncertainty) {
    std::snprintf(line, sizeof line, "  %-17s = %.4g +- ? %s (singular fit)\n", name, q.value, unit);
  } else {
    std::snprintf(line, sizeof line, "  %-17s = %.4g +- %.2g %s%s\n", name, q.value, *q.uncertainty, unit,
                  q.at_bound ? " (at its bound 0)" : q.significant ? "" : " (not significant)");
  }
  return line;
}

std::string decay_fit_lines(const DecayFit& f) {
  std::ostringstream os;
  os << "Decay fit, Nelson & Olsson (1986) Eq. (25): model " << decay_model_name(f.model);
  if (!f.model_reason.empty()) os << " (" << f.model_reason << ")";
  os << "\n" << decay_parameter_line("alpha", f.alpha, "1/s") << decay_parameter_line("beta", f.beta, "1/(s rad)")
     << decay_parameter_line("initial amplitude", f.initial_amplitude, "rad");
  char line[200];
  if (f.alpha.fitted && f.beta.fitted) {
    std::snprintf(line, sizeof line, "  correlation(alpha, beta) = %+.3f\n", f.correlation_alpha_beta);
    os << line;
  }
  if (f.uncertainty_scaling == "sigma") {
    std::snprintf(line, sizeof line, "  chi2/dof = %.4g (%d points, %d degrees of freedom, probability of a larger chi2 %.3g)\n",
                  f.dof > 0 ? f.chi2 / f.dof : 0.0, f.points, f.dof, f.probability.value_or(0.0));
    if (f.scaled) {
      os << line;
      std::snprintf(line, sizeof line, "  uncertainties scaled by the Birge ratio S = sqrt(chi2/dof) = %.3g\n",
                    *f.birge_ratio);
    }
  } else {
    std::snprintf(line, sizeof line,
                  "  no sigma given: uncertainties scaled by the residual variance %.3g rad^2 "
                  "(residual standard error %.3g rad; %d points)\n",
                  f.residual_standard_error * f.residual_standard_error, f.residual_standard_error, f.points);
  }
  os << line;
  return os.str();
}

}  // namespace

std::string decay_fit_table(const ParsedScene& scene, const DecayFit& fit, const std::vector<std::string>& warnings) {
  std::ostringstream os;
  if (!scene.title.empty()) os << one_line(scene.title, kShownTitleBytes, true) << "\n\n";
  os << decay_fit_lines(fit);
  for (const auto& w : warnings) os << "warning: " << w << "\n";
  return os.str();
}

std::string result_table(const ParsedScene& scene, const Analysis& a) {
  std::ostringstream os;
  char line[320];
  if (!scene.title.empty()) os << one_line(scene.title, kShownTitleBytes, true) << "\n\n";
  if (!scene.series) {
    const ObservationResult& o = a.observations.front();
    correction_table(os, o);
    os << "\n";
    std::snprintf(line, sizeof line, "Measured period T   = %.6f +- %.6f s (%d trial%s)\n", o.period_measured.value,
                  o.period_measured.uncertainty, o.trials, o.trials == 1 ? "" : "s");
    os << line;
    std::snprintf(line, sizeof line, "Ideal period T0     = %.6f %s s\n", o.period_ideal.value,
                  plus_minus(o.period_ideal.uncertainty, "%.6f").c_str());
    os << line;
    visit_period_model(scene.model, [&](auto model) {
      using Model = decltype(model);
      Model::observation_results_lines(a.fit.results_of<Model>(), os);
    });
  } else {
    // The setting's column: a length, a pivot's position along the body, or its distance from the centre.
    const std::string heading = std::string(setting_info(scene.observations.front().setting).symbol) + " (m)";
    std::snprintf(line, sizeof line, "%5s %9s %12s %12s %10s %12s %9s %12s\n", "obs", heading.c_str(), "theta0 (deg)",
                  "T meas (s)", "+- (s)", "T model (s)", "resid (sd)", "T-T0 (us)");
    os << line;
    for (std::size_t k = 0; k < a.observations.size(); ++k) {
      check_interrupt();
      const ObservationResult& o = a.observations[k];
      std::snprintf(line, sizeof line, "%5zu %9.4f %12.2f %12.6f %10.6f %12.6f %+10.2f %+12.2f\n", k, o.length,
                    degrees(o.amplitude), o.period_measured.value, o.period_measured.uncertainty,
                    o.period_model, o.residual.value_or(0.0), o.total_delta_T * 1e6);
      os << line;
    }
    os << "\nFit (" << a.fit.method << ", " << a.fit.dof << " degrees of freedom):\n";
    for (const auto& p : a.fit.parameters) {
      if (!p.fitted) continue;
      const std::string nu = p.uncertainty ? " (nu = " + dof_text(p.degrees_of_freedom) + ")" : "";
      std::snprintf(line, sizeof line, "  %-14s = %.8g %s %s%s\n", p.name, p.value,
                    plus_minus(p.uncertainty, "%.3g").c_str(), p.unit, nu.c_str());
      os << line;
      if (std::string(p.name) == "length_offset") {
        std::snprintf(line, sizeof line, "                   the lengths run to a point %.3g %s mm %s the centre of the bob\n",
                      std::fabs(p.value) * 1e3, plus_minus(p.uncertainty ? std::optional<double>(*p.uncertainty * 1e3) : std::nullopt, "%.3g").c_str(),
                      p.value >= 0.0 ? "above" : "below");
        os << line;
      }
    }
    if (a.fit.length_scatter) {
      std::snprintf(line, sizeof line,
                    "  lengths' scatter = %.3g mm beyond their stated uncertainty (chi2/dof = %.4g against the "
                    "periods' uncertainties alone, 1 with it)\n",
                    *a.fit.length_scatter * 1e3, *a.fit.chi2_stated / a.fit.dof);
      os << line;
    } else if (scene.period_uncertainty_from_scatter && a.fit.birge_ratio) {
      std::snprintf(line, sizeof line,
                    "  periods' sigma = from the scatter about the fit, %.3g times the printed digits' floor (%d degrees "
                    "of freedom): this fit cannot test itself; chi2 gives no verdict\n",
                    std::max(*a.fit.birge_ratio, 1.0), a.fit.dof);
      os << line;
    } else if (a.fit.dof > 0) {
      std::snprintf(line, sizeof line, "  chi2/dof       = %.4g (probability of a larger chi2: %.3g)\n",
                    a.fit.chi2 / a.fit.dof, a.fit.probability.value_or(0.0));
      os << line;
    }
    if (a.fit.scaled && !scene.period_uncertainty_from_scatter) {
      std::snprintf(line, sizeof line,
                    "  uncertainties scaled by the Birge ratio S = sqrt(chi2/dof) = %.3g: the observations scatter "
                    "more than their stated uncertainties allow\n",
                    *a.fit.birge_ratio);
      os << line;
    }
    visit_period_model(scene.model, [&](auto model) {
      using Model = decltype(model);
      Model::fit_results_lines(a.fit.results_of<Model>(), os);
    });
    if (a.amplitude_sweep) writer::amplitude_sweep_lines(*a.amplitude_sweep, false, os);
  }
  os << "g                   = " << rounded(a.g.value, a.g.uncertainty) << " m/s^2";
  const int g_decimals = a.g.uncertainty ? decimals_of(*a.g.uncertainty) : 5;
  std::string notes;
  if (a.fit.length_scatter) {
    notes = "with the lengths' scatter";
  } else if (scene.period_uncertainty_from_scatter) {
    notes = "the periods' sigma from the scatter about the fit";
  } else if (a.fit.scaled && a.g_uncertainty_unscaled) {
    notes = "scaled by S = " + format_fixed(*a.fit.birge_ratio, 2) + "; from the stated uncertainties +- " +
            format_fixed(*a.g_uncertainty_unscaled, g_decimals);
  }
  if (a.g_period_and_length_uncertainty) {
    notes += (notes.empty() ? "" : "; ") + std::string("period and length alone: +- ") +
             format_fixed(*a.g_period_and_length_uncertainty, g_decimals);
  }
  if (!notes.empty()) os << " (" << notes << ")";
  os << "\n";
  if (a.g_expanded) os << "g, expanded         = " << expanded_result(a.g.value, *a.g_expanded, false) << "\n";
  if (const auto& mc = a.monte_carlo) {
    const int d = decimals_of(mc->standard_uncertainty);
    os << "g, Monte Carlo      = " << format_fixed(mc->mean, d) << " +- " << format_fixed(mc->standard_uncertainty, d)
       << " m/s^2, 95 % in [" << format_fixed(mc->low, d) << ", " << format_fixed(mc->high, d) << "] ("
       << mc->draws
       << (!mc->judged ? " draws, too few to judge GUM's interval" : mc->validated ? " draws; GUM's interval validated"
                                                                                  : " draws; GUM's interval not validated")
       << " to " << format_fixed(mc->tolerance, d + 1) << ")\n";
  }
  if (a.expected_g) {
    std::snprintf(line, sizeof line, "expected g          = %.5f +- %.5f m/s^2 (%s)\n", a.expected_g->value,
                  a.expected_g->uncertainty, a.expected_g->source.c_str());
    os << line;
    if (a.z_score) {
      std::snprintf(line, sizeof line, "difference          = %+.5f m/s^2 = %+.2f combined sigma\n",
                    a.g.value - a.expected_g->value, *a.z_score);
    } else {
      std::snprintf(line, sizeof line, "difference          = %+.5f m/s^2 (no z: neither g nor the expected g has an "
                    "uncertainty)\n", a.g.value - a.expected_g->value);
    }
    os << line;
  } else if (a.surface_g) {
    std::snprintf(line, sizeof line,
                  "expected g          = %.5f +- %.5f m/s^2 (no site: standard gravity, +- the range of g on the "
                  "Earth's surface, %.4f to %.4f)\n",
                  a.surface_g->value, a.surface_g->uncertainty, a.surface_g->range->first, a.surface_g->range->second);
    os << line;
    std::snprintf(line, sizeof line, "difference          = %+.5f m/s^2", a.g.value - a.surface_g->value);
    os << line;
    if (a.surface_z) {
      std::snprintf(line, sizeof line, " = %+.2f combined sigma, the range counted as one", *a.surface_z);
      os << line;
    }
    os << "\n";
  }
  os << "status              = " << result_status_name(a.status) << "\n";
  for (const auto& r : a.status_reasons) os << "  " << r << "\n";
  if (a.decay_fit) os << "\n" << decay_fit_lines(*a.decay_fit);
  if (!a.budget.empty()) {
    // A series gives every observation its inputs: one line per field, its
    // rows in quadrature (the JSON lists each); the table shows the largest.
    constexpr std::size_t kShown = 12;
    std::vector<std::string> paths;
    std::vector<double> contributions;
    for (const auto& b : a.budget) paths.push_back(b.input), contributions.push_back(b.contribution);
    const std::vector<BudgetGroup> groups = group_budget(paths, contributions);
    os << "\nUncertainty budget of g (largest first; share of u(g)^2, GUM type, distribution, degrees of freedom):\n";
    for (std::size_t i = 0; i < groups.size() && i < kShown; ++i) {
      const GroupEvaluation e = group_evaluation(groups[i], a.budget, "\u221E");
      std::snprintf(line, sizeof line, "  %-32s %.6f m/s^2 %5.1f %%  %-3s %-11s  nu = %s\n",
                    group_name(groups[i], paths).c_str(), groups[i].together, 100.0 * e.variance_share,
                    e.type.c_str(), e.distribution.c_str(), e.dof.c_str());
      os << line;
    }
    if (groups.size() > kShown) os << "  ... and " << groups.size() - kShown << " more (JSON: g.budget)\n";
    // Correlated inputs do not add in quadrature: say what the pair gives together.
    if (const auto& c = a.budget_correlation) {
      double together = c->variance;
      for (const auto& b : a.budget) {
        if (b.input == c->first || b.input == c->second) together += b.contribution * b.contribution;
      }
      std::snprintf(line, sizeof line, "  %s and %s are correlated (%.6f): together %.6f m/s^2\n", c->first.c_str(),
                    c->second.c_str(), c->correlation, std::sqrt(std::max(together, 0.0)));
      os << line;
      // Shares over 100 % are each input's alone: the cross term takes the excess back
      // (shares of u(g)^2 before any Birge scaling, as variance_share is).
      const double u2 = a.g_uncertainty_unscaled ? *a.g_uncertainty_unscaled * *a.g_uncertainty_unscaled : 0.0;
      if (u2 > 0.0 && std::any_of(a.budget.begin(), a.budget.end(), [](const auto& b) { return b.variance_share > 1.0; })) {
        std::snprintf(line, sizeof line,
                      "  (their shares above count each alone; the cross term's, %.1f %%, takes back what they "
                      "add beyond u(g)^2)\n",
                      100.0 * c->variance / u2);
        os << line;
      }
    }
  }
  if (!a.inputs_without_uncertainty.empty()) {
    os << "Inputs without an uncertainty (they add nothing to the budget):";
    const std::vector<std::string>& paths = a.inputs_without_uncertainty;
    const std::vector<BudgetGroup> groups = group_budget(paths, std::vector<double>(paths.size(), 0.0));
    for (std::size_t i = 0; i < groups.size(); ++i) os << (i ? ", " : " ") << group_name(groups[i], paths);
    os << "\n";
  }
  std::vector<std::string> warnings = scene.warnings;
  warnings.insert(warnings.end(), a.warnings.begin(), a.warnings.end());
  for (const auto& assumption : collapse_repeats(scene.assumptions)) os << "assumption: " << assumption << "\n";
  for (const auto& w : collapse_repeats(warnings)) os << "warning: " << w << "\n";
  return os.str();
}

}  // namespace pendulum
