// The recording reader's stages one by one (lib/src/recordings/stages.hpp)
// and the layouts students publish (issue 19), written by the recording
// simulator with their quirks (tests/recording_simulation.hpp,
// published_csv): the roles the reader chose, the notes it gave, and the
// period within its stated uncertainty of the simulation's truth over 200
// recordings per layout.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "pendulum/input_error.hpp"
#include "pendulum/recordings/read.hpp"
#include "pendulum/recordings/swings.hpp"
#include "pendulum/json/scene_json.hpp"
#include "recording_simulation.hpp"
#include "../lib/src/recordings/stages.hpp"
#include "../lib/src/recordings/zip.hpp"

using namespace pendulum;
using namespace pendulum::recording_text;
using Catch::Matchers::Contains;
using test::PublishedLayout;

namespace {

/// The role the reader gave column `index` (from 1).
std::string role_of(const Recording& r, std::size_t index) {
  for (const auto& c : r.columns) {
    if (c.index == index) return c.role + (c.unit.empty() ? "" : ":" + c.unit) + "/" + c.decided_by;
  }
  return "none";
}

bool has_note(const Recording& r, const std::string& text) {
  return std::any_of(r.notes.begin(), r.notes.end(), [&](const RecordingNote& n) { return n.text.find(text) != std::string::npos; });
}

}  // namespace

TEST_CASE("Words: the header's spellings give roles and units", "[recordings][columns]") {
  struct Case {
    const char* cell;
    Role role;
    const char* unit;
  };
  const Case cases[] = {
      {"time", Role::time, ""},
      {"Time (s)", Role::time, "s"},
      {"t_{1}", Role::time, ""},
      {"VideoAnalysis: Time (s)", Role::time, "s"},
      {"Latest: Time (s)", Role::time, "s"},
      {"Time [ms]", Role::time, "ms"},
      {"\"Time, s\"", Role::time, "s"},
      {"Time (s) Run #2", Role::time, "s"},
      {"Angle (Degrees)", Role::angle, "deg"},
      {"angle (\xc2\xb0)", Role::angle, "deg"},  // °
      {"\xce\xb8 [rad]", Role::angle, "rad"},    // θ
      {"Angular Velocity (deg/s)", Role::omega, "deg/s"},
      {"VideoAnalysis: X (m)", Role::x, "m"},
      {"y (px)", Role::y, "px"},
      {"x_1", Role::x, ""},
      {"X'", Role::derivative, ""},
      {"vx", Role::derivative, ""},
      {"Gyroscope z (rad/s)", Role::rate, "rad/s"},
      {"Linear Acceleration y (m/s^2)", Role::linear_acceleration, "m/s^2"},
      {"Gate State", Role::state, ""},
      {"frame", Role::counter, ""},
      {"n", Role::counter, ""},
      {"d\xce\xb8", Role::uncertainty, ""},
      {"Pressure (hPa)", Role::other, "hpa"},
      // The unit after a slash (ISO 80000's table headings), words in the languages students write.
      {"Time/s", Role::time, "s"},
      {"Angle/rad", Role::angle, "rad"},
      {"AngVel/rad/s", Role::other, "rad/s"},
      {"x/y", Role::other, ""},
      {"tempo", Role::time, ""},
      {"Zeit (s)", Role::time, "s"},
      {"tijd [ms]", Role::time, "ms"},
      {"hoek", Role::angle, ""},
      {"\xc3\xa2ngulo (graus)", Role::angle, "deg"},  // Portuguese degrees
      {"# winkel in grad", Role::angle, "deg"},         // a comment line as the header, the unit after "in"
      {"#", Role::counter, ""},                          // but "#" alone is a counter
  };
  for (const auto& c : cases) {
    INFO(c.cell);
    const Column col = classify(c.cell);
    CHECK(col.role == c.role);
    CHECK(col.unit == c.unit);
  }
  CHECK(classify("Time (s) Run #2").run == 2);
  CHECK(classify("x/y").word == "x/y");
  // Latin-1 (a Windows exporter): 0xB0 is the degree sign.
  CHECK(classify("Angle (\xb0)").unit == "deg");
  CHECK(to_utf8("\xb5s") == "\xc2\xb5s");
  CHECK(to_utf8("\xc2\xb5s") == "\xc2\xb5s");
}

