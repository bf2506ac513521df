#include "pendulum/report/plots.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "pendulum/amplitude.hpp"
#include "pendulum/numeric.hpp"
#include "pendulum/input_error.hpp"

namespace pendulum::report {

namespace {
constexpr double kMicro = 1e6;   // s -> us
constexpr double kMilli = 1e3;   // m/s^2 -> mm/s^2
}  // namespace

Figure fit_figure(const FitPlotData& d) {
  const std::size_t n = d.observations.x.size();
  if (d.model_at_x.size() != n || d.observations.y.size() != n ||
      (!d.textbook_at_x.empty() && (d.textbook_at_x.size() != n || !d.textbook))) {
    throw std::invalid_argument("fit_figure: one model value per observation is needed");
  }
  Figure f;
  f.id = d.id;
  f.title = d.title;
  f.description = d.description;
  f.x = d.x;

  Panel top;
  top.y = d.y;
  if (d.model_band) top.bands.push_back(*d.model_band);
  if (d.textbook) top.curves.push_back(*d.textbook);
  top.curves.push_back(d.model);
  top.points.push_back(d.observations);

  Panel residuals;
  residuals.y.label = d.residual_label;
  residuals.height = 140.0;
  Reference zero;
  zero.colour = d.model.colour;
  zero.dash = Dash::solid;
  residuals.references.push_back(zero);
  Points r = d.observations;
  r.name.clear();
  for (std::size_t i = 0; i < r.y.size(); ++i) r.y[i] = d.observations.y[i] - d.model_at_x[i];
  residuals.points.push_back(r);
  if (!d.textbook_at_x.empty()) {
    Curve difference = *d.textbook;
    difference.name.clear();
    difference.x.clear();
    difference.y.clear();
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return d.observations.x[a] < d.observations.x[b]; });
    for (std::size_t i : order) {
      difference.x.push_back(d.observations.x[i]);
      difference.y.push_back(d.textbook_at_x[i] - d.model_at_x[i]);
    }
    residuals.curves.push_back(difference);
  }

  f.panels = {top, residuals};
  return f;
}

std::string estimate_text(const Estimate& e, int decimals, const std::string& unit) {
  const std::string u = unit.empty() ? "" : " " + unit;
  if (!e.uncertainty || !std::isfinite(*e.uncertainty)) {
    return format_fixed(e.value, decimals) + u + " (" + kUncertaintyUnknown + ")";
  }
  return format_fixed(e.value, decimals) + " \u00B1 " + format_fixed(*e.uncertainty, decimals) + u;
}

std::string value_with_uncertainty(double value, double uncertainty, bool sign) {
  const std::string plus = sign && value > 0.0 ? "+" : "";
  if (!(uncertainty > 0.0) || !std::isfinite(uncertainty)) {
    const std::string v = format_significant(value, 4);
    return (v.find_first_not_of("0.") == std::string::npos ? "" : plus) + v;
  }
  const int ku = static_cast<int>(std::floor(std::log10(uncertainty)));
  const int decimals = 1 - ku;
  if (decimals <= 8 && std::abs(value) < 1e6) {
    const std::string v = format_fixed(value, std::max(0, decimals));
    return (v.find_first_not_of("0.") == std::string::npos ? "" : plus) + v + " \u00B1 " +
           format_fixed(uncertainty, std::max(0, decimals));
  }
  // Very small or large: both over one power of ten, "(1.23 ± 0.45)×10⁻⁹".
  const int e = static_cast<int>(std::floor(std::log10(std::max(std::abs(value), uncertainty))));
  const double scale = std::pow(10.0, e);
  const int d = std::max(0, e - ku + 1);
  return "(" + plus + format_fixed(value / scale, d) + " \u00B1 " + format_fixed(uncertainty / scale, d) + ")" +
         (e == 0 ? std::string() : times_ten_to(e));
}

std::string duration_text(double seconds, int significant) {
  static const std::pair<double, const char*> units[] = {
      {1.0, "s"}, {1e-3, "ms"}, {1e-6, "\u00B5s"}, {1e-9, "ns"}, {1e-12, "ps"}, {1e-15, "fs"}};
  for (const auto& [scale, unit] : units) {
    if (std::abs(seconds) >= scale || scale == 1e-15) return format_significant(seconds / scale, significant) + " " + unit;
  }
  return "";
}

