// What a report's text says (issue 21): powers of ten, durations, values
// rounded to their uncertainty, the class chart's scale, the verdict in
// brief. Each expected string is worked by hand from the rule the header
// states (the digits of 10^k, the SI prefixes, two significant digits of the
// uncertainty), not taken from the code under test.
#include <catch2/catch.hpp>

#include <regex>
#include <string>
#include <vector>

#include "pendulum/report/plots.hpp"
#include "pendulum/report/svg_plot.hpp"
#include "pendulum/status.hpp"

using namespace pendulum::report;
using pendulum::brief_reason;

TEST_CASE("A log axis labels 10^5 as 10⁵ and not 100⁵", "[report][format]") {
  CategoryChart ch;
  ch.id = "c";
  ch.title = "sizes";
  ch.description = "sizes over twelve decades";
  ch.categories = {"large", "small"};
  ch.value = {"|x| (us), log scale", Scale::log, false};
  CategorySeries s;
  s.values = {3e5, 2e-3};
  ch.series = {s};
  const std::string svg = to_svg(ch, false);
  // Decades 10^-3 .. 10^6 (log_ticks), every other one labelled (at most 7):
  // 0.001, 0.1, 10, 1000 and 10⁵ (|k| <= 4 in plain digits).
  CHECK(svg.find(">0.001</text>") != std::string::npos);
  CHECK(svg.find(">10\u2075</text>") != std::string::npos);
  // No digit before the base 10 of a power: "100⁵" was the bug.
  CHECK_FALSE(std::regex_search(svg, std::regex("[0-9]10(\u207B)?(\u2070|\u00B9|\u00B2|\u00B3|\u2074|\u2075|\u2076|\u2077|\u2078|\u2079)")));
}

TEST_CASE("Values with an uncertainty: no x10⁰, durations with an SI prefix", "[report][format]") {
  // u = 2.5e-15 s on T = 2 s: both over 10^0 is no power at all.
  const std::string t = value_with_uncertainty(1.999999999999998, 2.5e-15, false);
  CHECK(t.find("\u00D710") == std::string::npos);
  // Two significant digits of u at its 10^-15 place: 16 decimals of the value.
  CHECK(t == "(1.9999999999999980 \u00B1 0.0000000000000025)");
  CHECK(duration_text(2.53e-16, 3) == "0.253 fs");  // below 1 fs: still fs, no power of ten
  CHECK(duration_text(2.53e-6, 3) == "2.53 \u00B5s");
  CHECK(duration_text(0.0152, 3) == "15.2 ms");
  CHECK(duration_text(1.5, 2) == "1.5 s");
}

TEST_CASE("class_chart: scaled to the ok results and the expected g with the rest at the edge", "[report][class]") {
  const Measured site{9.8113, 0.0};
  // Two slips (4 g and g/4, status suspect) and three ok results near 9.81.
  std::vector<ClassPoint> points{{"hughes", "#1", 39.377, 0.156, site, 189.8, false},
                                 {"quinn", "#2", 2.465, 0.006, site, -1221.7, false},
                                 {"a", "#3", 9.8356, 0.039, site, 0.62, true},
                                 {"b", "#4", 9.7846, 0.036, site, -0.74, true},
                                 {"c", "#5", 9.8089, 0.040, site, -0.06, true}};
  const CategoryChart ch = class_chart(points, "class");
  REQUIRE(ch.range);
  // 9.7846 - 0.036 = 9.7486 to 9.8356 + 0.039 = 9.8746.
  CHECK(ch.range->first == Approx(9.7486));
  CHECK(ch.range->second == Approx(9.8746));
  const std::string svg = to_svg(ch, false);
  // The axis ticks are within the class's range: no 0 to 40 axis.
  CHECK(svg.find(">40</text>") == std::string::npos);
  CHECK(svg.find(">9.80</text>") != std::string::npos);
  // The slips at the edges with their values (4 significant digits), in words too.
  CHECK(svg.find("39.38 \u25B6") != std::string::npos);
  CHECK(svg.find("\u25C0 2.465") != std::string::npos);
  CHECK(ch.notes[4] == "z = +189.80, suspect");
}

TEST_CASE("brief_reason: a status reason in a few words", "[status]") {
  // Reasons as status.cpp and the reader write them (tests/student_slips.json's cases).
  CHECK(brief_reason("g = 39.377 m/s^2 is 4.01 times the site's expected 9.81128 m/s^2: the period is half the true "
                     "one, as when half swings are counted as oscillations (an oscillation is a full swing, there and "
                     "back): halve timing.oscillations_per_trial") ==
        "g 4.01 times the expected g: half swings are counted as oscillations");
  CHECK(brief_reason("g = 9.6777 m/s^2 is 17.3 combined standard uncertainties from the site's expected 9.81128 m/s^2 "
                     "(difference -0.1336 m/s^2): an uncertainty stated too small, or a systematic error") ==
        "g 17.3 sigma from the expected g");
  CHECK(brief_reason("g = 9.6931 m/s^2 is 5.84 combined standard uncertainties from the site's expected 9.80814 m/s^2 "
                     "(difference -0.1151 m/s^2): the length taped to the top of the ball? Adding the ball's radius") ==
        "g 5.84 sigma from the expected g: the length taped to the top of the ball?");
  CHECK(brief_reason("g = 10.59 m/s^2 is 8% above standard gravity (9.80665 m/s^2; the scene gives no site), more "
                     "than 5%; no unit or counting slip makes this ratio") == "g 8% above standard gravity");
  CHECK(brief_reason("air.pressure: 1013 Pa is 1/100 of a room's air (50 to 110 kPa), the air of a vacuum chamber: a "
                     "barometer's 1013 hPa written as Pa? fix air.pressure.unit (\"hPa\")") ==
        "air.pressure: a barometer's 1013 hPa written as Pa?");
  CHECK(brief_reason("timing.trials: these look like a stopwatch's lap totals: give differences, the time of each "
                     "trial: [14.79, 14.73] (got 14.79, 29.52 s)") ==
        "timing.trials: these look like a stopwatch's lap totals");
  // No guess and a long first clause: cut at a word, "..." added.
  const std::string long_reason =
      "bob.wire: a wire of this diameter and this length and this density and this modulus and this "
      "temperature stretches by more than anyone would expect of a laboratory's pendulum wire";
  const std::string brief = brief_reason(long_reason);
  CHECK(brief.size() <= pendulum::kBriefReasonLength);
  CHECK(brief.substr(brief.size() - 3) == "...");
  CHECK(long_reason.compare(0, brief.size() - 3, brief, 0, brief.size() - 3) == 0);  // cut, not rewritten
  // A cut inside a parenthesis goes before it: no "(" is left open.
  CHECK(brief_reason("bob.wire: 2.1 m long: is the wire's length (pivot to the top of the bob, along the wire as it "
                     "hangs, with the tape held straight) in cm typed as m? fix bob.wire.length.unit") ==
        "bob.wire: is the wire's length...");
}
