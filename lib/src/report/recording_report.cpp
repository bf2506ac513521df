#include "pendulum/report/recording_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "pendulum/amplitude.hpp"
#include "pendulum/decay_fit.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/numeric.hpp"
#include "pendulum/report/plots.hpp"

namespace pendulum::report {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// Slices of the drawn signal: the figure's width in px, at least one per
/// pixel column of its plotting area.
constexpr std::size_t kSignalColumns = 720;
/// At most this many points in the period-against-amplitude plot.
constexpr std::size_t kMaxPeriodPoints = 200;

/// What the signal is, its axis label and the factor to the label's unit.
struct SignalMeaning {
  std::string words, label;
  double scale = 1.0;
};

SignalMeaning signal_meaning(SignalKind kind, bool has_amplitudes) {
  switch (kind) {
    case SignalKind::angular_rate:
      return {"angular rate about the swing axis", "angular rate on the swing axis (rad/s)", 1.0};
    case SignalKind::linear_acceleration:
      return {"linear acceleration along the swing axis", "acceleration on the swing axis (m/s\u00B2)", 1.0};
    case SignalKind::acceleration:
      return {"magnitude of the acceleration with gravity, less its mean (swings at twice the frequency)",
              "|a| \u2212 mean |a| (m/s\u00B2)", 1.0};
    case SignalKind::angle: return {"angle", "angle \u03B8 \u2212 mean (\u00B0)", kDegreesPerRadian};
    case SignalKind::position:  // drawn in the track's own unit (track_position)
      return {has_amplitudes ? "position along the track's principal axis (the crossings are found on the angle about "
                               "the centre of its circle)"
                             : "position along the track's principal axis",
              "position on the principal axis", 1.0};
    case SignalKind::gate_states:
      return {"photogate events (the middle of each blocking)", "beam: blocked (1) or open (0)", 1.0};
    case SignalKind::blocking_times: return {"photogate blocking times", "", 1.0};
    case SignalKind::event_stamps: return {"event stamps", "", 1.0};
    case SignalKind::unknown: return {"the signal (its quantity unknown), less its mean", "signal \u2212 mean", 1.0};
  }
  return {};
}

std::string seconds(double t) { return format_significant(t, 4) + " s"; }

/// A video track's position along its principal axis, less its mean, in the
/// track's unit (px, cm, ...): the direction of (x, y)'s largest variance, at
/// phi from x with tan 2 phi = 2 s_xy / (s_xx - s_yy).
std::vector<double> track_position(const Recording& r) {
  const std::vector<double>& x = r.channels.front();
  const std::vector<double>& y = r.channels.size() > 1 ? r.channels[1] : x;
  const double n = static_cast<double>(x.size());
  double mx = 0.0, my = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) mx += x[k] / n, my += y[k] / n;
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sxx += (x[k] - mx) * (x[k] - mx), syy += (y[k] - my) * (y[k] - my), sxy += (x[k] - mx) * (y[k] - my);
  }
  const double phi = r.channels.size() > 1 ? 0.5 * std::atan2(2.0 * sxy, sxx - syy) : 0.0;
  std::vector<double> p(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) p[k] = std::cos(phi) * (x[k] - mx) + std::sin(phi) * (y[k] - my);
  return p;
}

/// The unit the track's x column was read in ("px"), else "the file's unit".
std::string track_unit(const Recording& r) {
  for (const auto& c : r.columns) {
    if (c.role == "x" && !c.unit.empty()) return c.unit;
  }
  return "the file's unit";
}

/// Gate events as the beam's state between them: each event holds its state
/// until the next, so the trace steps at every event (a few per swing: no
/// decimation needed).
SignalTrace step_trace(const std::vector<double>& time, const std::vector<double>& state) {
  SignalTrace t;
  for (std::size_t k = 0; k < time.size(); ++k) {
    if (k > 0) t.time.push_back(time[k]), t.value.push_back(state[k - 1]);
    t.time.push_back(time[k]), t.value.push_back(state[k]);
  }
  return t;
}

}  // namespace

