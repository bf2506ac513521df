// pendulum-g import, reduce and a scene's "range" on the recordings with
// glitches in data/recordings/ (tests/tools/make_recordings.cpp, issue 19):
// the glitchy end found and cut, the reduction end to end, the recording
// named among an implausible period's causes.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "cli_run.hpp"
#include "long_decay.hpp"
#include "recording_simulation.hpp"

using nlohmann::json;
using Catch::Matchers::Contains;

namespace {
const std::string kGlitchy = std::string(PENDULUM_DATA_DIR) + "/recordings/tracker_glitchy_end.txt";
}  // namespace

TEST_CASE("import: a track's glitchy end is found, and --range cuts it", "[cli][recordings][glitches]") {
  const Run whole = run("import --range all " + kGlitchy);
  REQUIRE(whole.status == 0);
  const json a = json::parse(whole.out);
  // Clicked carelessly from 130 s on (make_recordings, seed 20): one glitch,
  // to the last crossing. It is 57 % of the record, and its start (3 cm of
  // scatter, 16 s) hides in the sigma that so large a glitch lifts; the
  // clean stretch, without it, shows where it starts (below).
  REQUIRE(a.at("glitches").size() == 1);
  const json& g = a.at("glitches")[0];
  CHECK(g.at("from").get<double>() > 125.0);
  CHECK(g.at("from").get<double>() < 150.0);
  CHECK(g.at("to").get<double>() > 299.0);
  CHECK(g.at("unit") == "s");
  // Its period is honest about it: the truth within its (widened) uncertainty.
  pendulum::test::RecordingSimulation s;
  s.duration = 300.0, s.rate_hz = 15.0, s.noise = 0.0, s.jitter = 0.0, s.drop = 0.0, s.seed = 20;
  const auto sim = pendulum::test::simulate_recording(s);
  auto truth_within = [&](double a_s, double b_s) {  // the mean period of the exact turning points in [a, b]
    double first = -1.0, last = 0.0;
    int n = 0;
    for (double t : sim.turning_times) {
      if (t < a_s || t > b_s) continue;
      if (first < 0.0) first = t;
      last = t, ++n;
    }
    return 2.0 * (last - first) / (n - 1.0);
  };
  const double period = a.at("period").at("value"), sigma = a.at("period").at("uncertainty");
  CHECK(std::fabs(period - truth_within(0.0, 300.0)) < sigma);
  CHECK(a.at("analysed_range").is_null());
  CHECK(a.at("cut").empty());

  // By default the glitchy end is cut (issue 38 item 1): the clean stretch
  // is analysed, and says what it cut and what the whole record gives.
  const Run clean = run("import " + kGlitchy);
  REQUIRE(clean.status == 0);
  const json c = json::parse(clean.out);
  CHECK(c.at("glitches").empty());
  REQUIRE(c.at("cut").size() == 1);
  // The first pass's clean stretch showed the careless clicks' start: cut too.
  CHECK(c.at("cut")[0].at("from").get<double>() <= g.at("from").get<double>());
  CHECK(c.at("cut")[0].at("from").get<double>() > 125.0);
  CHECK(c.at("cut")[0].at("from").get<double>() < 135.0);
  CHECK(c.at("cut")[0].at("to").get<double>() == g.at("to").get<double>());
  CHECK(c.at("cut")[0].at("periods_carried").is_null());
  CHECK(c.at("cut")[0].at("why") == "the catch or a glitchy end");
  const json& range = c.at("analysed_range");
  CHECK(range.at("by") == "clean stretch");
  CHECK(range.at("to").get<double>() < g.at("from").get<double>() + 1.0);
  CHECK(c.at("whole_record_period").at("value").get<double>() == period);
  const double pc = c.at("period").at("value"), uc = c.at("period").at("uncertainty");
  CHECK(uc < sigma / 5.0);
  CHECK(std::fabs(pc - truth_within(range.at("from").get<double>(), range.at("to").get<double>())) < 4.0 * uc + 2e-5);
  CHECK(c.at("notes")[0].at("text").get<std::string>().find("the clean stretch ") == 0);

  const Run cut = run("import --range 0:129 " + kGlitchy);
  REQUIRE(cut.status == 0);
  const json b = json::parse(cut.out);
  CHECK(b.at("glitches").empty());
  const double p = b.at("period").at("value"), u = b.at("period").at("uncertainty");
  // Four standard uncertainties and 2e-5 s for the crossings' phase, as the
  // families' test in tests/test_recordings.cpp.
  CHECK(std::fabs(p - truth_within(0.0, 129.0)) < 4.0 * u + 2e-5);
  CHECK(b.at("notes")[0].at("text").get<std::string>().find("analysed from 0 s to 129 s") == 0);

  const Run bad = run("import --range 9:3 " + kGlitchy);
  CHECK(bad.status != 0);
  CHECK(bad.out.empty());
  CHECK_THAT(bad.err, Contains("--range") && Contains("expected START:END in seconds"));
  const Run outside = run("import --range 400:500 " + kGlitchy);
  CHECK(outside.status == 1);
  CHECK_THAT(outside.err, Contains("no sample in the range 400:500 s"));
}