TEST_CASE("Split: delimiters, runs of spaces, quotes, decimal commas", "[recordings][columns]") {
  CHECK(sniff(std::string_view("t\tx\ty"), "0\t1\t2").delimiter == '\t');
  CHECK(sniff(std::string_view("Time (s);Angle (rad)"), "0,5;1,25").decimal_comma);
  CHECK(sniff(std::nullopt, "  0.1   2.0   3").delimiter == ' ');
  CHECK(sniff(std::string_view("t (ms)"), "100").delimiter == '\0');
  // A header of spaced words (a comment line) over rows split by ';' or a tab: the rows say.
  CHECK(sniff(std::string_view("# Perioden       t in s"), "1;3.05").delimiter == ';');
  CHECK(sniff(std::string_view("# n  t"), "1\t3.05").delimiter == '\t');
  // Not a comma: "Zeit" over "0,5" is one column with a decimal comma.
  CHECK(sniff(std::string_view("Zeit"), "0,5").delimiter == '\0');
  CHECK(sniff(std::string_view("Zeit"), "0,5").decimal_comma);
  const Dialect spaces{' ', false};
  const auto header = split_cells("   t     Time (s)   theta [deg]  ", spaces);
  REQUIRE(header.size() == 3);
  CHECK(header[1] == "Time (s)");
  CHECK(header[2] == "theta [deg]");
  const auto quoted = split_cells("\"Time, s\",\"Angle (rad)\"", Dialect{',', false});
  REQUIRE(quoted.size() == 2);
  CHECK(quoted[0] == "Time, s");
  // A trailing delimiter makes no column.
  CHECK(filled_cells(split_cells("t,x,y,", Dialect{',', false})) == 3);
  CHECK(filled_cells(split_cells("x y dx dy\t\t\t", Dialect{'\t', false})) == 1);
}

TEST_CASE("Content: a bob's height is a function of its x; a column that follows x's rate is not",
          "[recordings][columns]") {
  // x = 0.2 sin(2 pi t / 1.8) at 30 Hz over 60 s; heights in step with it
  // (an arc's, with a roll of 5 deg: part x), a tracker's drifting height
  // (issue 38's real PHY180 track: y wanders over 0.30-0.35 m, uncorrelated
  // with the swing), pure noise and an elliptical swing seen from above (its
  // quadrature part 59 % of y's variance but 7.5 % of x's amplitude) are
  // heights; a copy of x a fifth of a period late (90 % of its variance a
  // quarter period out of step, half x's amplitude) and x's own rate are not.
  // A record under three periods keeps x and y whatever y does: there a
  // drift follows the rate as a lag does.
  std::vector<double> t, x, arc, drift, noise, late, rate, ellipse;
  NormalDeviates normal(5);
  double walk = 0.33;
  const double w = 2.0 * M_PI / 1.8;
  for (int k = 0; k < 1800; ++k) {
    const double time = k / 30.0, e = 0.001 * normal.next();
    walk = std::clamp(walk + 0.002 * normal.next(), 0.30, 0.35);
    t.push_back(time);
    x.push_back(0.2 * std::sin(w * time));
    const double height = 0.8 - std::sqrt(0.64 - x.back() * x.back());
    arc.push_back(std::cos(0.087) * height + std::sin(0.087) * x.back() + e);
    drift.push_back(walk + e);
    noise.push_back(e);
    late.push_back(0.1 * std::sin(w * (time - 0.36)) + e);
    // A 15 % elliptical swing filmed from 30 deg above: y = e sin 30 (x's
    // amplitude) in quadrature beside the arc's height, 0.3 mm of noise.
    ellipse.push_back(0.15 * 0.5 * 0.2 * std::cos(w * time) + height + 0.3 * e);
    rate.push_back(0.2 * w * std::cos(w * time) + e);
  }
  CHECK(could_be_track_y(t, x, arc));
  CHECK(could_be_track_y(t, x, drift));
  CHECK(could_be_track_y(t, x, noise));
  CHECK(could_be_track_y(t, x, ellipse));
  CHECK_FALSE(could_be_track_y(t, x, late));
  CHECK_FALSE(could_be_track_y(t, x, rate));
  std::string short_track;
  for (std::size_t k = 0; k < 65; ++k) {  // 2.2 s: 1.2 periods, y drifting by 1 cm
    short_track += std::to_string(t[k]) + "\t" + std::to_string(x[k]) + "\t" + std::to_string(0.3 + 0.01 * t[k] / 2.2) + "\n";
  }
  CHECK(parse_recording(short_track, "short.txt").kind == SignalKind::position);
}

