#include "pendulum/analysis.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <ceres/jet.h>

namespace pendulum {

const char* status_name(Status s) {
  switch (s) {
    case Status::applied: return "applied";
    case Status::negligible: return "negligible";
    case Status::skipped: return "skipped";
  }
  return "";
}

namespace {

using Dual = ceres::Jet<double, 1>;

/// The reduction on dual numbers seeded on one input: its derivatives.
Reduction<Dual> reduce_seeded(const ParsedScene& scene, const std::string& input,
                              const ReductionOptions& options) {
  const Scene<Dual> dual = convert_scene<Dual>(
      scene.value, [&](const char* path, double x) {
        return input == path ? Dual(x, 0) : Dual(x);
      });
  return reduce(dual, options);
}

}  // namespace

Analysis analyse(const ParsedScene& scene, const AnalysisOptions& options) {
  ReductionOptions reduction = options.reduction;
  reduction.amplitude_tolerance =
      options.amplitude_fraction * scene.uncertainty.period / scene.value.period;
  const Reduction<double> r = reduce(scene.value, reduction);
  Analysis out;
  out.period_measured = {scene.value.period, scene.uncertainty.period};
  out.negligible_below = options.negligible_fraction * scene.uncertainty.period;

  double var_g = 0.0, var_t0 = 0.0, var_g0 = 0.0;
  for (const auto& input : options.propagated_inputs) {
    double value = 0.0, sigma = 0.0;
    bool found = false;
    zip_fields(scene.value, scene.uncertainty,
               [&](const char* path, const double& v, const double& u) {
                 if (input != path) return;
                 value = v;
                 sigma = u;
                 found = true;
               });
    if (!found) continue;  // the scene lacks this part
    const Reduction<Dual> d = reduce_seeded(scene, input, reduction);
    const double dg = d.g.v[0];
    var_g += dg * dg * sigma * sigma;
    var_t0 += d.period_ideal.v[0] * d.period_ideal.v[0] * sigma * sigma;
    var_g0 += d.g_uncorrected.v[0] * d.g_uncorrected.v[0] * sigma * sigma;
    out.budget.push_back({input, scene.si_unit.at(input), value, sigma, dg,
                          std::abs(dg) * sigma});
  }
  out.g = {r.g, std::sqrt(var_g)};
  out.period_ideal = {r.period_ideal, std::sqrt(var_t0)};
  out.g_uncorrected = {r.g_uncorrected, std::sqrt(var_g0)};

  out.total_delta_T = r.total_ratio * r.period_ideal;
  out.total_delta_g = 2.0 * r.g * r.total_ratio;
  for (int i = 0; i < kCorrectionCount; ++i) {
    const Term<double>& term = r.terms[i];
    CorrectionRow row;
    row.info = kCorrections[i];
    row.method = term.method;
    row.series_terms = term.series_terms;
    if (!term.ratio) {
      row.status = Status::skipped;
      row.reason = term.skip_reason;
    } else {
      row.ratio = *term.ratio;
      row.delta_T = *term.ratio * r.period_ideal;
      row.delta_g = 2.0 * r.g * *term.ratio;
      if (term.error_bound) row.error_bound_delta_T = *term.error_bound * r.period_ideal;
      row.status = std::abs(*row.delta_T) < out.negligible_below ? Status::negligible
                                                                  : Status::applied;
      if (row.status == Status::negligible) {
        std::ostringstream why;
        why << "|delta_T| below " << options.negligible_fraction
            << " of the period's uncertainty (" << out.negligible_below << " s)";
        row.reason = why.str();
      }
    }
    out.corrections.push_back(row);
  }

  // A non-finite number here is a bug, not an input error: never print it.
  auto check = [](double x, const char* what) {
    if (!std::isfinite(x)) throw std::logic_error(std::string("non-finite ") + what);
  };
  check(out.g.value, "g");
  check(out.g.uncertainty, "uncertainty of g");
  check(out.period_ideal.value, "ideal period");
  for (const auto& row : out.corrections) {
    if (row.delta_T) check(*row.delta_T, row.info.id);
  }
  return out;
}

}  // namespace pendulum