TEST_CASE("A scene's range cuts a recording's glitch, without it the recording is refused naming the range", "[cli][recordings][glitches]") {
  const std::string scene = std::string(PENDULUM_DATA_DIR) + "/recordings/tracker_glitchy_end_scene.json";
  const Run r = run("reduce " + scene);
  REQUIRE(r.status == 0);
  const json out = json::parse(r.out);
  // The simulation's g within 3 times g's uncertainty (length 0.5 mm and the period).
  CHECK(std::fabs(out.at("g").at("value").get<double>() - 9.80665) < 3.0 * out.at("g").at("uncertainty").get<double>());

  json without = json::parse(pendulum::test::read_text(scene));
  without["timing"].erase("range");
  without["decay"]["data"].erase("range");
  const std::string copy = std::string(PENDULUM_DATA_DIR) + "/recordings/.glitchy_without_range.json";
  const auto write_text = [](const std::string& path, const std::string& text) {
    FILE* f = std::fopen(path.c_str(), "w");
    REQUIRE(f);
    std::fwrite(text.data(), 1, text.size(), f);
    std::fclose(f);
  };
  write_text(copy, without.dump());
  const Run w = run("reduce " + copy);
  // Without the range the clean stretch is analysed by default (issue 38
  // item 1), and the reduction says what was cut.
  CHECK(w.status == 0);
  const json wo = json::parse(w.out);
  CHECK(std::fabs(wo.at("g").at("value").get<double>() - 9.80665) < 3.0 * wo.at("g").at("uncertainty").get<double>());
  CHECK_THAT(wo.dump(), Contains("the clean stretch ") && Contains("the catch or a glitchy end") &&
                            Contains("keeps the whole record"));
  // "range": "all" keeps the whole record, whose glitch costs it its
  // amplitudes (peak_outliers, c1a76f9): refused, naming the range that cuts it.
  without["timing"]["range"] = "all";
  without["decay"]["data"]["range"] = "all";
  write_text(copy, without.dump());
  const Run all = run("reduce --format table " + copy);
  std::remove(copy.c_str());
  CHECK(all.status == 1);
  CHECK(all.out.empty());
  CHECK_THAT(all.err, Contains("amplitude: missing, and the recording ") && Contains("tracker_glitchy_end.txt") &&
                          Contains("too few for the smooth curve") && Contains("a \"range\" in timing cuts a stretch"));
}

namespace {

// Writes `text` to `path`.
void write_file(const std::string& path, const std::string& text) {
  FILE* f = std::fopen(path.c_str(), "w");
  REQUIRE(f);
  std::fwrite(text.data(), 1, text.size(), f);
  std::fclose(f);
}

// A video track at 60 frames/s of theta = 0.25 rad cos(2 pi t / 1.8 s) on a
// 800 px radius, 20 s, its times as frame numbers 0, 1, ... under "t" (as a
// tracker without a frame rate writes them); with `theta_period` > 0 a
// "theta (deg)" column of a swing of that period beside the x and y.
std::string frame_track(double theta_period = 0.0) {
  std::string text = theta_period > 0.0 ? "t,theta (deg),x (px),y (px)\n" : "t,x,y\n";
  char row[128];
  for (int i = 0; i < 1200; ++i) {
    const double t = i / 60.0, a = 0.25 * std::cos(2.0 * M_PI * t / 1.8);
    if (theta_period > 0.0) {
      std::snprintf(row, sizeof row, "%.4f,%.3f,%.2f,%.2f\n", t,
                    0.25 * std::cos(2.0 * M_PI * t / theta_period) * 180.0 / M_PI, 400.0 + 800.0 * std::sin(a),
                    800.0 * std::cos(a));
    } else {
      std::snprintf(row, sizeof row, "%d,%.2f,%.2f\n", i, 400.0 + 800.0 * std::sin(a), 800.0 * std::cos(a));
    }
    text += row;
  }
  return text;
}

// The print resolution, 0.01 px on 800 px (1.25e-5 rad), over the swing's
// slope at a crossing (0.87 rad/s) moves a crossing by 1.4e-5 s at most, and
// the mean period over 10 periods by a tenth of that: 1e-5 s bounds it.
constexpr double kFramePeriodTolerance = 1e-5;

}  // namespace