TEST_CASE("Content: counters, constants, clocks and angle units from the numbers", "[recordings][columns]") {
  CHECK(examine({1, 2, 3, 4, 5}).counter);
  CHECK_FALSE(examine({0.0, 0.01, 0.02, 0.03}).counter);
  // A stride: whole numbers all stepping by one whole step, as N = 1, 3, 5 periods or a clock in ms.
  CHECK(examine({1, 3, 5, 7, 9}).stride == 2.0);
  CHECK(examine({0, 20, 40, 60}).stride == 20.0);
  CHECK(examine({1, 2, 3}).stride == 1.0);
  CHECK(examine({0.0, 0.5, 1.0}).stride == 0.0);
  CHECK(examine({1, 3, 4, 7}).stride == 0.0);
  // One typo in twenty steps (23 typed 24) leaves the stride: the majority step, 90 % of them.
  CHECK(examine({1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 24, 25, 27, 29, 31, 33, 35, 37, 39, 41}).stride == 2.0);
  CHECK(examine({0.0, 0.01, 0.02, 0.03}).increasing);
  CHECK(examine({0, 0, 0, 0}).constant);
  // The half range decides a unitless angle: beyond pi/2 is degrees.
  std::vector<double> deg, rad;
  for (int k = 0; k < 400; ++k) deg.push_back(2.0 * std::sin(0.05 * k)), rad.push_back(0.2 * std::sin(0.05 * k));
  CHECK(unitless_angle(examine(deg)).first == "deg");
  CHECK(unitless_angle(examine(rad)).first == "rad");
  // An angle and its rate, never a track's x and y.
  std::vector<double> t, th, om, x, y;
  for (int k = 0; k < 400; ++k) {
    t.push_back(0.01 * k);
    th.push_back(0.2 * std::cos(4.0 * t.back()));
    om.push_back(-0.8 * std::sin(4.0 * t.back()));
    x.push_back(std::sin(th.back()));
    y.push_back(-std::cos(th.back()));
  }
  CHECK(is_rate_of(t, th, om));
  CHECK_FALSE(is_rate_of(t, x, y));
  CHECK_FALSE(is_rate_of(t, y, x));
  // A rough period: a 1.8 s swing sampled at 100 Hz, in seconds and in milliseconds.
  std::vector<double> ts, ms, swing;
  for (int k = 0; k < 2000; ++k) {
    ts.push_back(0.01 * k), ms.push_back(10.0 * k);
    swing.push_back(3.0 + 0.5 * std::cos(2.0 * M_PI * ts.back() / 1.8));
  }
  CHECK(rough_period(ts, swing) == Approx(1.8).epsilon(0.01));
  CHECK(rough_period(ms, swing) == Approx(1800.0).epsilon(0.01));
  CHECK(std::isnan(rough_period(ts, std::vector<double>(2000, 1.0))));
  CHECK(median_step({0.0, 10.0, 30.0, 40.0, 50.0}) == 10.0);
  // A time's unit from its period: 60 s is a pendulum 900 m long.
  CHECK(unitless_time(1.8).first == "s");
  CHECK(unitless_time(59.0).first == "s");
  CHECK(unitless_time(1800.0).first == "ms");
  CHECK_THAT(unitless_time(1800.0).second, Contains("read as milliseconds") && Contains("1.8 s"));
  CHECK(unitless_time(1.8e6).first == "us");
  CHECK(unitless_time(1e12).first == "s");
  CHECK(unitless_time(std::nan("")).first == "s");
  // One signal can be an angle unless its numbers are whole (raw counts) or beyond +-180.
  std::vector<double> counts, wide, narrow;
  for (int k = 0; k < 400; ++k) {
    counts.push_back(std::round(150.0 * std::sin(0.05 * k)));
    wide.push_back(200.5 * std::sin(0.05 * k)), narrow.push_back(19.5 * std::sin(0.05 * k));
  }
  CHECK_FALSE(angle_by_numbers(examine(counts)));
  CHECK_FALSE(angle_by_numbers(examine(wide)));
  CHECK(angle_by_numbers(examine(narrow)));
}

TEST_CASE("Clean: repeated stamps kept with their quantum, glitches dropped with their line", "[recordings][columns]") {
  Table table;
  table.rows = 400;
  std::vector<double> t;
  for (int k = 0; k < 400; ++k) t.push_back(std::floor(k * 0.002 * 100.0) / 100.0);  // 500 Hz, a 10 ms clock
  Cleaned c = clean_times(t, {}, table, true, "f");
  CHECK(c.all);
  CHECK(c.quantum == Approx(0.01));
  std::vector<double> glitch;
  for (int k = 0; k < 400; ++k) glitch.push_back(k * 0.01);
  std::swap(glitch[100], glitch[101]);
  glitch.insert(glitch.begin() + 200, glitch[200]);
  c = clean_times(glitch, {}, table, true, "f");
  REQUIRE_FALSE(c.all);
  CHECK(c.keep.size() == 399);
  REQUIRE(c.notes.size() == 3);
  CHECK(c.notes[0].line == 101);  // row 100 (line 101) holds t[101], out of order
  CHECK_THAT(c.notes[1].text, Contains("a repeated sample"));
  CHECK_THAT(c.notes[2].text, Contains("a gap of 0.02 s"));  // where the sample out of order was dropped
  // Beyond 1 % out of order is a file not in time order.
  std::vector<double> back = {0.0, 0.1, 0.05, 0.2};
  CHECK_THROWS_WITH(clean_times(back, {}, table, true, "f"), Contains("f:3:1: time going backwards"));
  // A dropped frame is a gap.
  std::vector<double> gap;
  for (int k = 0; k < 100; ++k) {
    if (k != 50) gap.push_back(k / 60.0);
  }
  c = clean_times(gap, {}, table, true, "f");
  REQUIRE(c.notes.size() == 1);
  CHECK_THAT(c.notes[0].text, Contains("about 1 missing"));
}


