// pendulum-g on a phone hung by a string (issue 23, docs/phone.md): the
// starter scene `template phone` reduces to standard gravity, saying whose
// angle its amplitude is.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "cli_run.hpp"
#include "scene_files.hpp"

using Catch::Matchers::Contains;
using nlohmann::json;

// The phone's added mass, which no row models, is estimated as the potential
// flow's about its section across the swing, rho pi (a/2)^2 b (plausibility.cpp):
// at the template's 1013 hPa and 21 degC, rho = p M/(R T) = 1.19972 kg/m^3
// (M = 0.02896 kg/mol, R = 8.314462618 J/(mol K)). Edge-on, a = 0.8 cm and
// b = 16 cm: 0.00965 g, 2.54e-5 of T for 190 g, 48 us at 1.889 s, over the
// 22.5 us below which a correction is negligible (a tenth of the period's
// uncertainty: the three lengths' trials of ten swings scatter by 3.9 ms
// pooled, over 10 sqrt(3): 225 us). Face-first, a = 7.5 cm:
// 0.848 g, 2.23e-3 of T; turned edge-on, (7.5/0.8)^2 = 87.9 times less.
TEST_CASE("template phone: three string lengths reduce to standard gravity and the knot's mark, status ok",
          "[cli][template][phone]") {
  const std::string file = "/tmp/pendulum-g-phone-" + std::to_string(getpid());
  const std::string exe = PENDULUM_G_EXE;
  REQUIRE(std::system((exe + " template phone > " + file + ".json").c_str()) == 0);
  REQUIRE(std::system((exe + " reduce --strict " + file + ".json > " + file + ".out 2> " + file + ".err").c_str()) == 0);
  const json result = json::parse(pendulum::test::read_text(file + ".out"));
  const std::string added_mass = "bob: a box's added mass in air is not modelled (Eqs. (54)-(62) are a sphere's); "
                                 "estimated as the potential flow's about its section across the swing, 0.0096 g, it "
                                 "would lengthen the period by 2.5e-05 of itself (48 us, over the 22.5 us below which "
                                 "a correction is negligible), and g comes out low by about 5.1e-05 of itself";
  CHECK(pendulum::test::read_text(file + ".err") == "pendulum-g: warning: " + added_mass + "\n");
  std::system(("rm -f " + file + ".json " + file + ".out " + file + ".err").c_str());
  CHECK(result.at("status") == "ok");
  CHECK(result.at("warnings") == json{added_mass});
  // Its trials are a phone's slow mode at 9.80665 m/s^2 with the knot at
  // the top of the phone (template_command.cpp): g and the offset within
  // their uncertainties of those.
  const double g = result.at("g").at("value"), u = result.at("g").at("uncertainty");
  CHECK(std::abs(g - 9.80665) < u);
  for (const auto& p : result.at("fit").at("parameters")) {
    if (p.at("name") == "length_offset") CHECK(std::abs(p.at("value").get<double>()) < p.at("uncertainty").get<double>());
  }
  // The amplitude is the phone's own (its sensor's); the corrections took the
  // pendulum's, less on the shortest string: 0.9337046 of it at 0.3 m (mpmath,
  // docs/phone.md), which the fitted offset (within 0.1 mm of 0) moves by
  // dc/dl = 0.09/m, less than 1e-5.
  const json& first = result.at("fit").at("observations").at(0);
  CHECK(first.at("amplitude_of") == "body");
  CHECK(std::abs(first.at("amplitude_pendulum_rad").get<double>() / first.at("amplitude").at("value").get<double>() -
                 0.9337046) < 1e-5);
  bool slow_mode = false;
  for (const auto& row : first.at("corrections")) slow_mode |= row.at("method") == "slow_mode";
  CHECK(slow_mode);
}

TEST_CASE("A phone swung face-first is warned of its added mass, and how to turn it", "[cli][phone]") {
  const std::string file = "/tmp/pendulum-g-phone-face-" + std::to_string(getpid()) + ".json";
  json scene = json::parse(run("template phone").out);
  scene["bob"]["width"]["value"] = 0.8;
  scene["bob"]["depth"]["value"] = 7.5;
  std::ofstream(file) << scene.dump();
  const Run face = run("reduce " + file);
  scene["air"] = "vacuum";
  std::ofstream(file) << scene.dump();
  const Run vacuum = run("reduce " + file);
  std::remove(file.c_str());
  REQUIRE(face.status == 0);
  CHECK_THAT(face.err, Contains("0.85 g, it would lengthen the period by 0.0022 of itself ("));
  CHECK_THAT(face.err, Contains("and g comes out low by about 0.0045 of itself; swung a quarter turn about the vertical "
                                "(bob.width 7.5 cm along the swing, its face in the swing's plane) it would carry 88 "
                                "times less"));
  REQUIRE(vacuum.status == 0);
  CHECK(json::parse(vacuum.out).at("warnings").empty());
}
