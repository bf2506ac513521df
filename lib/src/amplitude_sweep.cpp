#include "pendulum/amplitude_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <boost/math/distributions/students_t.hpp>
#include <ceres/jet.h>

#include "pendulum/amplitude.hpp"
#include "pendulum/dispersion.hpp"
#include "pendulum/straight_line.hpp"
#include "text.hpp"

namespace pendulum {

namespace {

/// 2K(sin^2(theta0/2))/pi and its derivative in theta0 (1/rad).
std::pair<double, double> law_shape(double theta0) {
  const ceres::Jet<double, 1> x(theta0, 0);
  const auto f = 1.0 + finite_amplitude_agm(x);
  return {f.a, f.v[0]};
}

/// y = a + b x weighted by w (fit_straight_line with sigma_y = 1/sqrt(w)).
StraightLine weighted_line(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& w) {
  std::vector<double> sigma(w.size());
  for (std::size_t i = 0; i < w.size(); ++i) sigma[i] = 1.0 / std::sqrt(w[i]);
  return fit_straight_line(x, y, std::vector<double>(x.size(), 0.0), sigma, true);
}

/// c = slope/intercept of a line and its variance (first order).
std::pair<double, double> relative_slope(const StraightLine& l) {
  const double a = l.intercept, c = l.slope / a;
  const double var = l.var_slope / (a * a) + c * c * l.var_intercept / (a * a) - 2.0 * c * l.cov / (a * a);
  return {c, std::max(var, 0.0)};
}

}  // namespace

std::size_t distinct_amplitudes(std::vector<double> amplitudes) {
  if (amplitudes.empty()) return 0;
  std::sort(amplitudes.begin(), amplitudes.end());
  const double apart = 1e-6 * std::max(std::abs(amplitudes.front()), std::abs(amplitudes.back()));
  return static_cast<std::size_t>(
      std::unique(amplitudes.begin(), amplitudes.end(), [&](double a, double b) { return b - a <= apart; }) -
      amplitudes.begin());
}

AmplitudeSweep fit_amplitude_sweep(const std::vector<SweepPoint>& points, bool sigma_from_scatter) {
  const std::size_t n = points.size();
  if (n < 2) throw std::invalid_argument("an amplitude sweep needs two timings or more");
  std::vector<double> f(n), slope(n), v(n), w(n), theta2(n), period(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::tie(f[i], slope[i]) = law_shape(points[i].amplitude);
    theta2[i] = points[i].amplitude * points[i].amplitude;
    period[i] = points[i].period;
  }
  // T0 = sum w f T / sum w f^2, each weight 1/(sigma_T^2 + (T0 f' sigma_theta)^2 + s^2) at the last T0.
  // From the scatter, s^2 is the periods' own variance, common to all, that makes chi2 = n - 1 (zero
  // where the floors already explain the scatter): added, not multiplied, so that an amplitude's
  // uncertainty carried to its period is not scaled with it.
  AmplitudeSweep out;
  double t0 = 0.0, s2 = 0.0;
  auto chi2_at = [&](double t0_, double extra) {
    double chi2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) chi2 += std::pow(period[i] - t0_ * f[i], 2) / (v[i] + extra);
    return chi2;
  };
  for (int pass = 0; pass < 6; ++pass) {
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double carried = t0 * slope[i] * points[i].amplitude_sigma;
      v[i] = points[i].period_sigma * points[i].period_sigma + carried * carried;
      w[i] = 1.0 / (v[i] + s2);
      num += w[i] * f[i] * period[i];
      den += w[i] * f[i] * f[i];
    }
    t0 = num / den;
    out.t0 = {t0, 1.0 / std::sqrt(den)};
    if (sigma_from_scatter && chi2_at(t0, 0.0) > static_cast<double>(n - 1)) {
      double lo = 0.0, hi = 1.0;
      for (std::size_t i = 0; i < n; ++i) hi = std::max(hi, std::pow(period[i] - t0 * f[i], 2) * static_cast<double>(n));
      for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
        const double mid = (lo + hi) / 2.0;
        (chi2_at(t0, mid) > static_cast<double>(n - 1) ? lo : hi) = mid;
      }
      s2 = hi;
    }
  }
  const double floor_only = out.t0.uncertainty.value();
  for (std::size_t i = 0; i < n; ++i) out.chi2 += w[i] * std::pow(period[i] - t0 * f[i], 2);
  out.dof = static_cast<int>(n) - 1;
  out.sigma_from_scatter = sigma_from_scatter;
  if (!sigma_from_scatter) {
    // Stated uncertainties that the scatter exceeds improbably: the Birge ratio, with n - 1 degrees of freedom.
    const Dispersion d = dispersion(out.chi2, out.dof);
    out.probability = d.probability;
    out.scale = d.applied_scale();
    out.t0.uncertainty = floor_only * out.scale;
  } else {
    double den = 0.0;
    for (std::size_t i = 0; i < n; ++i) den += w[i] * f[i] * f[i];
    out.t0.uncertainty = 1.0 / std::sqrt(den);
    double floor_den = 0.0;
    for (std::size_t i = 0; i < n; ++i) floor_den += f[i] * f[i] / v[i];
    out.scale = *out.t0.uncertainty * std::sqrt(floor_den);
  }
  const bool from_scatter = sigma_from_scatter || out.scale > 1.0;
  out.t0_dof = from_scatter ? static_cast<double>(out.dof) : std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    out.law.push_back(t0 * f[i]);
    out.effective_sigma.push_back((sigma_from_scatter ? 1.0 : out.scale) / std::sqrt(w[i]));
    out.residual.push_back((period[i] - out.law.back()) / out.effective_sigma.back());
  }
  const auto [lo, hi] = std::minmax_element(points.begin(), points.end(),
                                            [](const auto& a, const auto& b) { return a.amplitude < b.amplitude; });
  out.low = lo->amplitude, out.high = hi->amplitude;

  std::vector<double> amplitudes;
  for (const SweepPoint& p : points) amplitudes.push_back(p.amplitude);
  if (distinct_amplitudes(amplitudes) < 3) return out;
  // The quadratic's c, and the law's own c fitted the same way to T0 f.
  const StraightLine measured = weighted_line(theta2, period, w);
  const StraightLine law = weighted_line(theta2, out.law, w);
  const auto [c, var_c] = relative_slope(measured);
  // c's uncertainty is from the quadratic's own scatter (n - 2 degrees of
  // freedom), judged by Student's t: a law that misses the periods does not
  // widen the test that finds it out, and uncertainties stated too small do
  // not refute a true law (with the stated ones where the scatter was below
  // them, 3 % of true laws were refuted for 1 % at uncertainties a quarter
  // of the scatter: a small scatter says nothing of c's own error).
  double chi2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) chi2 += w[i] * std::pow(period[i] - measured.intercept - measured.slope * theta2[i], 2);
  const double s_q = std::sqrt(chi2 / static_cast<double>(n - 2));
  const double sigma_c = std::sqrt(var_c) * s_q;
  if (!std::isfinite(c) || !std::isfinite(law.slope / law.intercept) || !(sigma_c > 0.0) || !std::isfinite(sigma_c)) return out;
  out.coefficient = Estimate{c, sigma_c};
  out.coefficient_law = law.slope / law.intercept;
  out.quadratic_t0 = measured.intercept;
  const double z = std::abs(c - out.coefficient_law) / sigma_c;
  out.coefficient_probability =
      2.0 * boost::math::cdf(boost::math::complement(boost::math::students_t(static_cast<double>(n - 2)), z));
  return out;
}

std::string sweep_law_finding(const AmplitudeSweep& s) {
  return "amplitude sweep: the periods rise with the amplitude as T0 (1 + c theta0^2) with c = " +
         format_number(s.coefficient->value, 3) + " +- " + format_number(*s.coefficient->uncertainty, 2) +
         " 1/rad^2, where the exact law gives " + format_number(s.coefficient_law, 4) +
         " at these amplitudes (1/16 at small ones; probability " + format_number(*s.coefficient_probability, 2) +
         "): amplitudes misread (their unit; a release angle where the timing's mean was wanted?), or a pendulum "
         "that is not simple (a string that stretches, a bob that turns)";
}

}  // namespace pendulum