std::optional<CategoryChart> corrections_chart(const SceneReport& r, const std::string& id) {
  CategoryChart ch;
  ch.id = id;
  ch.title = "Corrections to the period";
  ch.value = {"|\u0394T| (\u00B5s), log scale", Scale::log, false};
  CategorySeries applied{"applied", CategorySeries::Mark::bar, {}, {}, Colour::blue, true, Marker::circle};
  CategorySeries negligible{"negligible (still applied)", CategorySeries::Mark::bar, {}, {}, Colour::orange, false,
                            Marker::circle};
  bool any = false, unknown = false;
  int count = 0;
  for (const auto& c : r.corrections) {
    if (c.status == "skipped" || !c.delta_T) continue;
    ++count;
    const double size = std::abs(*c.delta_T) * kMicro;
    const std::optional<double> error =
        c.delta_T_uncertainty ? std::optional<double>(*c.delta_T_uncertainty * kMicro) : std::nullopt;
    const bool is_applied = c.status == "applied";
    ch.categories.push_back(c.title);
    ch.notes.push_back((*c.delta_T > 0.0 ? "+" : "") + format_significant(*c.delta_T * kMicro, 3) + " \u00B5s" +
                       (error ? "" : std::string(", ") + kUncertaintyUnknown));
    unknown = unknown || !error;
    applied.values.push_back(is_applied ? std::optional<double>(size) : std::nullopt);
    negligible.values.push_back(is_applied ? std::nullopt : std::optional<double>(size));
    applied.errors.push_back(error);
    negligible.errors.push_back(error);
    any = any || size > 0.0;
  }
  if (!any) return std::nullopt;
  ch.series = {applied, negligible};
  if (r.negligible_below > 0.0) {
    Reference threshold;
    threshold.name = "negligible below " + duration_text(r.negligible_below, 3);
    threshold.value = r.negligible_below * kMicro;
    threshold.colour = Colour::vermillion;
    ch.references.push_back(threshold);
  }
  ch.description = std::to_string(count) + (count == 1 ? " period correction" : " period corrections") +
                   ", each as the size of its change to the period, Delta T, in microseconds "
                   "on a logarithmic axis with its standard uncertainty as an error bar; filled bars are applied, "
                   "open bars are negligible (smaller than the threshold line) but still applied. The signed "
                   "value of each is written at the right of its row." +
                   (unknown ? std::string(" Where the uncertainty is unknown (the fit's covariance is singular), no "
                                          "error bar is drawn and the row says so.")
                            : "");
  return ch;
}

std::optional<CategoryChart> budget_chart(const SceneReport& r, const std::string& id) {
  if (r.budget.empty() || !r.g.uncertainty || !(*r.g.uncertainty > 0.0)) return std::nullopt;
  CategoryChart ch;
  ch.id = id;
  ch.title = "Uncertainty budget of g, largest first";
  ch.value = {"contribution to u(g) (mm/s\u00B2)", Scale::linear, true};
  CategorySeries bars{"contribution |\u2202g/\u2202x| u(x)", CategorySeries::Mark::bar, {}, {}, Colour::blue, true,
                      Marker::circle};
  const double total = *r.g.uncertainty;
  for (const auto& b : r.budget) {
    ch.categories.push_back(b.input);
    bars.values.push_back(b.contribution * kMilli);
    const double share = 100.0 * (b.contribution / total) * (b.contribution / total);
    ch.notes.push_back(share < 0.001 ? "< 0.001 % of u(g)\u00B2"
                                     : format_fixed(share, share < 0.1 ? 3 : 1) + " % of u(g)\u00B2");
  }
  ch.series = {bars};
  Reference all;
  all.name = "u(g) = " + format_significant(total * kMilli, 3) + " mm/s\u00B2, all in quadrature";
  all.value = total * kMilli;
  all.colour = Colour::vermillion;
  ch.references.push_back(all);
  ch.description = "The standard uncertainty of g, " + format_significant(total * kMilli, 3) +
                   " mm/s^2, split by input: each bar is one input's contribution, the absolute sensitivity of g "
                   "times the input's uncertainty, in mm/s^2, largest first; the contributions add in quadrature. "
                   "The largest is " + r.budget.front().input + ".";
  return ch;
}

std::optional<Figure> decay_figure(const SceneReport& r, const std::string& id) {
  if (!r.decay) return std::nullopt;
  return decay_figure(*r.decay, id);
}