TEST_CASE("import --columns frame:60fps reads the frame numbers that are refused without it on import and in a scene's columns",
          "[cli][recordings][columns]") {
  const std::string dir = temporary_file() + ".d";
  std::filesystem::create_directory(dir);
  const std::string file = dir + "/frames.csv";
  write_file(file, frame_track());

  // Read as seconds it would give 108 s (1.8 s x 60): refused, naming the option.
  const Run refused = run("import " + file);
  CHECK(refused.status == 1);
  CHECK(refused.out.empty());
  CHECK_THAT(refused.err, Contains("holds whole numbers stepping by one (0 to 1199)") &&
                              Contains("--columns (a scene's \"columns\"), e.g. \"frame:30fps,x,y\""));

  const Run read = run("import --columns \"frame:60fps,x:px,y:px\" " + file);
  REQUIRE(read.status == 0);
  const json a = json::parse(read.out);
  const json& time = a.at("columns")[0];
  CHECK(time.at("role") == "time");
  CHECK(time.at("unit") == "frame");
  CHECK(time.at("decided_by") == "option");
  CHECK_THAT(time.at("why").get<std::string>(), Contains("frame numbers at 60 frames/s"));
  CHECK(a.at("columns")[1].at("role") == "x");
  CHECK(a.at("columns")[2].at("unit") == "px");
  const double period = a.at("period").at("value").get<double>();
  CHECK(std::fabs(period - 1.8) < kFramePeriodTolerance);

  // A bad frame rate names what it expects.
  const Run bad = run("import --columns \"frame:sixty,x,y\" " + file);
  CHECK(bad.status == 1);
  CHECK_THAT(bad.err, Contains("expected frame numbers with their frame rate, e.g. \"frame:30fps\""));

  // The same through a scene's "columns": reduce takes import's period.
  const std::string scene = dir + "/scene.json";
  write_file(scene, R"({"schema": "pendulum-g/scene/1",
    "timing": {"recording": "frames.csv", "columns": "frame:60fps,x:px,y:px"},
    "length": {"value": 0.8, "unit": "m", "uncertainty": 0.0005}, "amplitude": {"value": 14.3, "unit": "deg"},
    "bob": {"diameter": {"value": 1.0, "unit": "mm"}, "mass": {"value": 4.0, "unit": "mg"}}, "air": "vacuum"})");
  const Run reduced = run("reduce " + scene);
  REQUIRE(reduced.status == 0);
  const json r = json::parse(reduced.out);
  CHECK(r.at("recordings")[0].at("period").at("value").get<double>() == period);
  write_file(scene, R"({"schema": "pendulum-g/scene/1", "timing": {"recording": "frames.csv"},
    "length": {"value": 0.8, "unit": "m"}, "amplitude": {"value": 14.3, "unit": "deg"}})");
  const Run unnamed = run("reduce " + scene);
  CHECK(unnamed.status == 1);
  CHECK_THAT(unnamed.err, Contains("timing.recording") && Contains("frame:30fps,x,y"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("import --columns picks one of two signals whose periods differ and that are refused without it",
          "[cli][recordings][columns]") {
  const std::string file = temporary_file() + ".csv";
  // theta swings at 1.2 s beside x and y at 1.8 s: no file can say which is the pendulum.
  write_file(file, frame_track(1.2));
  const Run refused = run("import " + file);
  CHECK(refused.status == 1);
  CHECK(refused.out.empty());
  CHECK_THAT(refused.err, Contains("two signals give different periods: the angle \"theta (deg)\" gives 1.2 +- ") &&
                              Contains("the x and y \"x (px)\", \"y (px)\" 1.8 +- ") &&
                              Contains("--columns (a scene's \"columns\"): \"t:s,theta:deg\" or \"t:s,-,x:px,y:px\""));
  // Each option reads its own: the formula's periods.
  const Run angle = run("import --columns \"t:s,theta:deg\" " + file);
  REQUIRE(angle.status == 0);
  CHECK(std::fabs(json::parse(angle.out).at("period").at("value").get<double>() - 1.2) < kFramePeriodTolerance);
  const Run track = run("import --columns \"t:s,-,x:px,y:px\" " + file);
  REQUIRE(track.status == 0);
  CHECK(std::fabs(json::parse(track.out).at("period").at("value").get<double>() - 1.8) < kFramePeriodTolerance);

  // theta of the same swing: read, with a note that the x and y agree.
  write_file(file, frame_track(1.8));
  const Run same = run("import " + file);
  std::remove(file.c_str());
  REQUIRE(same.status == 0);
  const json s = json::parse(same.out);
  CHECK(s.at("columns")[1].at("role") == "angle");
  bool noted = false;
  for (const auto& n : s.at("notes")) {
    noted |= n.at("text").get<std::string>().find("they agree") != std::string::npos;
  }
  CHECK(noted);
}

TEST_CASE("A timer log with a missed stamp reduces end to end", "[cli][recordings][stamps]") {
  // make_recordings, seed 19: the 18th of 41 presses missing, the file's count running on.
  const Run imported = run("import " + std::string(PENDULUM_DATA_DIR) + "/recordings/timer_missed_stamp.txt");
  REQUIRE(imported.status == 0);
  const json a = json::parse(imported.out);
  CHECK(a.at("columns")[0].at("role") == "counter");
  CHECK(a.at("columns")[1].at("role") == "event stamp");
  CHECK(a.at("periods") == 40);
  bool mended = false;
  for (const auto& n : a.at("notes")) {
    mended |= n.at("text").get<std::string>().find("1 stamp missed") != std::string::npos;
  }
  CHECK(mended);
  const Run r = run("reduce " + std::string(PENDULUM_DATA_DIR) + "/recordings/timer_missed_stamp_scene.json");
  REQUIRE(r.status == 0);
  const json out = json::parse(r.out);
  CHECK(out.at("recordings")[0].at("period") == a.at("period"));
  // The simulation's g within 3 times g's uncertainty (length, amplitude and the stamps' period).
  CHECK(std::fabs(out.at("g").at("value").get<double>() - 9.80665) < 3.0 * out.at("g").at("uncertainty").get<double>());
}

TEST_CASE("reduce: a long decay's recording scene says swing by swing and its g is the truth's", "[cli][recordings][swing_series]") {
  // tests/long_decay.hpp: 81 deg to 17 deg in 375 s (the issue's decay), the length exact.
  const std::string dir = temporary_file() + ".d";
  std::filesystem::create_directory(dir);
  pendulum::test::write_long_decay(dir + "/decay.csv", 81.0, 375.0, 31);
  write_file(dir + "/scene.json", R"({"schema": "pendulum-g/scene/1", "length": {"value": 2.72, "unit": "m"},
    "timing": {"recording": "decay.csv"}, "decay": {"data": {"recording": "decay.csv"}}})");
  const Run r = run("reduce " + dir + "/scene.json");
  const Run table = run("reduce --format table " + dir + "/scene.json");
  std::filesystem::remove_all(dir);
  REQUIRE(r.status == 0);
  const json out = json::parse(r.out);
  const json& how = out.at("recordings")[0].at("reduction");
  CHECK(how.at("requested") == "auto");
  CHECK(how.at("mode") == "swing_by_swing");
  CHECK(how.at("amplitude_shift_sigmas").get<double>() > how.at("threshold_sigmas").get<double>());
  CHECK(out.at("kind") == "series");
  const double g = out.at("g").at("value").get<double>(), sigma = out.at("g").at("uncertainty").get<double>();
  CHECK(std::fabs(g - pendulum::test::kLongDecayG) < 3.0 * sigma);
  REQUIRE(table.status == 0);
  CHECK_THAT(table.out + table.err, Contains("timing: reduced swing by swing"));
}
