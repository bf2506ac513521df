#include "pendulum/recordings/swing_series.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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
  // Each group's fit scales its covariance by its own few residuals; the
  // whole record's residual variance is far better known. With weights w_i
  // normalised to a mean of 1 over the crossings fitted, a crossing's time has
  // variance s^2 / w_i, so a group whose raw weights average `mean` of the
  // record's takes s^2 (record) * mean(record) / mean(group).
  auto raw_weight = [&](std::size_t i) { return events ? 1.0 : c[i].slope * c[i].slope * c[i].samples; };
  double record_mean = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) record_mean += raw_weight(i) / c.size();
  const double record_s2 = a.period.residual_rms * a.period.residual_rms * a.period.inflation;
  for (std::size_t s = 0; s + m < c.size(); s += m + 1) {
    const std::vector<Crossing> part(c.begin() + s, c.begin() + s + m + 1);
    const std::vector<double> theta(a.smooth_amplitudes.begin() + s, a.smooth_amplitudes.begin() + s + m);
    const PeriodEstimate p = fit_crossing_times(part, cpp, weighted_index ? theta : std::vector<double>{});
    double group_mean = 0.0, factor = 0.0;
    for (std::size_t i = s; i <= s + m; ++i) group_mean += raw_weight(i) / (m + 1);
    for (double t : theta) factor += finite_amplitude_agm(t) / m;
    SwingGroup g;
    g.start = part.front().time;
    g.end = part.back().time;
    g.periods = k;
    g.period = p.value;
    const double own_s2 = p.residual_rms * p.residual_rms * p.inflation;
    g.uncertainty = own_s2 > 0.0 && group_mean > 0.0
                        ? p.uncertainty * std::sqrt(record_s2 * record_mean / group_mean / own_s2)
                        : p.uncertainty;
    g.amplitude = amplitude_of_factor(factor);
    out.push_back(g);
  }
  if (out.size() < 2) out.clear();
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
