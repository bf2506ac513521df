// The pivot-scan plot of a physical pendulum (docs/report.md): T against the
// pivot with the model on each side of the centre of mass, never across it.
#include <cmath>

#include "pendulum/numeric.hpp"
#include "pendulum/report/plots.hpp"

namespace pendulum::report {

namespace {

/// "0.28953 ± 0.00034 m", or the value alone when its uncertainty is unknown.
std::string estimate_text(const Estimate& e, const std::string& unit) {
  const std::string v = e.uncertainty && *e.uncertainty > 0.0 ? value_with_uncertainty(e.value, *e.uncertainty, false)
                                                               : format_significant(e.value, 6) + " (uncertainty unknown)";
  return v + " " + unit;
}

Curve branch_curve(const PivotScanRecord::Branch& b, const std::string& name, Colour colour, Dash dash, double width) {
  Curve c;
  c.name = name;
  c.x = b.x;
  c.y = b.period;
  c.colour = colour;
  c.dash = dash;
  c.width = width;
  return c;
}

}  // namespace

std::optional<Figure> pivot_scan_figure(const SceneReport& r, const std::string& id) {
  if (!r.series || !r.pivot_scan || r.pivot_scan->model.empty()) return std::nullopt;
  const SeriesRecord& s = *r.series;
  const PivotScanRecord& d = *r.pivot_scan;
  const bool positions = d.setting == Setting::pivot_position;
  const bool kater = d.bessel_g.has_value();
  const std::string pivot = positions ? "pivot position" : "pivot distance";

  FitPlotData p;
  p.id = id;
  p.title = (kater ? "Kater's pendulum" : "Pivot scan") + std::string(": period T against ") + pivot + " and the fit";
  p.x = {positions ? "pivot position x along the body, from its mark (m)" : "pivot distance h from the centre of mass (m)",
         Scale::linear, false};
  p.y = {"period T (s)", Scale::linear, false};
  p.residual_label = "T \u2212 model (s)";
  p.observations.name = std::string(kater ? "knife edges: " : "") + "measured T \u00B1 u (period, pivot and amplitude)";
  p.observations.x = s.lengths;
  p.observations.y = s.periods;
  p.observations.y_error = d.uncertainties;
  p.model_at_x = s.periods_model;
  p.model = branch_curve(d.model.front(), "fitted model with every correction", Colour::vermillion, Dash::solid, 2.0);
  const std::string textbook_name = "textbook T = 2\u03C0\u221A((k\u00B2 + h\u00B2)/(g h)), g = " +
                                    format_fixed(d.textbook_g, 4) + " m/s\u00B2";
  if (!d.textbook.empty()) p.textbook = branch_curve(d.textbook.front(), textbook_name, Colour::black, Dash::dashed, 1.5);
  Figure f = fit_figure(p);
  Panel& top = f.panels[0];
  Panel& residuals = f.panels[1];
  top.y.range = std::pair{d.period_low, d.period_high};  // on the axis's ticks (pivot_scan_record)
  // The other side of the centre: the same curves, one legend entry each.
  for (std::size_t i = 1; i < d.textbook.size(); ++i) {
    top.curves.insert(top.curves.begin(), branch_curve(d.textbook[i], "", Colour::black, Dash::dashed, 1.5));
  }
  for (std::size_t i = 1; i < d.model.size(); ++i) {
    top.curves.push_back(branch_curve(d.model[i], "", Colour::vermillion, Dash::solid, 2.0));
  }
  for (const auto& b : d.textbook_minus_model) {
    residuals.curves.push_back(branch_curve(b, "", Colour::black, Dash::dashed, 1.5));
  }

  const std::string k_text = format_fixed(d.radius_of_gyration, 4);
  Points minimum;
  minimum.name = "minimum period, at h = k = " + k_text + " m";
  for (const auto& x : d.minimum_x) {
    minimum.x.push_back(x.value);
    minimum.x_error.push_back(x.uncertainty.value_or(0.0));
    minimum.y.push_back(d.minimum_model_period);
  }
  minimum.colour = Colour::green;
  minimum.marker = Marker::diamond;
  minimum.size = 6.0;
  top.points.push_back(minimum);

  const double x0 = s.lengths.front();
  if (d.conjugate_x) {
    Curve equal;
    equal.name = kater ? "conjugate of the first edge, l = h + h\u2032 = " + format_fixed(d.equivalent_length->value, 4) + " m"
                       : "equal period: first pivot and its conjugate, l = h + h\u2032 = " +
                             format_fixed(d.equivalent_length->value, 4) + " m";
    equal.x = {x0, d.conjugate_x->value};
    equal.y = {d.conjugate_period, d.conjugate_period};
    equal.colour = Colour::blue;
    equal.dash = Dash::dotted;
    top.curves.push_back(equal);
    Points conjugate;
    conjugate.x = {d.conjugate_x->value};
    conjugate.y = {d.conjugate_period};
    conjugate.colour = Colour::blue;
    conjugate.marker = Marker::square;
    conjugate.filled = false;
    top.points.push_back(conjugate);
  }
  if (kater) {
    // The knife edges as vertical lines through the plotted period range.
    for (std::size_t i = 0; i < s.lengths.size(); ++i) {
      Curve edge;
      if (i == 0) {
        edge.name = "knife edges, " + format_fixed(std::abs(s.lengths.back() - s.lengths.front()), 4) + " m apart";
      }
      edge.x = {s.lengths[i], s.lengths[i]};
      edge.y = {d.period_low, d.period_high};
      edge.colour = Colour::grey;
      edge.dash = Dash::dash_dot;
      edge.width = 1.0;
      top.curves.insert(top.curves.begin(), edge);
    }
  }

  const double amplitude = degrees(d.amplitude);
  std::string text = std::to_string(s.lengths.size()) + " measured periods against the " +
                     (positions ? "pivot's position along the body" : "pivot's distance from the centre of mass") +
                     ", with the physical-pendulum model fitted with every correction (g = " + format_fixed(r.g.value, 5) +
                     " m/s^2, k = " + format_fixed(d.radius_of_gyration, 5) + " m" +
                     (positions ? ", centre of mass at " + format_fixed(d.center, 5) + " m" : "") +
                     "), drawn " +
                     (positions ? "on each side of the centre of mass, never across it (the period diverges there), "
                                : "for h > 0 (the period diverges at the centre of mass, h = 0), ");
  if (d.amplitude_max == d.amplitude_min) {
    text += "at the observations' amplitude of " + format_fixed(amplitude, 2) + " deg";
  } else {
    text += "at the median amplitude " + format_fixed(amplitude, 2) + " deg (the observations' amplitudes range from " +
            format_fixed(degrees(d.amplitude_min), 2) + " to " + format_fixed(degrees(d.amplitude_max), 2) + " deg)";
  }
  text += "; the textbook curve T = 2 pi sqrt((k^2 + h^2)/(g h)) without corrections, from the straight line of T^2 h "
          "against h^2 fitted to the measured periods (g = " + format_fixed(d.textbook_g, 5) + " m/s^2, k = " +
          format_fixed(d.textbook_k, 5) + " m); the minimum period without corrections, T0 = " +
          estimate_text(d.minimum_period, "s") + ", at h = k = " + estimate_text(d.minimum_pivot_distance, "m");
  if (positions) {
    text += ", pivot positions";
    for (std::size_t i = 0; i < d.minimum_x.size(); ++i) {
      text += (i ? " and " : " ") + estimate_text(d.minimum_x[i], "m");
    }
  }
  if (d.conjugate_x) {
    text += "; the first pivot, at " + format_fixed(x0, 4) + " m, and its conjugate at " +
            estimate_text(*d.conjugate_x, "m") + " swing with the same period, " +
            format_fixed(d.conjugate_period, 5) + " s, as a simple pendulum of length l = h + h' = " +
            estimate_text(*d.equivalent_length, "m");
  }
  text += ".";
  if (kater) {
    text += " Kater's reversible pendulum: the knife edges are at " + format_fixed(s.lengths.front(), 5) + " m and " +
            format_fixed(s.lengths.back(), 5) + " m; Bessel's formula on their ideal periods gives g = " +
            format_fixed(*d.bessel_g, 5) + " m/s^2, the fit " + format_fixed(r.g.value, 5) + " m/s^2.";
  }
  text += " The error bars are the fit's effective uncertainties: the period's, with the pivot's and the amplitude's "
          "carried to the period through the model's slope. ";
  text += s.dof > 0 ? "Chi-squared " + format_significant(s.chi2, 4) + " for " + std::to_string(s.dof) + " degrees of freedom."
                    : "No degree of freedom is left: the model passes through every observation.";
  const Ticks axis = nice_ticks(d.period_low, d.period_high, panel_intervals(top.height));
  text += " The period axis stops at " + format_fixed(axis.hi, axis.decimals) +
          " s, where the curves leave it towards the centre of mass. The lower panel shows measured minus model, "
          "and the textbook curve minus the model (dashed).";
  f.description = text;
  return f;
}

}  // namespace pendulum::report