Figure decay_figure(const DecayRecord& d, const std::string& id) {
  FitPlotData p;
  p.id = id;
  p.title = "Decay of the amplitude, fit of Eq. (25) and residuals";
  p.x = {"time t (s)", Scale::linear, true};
  p.y = {"amplitude \u03B8\u2080 (\u00B0)", Scale::linear, true};
  p.residual_label = "residual (\u00B0)";
  p.observations.name = d.sigmas.empty() ? "measured amplitude" : "measured amplitude \u00B1 \u03C3";
  p.observations.x = d.times;
  p.observations.size = d.times.size() > 100 ? 2.2 : 4.0;
  for (double a : d.amplitudes) p.observations.y.push_back(degrees(a));
  for (double s : d.sigmas) p.observations.y_error.push_back(degrees(s));
  // A dense record light, the fit dark over it: they differ in greyscale too.
  const bool dense = d.times.size() > 100;
  p.observations.colour = dense ? Colour::sky_blue : Colour::black;
  for (double a : d.fitted) p.model_at_x.push_back(degrees(a));
  const bool band_known = !d.grid_uncertainty.empty();
  p.model.name = band_known ? "fit of Eq. (25)"
                            : std::string("fit of Eq. (25); ") + kUncertaintyUnknown + " (singular covariance): no band";
  p.model.x = d.grid;
  p.model.colour = dense ? Colour::black : Colour::vermillion;
  p.model.width = 2.5;
  for (double a : d.grid_fit) p.model.y.push_back(degrees(a));
  if (band_known) {
    Band band;
    band.name = "fit \u00B1 1\u03C3 (from the covariance)";
    band.x = d.grid;
    for (std::size_t i = 0; i < d.grid.size(); ++i) {
      band.lower.push_back(degrees(d.grid_fit[i] - d.grid_uncertainty[i]));
      band.upper.push_back(degrees(d.grid_fit[i] + d.grid_uncertainty[i]));
    }
    band.colour = Colour::orange;
    p.model_band = band;
  }
  p.description = std::to_string(d.times.size()) + " measured amplitudes in degrees from t = " +
                  format_significant(d.times.front(), 3) + " s to " + format_significant(d.times.back(), 4) +
                  " s, with the fit of Nelson and Olsson's decay law, " + d.model +
                  ", chi-squared " + format_significant(d.chi2, 4) + " for " + std::to_string(d.dof) +
                  " degrees of freedom; the lower panel shows measured minus fitted amplitude.";
  return fit_figure(p);
}

namespace {

/// An amplitude sweep: T against theta0, the exact law at the fitted T0 and
/// the quadratic the law is tested with (docs/series.md, "Amplitude sweeps").
Figure sweep_figure(const SeriesRecord& s, const std::string& id) {
  const AmplitudeSweep& w = *s.sweep;
  FitPlotData p;
  p.id = id;
  p.title = "Sweep: T against amplitude, the exact law, the quadratic";
  p.x = {"amplitude θ₀ (deg)", Scale::linear, true};
  p.y = {"T (s)", Scale::linear, false};
  p.residual_label = "T − law (s)";
  p.observations.name = "measured T ± its effective u(T)";
  for (std::size_t k = 0; k < s.periods.size(); ++k) {
    p.observations.x.push_back(degrees(s.amplitudes[k]));
    p.observations.y.push_back(s.periods[k]);
    p.observations.y_error.push_back(w.effective_sigma[k]);
    p.model_at_x.push_back(w.law[k]);
  }
  const double top = w.high * 1.05;
  constexpr int kSamples = 100;
  for (int i = 0; i <= kSamples; ++i) {
    const double a = std::min(top * i / kSamples, kPi * 0.999);
    p.model.x.push_back(degrees(a));
    p.model.y.push_back(w.t0.value * (1.0 + finite_amplitude_agm(a)));
  }
  p.model.name = "exact law T = T₀ 2K/π, T₀ = " + format_fixed(w.t0.value, 5) + " s";
  p.model.colour = Colour::vermillion;
  std::string quadratic_words;
  if (w.coefficient) {
    Curve quadratic;
    quadratic.name = "T = a (1 + c θ₀²), c = " + format_significant(w.coefficient->value, 3) + " /rad²";
    auto at = [&](double a) { return w.quadratic_t0 * (1.0 + w.coefficient->value * a * a); };
    for (double x : p.model.x) quadratic.x.push_back(x), quadratic.y.push_back(at(radians(x)));
    quadratic.colour = Colour::black;
    quadratic.dash = Dash::dashed;
    quadratic.width = 1.5;
    p.textbook = quadratic;
    for (double a : s.amplitudes) p.textbook_at_x.push_back(at(a));
    quadratic_words = " and the quadratic a (1 + c theta0^2) fitted with the same weights (c = " +
                      format_significant(w.coefficient->value, 3) + " per rad^2 against the law's " +
                      format_significant(w.coefficient_law, 3) + " at these amplitudes)";
  }
  p.description = std::to_string(s.periods.size()) + " measured periods against their amplitudes, with the exact " +
                  "law fitted (T0 = " + format_fixed(w.t0.value, 5) + " s)" + quadratic_words +
                  "; the lower panel shows measured minus law" + (w.coefficient ? ", and the quadratic minus the law." : ".");
  return fit_figure(p);
}

}  // namespace

