// The pendulum-g command's fit-decay on the bundled decay record.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "cli_run.hpp"

using nlohmann::json;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("fit-decay on the bundled record", "[cli][decay_fit]") {
  const std::string scene = std::string(PENDULUM_DATA_DIR) + "/nelson_olsson_1986_decay.json";
  const Run r = run("fit-decay " + scene);
  REQUIRE(r.status == 0);
  const json fit = json::parse(r.out);
  CHECK(fit.at("schema") == "pendulum-g/decay-fit/1");
  CHECK(fit.at("model") == "both");
  CHECK(fit.at("converged") == true);
  CHECK(fit.at("points") == 361);
  CHECK(fit.at("uncertainty_scaling") == "sigma");
  // Drawn from Eqs. (28)-(29): within 2 sigma of them.
  const double alpha = fit.at("alpha").at("value"), s_alpha = fit.at("alpha").at("uncertainty");
  const double beta = fit.at("beta").at("value"), s_beta = fit.at("beta").at("uncertainty");
  CHECK(std::abs(alpha - 2.49e-4) < 2 * s_alpha);
  CHECK(std::abs(beta - 3.17e-3) < 2 * s_beta);
  CHECK(fit.at("alpha").at("unit") == "1/s");
  CHECK(fit.at("beta").at("unit") == "1/(s rad)");
  // The air explains a third of the linear damping (text after Eq. 68).
  CHECK_THAT(fit.at("drag_theory").at("measured_over_predicted").at("alpha").get<double>(), WithinAbs(3.0, 0.3));

  const Run forced = run("fit-decay --model linear_only " + scene);
  REQUIRE(forced.status == 0);
  CHECK(json::parse(forced.out).at("beta").at("fitted") == false);

  // The reduction uses the fit and reports it.
  const Run reduced = run("reduce " + scene);
  REQUIRE(reduced.status == 0);
  const json result = json::parse(reduced.out);
  CHECK(result.at("decay_fit").at("alpha").at("value").get<double>() == alpha);
  CHECK(result.at("decay_fit").at("angle_of") == "pendulum");  // amplitudes typed, no "of"
  CHECK(correction(result, "amplitude_decay").at("status") == "applied");

  const Run none = run("fit-decay " + kNelsonOlsson);
  CHECK(none.status == 1);
  CHECK(none.out.empty());
  CHECK_THAT(none.err, Contains("decay.data: missing"));

  // A file holding only the record (issue 14): the same fit, no drag theory
  // (no pendulum to predict it for).
  const json whole = json::parse(pendulum::test::read_text(scene));
  const std::string only = temporary_file();
  std::ofstream(only) << json({{"title", "the record alone"}, {"decay", {{"data", whole.at("decay").at("data")}}}}).dump();
  const Run alone = run("fit-decay " + only);
  REQUIRE(alone.status == 0);
  const json alone_fit = json::parse(alone.out);
  CHECK(alone_fit.at("alpha").at("value").get<double>() == alpha);
  CHECK(alone_fit.at("beta").at("value").get<double>() == beta);
  CHECK_FALSE(alone_fit.contains("drag_theory"));
  // The residual variance by its name: the residual standard error squared.
  CHECK(alone_fit.at("residual_variance_rad2").get<double>() ==
        std::pow(alone_fit.at("residual_standard_error_rad").get<double>(), 2));
  // Without sigma, reduced_chi2 is that residual variance (rad^2), kept for
  // scripts that read it.
  json unweighted = json::parse(pendulum::test::read_text(only));
  unweighted["decay"]["data"].erase("sigma");
  std::ofstream(only) << unweighted.dump();
  const json plain = json::parse(run("fit-decay " + only).out);
  CHECK(plain.at("uncertainty_scaling") == "residual_variance");
  CHECK_THAT(plain.at("reduced_chi2").get<double>(), WithinRel(plain.at("residual_variance_rad2").get<double>(), 1e-12));
  // A table for people; in reduce's table too.
  const Run table = run("fit-decay --format table " + scene);
  REQUIRE(table.status == 0);
  CHECK_THAT(table.out, Contains("Decay fit, Nelson & Olsson (1986) Eq. (25): model both"));
  CHECK_THAT(table.out, Contains("  alpha             = "));
  CHECK_THAT(table.out, Contains("  beta              = "));
  CHECK_THAT(run("reduce --format table " + scene).out, Contains("Decay fit, Nelson & Olsson (1986) Eq. (25)"));
  // A decay-only file takes no parts: they need a pendulum.
  std::ofstream(only) << json({{"bob", whole.at("bob")}, {"decay", {{"data", whole.at("decay").at("data")}}}}).dump();
  const Run parts = run("fit-decay " + only);
  CHECK(parts.status == 1);
  CHECK_THAT(parts.err, Contains("bob: unknown key; this object takes: amplitude, decay, length, notes"));
  std::remove(only.c_str());
}

TEST_CASE("Shares over 100 % from a correlated alpha and beta are explained beside the cross term's", "[cli][decay_fit]") {
  // A phone's decay fit: alpha and beta correlated near -1, each alone
  // thousands of % of u(g)^2. The shares of every input and the cross term
  // add to 100 % (u(g)^2 = sum c_i^2 + 2 c_a c_b r), which the table says.
  const std::string scene = std::string(PENDULUM_DATA_DIR) + "/recordings/phyphox_pendulum_raw_scene.json";
  auto succeeded = [](const std::string& command) {
    const Run r = run(command);
    INFO(command << "\n" << r.err);
    REQUIRE(r.status == 0);
    return r;
  };
  const json result = json::parse(succeeded("reduce " + scene).out);
  double shares = 0.0, largest = 0.0;
  for (const json& b : result.at("g").at("budget")) {
    shares += b.at("variance_share_percent").get<double>();
    largest = std::max(largest, b.at("variance_share_percent").get<double>());
  }
  REQUIRE(largest > 100.0);
  const double u = result.at("g").at("uncertainty").get<double>();
  const double cross = 100.0 * result.at("g").at("budget_correlation").at("variance_m2_s4").get<double>() / (u * u);
  CHECK_THAT(shares + cross, WithinAbs(100.0, 1e-6));
  const std::string table = succeeded("reduce --format table " + scene).out;
  char expected[64];
  std::snprintf(expected, sizeof expected, "the cross term's, %.1f %%, takes back", cross);
  CHECK_THAT(table, Contains("their shares above count each alone") && Contains(expected));
  // Nelson & Olsson's own decay fit stays below 100 % everywhere: no such line.
  CHECK_THAT(succeeded("reduce --format table " + std::string(PENDULUM_DATA_DIR) + "/nelson_olsson_1986_decay.json").out,
             !Contains("count each alone"));
}