TEST_CASE("Clean: held frames repeat in the swing's fast middle, a sensor's rounding only where it turns",
          "[recordings][columns]") {
  // 20 s of a 10 deg swing of period 1 s at 30 rows/s, and two ways to repeat:
  // a camera's frame every 0.1 s held by the rows between (two rows in three
  // repeat, everywhere), and an encoder's 1 deg steps (a row repeats only
  // where the swing turns, slower than a step in 1/30 s: 2.1 deg a row at the
  // middle). Held frames: the median frame step is the resolution; the
  // encoder's rows are every one a sample.
  std::vector<double> t, held, encoder;
  for (int k = 0; k < 600; ++k) {
    t.push_back(k / 30.0);
    held.push_back(10.0 * std::sin(2.0 * M_PI * std::floor(t.back() * 10.0) / 10.0));
    encoder.push_back(std::round(10.0 * std::sin(2.0 * M_PI * t.back())));
  }
  Cleaned c = held_frames(t, {held});
  CHECK(c.quantum == Approx(0.1));
  REQUIRE(c.notes.size() == 1);
  CHECK_THAT(c.notes[0].text, Contains("held frames, a new one every 0.1 s"));
  // A track's frame is held in both its columns; one column's repeats alone are a coincidence.
  c = held_frames(t, {held, encoder});
  CHECK(c.quantum == 0.0);
  CHECK(c.notes.empty());
  c = held_frames(t, {encoder});
  CHECK(c.quantum == 0.0);
  CHECK(c.notes.empty());
  // A fine encoder sampled fast, whose steps repeat in the middle too: 0.25 deg
  // steps at 200 Hz of a 5 deg swing of period 1.8 s (0.09 deg a row at the
  // middle: runs of 3 there, and of tens where it turns); and the held frames
  // and the encoder each with their first 5 s at rest (a run a rest).
  std::vector<double> t_fast, fine;
  for (int k = 0; k < 4000; ++k) {
    t_fast.push_back(k / 200.0);
    fine.push_back(0.25 * std::round(20.0 * std::sin(2.0 * M_PI * t_fast.back() / 1.8)));
  }
  c = held_frames(t_fast, {fine});
  CHECK(c.quantum == 0.0);
  std::vector<double> held_rest = held, encoder_rest = encoder;
  for (int k = 0; k < 150; ++k) held_rest[k] = encoder_rest[k] = 0.0;
  CHECK(held_frames(t, {held_rest}).quantum == Approx(0.1));
  CHECK(held_frames(t, {encoder_rest}).quantum == 0.0);
}

