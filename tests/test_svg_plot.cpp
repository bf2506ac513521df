// The SVG plot module (lib/include/pendulum/report/svg_plot.hpp) and the
// generic fit-with-residuals figure (report/plots.hpp).
//
// Nice ticks, the stated rule: the step is the smallest s = m 10^k, m in
// {1, 2, 5}, with ceil(hi/s) - floor(lo/s) <= max_intervals; the axis runs
// from floor(lo/s) s to ceil(hi/s) s. Each case below is worked by hand from
// that rule, the rejected steps shown, so that the expected ticks do not
// come from the code under test.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "pendulum/report/plots.hpp"
#include "pendulum/report/svg_plot.hpp"

using namespace pendulum::report;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A number printed from NaN or infinity ("nan", "-inf"), not a word holding
// those letters ("dominant-baseline").
bool has_non_finite(const std::string& svg) {
  return std::regex_search(svg, std::regex("(^|[^a-z])-?(nan|inf)", std::regex::icase));
}

// Every coordinate attribute and polyline point lies inside the viewBox
// "0 0 W H": nothing is drawn off the picture. Returns the first outside.
std::string outside_view(const std::string& svg) {
  std::smatch box;
  REQUIRE(std::regex_search(svg, box, std::regex("viewBox=\"0 0 ([0-9.]+) ([0-9.]+)\"")));
  const double width = std::stod(box[1]), height = std::stod(box[2]);
  const std::regex attribute("\\b(x|x1|x2|cx|y|y1|y2|cy)=\"(-?[0-9.]+)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), attribute); it != std::sregex_iterator(); ++it) {
    const double v = std::stod((*it)[2]);
    const double limit = (*it)[1].str()[0] == 'x' || (*it)[1].str() == "cx" ? width : height;
    if (v < 0.0 || v > limit) return (*it).str();
  }
  const std::regex point("(-?[0-9.]+),(-?[0-9.]+)");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), point); it != std::sregex_iterator(); ++it) {
    const double x = std::stod((*it)[1]), y = std::stod((*it)[2]);
    if (x < 0.0 || x > width || y < 0.0 || y > height) return (*it).str();
  }
  return "";
}

}  // namespace

TEST_CASE("nice_ticks: hand-worked cases of the 1-2-5 rule", "[report][ticks]") {
  struct Case {
    double lo, hi;
    int max_intervals;
    std::vector<double> ticks;  // as decimal literals: the tick values are the nearest doubles
    int decimals;
    const char* worked;
  };
  const Case cases[] = {
      {0.0, 1.0, 6, {0.0, 0.2, 0.4, 0.6, 0.8, 1.0}, 1, "s=0.1: 10 > 6; s=0.2: 5"},
      {0.0, 3600.0, 8, {0, 500, 1000, 1500, 2000, 2500, 3000, 3500, 4000}, 0, "s=200: 18 > 8; s=500: ceil(7.2)=8"},
      {9.798, 9.839, 6, {9.79, 9.80, 9.81, 9.82, 9.83, 9.84}, 2,
       "s=0.005: 1968-1959=9 > 6; s=0.01: 984-979=5"},
      {-3.2, 7.9, 5, {-5.0, 0.0, 5.0, 10.0}, 0, "s=1: 8+4=12; s=2: 4+2=6 > 5; s=5: 2+1=3"},
      {0.3, 0.9, 6, {0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9}, 1,
       "s=0.1: 9-3=6 (0.3/0.1 = 2.9999999999999996 in double counts as 3)"},
      {1.2e-5, 9.8e-5, 5, {0.0, 2e-5, 4e-5, 6e-5, 8e-5, 1e-4}, 5, "s=1e-5: 10-1=9 > 5; s=2e-5: 5-0=5"},
      {5.0, 5.0, 6, {4.0, 4.5, 5.0, 5.5, 6.0}, 1, "widened to [4, 6]; s=0.2: 30-20=10 > 6; s=0.5: 12-8=4"},
      {1.0, 0.0, 6, {0.0, 0.2, 0.4, 0.6, 0.8, 1.0}, 1, "swapped to [0, 1]"},
      {-0.042, -0.013, 4, {-0.05, -0.04, -0.03, -0.02, -0.01}, 2, "s=0.005: -2+9=7 > 4; s=0.01: -1+5=4"},
      {0.0, 1e-300, 4, {-1.0, -0.5, 0.0, 0.5, 1.0}, 1,
       "narrower than 1e-290: one value, widened to 5e-301 -+ 1; s=0.2: 5+5=10 > 4; s=0.5: 2+2=4"},
  };
  for (const auto& c : cases) {
    INFO("[" << c.lo << ", " << c.hi << "] max " << c.max_intervals << ": " << c.worked);
    const Ticks t = nice_ticks(c.lo, c.hi, c.max_intervals);
    CHECK(t.values == c.ticks);
    CHECK(t.decimals == c.decimals);
    CHECK(t.lo == c.ticks.front());
    CHECK(t.hi == c.ticks.back());
  }
}

