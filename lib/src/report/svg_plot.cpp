#include "pendulum/report/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>

namespace pendulum::report {

namespace {

// 10^n, exact in double for 0 <= n <= 22 (so that i*m/10^n is the double
// nearest the decimal tick value).
double power_of_ten(int n) {
  if (n > 22) return std::pow(10.0, n);
  double p = 1.0;
  for (int i = 0; i < n; ++i) p *= 10.0;
  return p;
}

// 10^k: the exact quotient near 1, pow (with subnormals) far below.
double decade(int k) { return k >= -22 ? (k >= 0 ? power_of_ten(k) : 1.0 / power_of_ten(-k)) : std::pow(10.0, k); }

int exponent_of(double v) { return static_cast<int>(std::floor(std::log10(std::abs(v)))); }

}  // namespace

Ticks nice_ticks(double lo, double hi, int max_intervals) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || max_intervals < 1) {
    throw std::invalid_argument("nice_ticks: non-finite limits or no interval");
  }
  if (lo > hi) std::swap(lo, hi);
  if (!std::isfinite(hi - lo)) throw std::invalid_argument("nice_ticks: range too wide for a double");
  // A range that doubles barely resolve at its magnitude, or so narrow that
  // its steps would underflow, counts as one value.
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi)) || hi - lo < 1e-290) {
    const double mid = lo / 2 + hi / 2, d = std::max(std::abs(mid) / 10.0, 1.0);
    lo = mid - d;
    hi = mid + d;
  }
  // lo/s and hi/s within 1e-9 of an integer count as that integer, so that
  // 9.79/0.01 = 978.9999999 still starts at 979.
  auto floor_q = [](double q) { return std::floor(q + 1e-9 * std::max(1.0, std::abs(q))); };
  auto ceil_q = [](double q) { return std::ceil(q - 1e-9 * std::max(1.0, std::abs(q))); };
  const int k0 = static_cast<int>(std::floor(std::log10((hi - lo) / max_intervals))) - 1;
  for (int k = k0;; ++k) {
    for (int m : {1, 2, 5}) {
      const double step = m * decade(k);
      const double a = floor_q(lo / step), b = ceil_q(hi / step);
      if (b - a > max_intervals) continue;
      Ticks t;
      t.step = step;
      t.decimals = std::max(0, -k);
      for (double i = a; i <= b; ++i) {
        t.values.push_back(k >= 0 ? i * m * decade(k) : i * m / power_of_ten(-k));
      }
      t.lo = t.values.front();
      t.hi = t.values.back();
      return t;
    }
  }
}

int panel_intervals(double height) { return std::max(2, static_cast<int>(height / 50.0)); }

Ticks log_ticks(double lo, double hi) {
  if (!(lo > 0.0) || !(hi >= lo) || !std::isfinite(hi)) {
    throw std::invalid_argument("log_ticks: needs 0 < lo <= hi, finite");
  }
  // 1e-323 is the smallest decade a double holds (a subnormal).
  const int a = std::max(-323, static_cast<int>(std::floor(std::log10(lo) + 1e-12)));
  int b = static_cast<int>(std::ceil(std::log10(hi) - 1e-12));
  if (b == a) ++b;
  Ticks t;
  for (int k = a; k <= b; ++k) t.values.push_back(decade(k));
  t.label_every = (b - a + 5) / 6;  // at most 7 labels
  t.lo = t.values.front();
  t.hi = t.values.back();
  t.decimals = std::max(0, -a);
  return t;
}

std::string format_fixed(double value, int decimals) {
  std::string s(static_cast<std::size_t>(std::snprintf(nullptr, 0, "%.*f", decimals, value)), '\0');
  std::snprintf(s.data(), s.size() + 1, "%.*f", decimals, value);
  if (s[0] != '-') return s;
  if (s.find_first_not_of("-0.") == std::string::npos) return s.substr(1);  // "-0.00"
  return "\u2212" + s.substr(1);
}