TEST_CASE("Skipped rows: an empty cell, a sample out of order and a repeated one, each counted and noted",
          "[recordings][columns]") {
  // 400 samples at 100 Hz of a 4 deg swing of period 2 s; then row 101's
  // and 102's samples swapped, row 201's written twice, and row 301's angle
  // left empty: 401 data rows, of which the reader keeps 398.
  std::vector<std::string> rows;
  for (int k = 0; k < 400; ++k) {
    rows.push_back(std::to_string(k * 0.01) + "," + std::to_string(4.0 * std::cos(M_PI * k * 0.01)));
  }
  std::swap(rows[100], rows[101]);
  rows.insert(rows.begin() + 200, rows[200]);
  rows[301] = rows[301].substr(0, rows[301].find(',') + 1);
  std::string text = "t (s),theta (deg)\n";
  for (const std::string& r : rows) text += r + "\n";
  const Recording r = parse_recording(text, "s.csv");
  CHECK(r.rows == 401);
  CHECK(r.dropped == 3);
  CHECK(r.time.size() == 398);
  const auto noted = [&](const std::string& words) {
    return std::count_if(r.notes.begin(), r.notes.end(), [&](const RecordingNote& n) {
      return n.text.find(words) != std::string::npos;
    });
  };
  CHECK(noted("out of time order") == 1);
  CHECK(noted("a repeated sample") == 1);
}
TEST_CASE("Published layouts: the roles the reader chose and what it said", "[recordings][columns]") {
  test::RecordingSimulation s;
  s.duration = 20.0, s.drop = 0.0, s.noise = 0.0, s.theta0 = 5.0 * M_PI / 180.0;
  s.rate_hz = 30.0;
  const auto sim = simulate_recording(s);
  const auto read = [&](PublishedLayout layout, const std::string& columns = {}) {
    return parse_recording(test::published_csv(sim, s.length, layout, 0.0, 1), "p.csv", RecordingFormat::automatic, {},
                           columns);
  };
  const Recording rotary = read(PublishedLayout::rotary_degrees);
  CHECK(rotary.kind == SignalKind::angle);
  CHECK(role_of(rotary, 2) == "angle:deg/header");
  CHECK(*std::max_element(rotary.channels[0].begin(), rotary.channels[0].end()) == Approx(s.theta0).epsilon(0.01));

  const Recording opencv = read(PublishedLayout::opencv_angle);
  CHECK(opencv.format == RecordingFormat::columns);
  CHECK(role_of(opencv, 1) == "time:s/header");
  CHECK(role_of(opencv, 2) == "angle:deg/content");
  CHECK(has_note(opencv, "read as degrees"));
  CHECK(*std::max_element(opencv.channels[0].begin(), opencv.channels[0].end()) == Approx(s.theta0).epsilon(0.01));
  // The unit declared overrides the content.
  CHECK(role_of(read(PublishedLayout::opencv_angle, "t:s,theta:deg"), 2) == "angle:deg/option");

  const Recording tracker = read(PublishedLayout::tracker_degrees);
  CHECK(tracker.format == RecordingFormat::tracker);
  CHECK(role_of(tracker, 2) == "angle:deg/content");

  const Recording pixels = read(PublishedLayout::pixel_track);
  CHECK(pixels.kind == SignalKind::position);
  CHECK(role_of(pixels, 1) == "unused/header");
  CHECK(role_of(pixels, 3) == "x:px/header");

  const Recording logger = read(PublishedLayout::logger_pro_video);
  CHECK(logger.kind == SignalKind::position);
  CHECK(role_of(logger, 1) == "time:s/header");
  CHECK(role_of(logger, 2) == "x:m/header");

  const Recording txy = read(PublishedLayout::headerless_txy);
  CHECK(txy.kind == SignalKind::position);
  CHECK(role_of(txy, 1) == "time:s/content");
  CHECK(role_of(txy, 3) == "y/content");

  const Recording timer = read(PublishedLayout::headerless_timer);
  CHECK(timer.kind == SignalKind::event_stamps);
  CHECK(role_of(timer, 1) == "counter/content");
  CHECK(role_of(timer, 2) == "event stamp:s/content");
  REQUIRE(timer.counts.size() == timer.time.size());
  CHECK(timer.counts.front() == 1.0);

  // Issue 38: one signal beside a time, units and words the header gives otherwise.
  const Recording degrees = read(PublishedLayout::headerless_degrees);
  CHECK(degrees.kind == SignalKind::angle);
  CHECK(role_of(degrees, 1) == "time:s/content");
  CHECK(role_of(degrees, 2) == "angle:deg/content");
  CHECK(*std::max_element(degrees.channels[0].begin(), degrees.channels[0].end()) == Approx(s.theta0).epsilon(0.01));
  const Recording radians = read(PublishedLayout::headerless_radians);
  CHECK(role_of(radians, 2) == "angle:rad/content");
  CHECK(has_note(radians, "if it is degrees, say so"));

  const Recording microbit = read(PublishedLayout::microbit_ms);
  CHECK(microbit.kind == SignalKind::unknown);
  CHECK(role_of(microbit, 1) == "time:ms/content");
  CHECK(role_of(microbit, 2) == "signal/content");
  CHECK(has_note(microbit, "read as milliseconds"));
  CHECK(has_note(microbit, "whole numbers only"));
  CHECK(microbit.time[1] == Approx(1.0 / s.rate_hz).margin(1e-3));

  // The axis along the string swings at twice the swing's frequency: no track's x beside its y.
  const Recording axes = read(PublishedLayout::microbit_two_axes);
  CHECK(axes.kind == SignalKind::unknown);
  CHECK(role_of(axes, 1) == "time:ms/content");
  CHECK_THAT(role_of(axes, 2), Contains("unused"));
  CHECK(role_of(axes, 3) == "signal/content");
  CHECK(has_note(axes, "column 2\" swings at 2 times the frequency of \"column 3\": not a track's x"));

  const Recording stamped = read(PublishedLayout::timer_ms);
  CHECK(stamped.kind == SignalKind::event_stamps);
  CHECK(role_of(stamped, 2) == "event stamp:ms/content");
  CHECK(stamped.time.back() < s.duration);

  const Recording slash = read(PublishedLayout::slash_units);
  CHECK(slash.kind == SignalKind::angle);
  CHECK(role_of(slash, 1) == "time:s/header");
  CHECK(role_of(slash, 2) == "angle:rad/header");

  const Recording mismatch = read(PublishedLayout::header_mismatch);
  CHECK(mismatch.kind == SignalKind::angle);
  CHECK(role_of(mismatch, 2) == "angle:deg/content");
  CHECK(has_note(mismatch, "the header names 4 columns over rows of 2"));

  const Recording portuguese = read(PublishedLayout::portuguese);
  CHECK(portuguese.kind == SignalKind::position);
  CHECK(role_of(portuguese, 1) == "unused/header");
  CHECK(role_of(portuguese, 2) == "time:s/header");

  const Recording spaced = read(PublishedLayout::spaces);
  CHECK(spaced.kind == SignalKind::angle);
  CHECK(role_of(spaced, 2) == "angle:rad/header");

  test::RecordingSimulation fast = s;
  fast.rate_hz = 500.0;
  const auto logged = simulate_recording(fast);
  const Recording stamps = parse_recording(test::published_csv(logged, s.length, PublishedLayout::repeated_stamps, 0.0, 1), "r.csv");
  CHECK(stamps.time.size() == logged.t.size());
  CHECK(has_note(stamps, "the clock ticks in 0.01 s"));
  CHECK(stamps.time_quantum == Approx(0.01));

  // An all-zero angle beside a track's x and y is passed over.
  const Recording zero = parse_recording("t,theta,x,y\n0,0,1,2\n0.1,0,1.1,2.1\n0.2,0,1.2,2.0\n", "z.csv");
  CHECK(zero.kind == SignalKind::position);
  CHECK_THAT(role_of(zero, 2), Contains("unused"));

  // A phone's repeated and out-of-order samples: dropped, each noted at its line.
  test::RecordingSimulation g;
  g.duration = 30.0;
  const auto gyro = simulate_recording(g);
  const Recording phone = parse_recording(test::glitchy_phyphox_csv(gyro, 6, 6, 3), "phone.csv");
  CHECK(phone.time.size() == gyro.t.size() - 6);
  CHECK(std::count_if(phone.notes.begin(), phone.notes.end(),
                      [](const RecordingNote& n) { return n.line > 0 && n.text.find("dropped") != std::string::npos; }) == 12);
  CHECK(std::is_sorted(phone.time.begin(), phone.time.end()));
}