TEST_CASE("nice_ticks refuses what it cannot place", "[report][ticks]") {
  CHECK_THROWS_AS(nice_ticks(0.0, std::numeric_limits<double>::infinity()), std::invalid_argument);
  CHECK_THROWS_AS(nice_ticks(-1e308, 1e308), std::invalid_argument);  // hi - lo overflows
  CHECK_THROWS_AS(nice_ticks(std::nan(""), 1.0), std::invalid_argument);
  CHECK_THROWS_AS(nice_ticks(0.0, 1.0, 0), std::invalid_argument);
}

TEST_CASE("log_ticks: the decades around the data", "[report][ticks]") {
  // The corrections of Nelson & Olsson span 0.03 us to 600 us.
  CHECK(log_ticks(0.0272, 596.0).values == std::vector<double>{0.01, 0.1, 1.0, 10.0, 100.0, 1000.0});
  CHECK(log_ticks(0.0272, 596.0).decimals == 2);
  // Exact decades are their own ends; a range inside one decade gets that decade.
  CHECK(log_ticks(1.0, 100.0).values == std::vector<double>{1.0, 10.0, 100.0});
  CHECK(log_ticks(2.0, 3.0).values == std::vector<double>{1.0, 10.0});
  // 301 decades: every 50th labelled (at most 7 labels), the first at 1e-300.
  const Ticks wide = log_ticks(1e-300, 1.0);
  CHECK(wide.values.size() == 301);
  CHECK(wide.label_every == 50);
  CHECK(wide.values.front() == 1e-300);
  // Subnormal decades: the lowest is a positive double at or below lo, not 0
  // (was: 1/10^320 = 0, and log10(0) drew at -nan).
  const Ticks tiny = log_ticks(1e-320, 1e-319);
  CHECK(tiny.values.front() > 0.0);
  CHECK(tiny.values.front() <= 1e-320);
  CHECK_THROWS_AS(log_ticks(0.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(log_ticks(2.0, 1.0), std::invalid_argument);
}

TEST_CASE("Number formats: fixed, significant, with uncertainty", "[report][format]") {
  CHECK(format_fixed(-0.0001, 2) == "0.00");  // no "-0.00"
  CHECK(format_fixed(-1.5, 1) == "\u22121.5");  // a true minus sign
  CHECK(format_fixed(9.80340, 5) == "9.80340");
  CHECK(format_fixed(1e300, 0).size() == 301);  // however long: no fixed buffer
  CHECK(format_significant(9.996, 3) == "10.0");  // rounded before counting digits
  CHECK(format_significant(0.0331, 3) == "0.0331");
  CHECK(format_significant(-281.6412, 3) == "\u2212282");
  CHECK(format_significant(0.0, 3) == "0");
  CHECK(format_significant(123456.7, 3) == "123000");
  CHECK(format_significant(1.234e-300, 3) == "1.23\u00D710\u207B\u00B3\u2070\u2070");  // 1.23×10⁻³⁰⁰
  CHECK(format_significant(6.02e23, 3) == "6.02\u00D710\u00B2\u00B3");
  CHECK(times_ten_to(-5) == "\u00D710\u207B\u2075");
  // The uncertainty to two significant digits, the value to the same place.
  CHECK(value_with_uncertainty(596.0018, 119.1828, true) == "+596 \u00B1 119");
  CHECK(value_with_uncertainty(9.803402845946488, 0.001481899216290776, false) == "9.8034 \u00B1 0.0015");
  CHECK(value_with_uncertainty(0.0331, 0.0029, true) == "+0.0331 \u00B1 0.0029");
  CHECK(value_with_uncertainty(-77.05, 18.19, true) == "\u221277 \u00B1 18");
  // Beyond 8 decimals: one power of ten for both.
  CHECK(value_with_uncertainty(1.23e-9, 4.5e-11, false) == "(1.230 \u00B1 0.045)\u00D710\u207B\u2079");
  CHECK(xml_escape("a<b & \"c\" 'd'>") == "a&lt;b &amp; &quot;c&quot; &#39;d&#39;&gt;");
}

namespace {

// Synthetic series: y = 2 x + 1 plus known offsets, error bars 0.1; the
// textbook line y = 2 x. The residuals must come out as the offsets.
FitPlotData synthetic_series() {
  const std::vector<double> x{0.5, 1.0, 1.5, 2.0, 2.5}, offsets{0.1, -0.2, 0.05, 0.0, -0.15};
  FitPlotData d;
  d.id = "series";
  d.title = "Synthetic series: T\u00B2 & l";
  d.description = "five points on y = 2x + 1 with known offsets";
  d.x = {"length l (m)", Scale::linear, true};
  d.y = {"T\u00B2 (s\u00B2)", Scale::linear, true};
  d.residual_label = "residual (s\u00B2)";
  d.observations.name = "measured";
  for (std::size_t i = 0; i < x.size(); ++i) {
    d.observations.x.push_back(x[i]);
    d.observations.y.push_back(2 * x[i] + 1 + offsets[i]);
    d.observations.y_error.push_back(0.1);
    d.model_at_x.push_back(2 * x[i] + 1);
  }
  d.model.name = "fitted model";
  d.model.x = {0.0, 3.0};
  d.model.y = {1.0, 7.0};
  Curve textbook;
  textbook.name = "textbook line";
  textbook.x = {0.0, 3.0};
  textbook.y = {0.0, 6.0};
  textbook.colour = Colour::black;
  textbook.dash = Dash::dashed;
  d.textbook = textbook;
  Band band;
  band.name = "model \u00B1 1\u03C3";
  band.x = {0.0, 3.0};
  band.lower = {0.9, 6.9};
  band.upper = {1.1, 7.1};
  d.model_band = band;
  return d;
}

}  // namespace

TEST_CASE("fit_figure: observations, model, textbook line and residuals", "[report][fit]") {
  const FitPlotData d = synthetic_series();
  const Figure f = fit_figure(d);
  REQUIRE(f.panels.size() == 2);
  const Panel& top = f.panels[0];
  CHECK(top.points.size() == 1);
  CHECK(top.points[0].y == d.observations.y);
  CHECK(top.curves.size() == 2);  // textbook and model
  CHECK(top.bands.size() == 1);
  const Panel& residuals = f.panels[1];
  REQUIRE(residuals.points.size() == 1);
  const std::vector<double> offsets{0.1, -0.2, 0.05, 0.0, -0.15};
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    // y - model = offset, up to the rounding of 2x + 1 + offset (1 ulp of 7).
    CHECK_THAT(residuals.points[0].y[i], Catch::Matchers::WithinAbs(offsets[i], 1e-15));
    CHECK(residuals.points[0].y_error[i] == 0.1);  // the same error bars
  }
  CHECK(residuals.references.size() == 1);
  CHECK(residuals.references[0].value == 0.0);
  CHECK(residuals.curves.empty());

  // With the textbook at each x, textbook - model = 2x - (2x + 1) = -1 beneath,
  // in the textbook's dashes, ordered by x.
  FitPlotData with_textbook = d;
  with_textbook.observations.x = {2.5, 0.5, 1.5, 1.0, 2.0};
  for (double x : with_textbook.observations.x) with_textbook.textbook_at_x.push_back(2 * x);
  with_textbook.model_at_x.clear();
  for (double x : with_textbook.observations.x) with_textbook.model_at_x.push_back(2 * x + 1);
  const Figure g = fit_figure(with_textbook);
  REQUIRE(g.panels[1].curves.size() == 1);
  CHECK(g.panels[1].curves[0].x == std::vector<double>{0.5, 1.0, 1.5, 2.0, 2.5});
  CHECK(g.panels[1].curves[0].y == std::vector<double>(5, -1.0));
  CHECK(g.panels[1].curves[0].dash == Dash::dashed);

  FitPlotData bad = d;
  bad.model_at_x.pop_back();
  CHECK_THROWS_AS(fit_figure(bad), std::invalid_argument);
  bad = d;
  bad.textbook_at_x = {1.0};
  CHECK_THROWS_AS(fit_figure(bad), std::invalid_argument);
}

TEST_CASE("to_svg: accessible, escaped, deterministic, self-contained", "[report][svg]") {
  const Figure f = fit_figure(synthetic_series());
  const std::string inline_svg = to_svg(f, false);
  const std::string file_svg = to_svg(f, true);
  CHECK(inline_svg == to_svg(f, false));  // same bytes twice

  // <title> and <desc> first, named by aria-labelledby.
  CHECK(inline_svg.find("<svg id=\"series\"") == 0);
  CHECK(inline_svg.find("aria-labelledby=\"series-title series-desc\"") != std::string::npos);
  CHECK(inline_svg.find("<title id=\"series-title\">Synthetic series: T\u00B2 &amp; l</title>") !=
        std::string::npos);
  CHECK(inline_svg.find("<desc id=\"series-desc\">five points") != std::string::npos);
  // The namespace only in a file; nothing that loads anything, anywhere.
  CHECK(file_svg.find("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"") == 0);
  for (const char* bad : {"http", "//", "url(", "href", "<script"}) {
    INFO(bad);
    CHECK(inline_svg.find(bad) == std::string::npos);
  }
  CHECK_FALSE(has_non_finite(inline_svg));
  // Axis labels with units, legend entries, and the 0..3 x ticks (0.5 apart).
  for (const char* text : {"length l (m)", "T\u00B2 (s\u00B2)", "residual (s\u00B2)", "textbook line", "fitted model",
                           ">0.5</text>", ">2.5</text>"}) {
    INFO(text);
    CHECK(inline_svg.find(text) != std::string::npos);
  }
  // Five observations in each panel, plus one legend sample.
  CHECK(count(inline_svg, "<circle") == 11);
  CHECK(outside_view(inline_svg) == "");
}

TEST_CASE("CategoryChart on a log axis: bars, cut error bars, links", "[report][svg]") {
  CategoryChart ch;
  ch.id = "c";
  ch.title = "sizes";
  ch.description = "three sizes";
  ch.categories = {"big", "small", "zero"};
  ch.links = {"#a", "", ""};
  ch.notes = {"+600", "+0.03", "0"};
  ch.value = {"|x| (us), log scale", Scale::log, false};
  CategorySeries s;
  s.values = {600.0, 0.03, 0.0};  // 0 has no place on a log axis: not drawn
  s.errors = {100.0, 0.05, std::nullopt};  // 0.03 - 0.05 < 0: cut at the axis
  ch.series = {s};
  const std::string svg = to_svg(ch, false);
  CHECK(svg == to_svg(ch, false));
  CHECK_FALSE(has_non_finite(svg));
  CHECK(svg.find("<a href=\"#a\">") != std::string::npos);
  // Decades 0.01 .. 1000 label the axis.
  for (const char* tick : {">0.01</text>", ">0.1</text>", ">1</text>", ">1000</text>"}) {
    INFO(tick);
    CHECK(svg.find(tick) != std::string::npos);
  }
  // Two bars (frame and background are the other rects).
  CHECK(count(svg, "<rect") == 2 + 2);
  CHECK(outside_view(svg) == "");

  // The same rows on a linear axis: no minor ticks of a log axis beyond it
  // (was: 2..9 times each linear tick, drawn past the frame).
  ch.value = {"x (us)", Scale::linear, false};
  const std::string linear = to_svg(ch, false);
  CHECK(outside_view(linear) == "");
  // A grid line and a tick per tick value, and two error bars of three lines.
  CHECK(count(linear, "<line") == count(linear, "stroke=\"#DDDDDD\"") * 2 + 6);
}

TEST_CASE("class_chart: sorted by g, one expected line, a marker per row, or none", "[report][class]") {
  const Measured site{9.8026, 0.0};
  std::vector<ClassPoint> points{{"b", "#scene-1", 9.8324, 0.0058, site, 5.18},
                                 {"a", "#scene-2", 9.8034, 0.0015, site, 0.54},
                                 {"c", "#scene-3", 9.7000, 0.0100, site, -10.26}};
  const CategoryChart shared = class_chart(points, "class");
  CHECK(shared.categories == std::vector<std::string>{"c", "a", "b"});
  CHECK(shared.links == std::vector<std::string>{"#scene-3", "#scene-2", "#scene-1"});
  CHECK(shared.notes == std::vector<std::string>{"z = \u221210.26", "z = +0.54", "z = +5.18"});
  CHECK(shared.series.size() == 1);
  REQUIRE(shared.references.size() == 1);
  CHECK(shared.references[0].value == 9.8026);

  points[2].expected = Measured{9.7803, 0.0005};  // another site
  const CategoryChart sites = class_chart(points, "class");
  CHECK(sites.references.empty());
  REQUIRE(sites.series.size() == 2);
  CHECK(sites.series[1].values[0] == std::optional<double>(9.7803));

  for (auto& p : points) p.expected.reset(), p.z.reset();
  const CategoryChart none = class_chart(points, "class");
  CHECK(none.references.empty());
  CHECK(none.series.size() == 1);
  CHECK(none.notes[0] == "no expected g");
  CHECK_FALSE(has_non_finite(to_svg(none, false)));
}
