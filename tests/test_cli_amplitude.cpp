// The pendulum-g command's amplitude: T/T0 and its bound at one amplitude,
// and what it refuses.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

#include "cli_run.hpp"

using nlohmann::json;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;

TEST_CASE("The amplitude command prints T/T0 and its bound", "[cli][amplitude]") {
  const Run r = run("amplitude --theta0-deg 25");
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const json out = json::parse(r.out);
  CHECK(out.at("schema") == "pendulum-g/amplitude/1");
  CHECK(out.at("method") == "agm");
  // 2K(sin^2 12.5 deg)/pi = 1.0120305503050378424 (mpmath ellipk, 30 digits).
  CHECK_THAT(out.at("T_over_T0").get<double>(), WithinAbs(1.0120305503050378424, 3e-16));
  CHECK_THAT(out.at("delta_T_over_T0").get<double>(), WithinAbs(0.0120305503050378424, 1e-17));
  CHECK(out.at("error_bound_delta_T_over_T0").get<double>() <= 1.3e-17);
  CHECK_FALSE(out.contains("series_terms"));

  // Eq. (8) with 4 terms at 25 deg (m = sin^2 12.5 deg = 0.0468): the bound
  // on the omitted tail is A_5 m^5/(1 - m) = 1.434e-8, the tail 1.422e-8.
  const json series = json::parse(run("amplitude --theta0-deg 25 --method series --terms 4").out);
  CHECK(series.at("method") == "series");
  CHECK(series.at("series_terms") == 4);
  const double error = 0.0120305503050378424 - series.at("delta_T_over_T0").get<double>();
  CHECK(error > 0.0);
  CHECK(error <= series.at("error_bound_delta_T_over_T0").get<double>());
  CHECK_THAT(error, WithinAbs(1.4224e-8, 0.0001e-8));
}

TEST_CASE("The amplitude command refuses 180 deg and beyond, negatives and NaN", "[cli][amplitude][errors]") {
  for (const char* x : {"180", "200", "-1", "nan"}) {
    const Run r = run(std::string("amplitude --theta0-deg ") + x);
    INFO(x << "\nstderr: " << r.err);
    CHECK(r.status == 1);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, Contains("pendulum-g: error: --theta0-deg: got"));
    CHECK_THAT(r.err, Contains("deg; expected an amplitude from 0 to below 180 deg"));
  }
  // The value as a number is written (was 309 digits, and "-0.000000" for a negative one).
  CHECK_THAT(run("amplitude --theta0-deg 1e300").err, Contains("got 1e+300 deg;"));
  CHECK_THAT(run("amplitude --theta0-deg -1e-300").err, Contains("got -1e-300 deg;"));
  // A decimal number, as every option's (0x10 was read as 16 deg).
  const Run hexadecimal = run("amplitude --theta0-deg 0x10");
  CHECK(hexadecimal.status == 2);
  CHECK_THAT(hexadecimal.err, Contains("--theta0-deg: got \"0x10\"; expected a decimal number: an amplitude from 0"));
  CHECK(run("amplitude").status == 2);
  CHECK(run("amplitude --theta0-deg 10 --method magic").status == 2);
}