TEST_CASE("A count of periods against the time they took, under comment lines: a counter and its stamps",
          "[recordings][columns][stamps]") {
  // Cumulative timing as a student types it: comment lines (the bob, then
  // spaced column words with the length), then "N;t" for N = 1, 3, ..., 19
  // periods of a 3.0770 s swing (a 2.355 m pendulum), times to 1 ms. The
  // header's words are no columns of the rows, so the numbers decide: whole
  // numbers stepping by 2 beside an increasing time are a count.
  std::string text = "#Kugeldurchmesser 5.9cm\n# Perioden       t in s     L\xc3\xa4nge 2.355m\n";
  for (int n = 1; n <= 19; n += 2) {
    char row[32];
    std::snprintf(row, sizeof row, "%d;%.3f\n", n, 3.077 * n);
    text += row;
  }
  const Recording r = parse_recording(text, "cumulative.txt");
  CHECK(r.kind == SignalKind::event_stamps);
  CHECK(role_of(r, 1) == "counter/content");
  CHECK(role_of(r, 2) == "event stamp:s/content");
  CHECK(has_note(r, "the header names 1 column over rows of 2"));
  const SwingAnalysis a = analyse_swings(r, "cumulative.txt");
  CHECK(a.period.periods == 18);
  // The times are exact to their 1 ms print: the slope is 3.077 s within the clock's floor.
  CHECK(a.period.value == Approx(3.077).margin(3.0 * a.period.uncertainty + 1e-9));
  // One column, then a row of two: the message names no NUL delimiter.
  CHECK_THROWS_WITH(parse_recording("t\n0.5\n1.0\n1;2\n", "one.txt"),
                    Contains("mixed delimiters: found ';' in a file whose header names one column"));
}

TEST_CASE("Refusals: what cannot be read says the fix", "[recordings][columns]") {
  // plain reads one column: several need --columns.
  CHECK_THROWS_WITH(parse_recording("0.1\t1\n0.2\t2\n", "p.txt", RecordingFormat::plain),
                    Contains("--format plain reads one column") && Contains("--columns"));
  CHECK(parse_recording("1\t0.1\n2\t0.2\n3\t0.4\n", "p.txt", RecordingFormat::plain, {}, "-,t:s").time ==
        std::vector<double>{0.1, 0.2, 0.4});
  // A headerless time and three signals: which one, the file cannot say.
  CHECK_THROWS_WITH(parse_recording("0.1\t5\t0.5\t2\n0.2\t-3\t-2\t3.5\n0.3\t1\t1\t-5\n", "h.txt"),
                    Contains("headerless file of 4 columns") && Contains("--columns"));
  // Radians by the header, degrees by the numbers.
  CHECK_THROWS_WITH(parse_recording("Time (s),Angle (rad)\n0,-20\n0.1,0\n0.2,20\n0.3,0\n", "r.csv"),
                    Contains("over 180 deg: it holds degrees?"));
  CHECK_THROWS_WITH(parse_recording("0.1\t1\n", "h.txt", RecordingFormat::automatic, {}, "t:s,theta:furlong"),
                    Contains("expected deg or rad"));
  CHECK_THROWS_WITH(parse_recording("0.1\t1\n", "h.txt", RecordingFormat::automatic, {}, "t:s,spin"),
                    Contains("expected a role"));
}

