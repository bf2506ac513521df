// A physical pendulum's pivot scan for the report: the fitted model and the
// textbook curve sampled on each side of the centre of mass (docs/report.md).
#include <algorithm>
#include <cmath>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "pendulum/bodies.hpp"
#include "pendulum/models/physical_pendulum.hpp"
#include "pendulum/report/scene_report.hpp"
#include "pendulum/report/svg_plot.hpp"

namespace pendulum::report {

namespace {

using M = PhysicalPendulum;

constexpr int kBranchPoints = 400;
constexpr double kRangeMargin = 0.08;  // of the period range, above and below
constexpr double kSettingMargin = 0.05;  // of the settings' span, either side

/// The h in [a, b] where f, monotone there, crosses `level` (f(a) and f(b)
/// on either side of it), by bisection down to adjacent doubles.
double crossing(const std::function<double(double)>& f, double a, double b, double level) {
  const bool rising = f(a) < f(b);
  for (;;) {
    const double m = 0.5 * (a + b);
    if (m <= a || m >= b) return rising ? a : b;  // the end inside the range
    ((f(m) < level) == rising ? a : b) = m;
  }
}

/// The branch of the curve T(h) on one side (+1 or -1) of the centre c:
/// kBranchPoints uniform in h from where T comes down to `top` near the
/// centre (h < k, where T falls) to h_far, or to where T rises to `top`
/// again beyond h = k. Empty when no part of it is below `top`.
PivotScanRecord::Branch branch(const std::function<double(double)>& period, double k, double c, double side,
                               double h_far, double top) {
  PivotScanRecord::Branch b;
  if (!(h_far > 0.0)) return b;
  const double bottom = std::min(k, h_far);
  if (!(period(bottom) < top)) return b;
  const double h_near = crossing(period, bottom * 1e-9, bottom, top);
  const double h_end = period(h_far) <= top ? h_far : crossing(period, k, h_far, top);
  for (int i = 0; i < kBranchPoints; ++i) {
    const double h = h_near + (h_end - h_near) * i / (kBranchPoints - 1);
    b.x.push_back(c + side * h);
    b.period.push_back(period(h));
  }
  return b;
}

/// The analysis's amplitude method for an observation, from its row.
AmplitudeChoice amplitude_choice(const ObservationResult& o) {
  for (const auto& row : o.corrections) {
    if (row.info.id != std::string("finite_amplitude")) continue;
    for (AmplitudeMethod m : {AmplitudeMethod::small_angle, AmplitudeMethod::series, AmplitudeMethod::agm}) {
      if (row.method == method_name(m)) return {m, row.series_terms, 0.0};
    }
  }
  return {AmplitudeMethod::agm, 0, 0.0};
}

}  // namespace

std::optional<PivotScanRecord> pivot_scan_record(const ParsedScene& given, const Analysis& a) {
  // Only the rigid body's model reports a pivot scan (PhysicalPendulum::report), one body's (not a series of rods').
  const PivotScan* pivot_scan = a.fit.results_of<PhysicalPendulum>();
  if (!pivot_scan || !pivot_scan->textbook || !pivot_scan->minimum_period || a.observations.empty()) return std::nullopt;
  // The apparatus the analysis fitted with: alpha and beta from the decay record's fit.
  const std::optional<ParsedScene> fitted_decay = scene_with_fitted_decay(given, a.decay_fit);
  const ParsedScene& scene = fitted_decay ? *fitted_decay : given;
  const Apparatus<double>& app = scene.apparatus;
  const PivotScan& scan = *pivot_scan;
  std::array<double, M::kParameters> p{};
  for (int i = 0; i < M::kParameters; ++i) p[i] = a.fit.parameters[i].value;

  PivotScanRecord r;
  r.setting = scene.observations.front().setting;
  const bool positions = r.setting == Setting::pivot_position;
  r.center = !positions ? 0.0
             : app.body && app.body->center_of_mass_position ? *app.body->center_of_mass_position
                                                             : p[M::center_of_mass_position];
  r.radius_of_gyration = std::abs(M::gyration(p.data(), app));

  // The curve's observation: the median amplitude, timed like the first.
  std::vector<double> amplitudes;
  for (const auto& o : a.observations) amplitudes.push_back(o.amplitude);
  std::sort(amplitudes.begin(), amplitudes.end());
  const std::size_t n = amplitudes.size();
  r.amplitude = n % 2 ? amplitudes[n / 2] : 0.5 * (amplitudes[n / 2 - 1] + amplitudes[n / 2]);
  r.amplitude_min = amplitudes.front();
  r.amplitude_max = amplitudes.back();
  const auto nearest = std::min_element(a.observations.begin(), a.observations.end(), [&](const auto& x, const auto& y) {
    return std::abs(x.amplitude - r.amplitude) < std::abs(y.amplitude - r.amplitude);
  });
  r.amplitude_method = amplitude_choice(*nearest);
  r.oscillations_per_trial = scene.observations.front().oscillations_per_trial;
  Observation<double> like = scene.observations.front();
  like.amplitude = r.amplitude;
  // The model at the setting x; its working period is its ideal period there.
  auto model_at = [&](double x) {
    Observation<double> o = like;
    o.length = x;
    o.period = ideal_period(M::swing_at(p.data(), M::swing(o), app).length, p[M::g]);
    return predicted_period<M>(p.data(), M::swing(o), app, r.amplitude_method);
  };

  r.minimum_period = *scan.minimum_period;
  r.minimum_pivot_distance = *scan.minimum_pivot_distance;
  r.minimum_x = positions ? scan.minimum_pivot_positions : std::vector<Estimate>{r.minimum_pivot_distance};
  r.minimum_model_period = model_at(r.minimum_x.front().value);
  const PivotScan::Conjugate& first = scan.conjugates.front();
  r.conjugate_x = positions ? first.pivot_position : std::optional<Estimate>(first.pivot_distance);
  r.equivalent_length = first.equivalent_length;
  r.conjugate_period = model_at(scene.observations.front().length);
  r.bessel_g = scan.bessel_g;

  // The plotted ranges: every observation with its error bar, and the marks.
  double low = r.minimum_model_period, high = r.minimum_model_period;
  double x_lo = HUGE_VAL, x_hi = -HUGE_VAL;
  for (const auto& o : a.observations) {
    const double u = o.effective_uncertainty > 0.0 ? o.effective_uncertainty : o.period_measured.uncertainty;
    r.uncertainties.push_back(u);
    low = std::min(low, o.period_measured.value - u);
    high = std::max(high, o.period_measured.value + u);
    x_lo = std::min(x_lo, o.length);
    x_hi = std::max(x_hi, o.length);
  }
  for (const auto& x : r.minimum_x) x_lo = std::min(x_lo, x.value), x_hi = std::max(x_hi, x.value);
  if (r.conjugate_x) x_lo = std::min(x_lo, r.conjugate_x->value), x_hi = std::max(x_hi, r.conjugate_x->value);
  const double margin = kRangeMargin * std::max(high - low, 0.25 * kRangeMargin * high);
  // Out to the period axis's own ticks, so that the curves end at its top
  // label and the caption's "stops at" is that label.
  const Ticks axis = nice_ticks(low - margin, high + margin, panel_intervals(Panel{}.height));
  r.period_low = axis.lo;
  r.period_high = axis.hi;
  const double pad = kSettingMargin * (x_hi - x_lo);
  x_lo -= pad;
  x_hi += pad;

  // The textbook's straight line in h^2 on the measured periods, without corrections.
  const PivotScan::Textbook& t = *scan.textbook;
  r.textbook_g = t.g.value;
  r.textbook_g_uncertainty = t.g.uncertainty;
  r.textbook_k = *t.radius_of_gyration;  // one body's: a series of rods has no pivot scan record
  r.textbook_center = t.center_of_mass_position.value_or(0.0);
  auto textbook_at = [&](double h) {
    return ideal_period(equivalent_length(r.textbook_k, h), r.textbook_g);  // Kelley Eqs. (55)-(56), no K
  };

  for (const double side : positions ? std::vector<double>{-1.0, 1.0} : std::vector<double>{1.0}) {
    const double far = side > 0.0 ? x_hi : x_lo;
    const auto model_branch = branch([&](double h) { return model_at(r.center + side * h); }, r.radius_of_gyration,
                                     r.center, side, side * (far - r.center), r.period_high);
    if (!model_branch.x.empty()) r.model.push_back(model_branch);
    PivotScanRecord::Branch difference;
    for (std::size_t i = 0; i < model_branch.x.size(); ++i) {
      const double h = side * (model_branch.x[i] - r.textbook_center);
      if (!(h > 0.0) || !(textbook_at(h) <= r.period_high)) continue;
      difference.x.push_back(model_branch.x[i]);
      difference.period.push_back(textbook_at(h) - model_branch.period[i]);
    }
    if (!difference.x.empty()) r.textbook_minus_model.push_back(difference);
    const auto textbook_branch =
        branch(textbook_at, r.textbook_k, r.textbook_center, side, side * (far - r.textbook_center), r.period_high);
    if (!textbook_branch.x.empty()) r.textbook.push_back(textbook_branch);
  }
  return r;
}

}  // namespace pendulum::report