SignalTrace decimate_signal(const std::vector<double>& time, const std::vector<double>& value, std::size_t columns) {
  if (time.size() != value.size() || columns == 0) {
    throw std::invalid_argument("decimate_signal: one value per time and at least one column are needed");
  }
  const std::size_t n = time.size();
  if (n <= 2 * columns) return {time, value};
  const double t0 = time.front(), span = time.back() - time.front();
  std::vector<std::size_t> keep = {0};
  std::size_t lo = 0, hi = 0, column = 0;
  auto flush = [&] {
    for (std::size_t k : {std::min(lo, hi), std::max(lo, hi)}) {
      if (k != keep.back()) keep.push_back(k);
    }
  };
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t c = std::min(columns - 1, static_cast<std::size_t>((time[k] - t0) / span * columns));
    if (c != column) {
      flush();
      column = c;
      lo = hi = k;
    }
    if (value[k] < value[lo]) lo = k;
    if (value[k] > value[hi]) hi = k;
  }
  flush();
  if (keep.back() != n - 1) keep.push_back(n - 1);
  SignalTrace t;
  for (std::size_t k : keep) {
    t.time.push_back(time[k]);
    t.value.push_back(value[k]);
  }
  return t;
}

RecordingRecord make_recording_record(const RecordingSummary& summary, const Recording* samples) {
  const SwingAnalysis& a = summary.swings;
  RecordingRecord r;
  r.input = summary.set.empty() ? summary.file : summary.file + "/" + summary.set;  // as errors name a set
  r.format = recording_format_name(summary.format);
  r.rows = summary.rows;
  r.dropped = summary.dropped;
  r.period = a.period;
  r.crossings_per_period = a.crossings_per_period;
  r.analysed = a.analysed;
  r.cuts = a.cuts;
  r.whole_record_period = a.whole_record_period;
  // A crossing fit floors its own uncertainty at the clock's (its
  // resolution_floor, already in the uncertainty); else each end crossing is
  // known no better than the clock's step.
  constexpr double kFinestStamp = 1e-6;  // (s)
  const double dt = samples && samples->time_quantum > 0.0 ? samples->time_quantum : kFinestStamp;
  r.period_resolution = a.period.resolution_floor > 0.0 ? a.period.resolution_floor
                                                         : std::sqrt(2.0) * dt / std::max(1, a.period.periods);
  // The crossing fit's weights w_i = slope_i^2 samples_i / mean (1 for gate
  // events), and its residual variance s^2: sigma_i^2 = s^2 / w_i.
  double mean_weight = 0.0;
  for (const auto& c : a.crossings) mean_weight += c.slope * c.slope * c.samples / a.crossings.size();
  for (const auto& c : a.crossings) {
    const double w = c.samples > 0 && mean_weight > 0.0 ? c.slope * c.slope * c.samples / mean_weight : 1.0;
    r.crossings.push_back(c.time);
    r.crossing_sigmas.push_back(a.period.residual_rms / std::sqrt(w));
  }
  r.small_amplitude_period = a.small_amplitude_period;
  r.start_amplitude = a.start_amplitude;
  r.end_amplitude = a.end_amplitude;
  const SignalMeaning meaning = signal_meaning(summary.kind, !a.decay.amplitudes.empty());
  r.signal = meaning.words;
  if (samples) {
    const bool track = summary.kind == SignalKind::position;
    std::vector<double> s = track ? track_position(*samples) : swing_signal(*samples);
    if (!s.empty()) {
      for (double& x : s) x *= meaning.scale;
      r.samples = s.size();
      r.trace = summary.kind == SignalKind::gate_states ? step_trace(samples->time, s)
                                                         : decimate_signal(samples->time, s, kSignalColumns);
      r.trace_label = track ? meaning.label + " (" + track_unit(*samples) + ")" : meaning.label;
    }
  }
  // The decay record's times count from the first crossing (the fit's t = 0);
  // drawn as recorded.
  const double origin = r.crossings.front();
  for (std::size_t i = 0; i < a.decay.times.size(); ++i) {
    r.swing_times.push_back(a.decay.times[i] + origin);
    r.swing_amplitudes.push_back(a.decay.amplitudes[i]);
  }
  if (!a.decay.amplitudes.empty()) {
    try {
      validate_decay_data(a.decay, "decay");
      DecayRecord d = make_decay_record(a.decay, fit_decay(a.decay));
      for (double& t : d.times) t += origin;
      for (double& t : d.grid) t += origin;
      r.decay = d;
    } catch (const InputError& e) {
      r.decay_note = std::string("the decay fit does not apply: ") + e.what();
    }
  }
  for (PeriodPoint p : a.period_curve) {
    p.time += origin;
    r.periods.push_back(p);
  }
  return r;
}

