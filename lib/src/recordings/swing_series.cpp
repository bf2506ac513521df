#include "pendulum/recordings/swing_series.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "pendulum/amplitude.hpp"

namespace pendulum {

int periods_per_group(int periods) { return std::max(4, (periods + 49) / 50); }

double amplitude_of_factor(double factor) {
  double lo = 0.0, hi = kPi;  // the factor grows from 0 to infinity on [0, pi)
  while (hi - lo > 1e-15) {
    const double mid = (lo + hi) / 2.0;
    (finite_amplitude_agm(mid) < factor ? lo : hi) = mid;
  }
  return (lo + hi) / 2.0;
}

namespace {

/// SwingGroup::amplitude_uncertainty, for groups of m half swings from the
/// crossings `starts` (one a group): d ln(1 + F_j) = sum_i f'(theta_i) theta_i x_i^T dc / (m (1 + F_j))
/// over a group's swings (f the exact factor, F_j its mean, x_i the powers of
/// the curve's time at swing i), weighted over the groups into E^T dc; a
/// common shift dtheta moves the same mean by S dtheta, S the weighted mean
/// of f'(theta_j) / (1 + F_j). The uncertainty is sqrt(E^T C E) / S.
void set_amplitude_uncertainty(const SwingAnalysis& a, std::size_t m, const std::vector<std::size_t>& starts,
                               std::vector<SwingGroup>& groups) {
  const SwingAnalysis::SmoothCurve& curve = a.smooth_curve;
  const std::size_t q = curve.coefficients.size();
  if (q == 0 || curve.covariance.size() != q * q) return;
  // f'(theta), by a central difference (the exact factor is smooth on [0, pi)).
  auto slope = [](double theta) {
    const double h = 1e-6;
    return (finite_amplitude_agm(theta + h) - finite_amplitude_agm(theta - h)) / (2.0 * h);
  };
  Eigen::VectorXd e = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(q));
  double s = 0.0, weights = 0.0;
  for (std::size_t j = 0; j < groups.size(); ++j) {
    const SwingGroup& g = groups[j];
    const double w = g.period * g.period / (g.uncertainty * g.uncertainty);
    const double one_plus = 1.0 + finite_amplitude_agm(g.amplitude);
    for (std::size_t i = starts[j]; i < starts[j] + m; ++i) {
      const double theta = a.smooth_amplitudes[i];
      const double x = (a.swings[i].peak_time - curve.mid) / curve.half;
      double power = 1.0;
      for (std::size_t k = 0; k < q; ++k, power *= x) e[k] += w * slope(theta) * theta * power / (m * one_plus);
    }
    s += w * slope(g.amplitude) / one_plus;
    weights += w;
  }
  const Eigen::Map<const Eigen::MatrixXd> cov(curve.covariance.data(), q, q);
  const double spread = std::sqrt(std::max(e.dot(cov * e), 0.0)) / weights;
  if (!(s > 0.0) || !std::isfinite(spread)) return;
  for (SwingGroup& g : groups) g.amplitude_uncertainty = spread / (s / weights);
}

}  // namespace