namespace {

/// A published layout at a frame rate and a release amplitude; a track or not.
struct Family {
  PublishedLayout layout;
  double rate_hz;
  double theta0_deg;
  bool track;
};

/// Checks the roles read on seeds 1..200 of a family and returns how often
/// the period lies within its standard uncertainty of the truth: 20 s, l =
/// 0.80 m, alpha = 2e-3 1/s, beta = 4e-3 1/(s rad), jitter 0.2 ms, no
/// samples dropped, the first sample a seeded fraction of an interval after
/// the release (each seed its own sampling phase: with one phase for all,
/// an error that depends on it is one draw, not 200); an angle with 1.5 mm
/// / 0.8 m of noise (rad), a track with 1.5 mm on x and y. The truth: the
/// exact zero crossings of theta nearest to the ones found (the
/// simulation's, linear within 1 ms), their mean period, as
/// tests/test_recordings.cpp.
double period_coverage(const Family& f) {
  constexpr int kRuns = 200;
  int covered = 0;
  for (int seed = 1; seed <= kRuns; ++seed) {
    test::RecordingSimulation s;
    s.duration = 20.0, s.drop = 0.0, s.noise = 0.0, s.rate_hz = f.rate_hz;
    s.theta0 = f.theta0_deg * M_PI / 180.0, s.seed = static_cast<std::uint64_t>(seed);
    s.phase = test::seeded_phase(static_cast<std::uint64_t>(seed));
    const auto sim = simulate_recording(s);
    const double noise = f.track ? 0.0015 : 0.0015 / s.length;
    const Recording r =
        parse_recording(test::published_csv(sim, s.length, f.layout, noise, static_cast<std::uint64_t>(seed)), "sim");
    const SignalKind kind = f.track ? SignalKind::position
                            : f.layout == PublishedLayout::microbit_ms || f.layout == PublishedLayout::microbit_two_axes
                                ? SignalKind::unknown
                                : SignalKind::angle;
    REQUIRE(r.kind == kind);
    const SwingAnalysis a = analyse_swings(r, "sim");
    // The angle's unit read right (the other is 57 times off): the
    // amplitude at the first crossing, where there is one (a 2 deg swing
    // under 2 mrad of noise may have none), within a factor 1.5 of the
    // release's.
    if (kind == SignalKind::angle) CHECK_FALSE((a.start_amplitude > 1.5 * s.theta0 || a.start_amplitude < s.theta0 / 1.5));
    std::vector<double> exact;
    for (const auto& c : a.crossings) {
      const auto it = std::lower_bound(sim.zero_times.begin(), sim.zero_times.end(), c.time);
      double best = it == sim.zero_times.end() ? sim.zero_times.back() : *it;
      if (it != sim.zero_times.begin() && std::fabs(*(it - 1) - c.time) < std::fabs(best - c.time)) best = *(it - 1);
      exact.push_back(best);
    }
    const double truth = 2.0 * (exact.back() - exact.front()) / (exact.size() - 1.0);
    covered += std::fabs(a.period.value - truth) <= a.period.uncertainty;
  }
  const double coverage = static_cast<double>(covered) / kRuns;
  WARN("layout " << static_cast<int>(f.layout) << " at " << f.rate_hz << " Hz, " << f.theta0_deg << " deg: coverage "
                 << coverage);
  return coverage;
}

}  // namespace

TEST_CASE("Published layouts: the period within its uncertainty of the truth, 200 recordings each",
          "[recordings][columns][coverage]") {
  const Family families[] = {
      {PublishedLayout::rotary_degrees, 50.0, 4.0, false},  {PublishedLayout::opencv_angle, 30.0, 5.0, false},
      {PublishedLayout::opencv_angle, 30.0, 2.0, false},    {PublishedLayout::pixel_track, 60.0, 10.0, true},
      {PublishedLayout::pixel_track, 240.0, 10.0, true},    {PublishedLayout::tracker_degrees, 30.0, 3.0, false},
      {PublishedLayout::logger_pro_video, 30.0, 10.0, true}, {PublishedLayout::headerless_txy, 30.0, 10.0, true},
      {PublishedLayout::spaces, 30.0, 10.0, false},
      // Issue 38: a headerless angle in degrees at a small swing and in radians at a large
      // one; a micro:bit's whole milli-g on a millisecond clock, timed only.
      {PublishedLayout::headerless_degrees, 30.0, 5.0, false}, {PublishedLayout::headerless_radians, 30.0, 40.0, false},
      {PublishedLayout::microbit_ms, 50.0, 10.0, false}, {PublishedLayout::microbit_two_axes, 30.0, 20.0, false},
      // The rest of issue 38's: degrees at 40 deg, radians at 2 deg; a third signal beside the
      // angle that is no track's y; a fitting program's "X,Y,X',Y'" at 12 frames/s; a 12
      // frames/s track.
      {PublishedLayout::headerless_degrees, 30.0, 40.0, false}, {PublishedLayout::headerless_radians, 30.0, 2.0, false},
      {PublishedLayout::t_theta_extra, 30.0, 40.0, false},      {PublishedLayout::generic_names, 12.0, 20.0, false},
      {PublishedLayout::headerless_txy, 12.0, 10.0, true},
  };
  for (const Family& f : families) CHECK(std::fabs(period_coverage(f) - test::kOneSigmaCoverage) < test::coverage_tolerance(200));
}