std::optional<Figure> signal_figure(const RecordingRecord& r, const std::string& id) {
  if (!r.trace) return std::nullopt;
  Figure f;
  f.id = id;
  f.title = "The signal and the detected crossings";
  f.x = {"time t (s), as recorded", Scale::linear, false};
  Panel p;
  p.y = {r.trace_label, Scale::linear, true};
  p.height = 260.0;
  Curve signal;
  const bool decimated = r.trace->time.size() < r.samples;
  signal.name = decimated ? "signal: least and greatest sample per pixel column" : "signal";
  signal.x = r.trace->time;
  signal.y = r.trace->value;
  signal.colour = Colour::blue;
  signal.width = 1.0;
  // Ticks closer than about 4 px merge into a band: beyond kMaxCrossingTicks
  // on the plot's ~630 px, one tick per `every` crossings.
  const std::size_t every = (r.crossings.size() + kMaxCrossingTicks - 1) / kMaxCrossingTicks;
  const std::string thinned = every > 1 ? "; one tick per " + std::to_string(every) + ", so that they stay apart" : "";
  Points crossings;
  crossings.name = "detected crossing (" + std::to_string(r.crossings.size()) + thinned + ")";
  for (std::size_t i = 0; i < r.crossings.size(); i += every) crossings.x.push_back(r.crossings[i]);
  crossings.y.assign(crossings.x.size(), 0.0);
  crossings.colour = Colour::vermillion;
  crossings.marker = Marker::tick;
  crossings.size = 6.0;
  // What the clean stretch cut or bridged, shaded over the signal's range.
  const auto [lo, hi] = std::minmax_element(r.trace->value.begin(), r.trace->value.end());
  for (const Cut& k : r.cuts) {
    Band b;
    b.name = p.bands.empty() ? "cut by default (the clean stretch), or bridged with its count carried" : "";
    b.x = {k.start, k.end};
    b.lower = {*lo, *lo};
    b.upper = {*hi, *hi};
    b.colour = Colour::grey;
    p.bands.push_back(b);
  }
  p.curves.push_back(signal);
  p.points.push_back(crossings);
  f.panels = {p};
  f.description = "The " + r.signal + " against time, " + std::to_string(r.samples) + " samples from " +
                  seconds(r.trace->time.front()) + " to " + seconds(r.trace->time.back()) +
                  (decimated ? ", drawn as the least and the greatest sample in each of " +
                                   std::to_string(kSignalColumns) + " time slices (" +
                                   std::to_string(r.trace->time.size()) + " points)"
                             : "") +
                  ", with the " + std::to_string(r.crossings.size()) +
                  " crossings the analysis found marked by vertical ticks on the zero line" +
                  (every > 1 ? ", one tick per " + std::to_string(every) + " crossings" : std::string()) +
                  (r.cuts.empty() ? std::string() : "; the stretches the analysis cut or bridged shaded grey") + ".";
  return f;
}

std::optional<Figure> amplitude_figure(const RecordingRecord& r, const std::string& id) {
  if (r.swing_amplitudes.empty()) return std::nullopt;
  const std::string what = std::to_string(r.swing_amplitudes.size()) + " swing amplitudes in degrees from " +
                           seconds(r.swing_times.front()) + " to " + seconds(r.swing_times.back());
  if (r.decay) {
    Figure f = decay_figure(*r.decay, id);
    f.title = "Amplitude of each swing, fit of Eq. (25) and residuals";
    f.panels[0].y.include_zero = false;  // a recording decays by a few per cent
    f.x.label = "time t (s), as recorded";
    f.description = what + ", with the fit of Nelson and Olsson's decay law, " + r.decay->model +
                    " (its t = 0 is the first crossing), chi-squared " + format_significant(r.decay->chi2, 4) +
                    " for " + std::to_string(r.decay->dof) +
                    " degrees of freedom; the lower panel shows measured minus fitted amplitude.";
    return f;
  }
  Figure f;
  f.id = id;
  f.title = "Amplitude of each swing";
  f.x = {"time t (s), as recorded", Scale::linear, false};
  Panel p;
  p.y = {"amplitude \u03B8\u2080 (\u00B0)", Scale::linear, false};
  Points points;
  points.name = "amplitude of a swing";
  points.x = r.swing_times;
  for (double a : r.swing_amplitudes) points.y.push_back(degrees(a));
  points.size = r.swing_times.size() > 100 ? 2.2 : 4.0;
  p.points.push_back(points);
  f.panels = {p};
  f.description = what + "; " + r.decay_note + ".";
  return f;
}

