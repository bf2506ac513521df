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

}  // namespace

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
  g["budget"] = budget;

  json corrections = json::array();
  for (const auto& row : a.corrections) {
    json c = {{"id", row.info.id},
              {"title", row.info.title},
              {"status", status_name(row.status)},
              {"delta_T_s", optional_number(row.delta_T)},
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

  return {{"schema", kResultSchema},
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
          {"warnings", scene.warnings}};
}

std::string result_to_table(const ParsedScene& scene, const Analysis& a) {
  std::ostringstream os;
  char line[256];
  if (!scene.title.empty()) os << scene.title << "\n\n";
  std::snprintf(line, sizeof line, "%-26s %12s %16s  %-10s %s\n", "Correction", "dT (us)",
                "dg (1e-5 m/s^2)", "status", "method");
  os << line;
  for (const auto& row : a.corrections) {
    if (row.delta_T) {
      std::snprintf(line, sizeof line, "%-26s %+12.4f %+16.4f  %-10s %s\n", row.info.title,
                    *row.delta_T * 1e6, *row.delta_g * 1e5, status_name(row.status),
                    row.method.c_str());
    } else {
      std::snprintf(line, sizeof line, "%-26s %12s %16s  %-10s %s\n", row.info.title, "-", "-",
                    status_name(row.status), row.reason.c_str());
    }
    os << line;
  }
  std::snprintf(line, sizeof line, "%-26s %+12.4f %+16.4f\n\n", "Total", a.total_delta_T * 1e6,
                a.total_delta_g * 1e5);
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
  std::snprintf(line, sizeof line, "g                   = %.5f +- %.5f m/s^2\n", a.g.value,
                a.g.uncertainty);
  os << line;
  for (const auto& w : scene.warnings) os << "warning: " << w << "\n";
  return os.str();
}

}  // namespace pendulum
