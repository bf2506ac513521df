#include "pendulum/report/decay_record.hpp"

#include <algorithm>
#include <cmath>

#include <ceres/jet.h>

#include "pendulum/damping.hpp"
#include "pendulum/report/svg_plot.hpp"

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

}  // namespace pendulum::report
