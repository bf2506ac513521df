// The pendulum-g command's template: every starter scene reduces to an ok g
// with no warning.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "cli_run.hpp"

using nlohmann::json;
using Catch::Matchers::Contains;

namespace {

/// `template KIND`, saved and given to `reduce --strict`: exit 0, nothing on
/// stderr, status ok, no warning. Returns reduce's JSON.
json reduce_template(const std::string& kind) {
  const std::string file = temporary_file();
  const Run t = run("template " + kind + " > " + file);
  REQUIRE(t.status == 0);
  const Run r = run("reduce --strict " + file);
  std::remove(file.c_str());
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const json result = json::parse(r.out);
  CHECK(result.at("status") == "ok");
  CHECK(result.at("warnings").empty());
  return result;
}

}  // namespace

TEST_CASE("template prints a scene that reduces to an ok g with no warning", "[cli][template]") {
  const json result = reduce_template("");
  // Its trials are a 1 m pendulum's at standard gravity (2 pi sqrt(l/g)
  // with the corrections, about 2.0076 s), timed by hand: g within its
  // uncertainty of 9.80665 m/s^2.
  const double g = result.at("g").at("value"), u = result.at("g").at("uncertainty");
  CHECK(std::abs(g - 9.80665) < u);
}

TEST_CASE("template series prints a series that reduces to g and the ball's radius, status ok", "[cli][template]") {
  const json result = reduce_template("series");
  CHECK(result.at("kind") == "series");
  // Its trials are 2 pi sqrt((L + 12.7 mm)/g) at standard gravity with the
  // corrections, lengths taped to the top of the 25.4 mm ball, timed by hand:
  // g within its uncertainty of 9.80665 m/s^2, the offset within its
  // uncertainty of the ball's radius.
  const double g = result.at("g").at("value"), u = result.at("g").at("uncertainty");
  CHECK(std::abs(g - 9.80665) < u);
  bool offset_seen = false;
  for (const auto& p : result.at("fit").at("parameters")) {
    if (p.at("name") != "length_offset") continue;
    offset_seen = true;
    CHECK(std::abs(p.at("value").get<double>() - 0.0127) < p.at("uncertainty").get<double>());
  }
  CHECK(offset_seen);
  CHECK(run("template pendulum").status != 0);
}

TEST_CASE("template pivot-scan prints a metre stick that reduces to g, k and its centre, status ok",
          "[cli][template]") {
  // Its trials are a uniform 1 m stick's (k = 1/sqrt(12) m, centre 0.5 m) at
  // standard gravity, timed by hand: each within its uncertainty's reach.
  const json result = reduce_template("pivot-scan");
  const double g = result.at("g").at("value"), u = result.at("g").at("uncertainty");
  CHECK(std::abs(g - 9.80665) < u);
  for (const auto& p : result.at("fit").at("parameters")) {
    const double truth = p.at("name") == "radius_of_gyration"        ? 1.0 / std::sqrt(12.0)
                         : p.at("name") == "center_of_mass_position" ? 0.5
                                                                      : 9.80665;
    CHECK(std::abs(p.at("value").get<double>() - truth) < 2 * p.at("uncertainty").get<double>());
  }
}

TEST_CASE("template recording names a file beside the scene, with a recording there it reduces", "[cli][template]") {
  char folder[] = "/tmp/pendulum-g-template-XXXXXX";
  REQUIRE(mkdtemp(folder));
  const std::string dir = folder;
  REQUIRE(run("template recording > " + dir + "/scene.json").status == 0);
  // Without the file: the error names the key and the file.
  const Run missing = run("reduce " + dir + "/scene.json");
  CHECK(missing.status == 1);
  CHECK_THAT(missing.err, Contains("timing.recording: ") && Contains("my_recording.csv"));
  // With the synthetic phyphox recording of a 0.80 m pendulum at standard
  // gravity (data/recordings/phyphox_pendulum_raw.tsv) saved under that name.
  std::filesystem::copy_file(std::string(PENDULUM_DATA_DIR) + "/recordings/phyphox_pendulum_raw.tsv",
                             dir + "/my_recording.csv");
  const Run r = run("reduce " + dir + "/scene.json");
  std::filesystem::remove_all(dir);
  REQUIRE(r.status == 0);
  const json result = json::parse(r.out);
  // The simulated record damps as make_recordings.cpp was told (alpha 2e-3 /s,
  // beta 4e-3 /(s rad)), 28 times faster than air alone damps the template's
  // 25.4 mm steel ball:
  // the verdict names that slip (status.cpp, the damping check), and g stands.
  CHECK(result.at("status") == "suspect");
  REQUIRE(result.at("status_reasons").size() == 1);
  CHECK_THAT(result.at("status_reasons")[0].get<std::string>(), Contains("decay.data.time_unit: the record damps"));
  const double g = result.at("g").at("value"), u = result.at("g").at("uncertainty");
  CHECK(std::abs(g - 9.80665) < u);
}
