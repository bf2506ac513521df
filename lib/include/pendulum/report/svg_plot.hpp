#pragma once
/// \file svg_plot.hpp
/// \brief Scientific plots as SVG text: a plot is data (points with error
/// bars, curves, bands, reference lines, bars), and `to_svg` draws it with
/// real axes. Knows nothing of pendulums (docs/report.md).
///
/// Output is deterministic: the same plot gives the same bytes (fixed number
/// formats, no time stamps, ids from the plot's own `id`). It uses no url(),
/// no script and no external resource, so that it can sit inline in an
/// offline HTML page. Each SVG holds a <title> and a <desc> for screen readers.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pendulum::report {

/// Tick marks at round numbers: every value is an integer multiple of
/// `step`, and step = m 10^k with m in {1, 2, 5}.
struct Ticks {
  double lo = 0.0;     ///< axis start: the first tick
  double hi = 1.0;     ///< axis end: the last tick
  double step = 0.0;   ///< between ticks (0 on a log axis)
  std::vector<double> values;
  int decimals = 0;    ///< digits after the point that print every tick exactly
  int label_every = 1;  ///< label every n-th tick (log axes over many decades)
};

/// Linear ticks ("nice numbers"). Rule: the step is the smallest m 10^k,
/// m in {1, 2, 5}, for which [lo, hi] widened outwards to multiples of the
/// step spans at most `max_intervals` steps; the axis runs from the first to
/// the last of those multiples. lo > hi are swapped; lo == hi is widened to
/// lo -+ max(|lo|/10, 1) first. Throws std::invalid_argument for non-finite
/// limits or max_intervals < 1.
Ticks nice_ticks(double lo, double hi, int max_intervals = 6);

/// The most intervals a linear y axis of a panel `height` px tall has: one
/// per 50 px, at least 2. A range already on those ticks is drawn as given.
int panel_intervals(double height);

/// Log ticks: the decades 10^k from the one at or below lo to the one at or
/// above hi (0 < lo <= hi), at most 7 of them labelled. Throws
/// std::invalid_argument otherwise.
Ticks log_ticks(double lo, double hi);

/// A number with `decimals` fixed digits after the point, "-0" printed as
/// "0", the minus sign as U+2212.
std::string format_fixed(double value, int decimals);

/// A number with `significant` significant digits, for labels: 596.0,
/// 0.0331, 12; below 1e-4 and from 1e6 on as a mantissa times a power of
/// ten: 1.23×10⁻³⁰⁰.
std::string format_significant(double value, int significant);

/// "×10" and the exponent in superscript digits: times_ten_to(-5) is "×10⁻⁵".
std::string times_ten_to(int exponent);

/// Escapes & < > " ' for XML text and attributes.
std::string xml_escape(const std::string& text);

/// The Okabe-Ito palette (Okabe & Ito 2008), safe for the common colour-vision
/// deficiencies; every plot also tells its series apart by marker and dash,
/// so that it survives greyscale printing.
enum class Colour { black, blue, vermillion, green, orange, sky_blue, purple, grey };
const char* colour_hex(Colour c);

/// `tick`: a short vertical stroke through the point (e.g. an event on a
/// time axis). A series of ticks, or of more than 1000 filled circles, is
/// written as one path (a dot is a round-capped stroke of length 0), so that
/// a long record stays a small file.
enum class Marker { none, circle, square, triangle, diamond, tick };
enum class Dash { solid, dashed, dotted, dash_dot };

enum class Scale { linear, log };

struct Axis {
  std::string label;  ///< quantity and unit, e.g. "time t (s)"
  Scale scale = Scale::linear;
  bool include_zero = false;  ///< linear axes: widen the range to hold 0
  /// A figure's y axis: this range (lo, hi) in place of the data's, widened
  /// to ticks as any; data beyond it are the caller's to cut.
  std::optional<std::pair<double, double>> range = std::nullopt;
};

/// Measured points; error vectors are empty or one per point (standard
/// uncertainties, drawn as +-1 bars).
struct Points {
  std::string name;  ///< legend entry; "" for none
  std::vector<double> x, y, x_error, y_error;
  Colour colour = Colour::black;
  Marker marker = Marker::circle;
  bool filled = true;
  double size = 4.0;  ///< marker radius (px)
};

/// A curve drawn through (x, y).
struct Curve {
  std::string name;
  std::vector<double> x, y;
  Colour colour = Colour::blue;
  Dash dash = Dash::solid;
  double width = 2.0;  ///< (px)
};

/// A shaded region between two curves, e.g. a fit's +-1 sigma.
struct Band {
  std::string name;
  std::vector<double> x, lower, upper;
  Colour colour = Colour::sky_blue;
};

/// A horizontal line at `value` (vertical in a CategoryChart), with an
/// optional shaded band value -+ half_width.
struct Reference {
  std::string name;
  double value = 0.0;
  double half_width = 0.0;
  Colour colour = Colour::vermillion;
  Dash dash = Dash::dashed;
};

/// One panel of an x-y figure: its own y axis, the figure's x axis.
struct Panel {
  Axis y;
  std::vector<Band> bands;
  std::vector<Reference> references;
  std::vector<Curve> curves;
  std::vector<Points> points;
  double height = 300.0;  ///< plotting area (px)
};

/// Panels stacked over one shared x axis (e.g. a fit over its residuals).
struct Figure {
  std::string id;           ///< unique in the page; prefixes the SVG's ids
  std::string title;        ///< shown at the top and in <title>
  std::string description;  ///< <desc>: what the plot shows, in words
  Axis x;
  std::vector<Panel> panels;
  double width = 720.0;  ///< whole SVG (px)
};

/// One set of values over the categories of a CategoryChart.
struct CategorySeries {
  enum class Mark { bar, point };
  std::string name;
  Mark mark = Mark::bar;
  /// One entry per category; empty optional: nothing drawn in that row.
  std::vector<std::optional<double>> values;
  std::vector<std::optional<double>> errors;  ///< empty, or one per category
  Colour colour = Colour::blue;
  bool filled = true;  ///< open bars or markers tell a second series apart
  Marker marker = Marker::circle;  ///< for Mark::point
};

/// Horizontal rows, one per category, with bars or points along one value
/// axis: long labels stay readable, and a log axis shows sizes that span
/// decades. On a log axis a bar starts at the axis and an error bar that
/// reaches below it is cut there, without its cap; the axis spans at most
/// nine decades below the largest value, and smaller values are not drawn.
struct CategoryChart {
  std::string id, title, description;
  std::vector<std::string> categories;  ///< row labels, top to bottom
  /// Empty, or one per category: a same-page link ("#scene-2") for the label.
  std::vector<std::string> links;
  std::vector<std::string> notes;  ///< empty, or one text per row, right of the plot
  Axis value;
  std::vector<CategorySeries> series;
  std::vector<Reference> references;  ///< vertical lines
  /// Linear axes: when set, the axis spans [first, second] (widened to its
  /// ticks) whatever the values; a point beyond is drawn at the axis's edge,
  /// open, with its value written beside it and no error bar.
  std::optional<std::pair<double, double>> range;
  double width = 720.0;
};

/// The SVG of a figure or chart. `standalone`: an SVG file (XML declaration
/// and namespace); otherwise markup to place inside HTML.
/// Throws std::invalid_argument for a plot with nothing finite to draw.
std::string to_svg(const Figure& figure, bool standalone);
std::string to_svg(const CategoryChart& chart, bool standalone);

}  // namespace pendulum::report