std::string times_ten_to(int exponent) {
  static const char* const digits[] = {"\u2070", "\u00B9", "\u00B2", "\u00B3", "\u2074",
                                       "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  std::string s;
  for (char c : std::to_string(std::abs(exponent))) s += digits[c - '0'];
  return "\u00D710" + std::string(exponent < 0 ? "\u207B" : "") + s;
}

std::string format_significant(double value, int significant) {
  if (value == 0.0 || !std::isfinite(value)) return format_fixed(value, 0);
  // Round first, so that 9.996 to 3 digits is 10.0, not 10.00.
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*e", significant - 1, value);
  const double rounded = std::strtod(buffer, nullptr);
  const int k = exponent_of(rounded);
  if (k < -4 || k >= 6) return format_fixed(rounded / decade(k), significant - 1) + times_ten_to(k);
  return format_fixed(rounded, std::max(0, significant - 1 - k));
}

std::string xml_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

const char* colour_hex(Colour c) {
  switch (c) {
    case Colour::black: return "#000000";
    case Colour::blue: return "#0072B2";
    case Colour::vermillion: return "#D55E00";
    case Colour::green: return "#009E73";
    case Colour::orange: return "#E69F00";
    case Colour::sky_blue: return "#56B4E9";
    case Colour::purple: return "#CC79A7";
    case Colour::grey: return "#767676";
  }
  return "#000000";
}

namespace {

constexpr double kTickFont = 13.0, kLabelFont = 14.0, kTitleFont = 16.0;
constexpr const char* kGrid = "#DDDDDD";
constexpr double kChartMarker = 4.5;  // marker radius in a CategoryChart (px)
constexpr std::size_t kDenseMarkers = 1000;  // more filled circles than this: one path

// Width of a text in DejaVu Sans, generously (digits are 0.64 em).
double text_width(const std::string& s, double font) {
  std::size_t chars = 0;
  for (unsigned char c : s) chars += (c & 0xC0) != 0x80;  // UTF-8 lead bytes
  return 0.64 * font * static_cast<double>(chars);
}

// Coordinates: two decimals, enough for a print at 600 dpi.
std::string num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", v == 0.0 ? 0.0 : v);
  return buffer;
}

const char* dash_array(Dash d) {
  switch (d) {
    case Dash::solid: return "";
    case Dash::dashed: return " stroke-dasharray=\"8 5\"";
    case Dash::dotted: return " stroke-dasharray=\"2 4\"";
    case Dash::dash_dot: return " stroke-dasharray=\"9 4 2 4\"";
  }
  return "";
}

/// The SVG text being written, with the primitives the plots need.
class Canvas {
 public:
  void line(double x1, double y1, double x2, double y2, const char* colour, double width,
            Dash dash = Dash::solid) {
    s_ += "<line x1=\"" + num(x1) + "\" y1=\"" + num(y1) + "\" x2=\"" + num(x2) + "\" y2=\"" + num(y2) +
          "\" stroke=\"" + colour + "\" stroke-width=\"" + num(width) + "\"" + dash_array(dash) + "/>\n";
  }
  void rect(double x, double y, double w, double h, const std::string& fill, const std::string& stroke,
            double opacity = 1.0) {
    s_ += "<rect x=\"" + num(x) + "\" y=\"" + num(y) + "\" width=\"" + num(std::max(w, 0.0)) + "\" height=\"" +
          num(std::max(h, 0.0)) + "\" fill=\"" + fill + "\"" +
          (opacity < 1.0 ? " fill-opacity=\"" + num(opacity) + "\"" : "") +
          (stroke.empty() ? "" : " stroke=\"" + stroke + "\" stroke-width=\"1.5\"") + "/>\n";
  }
  void text(double x, double y, const std::string& content, double font, const char* anchor = "start",
            const std::string& extra = "") {
    s_ += "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" font-size=\"" + num(font) + "\"" +
          (std::string(anchor) == "start" ? "" : std::string(" text-anchor=\"") + anchor + "\"") + extra + ">" +
          xml_escape(content) + "</text>\n";
  }
  void polyline(const std::vector<std::pair<double, double>>& p, const char* colour, double width, Dash dash) {
    if (p.size() < 2) return;
    s_ += "<polyline fill=\"none\" stroke=\"" + std::string(colour) + "\" stroke-width=\"" + num(width) + "\"" +
          dash_array(dash) + " stroke-linejoin=\"round\" points=\"";
    for (std::size_t i = 0; i < p.size(); ++i) s_ += (i ? " " : "") + num(p[i].first) + "," + num(p[i].second);
    s_ += "\"/>\n";
  }
  void polygon(const std::vector<std::pair<double, double>>& p, const char* colour, double opacity) {
    s_ += "<polygon fill=\"" + std::string(colour) + "\" fill-opacity=\"" + num(opacity) + "\" points=\"";
    for (std::size_t i = 0; i < p.size(); ++i) s_ += (i ? " " : "") + num(p[i].first) + "," + num(p[i].second);
    s_ += "\"/>\n";
  }
  void marker(Marker m, double x, double y, double r, const char* colour, bool filled) {
    const std::string paint = std::string(" fill=\"") + (filled ? colour : "#FFFFFF") + "\" stroke=\"" + colour +
                              "\" stroke-width=\"1.5\"/>\n";
    switch (m) {
      case Marker::none: return;
      case Marker::circle:
        s_ += "<circle cx=\"" + num(x) + "\" cy=\"" + num(y) + "\" r=\"" + num(r) + "\"" + paint;
        return;
      case Marker::square:
        s_ += "<rect x=\"" + num(x - 0.9 * r) + "\" y=\"" + num(y - 0.9 * r) + "\" width=\"" + num(1.8 * r) +
              "\" height=\"" + num(1.8 * r) + "\"" + paint;
        return;
      case Marker::triangle:
        s_ += "<path d=\"M" + num(x) + "," + num(y - 1.2 * r) + " L" + num(x + 1.1 * r) + "," + num(y + 0.8 * r) +
              " L" + num(x - 1.1 * r) + "," + num(y + 0.8 * r) + " Z\"" + paint;
        return;
      case Marker::diamond:
        s_ += "<path d=\"M" + num(x) + "," + num(y - 1.3 * r) + " L" + num(x + 1.1 * r) + "," + num(y) + " L" +
              num(x) + "," + num(y + 1.3 * r) + " L" + num(x - 1.1 * r) + "," + num(y) + " Z\"" + paint;
        return;
      case Marker::tick: markers(m, {{x, y}}, r, colour); return;
    }
  }
  /// Many markers as one path: ticks, or dots (round-capped strokes of
  /// length 0, drawn by every SVG renderer as discs of the stroke's width).
  void markers(Marker m, const std::vector<std::pair<double, double>>& at, double r, const char* colour) {
    if (at.empty()) return;
    const bool tick = m == Marker::tick;
    s_ += "<path fill=\"none\" stroke=\"" + std::string(colour) + "\" stroke-width=\"" + num(tick ? 2.0 : 2.0 * r) +
          "\"" + (tick ? "" : " stroke-linecap=\"round\"") + " d=\"";
    for (const auto& [x, y] : at) {
      s_ += tick ? "M" + num(x) + "," + num(y - 1.6 * r) + "v" + num(3.2 * r) : "M" + num(x) + "," + num(y) + "h0";
    }
    s_ += "\"/>\n";
  }
  void raw(const std::string& markup) { s_ += markup; }
  const std::string& str() const { return s_; }

 private:
  std::string s_;
};

/// Maps data values on an axis to pixels between p0 (at lo) and p1 (at hi).
struct Mapping {
  Scale scale;
  double lo, hi, p0, p1;
  double operator()(double v) const {
    const double f = scale == Scale::log ? (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo))
                                         : (v - lo) / (hi - lo);
    return p0 + f * (p1 - p0);
  }
};

