#include "pendulum/amplitude_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <ceres/jet.h>

#include "pendulum/amplitude.hpp"
#include "pendulum/dispersion.hpp"
#include "text.hpp"

namespace pendulum {

namespace {

/// 2K(sin^2(theta0/2))/pi and its derivative in theta0 (1/rad).
std::pair<double, double> law_shape(double theta0) {
  const ceres::Jet<double, 1> x(theta0, 0);
  const auto f = 1.0 + finite_amplitude_agm(x);
  return {f.a, f.v[0]};
}

/// The weighted straight line y = a + b x: a, b and their covariance.
struct Line {
  double a, b, var_a, var_b, cov;
};

Line weighted_line(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& w) {
  double s = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    s += w[i], sx += w[i] * x[i], sy += w[i] * y[i], sxx += w[i] * x[i] * x[i], sxy += w[i] * x[i] * y[i];
  }
  const double d = s * sxx - sx * sx;
  return {(sxx * sy - sx * sxy) / d, (s * sxy - sx * sy) / d, sxx / d, s / d, -sx / d};
}

/// c = b/a of a line and its variance (first order).
std::pair<double, double> relative_slope(const Line& l) {
  const double c = l.b / l.a;
  const double var = l.var_b / (l.a * l.a) + c * c * l.var_a / (l.a * l.a) - 2.0 * c * l.cov / (l.a * l.a);
  return {c, std::max(var, 0.0)};
}

}  // namespace

AmplitudeSweep fit_amplitude_sweep(const std::vector<SweepPoint>& points, bool sigma_from_scatter) {
  const std::size_t n = points.size();
  if (n < 2) throw std::invalid_argument("an amplitude sweep needs two timings or more");
  std::vector<double> f(n), slope(n), w(n), theta2(n), period(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::tie(f[i], slope[i]) = law_shape(points[i].amplitude);
    theta2[i] = points[i].amplitude * points[i].amplitude;
    period[i] = points[i].period;
  }
  // T0 = sum w f T / sum w f^2, the weights 1/(sigma_T^2 + (T0 f' sigma_theta)^2) at the last T0.
  AmplitudeSweep out;
  double t0 = 0.0;
  for (int pass = 0; pass < 4; ++pass) {
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double carried = t0 * slope[i] * points[i].amplitude_sigma;
      w[i] = 1.0 / (points[i].period_sigma * points[i].period_sigma + carried * carried);
      num += w[i] * f[i] * points[i].period;
      den += w[i] * f[i] * f[i];
    }
    t0 = num / den;
    out.t0 = {t0, 1.0 / std::sqrt(den)};
  }
  for (std::size_t i = 0; i < n; ++i) out.chi2 += w[i] * std::pow(points[i].period - t0 * f[i], 2);
  out.dof = static_cast<int>(n) - 1;
  const Dispersion d = dispersion(out.chi2, out.dof);
  out.sigma_from_scatter = sigma_from_scatter;
  out.scale = sigma_from_scatter ? std::max(d.birge_ratio.value_or(1.0), 1.0) : d.applied_scale();
  if (!sigma_from_scatter) out.probability = d.probability;
  out.t0.uncertainty = *out.t0.uncertainty * out.scale;
  out.t0_dof = sigma_from_scatter ? static_cast<double>(out.dof) : std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    out.law.push_back(t0 * f[i]);
    out.effective_sigma.push_back(out.scale / std::sqrt(w[i]));
    out.residual.push_back((points[i].period - out.law.back()) / out.effective_sigma.back());
  }
  const auto [lo, hi] = std::minmax_element(points.begin(), points.end(),
                                            [](const auto& a, const auto& b) { return a.amplitude < b.amplitude; });
  out.low = lo->amplitude, out.high = hi->amplitude;

  std::vector<double> distinct = theta2;
  std::sort(distinct.begin(), distinct.end());
  if (std::unique(distinct.begin(), distinct.end()) - distinct.begin() < 3) return out;
  // The quadratic's c, and the law's own c fitted the same way to T0 f.
  const Line measured = weighted_line(theta2, period, w);
  const Line law = weighted_line(theta2, out.law, w);
  const auto [c, var_c] = relative_slope(measured);
  out.coefficient_law = law.b / law.a;
  // The quadratic's own scatter (n - 2 degrees of freedom) scales its
  // uncertainty as the law's scales T0's: a law that misses the periods
  // must not widen the test that finds it out.
  double chi2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) chi2 += w[i] * std::pow(period[i] - measured.a - measured.b * theta2[i], 2);
  const Dispersion q = dispersion(chi2, static_cast<int>(n) - 2);
  const double s_q = sigma_from_scatter ? std::max(q.birge_ratio.value_or(1.0), 1.0) : q.applied_scale();
  const double scale2 = s_q * s_q;
  out.coefficient = Estimate{c, std::sqrt(var_c * scale2)};
  out.quadratic_t0 = measured.a;
  if (*out.coefficient->uncertainty > 0.0) {
    const double z = std::abs(c - out.coefficient_law) / *out.coefficient->uncertainty;
    out.coefficient_probability =
        sigma_from_scatter ? (n > 2 ? 2.0 * boost::math::cdf(boost::math::complement(
                                                boost::math::students_t(static_cast<double>(n - 2)), z))
                                    : 1.0)
                           : 2.0 * boost::math::cdf(boost::math::complement(boost::math::normal(), z));
  }
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
