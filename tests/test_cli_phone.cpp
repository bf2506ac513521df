// pendulum-g on a phone hung by a string (issue 23, docs/phone.md): the
// starter scene `template phone` reduces to standard gravity, saying whose
// angle its amplitude is.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "scene_files.hpp"

using nlohmann::json;

TEST_CASE("template phone: three string lengths reduce to standard gravity and the knot's mark, status ok",
          "[cli][template][phone]") {
  const std::string file = "/tmp/pendulum-g-phone-" + std::to_string(getpid());
  const std::string exe = PENDULUM_G_EXE;
  REQUIRE(std::system((exe + " template phone > " + file + ".json").c_str()) == 0);
  REQUIRE(std::system((exe + " reduce --strict " + file + ".json > " + file + ".out 2> " + file + ".err").c_str()) == 0);
  const json result = json::parse(pendulum::test::read_text(file + ".out"));
  CHECK(pendulum::test::read_text(file + ".err").empty());
  std::system(("rm -f " + file + ".json " + file + ".out " + file + ".err").c_str());
  CHECK(result.at("status") == "ok");
  CHECK(result.at("warnings").empty());
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
