// pendulum-g import, reduce and a scene's "range" on the recordings with
// glitches in data/recordings/ (tests/tools/make_recordings.cpp, issue 19):
// the glitchy end found and cut, the reduction end to end, the recording
// named among an implausible period's causes.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "cli_run.hpp"
#include "recording_simulation.hpp"

using nlohmann::json;
using Catch::Matchers::Contains;

namespace {
const std::string kGlitchy = std::string(PENDULUM_DATA_DIR) + "/recordings/tracker_glitchy_end.txt";
}  // namespace

TEST_CASE("import: a track's glitchy end is found, and --range cuts it", "[cli][recordings][glitches]") {
  const Run whole = run("import " + kGlitchy);
  REQUIRE(whole.status == 0);
  const json a = json::parse(whole.out);
  // Clicked carelessly from 130 s on (make_recordings, seed 20): one glitch,
  // from within a few periods of 130 s to the last crossing.
  REQUIRE(a.at("glitches").size() == 1);
  const json& g = a.at("glitches")[0];
  CHECK(g.at("from").get<double>() > 125.0);
  CHECK(g.at("from").get<double>() < 140.0);
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

TEST_CASE("A scene's range cuts a recording's glitch; without it the recording is named", "[cli][recordings][glitches]") {
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
  {
    FILE* f = std::fopen(copy.c_str(), "w");
    REQUIRE(f);
    const std::string text = without.dump();
    std::fwrite(text.data(), 1, text.size(), f);
    std::fclose(f);
  }
  const Run w = run("reduce --format table " + copy);
  std::remove(copy.c_str());
  REQUIRE(w.status == 0);
  CHECK_THAT(w.err + w.out, Contains("timing.recording: ") && Contains("does not fit the swing") &&
                                Contains("a \"range\" cuts it"));
  CHECK_THAT(w.err + w.out, Contains("or the recording ") && Contains("(read as tracker, columns \"x\", \"y\") timed "
                                                                        "something other than the swing"));
}