/// The range of the finite values seen, for an axis.
struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  bool log = false;
  void add(double v) {
    if (!std::isfinite(v) || (log && v <= 0.0)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  bool empty() const { return lo > hi; }
};

Ticks axis_ticks(const Axis& axis, Range r, int max_intervals) {
  if (r.empty()) throw std::invalid_argument("plot: no finite value on the axis \"" + axis.label + "\"");
  if (axis.scale == Scale::log) return log_ticks(r.lo, r.hi);
  if (axis.include_zero) {
    r.add(0.0);
  }
  return nice_ticks(r.lo, r.hi, max_intervals);
}

std::string tick_label(const Ticks& t, const Axis& axis, double v) {
  if (axis.scale == Scale::log) {
    const int k = static_cast<int>(std::lround(std::log10(v)));
    return std::abs(k) <= 4 ? format_fixed(v, std::max(0, -k)) : times_ten_to(k).substr(2);  // "10⁵": the "×" (2 bytes in UTF-8) dropped
  }
  const double largest = std::max(std::abs(t.lo), std::abs(t.hi));
  if (t.decimals <= 6 && largest < 1e6) return format_fixed(v, t.decimals);
  // Very small or large: a mantissa with the digits the step needs, times a
  // power of ten common to the axis.
  if (v == 0.0) return "0";
  const int e = exponent_of(largest), k = static_cast<int>(std::floor(std::log10(t.step) + 1e-9));
  return format_fixed(v / decade(e), std::max(0, e - k)) + times_ten_to(e);
}

bool labelled(const Ticks& t, std::size_t i) { return i % static_cast<std::size_t>(t.label_every) == 0; }

double max_tick_label_width(const Ticks& t, const Axis& axis) {
  double w = 0.0;
  for (std::size_t i = 0; i < t.values.size(); ++i) {
    if (labelled(t, i)) w = std::max(w, text_width(tick_label(t, axis, t.values[i]), kTickFont));
  }
  return w;
}

/// Minor ticks of a log axis: 2..9 times each decade inside it, when every
/// decade is labelled.
std::vector<double> log_minor_ticks(const Ticks& t) {
  std::vector<double> minor;
  if (t.label_every > 1) return minor;
  for (std::size_t i = 0; i + 1 < t.values.size(); ++i) {
    for (int m = 2; m <= 9; ++m) minor.push_back(m * t.values[i]);
  }
  return minor;
}

/// Grid lines and ticks of an x axis under a plot from y_top to y_bottom;
/// labels only on the bottom panel, and only every label_every-th.
void draw_x_ticks(Canvas& c, const Ticks& t, const Axis& axis, const Mapping& m, double y_top, double y_bottom,
                  bool labels) {
  for (std::size_t i = 0; i < t.values.size(); ++i) {
    const double x = m(t.values[i]);
    c.line(x, y_bottom, x, y_bottom + (labelled(t, i) ? 6 : 3), "#000000", 1.0);
    if (!labelled(t, i)) continue;
    c.line(x, y_top, x, y_bottom, kGrid, 1.0);
    if (labels) c.text(x, y_bottom + 20, tick_label(t, axis, t.values[i]), kTickFont, "middle");
  }
  if (axis.scale != Scale::log) return;
  for (double v : log_minor_ticks(t)) c.line(m(v), y_bottom, m(v), y_bottom + 3, "#000000", 1.0);
}

/// The same for a y axis left of a plot from x_left to x_right.
void draw_y_ticks(Canvas& c, const Ticks& t, const Axis& axis, const Mapping& m, double x_left, double x_right) {
  for (std::size_t i = 0; i < t.values.size(); ++i) {
    const double y = m(t.values[i]);
    c.line(x_left - (labelled(t, i) ? 6 : 3), y, x_left, y, "#000000", 1.0);
    if (!labelled(t, i)) continue;
    c.line(x_left, y, x_right, y, kGrid, 1.0);
    c.text(x_left - 9, y + 4.5, tick_label(t, axis, t.values[i]), kTickFont, "end");
  }
  if (axis.scale != Scale::log) return;
  for (double v : log_minor_ticks(t)) c.line(x_left - 3, m(v), x_left, m(v), "#000000", 1.0);
}

/// A legend entry's sample drawing and text.
struct LegendEntry {
  std::string name;
  std::function<void(Canvas&, double x, double y)> sample;  // 28 px wide, centred on y
};

/// Lays the legend out in rows from x0 within `width`; returns the height.
double legend_height(const std::vector<LegendEntry>& entries, double width) {
  if (entries.empty()) return 0.0;
  double x = 0.0, rows = 1.0;
  for (const auto& e : entries) {
    const double w = 34.0 + text_width(e.name, kTickFont) + 18.0;
    if (x > 0.0 && x + w > width) {
      ++rows;
      x = 0.0;
    }
    x += w;
  }
  return rows * 22.0;
}

void draw_legend(Canvas& c, const std::vector<LegendEntry>& entries, double x0, double y0, double width) {
  double x = 0.0, y = y0 + 11.0;
  for (const auto& e : entries) {
    const double w = 34.0 + text_width(e.name, kTickFont) + 18.0;
    if (x > 0.0 && x + w > width) {
      x = 0.0;
      y += 22.0;
    }
    e.sample(c, x0 + x, y);
    c.text(x0 + x + 34.0, y + 4.5, e.name, kTickFont);
    x += w;
  }
}

LegendEntry points_legend(const Points& p) {
  return {p.name, [p](Canvas& c, double x, double y) {
            if (!p.y_error.empty()) c.line(x + 14, y - 8, x + 14, y + 8, colour_hex(p.colour), 1.2);
            c.marker(p.marker, x + 14, y, p.size, colour_hex(p.colour), p.filled);
          }};
}
LegendEntry curve_legend(const Curve& k) {
  return {k.name, [k](Canvas& c, double x, double y) { c.line(x, y, x + 28, y, colour_hex(k.colour), k.width, k.dash); }};
}
LegendEntry band_legend(const Band& b) {
  return {b.name, [b](Canvas& c, double x, double y) { c.rect(x, y - 7, 28, 14, colour_hex(b.colour), "", 0.35); }};
}
LegendEntry reference_legend(const Reference& r, bool vertical) {
  return {r.name, [r, vertical](Canvas& c, double x, double y) {
            if (r.half_width > 0.0) c.rect(x, y - 7, 28, 14, colour_hex(r.colour), "", 0.15);
            if (vertical) {
              c.line(x + 14, y - 9, x + 14, y + 9, colour_hex(r.colour), 2.0, r.dash);
            } else {
              c.line(x, y, x + 28, y, colour_hex(r.colour), 2.0, r.dash);
            }
          }};
}

std::string svg_open(const std::string& id, const std::string& title, const std::string& description, double width,
                     double height, bool standalone) {
  std::string s;
  if (standalone) s += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += "<svg";
  // A namespace name, not a resource: inline SVG in HTML needs none.
  if (standalone) s += " xmlns=\"http://www.w3.org/2000/svg\"";
  s += " id=\"" + xml_escape(id) + "\" viewBox=\"0 0 " + num(width) + " " + num(height) + "\" width=\"" + num(width) +
       "\" height=\"" + num(height) + "\" role=\"img\" aria-labelledby=\"" + xml_escape(id) + "-title " +
       xml_escape(id) + "-desc\" font-family=\"DejaVu Sans, Verdana, Arial, sans-serif\">\n";
  s += "<title id=\"" + xml_escape(id) + "-title\">" + xml_escape(title) + "</title>\n";
  s += "<desc id=\"" + xml_escape(id) + "-desc\">" + xml_escape(description) + "</desc>\n";
  s += "<rect x=\"0\" y=\"0\" width=\"" + num(width) + "\" height=\"" + num(height) + "\" fill=\"#FFFFFF\"/>\n";
  return s;
}

std::vector<std::pair<double, double>> pixels(const Points& p, const Mapping& mx, const Mapping& my) {
  std::vector<std::pair<double, double>> at;
  for (std::size_t j = 0; j < p.x.size(); ++j) at.emplace_back(mx(p.x[j]), my(p.y[j]));
  return at;
}

void require_id(const std::string& id) {
  if (id.empty()) throw std::invalid_argument("plot: an id is needed to label the SVG");
}

}  // namespace

