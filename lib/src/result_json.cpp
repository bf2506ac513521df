#include "pendulum/result_json.hpp"

#include <cstdio>
#include <sstream>

namespace pendulum {

namespace {

constexpr const char* kResultSchema = "pendulum-g/result/1";

nlohmann::ordered_json measured(const ValueWithUncertainty& x, const char* unit) {
  return {{"value", x.value}, {"uncertainty", x.uncertainty}, {"unit", unit}};
}

nlohmann::ordered_json optional_number(const std::optional<double>& x) {
  return x ? nlohmann::ordered_json(*x) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json parameter(const FittedParameter& q, const char* unit) {
  return {{"value", q.value},
          {"uncertainty", q.uncertainty ? nlohmann::ordered_json(*q.uncertainty) : nlohmann::ordered_json(nullptr)},
          {"unit", unit},
          {"fitted", q.fitted},
          {"at_bound", q.at_bound},
          {"significant", q.significant}};
}

}  // namespace

nlohmann::ordered_json decay_fit_to_json(const DecayFit& f, const std::optional<Decay<double>>& given) {
  using json = nlohmann::ordered_json;
  json out = {{"equation", "Nelson & Olsson (1986) Eq. (25)"},
              {"model", decay_model_name(f.model)},
              {"model_reason", f.model_reason},
              {"alpha", parameter(f.alpha, "1/s")},
              {"beta", parameter(f.beta, "1/(s rad)")},
              {"initial_amplitude", parameter(f.initial_amplitude, "rad")},
              {"correlation_alpha_beta", f.correlation_alpha_beta},
              {"chi2", f.chi2},
              {"dof", f.dof},
              {"reduced_chi2", f.dof > 0 ? json(f.chi2 / f.dof) : json(nullptr)},
              {"residual_standard_error_rad", f.residual_standard_error},
              {"uncertainty_scaling", f.uncertainty_scaling},
              {"points", f.points},
              {"converged", f.converged},
              {"termination", f.termination},
              {"iterations", f.iterations}};
  if (given) out["given"] = {{"alpha_1_s", given->alpha}, {"beta_1_s_rad", given->beta}};
  return out;
}

nlohmann::ordered_json drag_to_json(const DragPrediction<double>& d, const Decay<double>& decay) {
  using json = nlohmann::ordered_json;
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

nlohmann::ordered_json result_to_json(const ParsedScene& scene, const Analysis& a,
                              const AnalysisOptions& options, const std::string& input) {
  using json = nlohmann::ordered_json;
  json budget = json::array();
  for (const auto& b : a.budget) {
    budget.push_back({{"input", b.input},
                      {"value", b.value},
                      {"uncertainty", b.uncertainty},
                      {"unit", b.unit},
                      {"sensitivity", b.sensitivity},
                      {"contribution_m_s2", b.contribution}});
  }
  json g = measured(a.g, "m/s^2");
  g["uncertainty_period_and_length"] = a.g_period_and_length_uncertainty;
  g["budget"] = budget;
  if (a.budget_correlation) {
    g["budget_correlation"] = {{"inputs", {a.budget_correlation->first, a.budget_correlation->second}},
                               {"correlation", a.budget_correlation->correlation},
                               {"variance_m2_s4", a.budget_correlation->variance}};
  }
  g["inputs_without_uncertainty"] = a.inputs_without_uncertainty;

  json corrections = json::array();
  for (const auto& row : a.corrections) {
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
    corrections.push_back(std::move(c));
  }

  json period = {{"measured", measured(a.period_measured, "s")},
                 {"ideal", measured(a.period_ideal, "s")},
                 {"trials", scene.trial_count},
                 {"oscillations_per_trial", scene.value.oscillations_per_trial}};

  json warnings = scene.warnings;
  for (const auto& w : a.warnings) warnings.push_back(w);
  json out = {{"schema", kResultSchema},
          {"input", input},
          {"title", scene.title},
          {"g", g},
          {"g_uncorrected", measured(a.g_uncorrected, "m/s^2")},
          {"period", period},
          {"total_delta_T_s", a.total_delta_T},
          {"total_delta_g_m_s2", a.total_delta_g},
          {"negligible_threshold",
           {{"fraction_of_period_uncertainty", options.negligible_fraction},
            {"delta_T_s", a.negligible_below}}},
          {"corrections", corrections},
          {"assumptions", scene.assumptions},
          {"warnings", warnings}};
  if (a.expected_g) {
    out["expected_g"] = {{"value", a.expected_g->value},
                         {"uncertainty", a.expected_g->uncertainty},
                         {"unit", "m/s^2"},
                         {"source", a.expected_g->source},
                         {"note", a.expected_g->note}};
    out["comparison"] = {{"difference_m_s2", a.g.value - a.expected_g->value},
                         {"z", a.z_score ? json(*a.z_score) : json(nullptr)}};
  }
  if (a.decay_fit) out["decay_fit"] = decay_fit_to_json(*a.decay_fit, a.decay_given);
  if (a.drag) {
    const Decay<double> used = a.decay_fit ? Decay<double>{a.decay_fit->alpha.value, a.decay_fit->beta.value}
                                           : *scene.value.decay;
    out["drag_theory"] = drag_to_json(*a.drag, used);
  }
  return out;
}

nlohmann::ordered_json batch_summary(const std::string& input, const ParsedScene& scene,
                                     const Analysis& a) {
  using json = nlohmann::ordered_json;
  json out = {{"input", input},
              {"ok", true},
              {"title", scene.title},
              {"g_m_s2", a.g.value},
              {"g_uncertainty_m_s2", a.g.uncertainty},
              {"largest_budget_input", a.budget.empty() ? json(nullptr) : json(a.budget.front().input)},
              {"largest_budget_m_s2", a.budget.empty() ? json(nullptr) : json(a.budget.front().contribution)},
              {"expected_g_m_s2", a.expected_g ? json(a.expected_g->value) : json(nullptr)},
              {"z", a.z_score ? json(*a.z_score) : json(nullptr)},
              {"warnings", scene.warnings.size() + a.warnings.size()}};
  return out;
}

nlohmann::ordered_json batch_failure(const std::string& input, const std::string& error) {
  return {{"input", input}, {"ok", false}, {"error", error}};
}

namespace {
// RFC 4180: quote a field that holds a comma, quote or line break.
std::string csv_field(const nlohmann::ordered_json& v) {
  if (v.is_null()) return "";
  std::string text = v.is_string() ? v.get<std::string>() : v.dump();
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}
constexpr const char* kCsvColumns[] = {"input", "ok", "g_m_s2", "g_uncertainty_m_s2", "largest_budget_input",
                                       "largest_budget_m_s2", "expected_g_m_s2", "z", "warnings", "error"};
}  // namespace

std::string batch_csv_header() {
  std::string line;
  for (const char* c : kCsvColumns) line += (line.empty() ? "" : ",") + std::string(c);
  return line + "\n";
}

std::string batch_csv_row(const nlohmann::ordered_json& summary) {
  std::string line;
  bool first = true;
  for (const char* c : kCsvColumns) {
    if (!first) line += ",";
    first = false;
    if (summary.contains(c)) line += csv_field(summary.at(c));
  }
  return line + "\n";
}

std::string result_to_table(const ParsedScene& scene, const Analysis& a) {
  std::ostringstream os;
  char line[256];
  if (!scene.title.empty()) os << scene.title << "\n\n";
  std::snprintf(line, sizeof line, "%-26s %12s %10s %16s  %-10s %s\n", "Correction", "dT (us)",
                "+- (us)", "dg (1e-5 m/s^2)", "status", "method");
  os << line;
  for (const auto& row : a.corrections) {
    if (row.delta_T) {
      std::snprintf(line, sizeof line, "%-26s %+12.4f %10.4f %+16.4f  %-10s %s\n", row.info.title,
                    *row.delta_T * 1e6, *row.delta_T_uncertainty * 1e6, *row.delta_g * 1e5,
                    status_name(row.status), row.method.c_str());
    } else {
      std::snprintf(line, sizeof line, "%-26s %12s %10s %16s  %-10s %s\n", row.info.title, "-", "",
                    "-", status_name(row.status), row.reason.c_str());
    }
    os << line;
  }
  std::snprintf(line, sizeof line, "%-26s %+12.4f %10s %+16.4f\n\n", "Total", a.total_delta_T * 1e6,
                "", a.total_delta_g * 1e5);
  os << line;
  std::snprintf(line, sizeof line, "Measured period T   = %.6f +- %.6f s (%d trials)\n",
                a.period_measured.value, a.period_measured.uncertainty, scene.trial_count);
  os << line;
  std::snprintf(line, sizeof line, "Ideal period T0     = %.6f +- %.6f s\n", a.period_ideal.value,
                a.period_ideal.uncertainty);
  os << line;
  std::snprintf(line, sizeof line, "g (uncorrected)     = %.5f +- %.5f m/s^2\n",
                a.g_uncorrected.value, a.g_uncorrected.uncertainty);
  os << line;
  std::snprintf(line, sizeof line,
                "g                   = %.5f +- %.5f m/s^2 (period and length alone: +- %.5f)\n",
                a.g.value, a.g.uncertainty, a.g_period_and_length_uncertainty);
  os << line;
  if (a.expected_g) {
    std::snprintf(line, sizeof line, "expected g          = %.5f +- %.5f m/s^2 (%s)\n", a.expected_g->value,
                  a.expected_g->uncertainty, a.expected_g->source.c_str());
    os << line;
    if (a.z_score) {
      std::snprintf(line, sizeof line, "difference          = %+.5f m/s^2 = %+.2f combined sigma\n",
                    a.g.value - a.expected_g->value, *a.z_score);
      os << line;
    }
  }
  if (!a.budget.empty()) {
    os << "\nUncertainty budget of g (largest first):\n";
    for (const auto& b : a.budget) {
      std::snprintf(line, sizeof line, "  %-28s %.6f m/s^2\n", b.input.c_str(), b.contribution);
      os << line;
    }
  }
  for (const auto& w : scene.warnings) os << "warning: " << w << "\n";
  for (const auto& w : a.warnings) os << "warning: " << w << "\n";
  return os.str();
}

}  // namespace pendulum
