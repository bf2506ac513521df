#include "pendulum/dispersion.hpp"

#include <algorithm>
#include <cmath>

#include <boost/math/special_functions/gamma.hpp>

#include "text.hpp"

namespace pendulum {

Dispersion dispersion(double chi2, int dof) {
  Dispersion d;
  d.chi2 = chi2;
  d.dof = dof;
  if (dof <= 0 || !(chi2 >= 0.0) || !std::isfinite(chi2)) return d;
  d.probability = boost::math::gamma_q(dof / 2.0, chi2 / 2.0);
  d.birge_ratio = std::sqrt(chi2 / dof);
  d.over_dispersed = *d.probability < kOverDispersedProbability && *d.birge_ratio > 1.0;
  return d;
}

double scaled_uncertainty(double sigma, double sigma_scatter, double scale) {
  return std::sqrt(std::max(sigma * sigma + (scale * scale - 1.0) * sigma_scatter * sigma_scatter, 0.0));
}

std::optional<double> length_scatter(const std::vector<double>& residual, const std::vector<double>& variance,
                                     const std::vector<double>& slope, int dof) {
  // chi2(t), t = tau^2, falls and is convex: Newton's steps from t = 0 stay
  // below the root and rise to it monotonically.
  const auto chi2 = [&](double t, double* derivative) {
    double sum = 0.0, d = 0.0;
    for (std::size_t k = 0; k < residual.size(); ++k) {
      const double v = variance[k] + slope[k] * slope[k] * t, q = residual[k] * residual[k] / v;
      sum += q;
      d -= q * slope[k] * slope[k] / v;
    }
    if (derivative) *derivative = d;
    return sum;
  };
  if (dof <= 0 || !(chi2(0.0, nullptr) > dof)) return 0.0;
  double unexplained = 0.0;  // chi2 as t grows without bound
  for (std::size_t k = 0; k < residual.size(); ++k) {
    if (slope[k] == 0.0) unexplained += residual[k] * residual[k] / variance[k];
  }
  if (unexplained >= dof) return std::nullopt;
  double t = 0.0;
  for (int i = 0; i < 200; ++i) {
    double d = 0.0;
    const double step = (chi2(t, &d) - dof) / -d;
    if (!(step > 1e-15 * t)) break;
    t += step;
  }
  return std::sqrt(t);
}

std::string dispersion_finding(const Dispersion& d, const std::string& points) {
  return points + " " + format_number(*d.birge_ratio, 3) +
         " times as much as their stated uncertainties allow (chi2/dof = " + format_number(d.chi2 / d.dof, 3) +
         ", chi2 = " + format_number(d.chi2, 4) + " for " + std::to_string(d.dof) +
         " degrees of freedom, probability " + format_number(*d.probability, 2) + ")";
}

}  // namespace pendulum