std::string to_svg(const Figure& f, bool standalone) {
  require_id(f.id);
  if (f.panels.empty()) throw std::invalid_argument("plot \"" + f.id + "\": no panel");

  // Ranges: x over every panel, y per panel.
  Range xr;
  xr.log = f.x.scale == Scale::log;
  std::vector<Range> yr(f.panels.size());
  for (std::size_t i = 0; i < f.panels.size(); ++i) {
    const Panel& p = f.panels[i];
    Range& y = yr[i];
    y.log = p.y.scale == Scale::log;
    for (const auto& b : p.bands) {
      for (std::size_t j = 0; j < b.x.size(); ++j) {
        xr.add(b.x[j]);
        y.add(b.lower[j]);
        y.add(b.upper[j]);
      }
    }
    for (const auto& r : p.references) {
      y.add(r.value - r.half_width);
      y.add(r.value + r.half_width);
    }
    for (const auto& k : p.curves) {
      for (double v : k.x) xr.add(v);
      for (double v : k.y) y.add(v);
    }
    for (const auto& pt : p.points) {
      for (std::size_t j = 0; j < pt.x.size(); ++j) {
        const double ex = pt.x_error.empty() ? 0.0 : pt.x_error[j];
        const double ey = pt.y_error.empty() ? 0.0 : pt.y_error[j];
        xr.add(pt.x[j] - ex);
        xr.add(pt.x[j] + ex);
        y.add(pt.y[j] - ey);
        y.add(pt.y[j] + ey);
      }
    }
  }
  const Ticks xt = axis_ticks(f.x, xr, 8);
  std::vector<Ticks> yt;
  double left = 0.0;
  for (std::size_t i = 0; i < f.panels.size(); ++i) {
    if (const auto& fixed = f.panels[i].y.range) {
      yr[i] = Range{};
      yr[i].log = f.panels[i].y.scale == Scale::log;
      yr[i].add(fixed->first);
      yr[i].add(fixed->second);
    }
    yt.push_back(axis_ticks(f.panels[i].y, yr[i], panel_intervals(f.panels[i].height)));
    left = std::max(left, max_tick_label_width(yt.back(), f.panels[i].y));
  }
  left += 8.0 + 6.0 + 28.0;  // tick, gap, rotated label
  const double right = 16.0 + text_width(tick_label(xt, f.x, xt.hi), kTickFont) / 2.0;
  const double plot_width = f.width - left - right;

  std::vector<LegendEntry> legend;
  for (const auto& p : f.panels) {
    for (const auto& b : p.bands) if (!b.name.empty()) legend.push_back(band_legend(b));
    for (const auto& r : p.references) if (!r.name.empty()) legend.push_back(reference_legend(r, false));
    for (const auto& k : p.curves) if (!k.name.empty()) legend.push_back(curve_legend(k));
    for (const auto& pt : p.points) if (!pt.name.empty()) legend.push_back(points_legend(pt));
  }
  const double title_h = 30.0, legend_h = legend_height(legend, plot_width), gap = 14.0;
  double top = title_h + legend_h + 8.0, height = top;
  for (const auto& p : f.panels) height += p.height + gap;
  height += 22.0 + 26.0 - gap + 8.0;  // x tick labels, x label

  Canvas c;
  c.raw(svg_open(f.id, f.title, f.description, f.width, height, standalone));
  c.text(left, 21.0, f.title, kTitleFont, "start", " font-weight=\"bold\"");
  draw_legend(c, legend, left, title_h, plot_width);

  const Mapping mx{f.x.scale, xt.lo, xt.hi, left, left + plot_width};
  double y0 = top;
  for (std::size_t i = 0; i < f.panels.size(); ++i) {
    const Panel& p = f.panels[i];
    const Ticks& ty = yt[i];
    const Mapping my{p.y.scale, ty.lo, ty.hi, y0 + p.height, y0};
    const bool bottom = i + 1 == f.panels.size();
    // Grid and ticks.
    draw_y_ticks(c, ty, p.y, my, left, left + plot_width);
    draw_x_ticks(c, xt, f.x, mx, y0, y0 + p.height, bottom);
    const double cy = y0 + p.height / 2.0;
    c.text(16.0, cy, p.y.label, kLabelFont, "middle",
           " transform=\"rotate(-90 16.00 " + num(cy) + ")\" dominant-baseline=\"middle\"");

    // Data, back to front.
    for (const auto& b : p.bands) {
      std::vector<std::pair<double, double>> poly;
      for (std::size_t j = 0; j < b.x.size(); ++j) poly.emplace_back(mx(b.x[j]), my(b.upper[j]));
      for (std::size_t j = b.x.size(); j-- > 0;) poly.emplace_back(mx(b.x[j]), my(b.lower[j]));
      c.polygon(poly, colour_hex(b.colour), 0.35);
    }
    for (const auto& r : p.references) {
      if (r.half_width > 0.0) {
        c.rect(left, my(r.value + r.half_width), plot_width, my(r.value - r.half_width) - my(r.value + r.half_width),
               colour_hex(r.colour), "", 0.15);
      }
      c.line(left, my(r.value), left + plot_width, my(r.value), colour_hex(r.colour), 2.0, r.dash);
    }
    for (const auto& pt : p.points) {
      const char* colour = colour_hex(pt.colour);
      const double cap = pt.x.size() > 50 ? 0.0 : 3.5;  // caps crowd a dense record
      for (std::size_t j = 0; j < pt.x.size(); ++j) {
        const double x = mx(pt.x[j]), y = my(pt.y[j]);
        if (!pt.y_error.empty() && pt.y_error[j] > 0.0) {
          const double a = my(pt.y[j] - pt.y_error[j]), b = my(pt.y[j] + pt.y_error[j]);
          c.line(x, a, x, b, colour, 1.0);
          if (cap > 0.0) {
            c.line(x - cap, a, x + cap, a, colour, 1.0);
            c.line(x - cap, b, x + cap, b, colour, 1.0);
          }
        }
        if (!pt.x_error.empty() && pt.x_error[j] > 0.0) {
          const double a = mx(pt.x[j] - pt.x_error[j]), b = mx(pt.x[j] + pt.x_error[j]);
          c.line(a, y, b, y, colour, 1.0);
          if (cap > 0.0) {
            c.line(a, y - cap, a, y + cap, colour, 1.0);
            c.line(b, y - cap, b, y + cap, colour, 1.0);
          }
        }
      }
      if (pt.marker == Marker::tick) continue;  // over the curves, below
      if (pt.marker == Marker::circle && pt.filled && pt.x.size() > kDenseMarkers) {
        c.markers(pt.marker, pixels(pt, mx, my), pt.size, colour);
        continue;
      }
      for (std::size_t j = 0; j < pt.x.size(); ++j) {
        c.marker(pt.marker, mx(pt.x[j]), my(pt.y[j]), pt.size, colour, pt.filled);
      }
    }
    // Curves over the points: a fit stays visible through a dense record.
    for (const auto& k : p.curves) {
      std::vector<std::pair<double, double>> line;
      for (std::size_t j = 0; j < k.x.size(); ++j) {
        if (std::isfinite(k.x[j]) && std::isfinite(k.y[j])) line.emplace_back(mx(k.x[j]), my(k.y[j]));
      }
      c.polyline(line, colour_hex(k.colour), k.width, k.dash);
    }
    // Ticks mark events on a curve (the crossings of a signal): over it.
    for (const auto& pt : p.points) {
      if (pt.marker == Marker::tick) c.markers(pt.marker, pixels(pt, mx, my), pt.size, colour_hex(pt.colour));
    }
    c.rect(left, y0, plot_width, p.height, "none", "#000000");
    y0 += p.height + gap;
  }
  const double axis_bottom = y0 - gap;
  c.text(left + plot_width / 2.0, axis_bottom + 44.0, f.x.label, kLabelFont, "middle");
  c.raw("</svg>\n");
  return c.str();
}