std::optional<Figure> series_figure(const SceneReport& r, const std::string& id) {
  if (!r.series || r.pivot_scan) return std::nullopt;  // a pivot scan has its own plot
  const SeriesRecord& s = *r.series;
  if (s.sweep) return sweep_figure(s, id);
  FitPlotData p;
  p.id = id;
  p.title = "Series: T\u00B2 against length, the fit and the textbook line";
  p.x = {s.length_words + " (m)", Scale::linear, true};
  p.y = {"T\u00B2 (s\u00B2)", Scale::linear, true};
  p.residual_label = "T\u00B2 \u2212 model (s\u00B2)";
  p.observations.name = "measured T\u00B2 \u00B1 2T u(T)";
  std::vector<std::pair<double, double>> model;
  double longest = 0.0;
  for (std::size_t k = 0; k < s.lengths.size(); ++k) {
    p.observations.x.push_back(s.lengths[k]);
    p.observations.y.push_back(s.periods[k] * s.periods[k]);
    p.observations.y_error.push_back(2.0 * s.periods[k] * s.period_uncertainties[k]);
    p.model_at_x.push_back(s.periods_model[k] * s.periods_model[k]);
    model.emplace_back(s.lengths[k], s.periods_model[k] * s.periods_model[k]);
    longest = std::max(longest, s.lengths[k]);
  }
  std::sort(model.begin(), model.end());
  p.model.name = "fitted model with every correction";
  for (const auto& [x, y] : model) {
    p.model.x.push_back(x);
    p.model.y.push_back(y);
  }
  p.model.colour = Colour::vermillion;
  std::string textbook_words = "no textbook straight line (the lengths do not determine one)";
  if (s.textbook_g) {
    const double g = *s.textbook_g;
    auto line = [&](double x) { return gravity_for_slope(g) * (x + s.textbook_length_offset); };  // T^2 = (4 pi^2/g) L
    Curve textbook;
    textbook.name = "textbook T\u00B2 = 4\u03C0\u00B2(L + L\u2080)/g, g = " + format_fixed(g, 4) + " m/s\u00B2";
    textbook.x = {0.0, longest};
    for (double x : textbook.x) textbook.y.push_back(line(x));
    textbook.colour = Colour::black;
    textbook.dash = Dash::dashed;
    textbook.width = 1.5;
    p.textbook = textbook;
    for (double x : s.lengths) p.textbook_at_x.push_back(line(x));
    textbook_words = "the textbook straight line without corrections (g = " + format_fixed(g, 5) + " m/s^2)";
  }
  p.description = std::to_string(s.lengths.size()) +
                  " measured periods, squared, against their lengths, with the period model fitted with every "
                  "correction (g = " + format_fixed(r.g.value, 5) + " m/s^2) and " + textbook_words +
                  "; chi-squared " + format_significant(s.chi2, 4) + " for " + std::to_string(s.dof) +
                  " degrees of freedom; the lower panel shows measured minus model" +
                  (s.textbook_g ? ", and the textbook line minus the model." : ".");
  return fit_figure(p);
}

