#include "pendulum/analysis.hpp"

#include <algorithm>
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
  ReductionOptions reduction = options.reduction;
  reduction.amplitude_tolerance =
      options.amplitude_fraction * scene.uncertainty.period / scene.value.period;
  const Reduction<double> r = reduce(scene.value, reduction);
  out.period_measured = {scene.value.period, scene.uncertainty.period};
  out.negligible_below = options.negligible_fraction * scene.uncertainty.period;

  // Every input with a stated uncertainty, and the derivatives of g, T0 and
  // each row with respect to it, by one dual-number reduction per input.
  struct Input {
    std::string path;
    double value, sigma;
    Reduction<Dual> d;
  };
  std::vector<Input> inputs;
  zip_fields(scene.value, scene.uncertainty, [&](const char* path, const double& v, const double& u) {
    if (u > 0.0) inputs.push_back({path, v, u, reduce_seeded(scene, path, reduction)});
  });
  // Their covariance matrix: diagonal but for alpha and beta of one fit.
  const std::size_t k = inputs.size();
  std::vector<double> cov(k * k, 0.0);
  for (std::size_t a = 0; a < k; ++a) {
    cov[a * k + a] = inputs[a].sigma * inputs[a].sigma;
    for (std::size_t b = 0; b < k; ++b) {
      if (out.decay_fit && inputs[a].path == "decay.alpha" && inputs[b].path == "decay.beta") {
        cov[a * k + b] = cov[b * k + a] = out.decay_fit->covariance[1];
      }
    }
  }
  // Var f = sum_ab df/da cov(a, b) df/db over the inputs `keep` accepts.
  std::vector<double> d(k);
  const auto variance = [&](auto&& derivative, auto&& keep) {
    for (std::size_t a = 0; a < k; ++a) d[a] = keep(inputs[a]) ? derivative(inputs[a].d) : 0.0;
    double v = 0.0;
    for (std::size_t a = 0; a < k; ++a) {
      if (d[a] == 0.0) continue;
      for (std::size_t b = 0; b < k; ++b) v += d[a] * cov[a * k + b] * d[b];
    }
    return std::sqrt(std::max(v, 0.0));
  };
  const auto all = [](const Input&) { return true; };
  const auto g_of = [](const Reduction<Dual>& d) { return d.g.v[0]; };
  out.g = {r.g, variance(g_of, all)};
  out.g_period_and_length_uncertainty = variance(g_of, [](const Input& a) {
    return a.path == "timing.trials" || a.path == "length";
  });
  out.period_ideal = {r.period_ideal, variance([](const Reduction<Dual>& d) { return d.period_ideal.v[0]; }, all)};
  out.g_uncorrected = {r.g_uncorrected, variance([](const Reduction<Dual>& d) { return d.g_uncorrected.v[0]; }, all)};
  for (const Input& a : inputs) {
    out.budget.push_back({a.path, scene.si_unit.at(a.path), a.value, a.sigma, g_of(a.d),
                          std::abs(g_of(a.d)) * a.sigma});
  }
  std::stable_sort(out.budget.begin(), out.budget.end(),
                   [](const BudgetEntry& x, const BudgetEntry& y) { return x.contribution > y.contribution; });
  if (out.decay_fit && out.decay_fit->alpha.uncertainty && out.decay_fit->beta.uncertainty) {
    double d_alpha = 0.0, d_beta = 0.0;
    for (const Input& a : inputs) {
      if (a.path == "decay.alpha") d_alpha = g_of(a.d);
      if (a.path == "decay.beta") d_beta = g_of(a.d);
    }
    out.budget_correlation = BudgetCorrelation{"decay.alpha", "decay.beta", out.decay_fit->correlation_alpha_beta,
                                               2.0 * d_alpha * d_beta * out.decay_fit->covariance[1]};
  }
  zip_fields(scene.value, scene.uncertainty, [&](const char* path, const double&, const double& u) {
    if (u == 0.0) out.inputs_without_uncertainty.push_back(path);
  });

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
      row.delta_T_uncertainty = variance(
          [i](const Reduction<Dual>& d) { return (*d.terms[i].ratio * d.period_ideal).v[0]; }, all);
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

  if (scene.site) out.expected_g = expected_gravity(*scene.site);
  if (out.expected_g) {
    const double combined = std::hypot(out.g.uncertainty, out.expected_g->uncertainty);
    const double z = (out.g.value - out.expected_g->value) / combined;
    if (combined > 0.0 && std::isfinite(z)) out.z_score = z;
  }

  // An uncertainty so large that the propagated ones overflow (1e300 on a
  // rate, say) is the input's fault: name the input that contributes most.
  bool finite_uncertainties = std::isfinite(out.g.uncertainty) &&
                              std::isfinite(out.period_ideal.uncertainty) &&
                              std::isfinite(out.g_uncorrected.uncertainty);
  for (const auto& row : out.corrections) {
    if (row.delta_T_uncertainty && !std::isfinite(*row.delta_T_uncertainty)) finite_uncertainties = false;
  }
  if (!finite_uncertainties && !out.budget.empty()) {
    const auto worst = std::max_element(out.budget.begin(), out.budget.end(), [](const auto& x, const auto& y) {
      return !(std::abs(x.sensitivity) * x.uncertainty >= std::abs(y.sensitivity) * y.uncertainty);
    });
    std::ostringstream why;
    why << "got " << worst->uncertainty << " " << worst->unit
        << "; expected an uncertainty small enough for g's uncertainty to stay finite";
    throw InputError(worst->input + ".uncertainty", why.str());
  }

  // A non-finite number here is a bug, not an input error: never print it.
  auto check = [](double x, const char* what) {
    if (!std::isfinite(x)) throw std::logic_error(std::string("non-finite ") + what);
  };
  check(out.g.value, "g");
  check(out.g.uncertainty, "uncertainty of g");
  check(out.period_ideal.uncertainty, "uncertainty of the ideal period");
  check(out.period_ideal.value, "ideal period");
  for (const auto& row : out.corrections) {
    if (row.delta_T) check(*row.delta_T, row.info.id);
  }
  return out;
}

}  // namespace pendulum