std::string to_svg(const CategoryChart& ch, bool standalone) {
  require_id(ch.id);
  const std::size_t rows = ch.categories.size();
  if (rows == 0) throw std::invalid_argument("chart \"" + ch.id + "\": no category");
  const bool log = ch.value.scale == Scale::log;

  // Which series have a value in each row: they share the row's height.
  std::vector<std::vector<std::size_t>> in_row(rows);
  Range vr;
  vr.log = log;
  const bool clipped = ch.range && !log;
  for (std::size_t s = 0; s < ch.series.size(); ++s) {
    const auto& se = ch.series[s];
    for (std::size_t r = 0; r < rows && r < se.values.size(); ++r) {
      if (!se.values[r] || !std::isfinite(*se.values[r]) || (log && *se.values[r] <= 0.0)) continue;
      in_row[r].push_back(s);
      if (clipped) continue;
      const double v = *se.values[r];
      const double e = se.errors.empty() || !se.errors[r] ? 0.0 : *se.errors[r];
      vr.add(v);
      vr.add(v + e);
      if (!log || v - e > 0.0) vr.add(v - e);
    }
  }
  if (clipped) {
    vr.add(ch.range->first);
    vr.add(ch.range->second);
  } else {
    for (const auto& r : ch.references) {
      vr.add(r.value - r.half_width);
      vr.add(r.value + r.half_width);
    }
  }
  Axis value_axis = ch.value;
  const bool bars = std::any_of(ch.series.begin(), ch.series.end(),
                                [](const CategorySeries& s) { return s.mark == CategorySeries::Mark::bar; });
  if (bars) value_axis.include_zero = true;
  // A log axis shows the nine decades below the largest value; anything
  // smaller is not drawn (its note still gives it).
  if (log && !vr.empty()) vr.lo = std::max(vr.lo, vr.hi * 1e-9);
  const Ticks t = axis_ticks(value_axis, vr, 6);

  double label_w = 0.0, note_w = 0.0;
  for (const auto& l : ch.categories) label_w = std::max(label_w, text_width(l, kTickFont) * 0.9);
  // A note starts 12 px right of the plot and keeps 8 px clear of the edge
  // (signed microseconds are digits, 0.64 em each: at full width).
  for (const auto& n : ch.notes) note_w = std::max(note_w, text_width(n, kTickFont));
  const double left = 12.0 + label_w + 10.0;
  const double right = std::max(note_w > 0.0 ? note_w + 20.0 : 0.0,
                                 10.0 + text_width(tick_label(t, value_axis, t.hi), kTickFont) / 2.0);
  // Long labels widen the chart rather than squeeze the plot; a page scales it down.
  const double width = std::max(ch.width, left + right + 360.0), plot_width = width - left - right;

  std::vector<LegendEntry> legend;
  for (const auto& r : ch.references) if (!r.name.empty()) legend.push_back(reference_legend(r, true));
  for (const auto& se : ch.series) {
    if (se.name.empty()) continue;
    if (se.mark == CategorySeries::Mark::bar) {
      legend.push_back({se.name, [se](Canvas& c, double x, double y) {
                          c.rect(x + 2, y - 6, 24, 12, se.filled ? colour_hex(se.colour) : "#FFFFFF",
                                 colour_hex(se.colour));
                        }});
    } else {
      const bool error_bars = !se.errors.empty();
      legend.push_back({se.name, [se, error_bars](Canvas& c, double x, double y) {
                          if (error_bars) c.line(x + 3, y, x + 25, y, "#000000", 1.2);  // as in the rows
                          c.marker(se.marker, x + 14, y, kChartMarker, colour_hex(se.colour), se.filled);
                        }});
    }
  }
  const double title_h = 30.0, legend_h = legend_height(legend, width - 24.0), row_h = 28.0;
  const double top = title_h + legend_h + 8.0, plot_h = row_h * static_cast<double>(rows);
  const double height = top + plot_h + 22.0 + 26.0 + 8.0;

  Canvas c;
  c.raw(svg_open(ch.id, ch.title, ch.description, width, height, standalone));
  c.text(12.0, 21.0, ch.title, kTitleFont, "start", " font-weight=\"bold\"");
  draw_legend(c, legend, 12.0, title_h, width - 24.0);

  const Mapping mv{value_axis.scale, t.lo, t.hi, left, left + plot_width};
  draw_x_ticks(c, t, value_axis, mv, top, top + plot_h, true);
  c.text(left + plot_width / 2.0, top + plot_h + 44.0, value_axis.label, kLabelFont, "middle");

  for (const auto& r : ch.references) {
    if (r.half_width > 0.0) {
      c.rect(mv(r.value - r.half_width), top, mv(r.value + r.half_width) - mv(r.value - r.half_width), plot_h,
             colour_hex(r.colour), "", 0.15);
    }
    c.line(mv(r.value), top, mv(r.value), top + plot_h, colour_hex(r.colour), 2.0, r.dash);
  }
  const double base = log ? t.lo : std::clamp(0.0, t.lo, t.hi);
  for (std::size_t r = 0; r < rows; ++r) {
    const double row_top = top + row_h * static_cast<double>(r), mid = row_top + row_h / 2.0;
    const std::string& label = ch.categories[r];
    if (!ch.links.empty() && !ch.links[r].empty()) {
      c.raw("<a href=\"" + xml_escape(ch.links[r]) + "\">");
      c.text(left - 10, mid + 4.5, label, kTickFont, "end", " fill=\"#0050A0\" text-decoration=\"underline\"");
      c.raw("</a>\n");
    } else {
      c.text(left - 10, mid + 4.5, label, kTickFont, "end");
    }
    if (!ch.notes.empty()) c.text(left + plot_width + 12, mid + 4.5, ch.notes[r], kTickFont);

    const double slot = (row_h - 8.0) / static_cast<double>(std::max<std::size_t>(1, in_row[r].size()));
    for (std::size_t k = 0; k < in_row[r].size(); ++k) {
      const auto& se = ch.series[in_row[r][k]];
      const char* colour = colour_hex(se.colour);
      const double v = *se.values[r];
      if (log && v < t.lo) continue;
      const double e = se.errors.empty() || !se.errors[r] ? 0.0 : *se.errors[r];
      const double y = row_top + 4.0 + slot * (static_cast<double>(k) + 0.5);
      if (clipped && (v < t.lo || v > t.hi)) {
        // Off the scale: an open marker at the edge, its value inside the plot beside it.
        const bool low = v < t.lo;
        const double edge = mv(low ? t.lo : t.hi);
        c.marker(se.marker, edge, y, kChartMarker, colour, false);
        c.text(edge + (low ? 10.0 : -10.0), y + 4.5, (low ? "\u25C0 " : "") + format_significant(v, 4) + (low ? "" : " \u25B6"),
               kTickFont, low ? "start" : "end");
        continue;
      }
      if (se.mark == CategorySeries::Mark::bar) {
        const double h = std::min(16.0, slot - 2.0);
        const double a = std::min(mv(base), mv(v)), b = std::max(mv(base), mv(v));
        c.rect(a, y - h / 2.0, b - a, h, se.filled ? colour : "#FFFFFF", colour);
      }
      if (e > 0.0) {
        const bool cut = log && v - e <= t.lo;
        const double a = cut ? mv(t.lo) : mv(v - e), b = mv(v + e);
        c.line(a, y, b, y, "#000000", 1.2);
        if (!cut) c.line(a, y - 4, a, y + 4, "#000000", 1.2);
        c.line(b, y - 4, b, y + 4, "#000000", 1.2);
      }
      if (se.mark == CategorySeries::Mark::point) c.marker(se.marker, mv(v), y, kChartMarker, colour, se.filled);
    }
  }
  c.rect(left, top, plot_width, plot_h, "none", "#000000");
  c.raw("</svg>\n");
  return c.str();
}

}  // namespace pendulum::report