std::optional<Figure> period_amplitude_figure(const RecordingRecord& r, const std::string& id) {
  // Consecutive periods averaged in groups of m: their mean is the time from
  // the group's first crossing to its last over m.
  const std::size_t n = r.periods.size(), m = (n + kMaxPeriodPoints - 1) / kMaxPeriodPoints;
  const std::size_t cpp = static_cast<std::size_t>(r.crossings_per_period);
  FitPlotData d;
  d.id = id;
  d.title = "Period against amplitude, and the exact period of Eq. (8)";
  d.x = {"amplitude \u03B8\u2080 (\u00B0)", Scale::linear, false};
  d.y = {"period T (s)", Scale::linear, false};
  d.residual_label = "T \u2212 theory (s)";
  d.observations.name = m > 1 ? "mean period of " + std::to_string(m) + " consecutive swings \u00B1 \u03C3"
                              : "period of one full swing \u00B1 \u03C3";
  d.observations.colour = Colour::black;
  d.observations.size = n / m > 100 ? 2.5 : 4.0;
  auto ratio = [](double theta) { return 1.0 + finite_amplitude_agm(theta); };  // T/T0, Eq. (8), exact
  std::vector<double> amplitudes;
  double lo = kNaN, hi = kNaN;
  for (std::size_t i = 0; i + m <= n; i += m) {
    double amplitude = 0.0, period = 0.0;
    bool known = true;
    for (std::size_t k = i; k < i + m; ++k) {
      amplitude += r.periods[k].amplitude;
      period += r.periods[k].period;
      known = known && std::isfinite(r.periods[k].amplitude);
    }
    if (!known) continue;
    amplitude /= static_cast<double>(m);
    d.observations.x.push_back(degrees(amplitude));
    d.observations.y.push_back(period / static_cast<double>(m));
    d.observations.y_error.push_back(std::hypot(r.crossing_sigmas[i * cpp], r.crossing_sigmas[(i + m) * cpp]) /
                                      static_cast<double>(m));
    amplitudes.push_back(amplitude);
    lo = std::isnan(lo) ? amplitude : std::min(lo, amplitude);
    hi = std::isnan(hi) ? amplitude : std::max(hi, amplitude);
  }
  if (amplitudes.empty()) return std::nullopt;
  // T0 fitted to these periods, equal weights: min sum (T_i - T0 f_i)^2.
  double tf = 0.0, ff = 0.0;
  for (std::size_t i = 0; i < amplitudes.size(); ++i) {
    tf += d.observations.y[i] * ratio(amplitudes[i]);
    ff += ratio(amplitudes[i]) * ratio(amplitudes[i]);
  }
  const double t0 = tf / ff;
  for (double a : amplitudes) d.model_at_x.push_back(t0 * ratio(a));
  constexpr int kGrid = 121;
  for (int i = 0; i < kGrid; ++i) {
    const double theta = lo + (hi - lo) * i / (kGrid - 1);
    d.model.x.push_back(degrees(theta));
    d.model.y.push_back(t0 * ratio(theta));
  }
  d.model.name = "exact period T\u2080(1 + \u0394T/T\u2080(\u03B8\u2080)), T\u2080 = " + format_fixed(t0, 7) +
                 " s fitted to these periods";
  d.model.colour = Colour::vermillion;
  d.description = std::to_string(d.observations.x.size()) + " periods in seconds against the amplitude in degrees" +
                  (m > 1 ? " (each the mean of " + std::to_string(m) + " consecutive full swings)" : "") +
                  ", with error bars from the two crossing times that bound each" +
                  ", and the exact finite-amplitude period of Nelson and Olsson's Eq. (8) times the "
                  "small-amplitude period T0 fitted to these periods by least squares, " + format_fixed(t0, 7) +
                  " s; the lower panel shows the measured minus the theoretical period.";
  return fit_figure(d);
}

std::vector<std::string> recording_plot_names(const RecordingRecord& r) {
  std::vector<std::string> names;
  if (r.trace) names.push_back("signal");
  if (!r.swing_amplitudes.empty()) names.push_back("amplitude");
  if (period_amplitude_figure(r, "x")) names.push_back("period-amplitude");
  return names;
}

std::string recording_plot_svg(const RecordingRecord& r, const std::string& name) {
  if (name == "signal") {
    if (auto f = signal_figure(r, "signal")) return to_svg(*f, true);
    throw InputError(r.input, "a column of blocking times has no signal to plot, only the blocking instants");
  }
  if (name == "amplitude") {
    if (auto f = amplitude_figure(r, "amplitude")) return to_svg(*f, true);
    throw InputError(r.input, "the recording gives no amplitudes to plot (docs/recordings.md)");
  }
  if (name == "period-amplitude") {
    if (auto f = period_amplitude_figure(r, "period-amplitude")) return to_svg(*f, true);
    throw InputError(r.input, "the recording gives no amplitudes, so no period against amplitude");
  }
  std::string known;
  for (const auto& n : recording_plot_names(r)) known += (known.empty() ? "" : ", ") + n;
  throw InputError(r.input, "no plot \"" + name + "\" for a recording; this one has: " + known);
}

}  // namespace pendulum::report
