#pragma once
/// \file plots.hpp
/// \brief The plots of a report, built from report data (scene_report.hpp)
/// with the SVG module (svg_plot.hpp): corrections, budget, decay record,
/// the generic fit-with-residuals figure, and the class's g values.

#include <optional>
#include <string>
#include <vector>

#include "pendulum/report/scene_report.hpp"
#include "pendulum/report/svg_plot.hpp"

namespace pendulum::report {

/// Observations, a fitted model, an optional comparison curve (the textbook
/// line) and the residuals y - model beneath: a decay record, a length
/// series, a pivot scan. All values in the units of the axes' labels.
struct FitPlotData {
  std::string id, title, description;
  Axis x, y;
  std::string residual_label;  ///< e.g. "residual (s)"
  Points observations;
  /// The model at each observation's x: the residuals are y - model_at_x.
  std::vector<double> model_at_x;
  Curve model;                ///< the model on a fine grid
  std::optional<Band> model_band;  ///< e.g. the fit's +-1 sigma
  std::optional<Curve> textbook;   ///< e.g. T^2 = 4 pi^2 l / g
  /// The textbook curve at each observation's x, if any: the residual panel
  /// then shows textbook - model, where the two curves differ too little
  /// to tell apart above.
  std::vector<double> textbook_at_x;
};

/// Two panels over one x axis: the observations with error bars, the model,
/// its band and the textbook curve; beneath, the residuals with the same
/// error bars about a line at zero, and textbook - model when given. Throws
/// std::invalid_argument when model_at_x (or a non-empty textbook_at_x) and
/// the observations differ in length.
Figure fit_figure(const FitPlotData& data);

/// What the report writes where an uncertainty is unknown (a singular fit),
/// in place of an error bar or a "± 0".
inline constexpr const char* kUncertaintyUnknown = "uncertainty unknown";

/// "9.80340 ± 0.00148 m/s²" with `decimals` fixed digits, or for an unknown
/// uncertainty "9.80340 m/s² (uncertainty unknown)".
std::string estimate_text(const Estimate& e, int decimals, const std::string& unit);

/// A value and its uncertainty with the uncertainty to two significant
/// digits and the value to the same decimal place: "+596 ± 119",
/// "9.8034 ± 0.0015"; `sign` prints a + on positive values.
std::string value_with_uncertainty(double value, double uncertainty, bool sign);

/// A duration with the SI prefix that puts `significant` digits of it
/// between 1 and 1000: "2.53 \u00B5s", "0.253 fs" at most (below 1 fs);
/// no power of ten.
std::string duration_text(double seconds, int significant);

/// |DeltaT| of every correction not skipped, with its uncertainty, on a log
/// axis in microseconds, applied and negligible told apart, and the
/// negligible threshold; empty when no correction has a size.
std::optional<CategoryChart> corrections_chart(const SceneReport& r, const std::string& id);

/// Each input's contribution to u(g), largest first, with its share of
/// u(g)^2; empty when no input has an uncertainty.
std::optional<CategoryChart> budget_chart(const SceneReport& r, const std::string& id);

/// The decay record in degrees with the fit of Eq. (25), its +-1 sigma band
/// (none, and the legend says why, when the fit's covariance is unknown)
/// and the residuals; empty without a record.
std::optional<Figure> decay_figure(const SceneReport& r, const std::string& id);
Figure decay_figure(const DecayRecord& d, const std::string& id);

/// A series: T^2 against L with 2 T sigma_eff error bars, the fitted model at
/// each length, the textbook line T^2 = (4 pi^2/g)(L + L0) and the
/// residuals; empty for a scene of one observation.
std::optional<Figure> series_figure(const SceneReport& r, const std::string& id);

/// A physical pendulum's series as a pivot scan: T against the pivot's
/// setting with u(T) error bars, the fitted model as a curve on each side of
/// the centre of mass, the textbook curve, the minimum period and the first
/// pivot's conjugate (Kater's knife edges with Bessel's g), and the
/// residuals; empty for any other scene (src/report/pivot_scan_plot.cpp).
std::optional<Figure> pivot_scan_figure(const SceneReport& r, const std::string& id);

/// One student's result in a class chart.
struct ClassPoint {
  std::string label, link;
  double g;                          ///< (m/s^2)
  std::optional<double> uncertainty; ///< (m/s^2); empty when unknown
  std::optional<Measured> expected;  ///< (m/s^2)
  std::optional<double> z;
  bool ok = true;  ///< status ok: the chart's scale is the ok results'
};

/// Every g with its error bar, sorted by g, against the expected g and its
/// band (one line when the class shares it, a marker per row otherwise).
/// The axis spans the ok results with their error bars and the expected g
/// with its band (standard gravity without one), so that a slip 4 times off
/// does not squeeze the class into one column; a result beyond is drawn at
/// the edge with its value.
CategoryChart class_chart(std::vector<ClassPoint> points, const std::string& id);

/// The plots the scene's data allow, by name: corrections, budget, decay,
/// series, pivot-scan.
std::vector<std::string> plot_names(const SceneReport& r);

/// One plot as a standalone SVG file. Throws InputError naming what the
/// scene lacks, or the plots it has, for an unknown or impossible plot.
std::string plot_svg(const SceneReport& r, const std::string& name);

}  // namespace pendulum::report