std::vector<SwingGroup> swing_groups(const SwingAnalysis& a) {
  const std::vector<Crossing>& c = a.crossings;
  const int cpp = a.crossings_per_period;
  std::vector<SwingGroup> out;
  if (a.smooth_amplitudes.size() + 1 != c.size() || c.empty()) return out;
  const int k = periods_per_group(a.period.periods);
  const std::size_t m = static_cast<std::size_t>(k * cpp);  // crossings spanned by a group, less one
  // The fit's index takes the smooth amplitudes where the whole record's did
  // (a swing's samples: not a photogate, whose amplitudes drift with its bias).
  const bool events = c[0].samples == 0;
  const bool weighted_index = cpp == 2 && !events;
  // Each group's fit scales its covariance by its own few residuals (5
  // degrees of freedom); pooled over the groups they are well known. The
  // whole record's are not the groups' to take: its index sums the smooth
  // amplitude's errors, which a group's own line takes up. With weights w_i
  // normalised to a mean of 1 over the crossings fitted, a crossing's time
  // has variance s^2 / w_i, so a group whose raw weights average `mean`
  // contributes its sum of squares times `mean` to the pooled s^2 of a raw
  // weight of 1, and takes that s^2 / mean.
  auto raw_weight = [&](std::size_t i) { return events ? 1.0 : c[i].slope * c[i].slope * c[i].samples; };
  // fit_crossing_times's parameters: 1, x, x^2, (-1)^i, and x^3 on the plain index from 12 crossings.
  const double dof_each = m + 1.0 - (weighted_index || m + 1 < 12 ? 4.0 : 5.0);
  std::vector<PeriodEstimate> fits;
  std::vector<std::size_t> starts;  // each group's first crossing
  std::vector<double> means;
  double pooled_ssr = 0.0, pooled_lag = 0.0, pooled_plain = 0.0, dof = 0.0;
  for (std::size_t s = 0; s + m < c.size(); s += m + 1) {
    // No group across a bridged glitch (step 8): its swings are not k periods.
    if (std::any_of(c.begin() + s + 1, c.begin() + s + m + 1, [](const Crossing& x) { return x.steps > 1; })) continue;
    const std::vector<Crossing> part(c.begin() + s, c.begin() + s + m + 1);
    const std::vector<double> theta(a.smooth_amplitudes.begin() + s, a.smooth_amplitudes.begin() + s + m);
    const PeriodEstimate p = fit_crossing_times(part, cpp, weighted_index ? theta : std::vector<double>{});
    double mean = 0.0, factor = 0.0;
    for (std::size_t i = s; i <= s + m; ++i) mean += raw_weight(i) / (m + 1);
    for (double t : theta) factor += finite_amplitude_agm(t) / m;
    const double ssr = p.residual_rms * p.residual_rms * dof_each;
    pooled_ssr += ssr * mean, pooled_plain += ssr, pooled_lag += p.lag1_correlation * ssr;
    dof += dof_each;
    SwingGroup g;
    g.start = part.front().time;
    g.end = part.back().time;
    g.periods = k;
    g.period = p.value;
    g.amplitude = amplitude_of_factor(factor);
    out.push_back(g);
    starts.push_back(s);
    fits.push_back(p);
    means.push_back(mean);
  }
  if (out.size() < 2) return {};
  // The AR(1) factor of fit_crossing_times, from the pooled lag-1 correlation.
  const double rho = std::min(pooled_plain > 0.0 ? pooled_lag / pooled_plain : 0.0, 0.95);
  const double s2 = pooled_ssr / dof * (rho > 0.0 ? (1.0 + rho) / (1.0 - rho) : 1.0);
  for (std::size_t j = 0; j < out.size(); ++j) {
    const PeriodEstimate& p = fits[j];
    const double own_s2 = p.residual_rms * p.residual_rms * p.inflation;
    out[j].uncertainty = own_s2 > 0.0 && means[j] > 0.0 ? p.uncertainty * std::sqrt(s2 / means[j] / own_s2) : p.uncertainty;
  }
  set_amplitude_uncertainty(a, m, starts, out);
  return out;
}

double amplitude_shift_sigmas(const SwingAnalysis& a, bool decay_corrected) {
  if (!std::isfinite(a.start_amplitude) || !std::isfinite(a.end_amplitude) || !(a.period.uncertainty > 0.0)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  auto h = [&](double theta) {
    return finite_amplitude_agm(theta) - (decay_corrected ? theta * theta / 16.0 : 0.0);
  };
  // T0 to the precision a ratio needs: the mean period over the mean factor of the ends.
  const double t0 = a.period.value / (1.0 + (finite_amplitude_agm(a.start_amplitude) + finite_amplitude_agm(a.end_amplitude)) / 2.0);
  return t0 * std::abs(h(a.start_amplitude) - h(a.end_amplitude)) / a.period.uncertainty;
}

}  // namespace pendulum
