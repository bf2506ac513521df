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

std::string dispersion_finding(const Dispersion& d, const std::string& points) {
  return points + " " + format_number(*d.birge_ratio, 3) +
         " times as much as their stated uncertainties allow (chi2/dof = " + format_number(d.chi2 / d.dof, 3) +
         ", chi2 = " + format_number(d.chi2, 4) + " for " + std::to_string(d.dof) +
         " degrees of freedom, probability " + format_number(*d.probability, 2) + ")";
}

}  // namespace pendulum