TEST_CASE("Large swings: the period within its uncertainty of the truth at 60 and 83 deg (known to fail)",
          "[recordings][columns][coverage][!shouldfail]") {
  // Issue 38's OpenCV track swung from 83 deg. Here the roles and the unit
  // are read right, but the period is 3e-5 (60 deg) to 6e-5 (83 deg) of
  // itself short, 1.5 to 3 of its sigmas, in nearly every seed: coverage
  // 0.165 and 0 (session 28). The smooth amplitude curve of the index (a
  // line in log theta over these 20 swings) starts 0.6 % high and ends
  // 0.2 % low; its own uncertainty adds 5e-6 s to the period's, a tenth of
  // the error. Expected to fail ([!shouldfail]: its passing fails the run,
  // and the tag goes) until the index is unbiased there.
  for (const Family& f : {Family{PublishedLayout::headerless_degrees, 30.0, 60.0, false},
                          Family{PublishedLayout::headerless_radians, 20.0, 83.0, false}}) {
    CHECK(std::fabs(period_coverage(f) - test::kOneSigmaCoverage) < test::coverage_tolerance(200));
  }
}

TEST_CASE("A scene's recording reference declares the columns as import --columns does", "[recordings][columns][scene]") {
  const std::string folder = std::string(PENDULUM_DATA_DIR) + "/recordings";
  const std::string text = R"({"timing": {"recording": "tracker_headerless_xy.txt", "columns": "t:s,x:m,y:m"},
                               "length": {"value": 0.8, "unit": "m"}})";
  const ParsedScene s = parse_scene(text, {folder});
  const RecordingSummary r =
      analyse_recording(folder + "/tracker_headerless_xy.txt", RecordingFormat::automatic, {}, {}, {}, "t:s,x:m,y:m");
  REQUIRE(s.recordings.size() == 1);
  const auto& columns = s.recordings[0].summary.columns;
  REQUIRE(columns.size() == 3);
  CHECK(columns[1].role == "x");
  CHECK(columns[1].unit == "m");
  CHECK(columns[1].decided_by == "option");
  CHECK(s.observations[0].period == r.swings.period.value);
  // An unknown role is refused at the reference.
  try {
    parse_scene(R"({"timing": {"recording": "tracker_headerless_xy.txt", "columns": "t:s,spin,y"},
                    "length": {"value": 0.8, "unit": "m"}})",
                {folder});
    FAIL("an unknown role read");
  } catch (const InputError& e) {
    CHECK(e.path() == "timing.recording");
    CHECK_THAT(e.what(), Contains("expected a role"));
  }
}

TEST_CASE("A phyphox experiment file is read as the CSV export of its best set", "[recordings][columns][phyphox]") {
  // 30 s of the gyroscope simulation (tests/recording_simulation.hpp, defaults: 0.8 m, 100 Hz).
  test::RecordingSimulation s;
  s.duration = 30.0;
  const auto sim = simulate_recording(s);
  const std::string xml = test::phyphox_experiment_xml(sim);
  REQUIRE(looks_like_phyphox_experiment(xml));
  CHECK_FALSE(looks_like_phyphox_experiment(test::phyphox_gyroscope_csv(sim, false)));
  const Recording r = read_phyphox_experiment(xml, "p.phyphox", RecordingFormat::automatic, {});
  CHECK(r.format == RecordingFormat::phyphox);
  CHECK(r.kind == SignalKind::angular_rate);
  CHECK(r.set == "Raw Data");
  CHECK(has_note(r, "the set \"Autocorrelation\" is not used"));
  // Its numbers are the CSV export's, value for value (both print 10 significant digits).
  const Recording csv = parse_recording(test::phyphox_gyroscope_csv(sim, false), "p.csv");
  CHECK(r.time == csv.time);
  CHECK(r.channels == csv.channels);
  CHECK(analyse_swings(r, "p").period.value == analyse_swings(csv, "p").period.value);
  // A set by its name; one that is not there names those that are.
  CHECK(read_phyphox_experiment(xml, "p.phyphox", RecordingFormat::automatic, "raw data").set == "Raw Data");
  CHECK_THROWS_WITH(read_phyphox_experiment(xml, "p.phyphox", RecordingFormat::automatic, "Gyroscope"),
                    Contains("no set \"Gyroscope\"; expected one of its sets: \"Autocorrelation\", \"Raw Data\""));
  CHECK_THROWS_WITH(read_phyphox_experiment("<phyphox version=\"1.14\"><data-containers/></phyphox>", "e.phyphox",
                                            RecordingFormat::automatic, {}),
                    Contains("without an <export>"));
}
