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

std::vector<std::string> review_decay_fit(const DecayFit& fit) {
  std::vector<std::string> warnings;
  if (!fit.converged) warnings.push_back("decay fit: did not converge (" + fit.termination + ")");
  if (fit.uncertainty_scaling == "sigma" && fit.dof > 0) {
    const double reduced = fit.chi2 / fit.dof;
    // chi2/dof has standard deviation sqrt(2/dof) when the sigmas are right.
    if (std::abs(reduced - 1.0) > 4.0 * std::sqrt(2.0 / fit.dof)) {
      std::ostringstream w;
      w << "decay fit: chi2/dof = " << reduced << " with " << fit.dof
        << " degrees of freedom; the stated sigma or the model (Eq. 25) does not fit the data";
      warnings.push_back(w.str());
    }
  }
  for (const auto& [name, q] : {std::pair{"alpha", fit.alpha}, std::pair{"beta", fit.beta}}) {
    if (q.fitted && !q.at_bound && !q.significant) {
      warnings.push_back(std::string("decay fit: ") + name +
                         " is not significant (less than two standard uncertainties from 0)");
    }
  }
  return warnings;
}

ParsedScene with_fitted_decay(const ParsedScene& scene, const DecayFit& fit) {
  ParsedScene out = scene;
  out.value.decay = Decay<double>{fit.alpha.value, fit.beta.value};
  out.uncertainty.decay = Decay<double>{fit.alpha.uncertainty.value_or(0.0),
                                        fit.beta.uncertainty.value_or(0.0)};
  out.si_unit["decay.alpha"] = "1/s";
  out.si_unit["decay.beta"] = "1/(s rad)";
  return out;
}

Analysis analyse(const ParsedScene& given, const AnalysisOptions& options) {
  Analysis out;
  std::optional<ParsedScene> fitted;
  if (given.decay_data) {
    out.decay_fit = fit_decay(*given.decay_data);
    out.decay_given = given.value.decay;
    out.warnings = review_decay_fit(*out.decay_fit);
    fitted = with_fitted_decay(given, *out.decay_fit);
  }
  const ParsedScene& scene = fitted ? *fitted : given;
  if (scene.value.decay) out.drag = predict_drag(scene.value);
  const Reduction<double> r = reduce(scene.value, options.reduction);
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
    const Reduction<Dual> d = reduce_seeded(scene, input, options.reduction);
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
    if (!term.ratio) {
      row.status = Status::skipped;
      row.reason = term.skip_reason;
    } else {
      row.ratio = *term.ratio;
      row.delta_T = *term.ratio * r.period_ideal;
      row.delta_g = 2.0 * r.g * *term.ratio;
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