CategoryChart class_chart(std::vector<ClassPoint> points, const std::string& id) {
  std::stable_sort(points.begin(), points.end(), [](const ClassPoint& a, const ClassPoint& b) { return a.g < b.g; });
  CategoryChart ch;
  ch.id = id;
  ch.title = "g of every scene, sorted, against the expected g";
  ch.value = {"g (m/s\u00B2)", Scale::linear, false};
  CategorySeries g{"g \u00B1 u(g)", CategorySeries::Mark::point, {}, {}, Colour::blue, true, Marker::circle};
  CategorySeries expected{"expected g at the site", CategorySeries::Mark::point, {}, {}, Colour::vermillion, false,
                          Marker::diamond};
  bool shared = !points.empty() && points.front().expected;
  for (const auto& p : points) {
    shared = shared && p.expected && p.expected->value == points.front().expected->value &&
             p.expected->uncertainty == points.front().expected->uncertainty;
  }
  for (const auto& p : points) {
    ch.categories.push_back(p.label);
    ch.links.push_back(p.link);
    std::string note =
        p.z ? "z = " + std::string(*p.z > 0.0 ? "+" : "") + format_fixed(*p.z, 2) : p.expected ? "" : "no expected g";
    if (!p.uncertainty) note += std::string(note.empty() ? "" : ", ") + kUncertaintyUnknown;
    if (!p.ok) note += std::string(note.empty() ? "" : ", ") + "suspect";
    ch.notes.push_back(note);
    g.values.push_back(p.g);
    g.errors.push_back(p.uncertainty);
    expected.values.push_back(p.expected && !shared ? std::optional<double>(p.expected->value) : std::nullopt);
  }
  ch.series = {g};
  if (shared) {
    Reference line;
    const Measured e = *points.front().expected;
    line.name = "expected g = " +
                (e.uncertainty > 0.0 ? value_with_uncertainty(e.value, e.uncertainty, false) : format_fixed(e.value, 5)) +
                " m/s\u00B2";
    line.value = e.value;
    line.half_width = e.uncertainty;
    ch.references.push_back(line);
  } else if (std::any_of(expected.values.begin(), expected.values.end(), [](const auto& v) { return v.has_value(); })) {
    ch.series.push_back(expected);
  }
  // The scale: the ok results and the expected g (standard gravity when no
  // row has one), each with its uncertainty.
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  auto hold = [&](double v, double u) { lo = std::min(lo, v - u), hi = std::max(hi, v + u); };
  bool any_expected = false;
  for (const auto& p : points) {
    if (p.ok) hold(p.g, p.uncertainty.value_or(0.0));
    if (p.expected) hold(p.expected->value, p.expected->uncertainty), any_expected = true;
  }
  if (!any_expected) hold(kStandardGravity, 0.0);
  ch.range = std::pair{lo, hi};
  const bool off_scale = std::any_of(points.begin(), points.end(), [&](const ClassPoint& p) {
    return p.g < lo || p.g > hi;
  });
  ch.description = std::to_string(points.size()) +
                   " measured values of g with their standard uncertainties, sorted from smallest to largest, "
                   "against the g expected at the site; the z-score of each is written at the right of its row." +
                   (std::all_of(points.begin(), points.end(), [](const ClassPoint& p) { return p.uncertainty.has_value(); })
                        ? std::string()
                        : std::string(" Where an uncertainty is unknown (a singular fit) the row says so and has no "
                                      "error bar.")) +
                   (off_scale ? " The axis spans the results whose status is ok and the expected g; a result beyond "
                                "it is drawn at the edge, open, with its value."
                              : "");
  return ch;
}

std::vector<std::string> plot_names(const SceneReport& r) {
  std::vector<std::string> names;
  if (corrections_chart(r, "x")) names.push_back("corrections");
  if (budget_chart(r, "x")) names.push_back("budget");
  if (r.decay) names.push_back("decay");
  if (r.series) names.push_back(r.pivot_scan ? "pivot-scan" : "series");
  return names;
}

std::string plot_svg(const SceneReport& r, const std::string& name) {
  if (name == "corrections") {
    if (auto c = corrections_chart(r, "corrections")) return to_svg(*c, true);
    throw InputError("", "no correction has a size to plot");
  }
  if (name == "budget") {
    if (auto c = budget_chart(r, "budget")) return to_svg(*c, true);
    throw InputError("", "no input states an uncertainty, so there is no budget to plot");
  }
  if (name == "decay") {
    if (auto f = decay_figure(r, "decay")) return to_svg(*f, true);
    throw InputError("decay.data", "the scene has no decay record to plot");
  }
  // A physical pendulum's series is plotted as a pivot scan, under either name.
  if (name == "series" || name == "pivot-scan") {
    if (auto f = pivot_scan_figure(r, "pivot-scan")) return to_svg(*f, true);
  }
  if (name == "series") {
    if (auto f = series_figure(r, "series")) return to_svg(*f, true);
    throw InputError("observations", "the scene is not a series of observations");
  }
  if (name == "pivot-scan") {
    throw InputError("observations", "the scene is not a pivot scan (a physical pendulum's series of "
                                     "pivot_position or pivot_distance observations)");
  }
  std::string known;
  for (const auto& n : plot_names(r)) known += (known.empty() ? "" : ", ") + n;
  throw InputError("", "no plot \"" + name + "\"; this scene has: " + known);
}

}  // namespace pendulum::report
