// The fit of the decay law, Eq. (25): derivatives, recovery, coverage of the
// uncertainties, the limits alpha -> 0 and beta -> 0, model choice, bad data,
// and the bundled record.
#include <catch2/catch.hpp>
#include <ceres/jet.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Dense>

#include "pendulum/reduce_scene.hpp"
#include "simulations/decay_simulation.hpp"
#include "pendulum/json/scene_json.hpp"
#include "reference.hpp"
#include "scene_files.hpp"
#include "textbook_decay_fit.hpp"

using namespace pendulum;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
// Fig. 2 of Nelson & Olsson: theta0m = 17.5 deg, sigma = 0.3 deg, Eqs. (28)-(29).
constexpr double kTheta0m = 17.5 * test::kDegree;
constexpr double kSigma = 0.3 * test::kDegree;

DecaySimulation paper_record(std::uint64_t seed, int points = 61, double duration = 3600.0) {
  return {test::kAlpha, test::kBeta, kTheta0m, kSigma, duration, points, seed};
}
}  // namespace

TEST_CASE("Analytic Jacobian of the fit equals automatic differentiation", "[decay_fit][jet]") {
  using J = ceres::Jet<double, 3>;
  DecayData d;
  for (int i = 0; i < 40; ++i) {
    d.times.push_back(i * i * 7.0);  // 0 ... 10647 s: both sides of alpha t = 0.1
    d.amplitudes.push_back(0.1);
  }
  const std::array<std::array<double, 3>, 4> points{{{test::kAlpha, test::kBeta, kTheta0m},
                                                     {0.0, test::kBeta, kTheta0m},
                                                     {test::kAlpha, 0.0, kTheta0m},
                                                     {1e-9, 1e-9, 1e-3}}};
  for (const auto& p : points) {
    std::vector<double> r(d.times.size()), jac(3 * d.times.size());
    detail::decay_residuals(d, p.data(), r.data(), jac.data());
    for (std::size_t i = 0; i < d.times.size(); ++i) {
      const J model = decayed_amplitude(J(p[2], 2), J(p[0], 0), J(p[1], 1), J(d.times[i]));
      INFO("alpha " << p[0] << " beta " << p[1] << " t " << d.times[i]);
      CHECK_THAT(r[i], WithinAbs(model.a - 0.1, 1e-15));
      for (int c = 0; c < 3; ++c) {
        const double ad = model.v[c];
        CHECK_THAT(jac[c * d.times.size() + i], WithinAbs(ad, 1e-12 * std::abs(ad) + 1e-300));
      }
    }
  }
}

TEST_CASE("The fit's model reduces to Eqs. (33) and (46)", "[decay_fit]") {
  DecayData d;
  for (double t : {0.0, 10.0, 400.0, 3600.0, 10800.0}) {
    d.times.push_back(t);
    d.amplitudes.push_back(0.0);  // residual = model
  }
  std::vector<double> r(5);
  const double linear[3] = {test::kAlpha, 0.0, kTheta0m};
  detail::decay_residuals(d, linear, r.data(), nullptr);
  for (int i = 0; i < 5; ++i) CHECK_THAT(r[i], WithinRel(kTheta0m * std::exp(-test::kAlpha * d.times[i]), 1e-15));
  const double quadratic[3] = {0.0, test::kBeta, kTheta0m};
  detail::decay_residuals(d, quadratic, r.data(), nullptr);
  for (int i = 0; i < 5; ++i) CHECK_THAT(r[i], WithinRel(kTheta0m / (1 + test::kBeta * kTheta0m * d.times[i]), 1e-15));
}

TEST_CASE("The fast fit finds the textbook Ceres optimum", "[decay_fit]") {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    for (int points : {10, 61, 1000}) {
      const DecayData d = simulate_decay(paper_record(seed, points, 10800.0));
      const DecayFit f = fit_decay(d, {DecayModel::both});
      const auto ref = test::textbook_decay_fit(d, {test::kAlpha, test::kBeta, kTheta0m});
      INFO("seed " << seed << " points " << points);
      REQUIRE(f.converged);
      // 1e-7: the fast fit stops at a relative cost change of 1e-13 (the
      // reference at 1e-16); issue 3 asks for 1e-6 against scipy.
      CHECK_THAT(f.alpha.value, WithinRel(ref[0], 1e-7));
      CHECK_THAT(f.beta.value, WithinRel(ref[1], 1e-7));
      CHECK_THAT(f.initial_amplitude.value, WithinRel(ref[2], 1e-7));
    }
  }
}

TEST_CASE("Recovery of alpha and beta from synthetic records", "[decay_fit]") {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const DecayFit f = fit_decay(simulate_decay(paper_record(seed, 121)));
    INFO("seed " << seed);
    REQUIRE(f.converged);
    CHECK(f.model == DecayModel::both);
    // Within 3 standard uncertainties of the truth (99.7% each).
    CHECK(std::abs(f.alpha.value - test::kAlpha) < 3 * *f.alpha.uncertainty);
    CHECK(std::abs(f.beta.value - test::kBeta) < 3 * *f.beta.uncertainty);
    CHECK(std::abs(f.initial_amplitude.value - kTheta0m) < 3 * *f.initial_amplitude.uncertainty);
  }
}

TEST_CASE("Linear-only and quadratic-only records fit without NaN", "[decay_fit]") {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    DecaySimulation linear = paper_record(seed, 121);
    linear.beta = 0.0;
    linear.alpha = 5e-4;
    const DecayFit fl = fit_decay(simulate_decay(linear));
    INFO("seed " << seed << ": " << fl.model_reason);
    CHECK(fl.converged);
    CHECK(std::isfinite(fl.alpha.value));
    CHECK(std::abs(fl.alpha.value - linear.alpha) < 3 * *fl.alpha.uncertainty);
    // beta either ends on its bound (reported) or is not significant.
    CHECK((fl.beta.at_bound || !fl.beta.significant));

    DecaySimulation quadratic = paper_record(seed, 121);
    quadratic.alpha = 0.0;
    const DecayFit fq = fit_decay(simulate_decay(quadratic));
    INFO(fq.model_reason);
    CHECK(fq.converged);
    CHECK(std::abs(fq.beta.value - quadratic.beta) < 3 * *fq.beta.uncertainty);
    CHECK((fq.alpha.at_bound || !fq.alpha.significant));
  }
}

TEST_CASE("Coverage: +-1 sigma holds the truth 68% of the time", "[decay_fit][coverage]") {
  // 400 records of 61 points over 1 h (seeds 1000-1399). If the uncertainties
  // are right, the count inside +-1 sigma is Binomial(400, 0.6827): mean 273,
  // standard deviation 9.3; the test allows 3.5 standard deviations.
  const int n = 400;
  for (const bool weighted : {true, false}) {
    int alpha_in = 0, beta_in = 0;
    for (int k = 0; k < n; ++k) {
      DecayData d = simulate_decay(paper_record(1000 + k));
      if (!weighted) d.sigmas.clear();  // covariance scaled by SSR/dof instead
      const DecayFit f = fit_decay(d, {DecayModel::both});
      REQUIRE(f.converged);
      CHECK(f.separable);  // an hour from 17.5 deg: both terms many sigma from 0
      alpha_in += std::abs(f.alpha.value - test::kAlpha) <= *f.alpha.uncertainty;
      beta_in += std::abs(f.beta.value - test::kBeta) <= *f.beta.uncertainty;
    }
    INFO((weighted ? "given sigma" : "residual variance") << ": alpha " << alpha_in << ", beta "
                                                          << beta_in << " of " << n);
    CHECK(std::abs(alpha_in - 273.1) <= 3.5 * 9.3);
    CHECK(std::abs(beta_in - 273.1) <= 3.5 * 9.3);
  }
}

namespace {
// A student's record (issue 14, section 3): ten minutes, eleven amplitudes
// read once a minute from a 5 deg release, both kinds of damping present with
// comparable effect (alpha = 2e-4 1/s against beta theta0m = 3.5e-4 1/s at
// beta = 0.004 1/(s rad)), read to sigma_deg.
constexpr double kStudentAlpha = 2e-4, kStudentBeta = 0.004;
DecaySimulation student_record(std::uint64_t seed, double sigma_deg) {
  return {kStudentAlpha, kStudentBeta, 5.0 * test::kDegree, sigma_deg * test::kDegree, 600.0, 11, seed};
}
}  // namespace

TEST_CASE("A student's ten-minute record: the reported sigma covers the truth whatever the fit ends on",
          "[decay_fit][coverage]") {
  // 400 records per reading error (seeds 5000-5399). If the uncertainties are
  // right, the count within +-1 sigma is Binomial(400, 0.6827): 273.1 +- 9.3.
  // Read to 0.05 deg the record fixes only alpha + beta theta: both estimates
  // are confined between 0 and that sum/rate, less than two two-term sigmas,
  // so no record separates the terms and the +-1 sigma interval holds the
  // truth more often than 68% (conservative). Read to 0.02 deg about half
  // the records show one term significantly: nominal coverage. Before, a term
  // on its bound was dropped and the other quoted with its one-term sigma:
  // 227 of the 400 records at 0.05 deg, each 6-20 sigma from the truth (173
  // covered).
  const double expected = 273.1, sd = 9.3;
  for (const double sigma_deg : {0.05, 0.02}) {
    int alpha_in = 0, beta_in = 0, separable = 0, at_bound = 0;
    double worst = 0.0;
    for (int k = 0; k < 400; ++k) {
      const DecayFit f = fit_decay(simulate_decay(student_record(5000 + k, sigma_deg)));
      REQUIRE(f.converged);
      REQUIRE(f.model == DecayModel::both);
      REQUIRE((f.alpha.uncertainty && f.beta.uncertainty));
      const double za = std::abs(f.alpha.value - kStudentAlpha) / *f.alpha.uncertainty;
      const double zb = std::abs(f.beta.value - kStudentBeta) / *f.beta.uncertainty;
      alpha_in += za <= 1.0;
      beta_in += zb <= 1.0;
      worst = std::max({worst, za, zb});
      separable += f.separable;
      at_bound += f.alpha.at_bound || f.beta.at_bound;
    }
    INFO("sigma " << sigma_deg << " deg: alpha " << alpha_in << ", beta " << beta_in << " of 400 within 1 sigma; "
                  << at_bound << " on a bound, " << separable << " separable, worst " << worst << " sigma");
    CHECK(alpha_in >= expected - 3.5 * sd);
    CHECK(beta_in >= expected - 3.5 * sd);
    // 800 Gaussian deviates pass 4 sigma together with probability 0.05.
    CHECK(worst < 4.0);
    if (sigma_deg == 0.05) {
      CHECK(separable == 0);
    } else {
      CHECK(alpha_in <= expected + 3.5 * sd);
      CHECK(beta_in <= expected + 3.5 * sd);
      CHECK(separable > 0);
    }
    CHECK(at_bound > 0);  // the case the issue found
  }
}

TEST_CASE("A term on its bound keeps the two-term covariance, and the damping rows carry it", "[decay_fit]") {
  // The first of the student's records (0.05 deg) whose alpha ends on 0.
  std::uint64_t seed = 5000;
  DecayData d = simulate_decay(student_record(seed, 0.05));
  while (!fit_decay(d).alpha.at_bound) d = simulate_decay(student_record(++seed, 0.05));
  const DecayFit f = fit_decay(d);
  INFO("seed " << seed << ": " << f.model_reason);
  CHECK(f.model == DecayModel::both);
  CHECK(f.alpha.value == 0.0);
  CHECK(!f.separable);
  CHECK_THAT(f.model_reason, Contains("cannot tell linear from quadratic damping") &&
                                 Contains("alpha reached its bound 0"));
  // The covariance is (J^T J)^-1 of all three parameters at the bound,
  // formed here from the residuals' analytic Jacobian.
  const std::size_t n = d.times.size();
  std::vector<double> r(n), jac(3 * n);
  const double p[3] = {f.alpha.value, f.beta.value, f.initial_amplitude.value};
  detail::decay_residuals(d, p, r.data(), jac.data());
  Eigen::Matrix3d jtj = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3>>(jac.data(), n, 3).transpose() *
                        Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3>>(jac.data(), n, 3);
  const Eigen::Matrix3d c = jtj.inverse();
  CHECK_THAT(*f.alpha.uncertainty, WithinRel(std::sqrt(c(0, 0)), 1e-6));
  CHECK_THAT(*f.beta.uncertainty, WithinRel(std::sqrt(c(1, 1)), 1e-6));
  CHECK_THAT(f.correlation_alpha_beta, WithinRel(c(0, 1) / std::sqrt(c(0, 0) * c(1, 1)), 1e-6));
  // The complaint: beta several sigma from the truth. Now within one.
  CHECK(std::abs(f.beta.value - kStudentBeta) < *f.beta.uncertainty);
  const auto warnings = review_decay_fit(f);
  CHECK(std::any_of(warnings.begin(), warnings.end(), [](const std::string& w) {
    return w.find("cannot tell linear from quadratic damping") != std::string::npos;
  }));

  // Into the reduction: the record's share of each damping row's variance is
  // g^T C g with g the row's derivatives in (alpha, beta) and C the two-term
  // covariance. The share is the difference between the scene's row variance
  // and the same scene's with alpha and beta held without uncertainty.
  nlohmann::json scene_json = {
      {"timing", {{"oscillations_per_trial", 10}, {"unit", "s"}, {"trials", {20.09, 20.03, 20.12, 20.06, 20.08}}}},
      {"length", {{"value", 1.0}, {"uncertainty", 0.002}, {"unit", "m"}}},
      {"amplitude", {{"value", 5.0}, {"uncertainty", 1.0}, {"unit", "deg"}}},
      {"decay", {{"data", {{"time_unit", "s"}, {"amplitude_unit", "rad"}, {"times", d.times},
                           {"amplitudes", d.amplitudes}, {"sigmas", d.sigmas}}}}}};
  const ParsedScene scene = parse_scene(scene_json.dump());
  const Analysis with_record = reduce_scene(scene);
  REQUIRE(with_record.decay_fit);
  CHECK(with_record.decay_fit->beta.uncertainty == f.beta.uncertainty);
  ParsedScene held = scene;
  held.decay_data.reset();
  use_fitted_decay(held, f);
  REQUIRE(held.input_covariances.size() == 1);
  CHECK(held.input_covariances[0].covariance == f.covariance[1]);
  held.apparatus_uncertainty.decay = Decay<double>{0.0, 0.0};
  held.input_covariances.clear();
  const Analysis without = reduce_scene(held);

  using J = ceres::Jet<double, 2>;
  const Apparatus<J> dual = convert_apparatus<J>(held.apparatus, [](const Field& field, double x) {
    const std::string path = field.path;
    return path == "decay.alpha" ? J(x, 0) : path == "decay.beta" ? J(x, 1) : J(x);
  });
  const Reduction<J> reduction =
      reduce(dual, convert_observation<J>(held.observations[0], [](const Field&, double x) { return J(x); }));
  for (const CorrectionId id : {CorrectionId::quadratic_damping, CorrectionId::amplitude_decay}) {
    const int i = static_cast<int>(id);
    const J dt = *reduction.terms[i].ratio * reduction.period_ideal;  // s
    const double share = dt.v[0] * dt.v[0] * f.covariance[0] + 2 * dt.v[0] * dt.v[1] * f.covariance[1] +
                         dt.v[1] * dt.v[1] * f.covariance[4];
    const double u_with = *with_record.observations[0].corrections[i].delta_T_uncertainty;
    const double u_without = *without.observations[0].corrections[i].delta_T_uncertainty;
    INFO(kCorrections[i].id << ": " << u_with << " s with the record's share, " << u_without << " s without");
    CHECK_THAT(u_with * u_with - u_without * u_without, WithinRel(share, 1e-6));
  }
}

TEST_CASE("A record that leaves the two-term covariance singular: unknown uncertainties and a warning",
          "[decay_fit]") {
  // The precise readings rise and only the imprecise last one falls (the
  // unweighted slope of ln theta is negative, so the record is valid): the
  // weighted fit ends with alpha = beta = 0 on their bounds, where
  // d theta/d alpha = -theta0m t and d theta/d beta = -theta0m^2 t (Eq. 25)
  // are proportional, so J^T J is singular.
  DecayData d;
  d.times = {0.0, 60.0, 120.0, 180.0};
  d.amplitudes = {0.100, 0.101, 0.102, 0.050};
  d.sigmas = {1e-4, 1e-4, 1e-4, 1.0};
  REQUIRE_NOTHROW(validate_decay_data(d, "decay.data"));
  const DecayFit f = fit_decay(d);
  CHECK(f.model == DecayModel::both);
  CHECK(f.alpha.at_bound);
  CHECK(f.beta.at_bound);
  CHECK(!f.alpha.uncertainty);
  CHECK(!f.beta.uncertainty);
  CHECK(!f.separable);
  CHECK_THAT(f.model_reason, Contains("covariance is singular"));
  std::string warnings;
  for (const auto& w : review_decay_fit(f)) warnings += w + "\n";
  INFO(warnings);
  CHECK_THAT(warnings, Contains("decay fit: the record cannot fix alpha (the fit's covariance is singular)") &&
                           Contains("decay fit: the record cannot fix beta (the fit's covariance is singular)"));
}

TEST_CASE("Too little data for both terms: the simpler model, and why", "[decay_fit]") {
  // Three points with theta0m free leave no degree of freedom for both.
  DecayData three;
  three.times = {0.0, 600.0, 1200.0};
  three.amplitudes = {0.30, 0.25, 0.21};
  const DecayFit f3 = fit_decay(three);
  CHECK(f3.model != DecayModel::both);
  CHECK_THAT(f3.model_reason, Contains("no degree of freedom"));
  CHECK(f3.dof == 1);
  // A record too short for the curvature that tells alpha from beta:
  // 20 s of a 17.5 deg decay, read to 0.3 deg. Both terms, with the two-term
  // uncertainties, each larger than the paper's value.
  const DecayFit short_record = fit_decay(simulate_decay(paper_record(7, 21, 20.0)));
  CHECK(short_record.model == DecayModel::both);
  CHECK(!short_record.separable);
  CHECK_THAT(short_record.model_reason, Contains("cannot tell linear from quadratic damping"));
  CHECK(*short_record.alpha.uncertainty > test::kAlpha);
  CHECK(*short_record.beta.uncertainty > test::kBeta);
}

TEST_CASE("Bad decay records are refused by path", "[decay_fit][errors]") {
  auto fails = [](DecayData d, const std::string& path, const std::string& message) {
    try {
      validate_decay_data(d, "decay.data");
      FAIL("no error; expected one at " << path);
    } catch (const InputError& e) {
      CHECK(e.path() == path);
      CHECK_THAT(std::string(e.what()), Contains(message));
    }
  };
  DecayData good;
  good.times = {0, 60, 120, 180};
  good.amplitudes = {0.30, 0.28, 0.27, 0.25};
  CHECK_NOTHROW(validate_decay_data(good, "decay.data"));
  DecayData d = good;
  d.times = {0, 60};
  d.amplitudes = {0.3, 0.28};
  fails(d, "decay.data.times", "expected at least 3");
  d = good;
  d.times[2] = 60;
  fails(d, "decay.data.times[2]", "strictly increasing times");
  d = good;
  d.times[2] = 30;
  fails(d, "decay.data.times[2]", "strictly increasing times");
  d = good;
  d.amplitudes[1] = 0.0;
  fails(d, "decay.data.amplitudes[1]", "expected a positive amplitude");
  d = good;
  d.amplitudes[3] = std::nan("");
  fails(d, "decay.data.amplitudes[3]", "expected a positive amplitude");
  d = good;
  d.amplitudes = {0.25, 0.27, 0.28, 0.30};
  fails(d, "decay.data.amplitudes", "do not decrease");
  d = good;
  d.amplitudes.pop_back();
  fails(d, "decay.data.amplitudes", "one per time");
  d = good;
  d.sigmas = {0.01, 0.01, -0.01, 0.01};
  fails(d, "decay.data.sigmas[2]", "positive uncertainty");
}

TEST_CASE("The bundled decay record is what its generator writes", "[decay_fit][data]") {
  const std::string command = std::string(PENDULUM_MAKE_DECAY_SCENE) + " " + PENDULUM_DATA_DIR +
                              "/nelson_olsson_1986.json";
  int status = 0;
  const std::string text = test::command_output(command, status);
  REQUIRE(status == 0);
  const auto generated = nlohmann::json::parse(text);
  const auto bundled = nlohmann::json::parse(test::read_text(std::string(PENDULUM_DATA_DIR) +
                                                             "/nelson_olsson_1986_decay.json"));
  CHECK(generated.at("decay").at("data").at("generator") == bundled.at("decay").at("data").at("generator"));
  const auto& a = generated.at("decay").at("data").at("amplitudes");
  const auto& b = bundled.at("decay").at("data").at("amplitudes");
  REQUIRE(a.size() == b.size());
  // Readings are rounded to 1e-6 deg; another libm may move one by a unit.
  for (std::size_t i = 0; i < a.size(); ++i) CHECK_THAT(a[i].get<double>(), WithinAbs(b[i].get<double>(), 1.01e-6));
  CHECK(generated.at("decay").at("data").at("times") == bundled.at("decay").at("data").at("times"));
}

TEST_CASE("The bundled record gives back the paper's alpha and beta, and Table II's damping rows",
          "[decay_fit][table2]") {
  const ParsedScene scene = parse_scene(test::read_text(std::string(PENDULUM_DATA_DIR) +
                                                        "/nelson_olsson_1986_decay.json"));
  REQUIRE(scene.decay_data);
  const Analysis a = reduce_scene(scene);
  REQUIRE(a.decay_fit);
  const DecayFit& f = *a.decay_fit;
  // Drawn from Eqs. (28)-(29): the fit must find them within 2 sigma.
  CHECK(std::abs(f.alpha.value - test::kAlpha) < 2 * *f.alpha.uncertainty);
  CHECK(std::abs(f.beta.value - test::kBeta) < 2 * *f.beta.uncertainty);
  CHECK(a.warnings.empty());

  // The damping rows from the fitted alpha and beta against Table II: the
  // issue 2 tolerance plus twice the row's own uncertainty, propagated from
  // the fit's covariance through the reduction by automatic differentiation.
  using J = ceres::Jet<double, 2>;
  ParsedScene fitted = scene;
  use_fitted_decay(fitted, f);
  const Apparatus<J> dual = convert_apparatus<J>(fitted.apparatus, [](const Field& field, double x) {
    const std::string p = field.path;
    return p == "decay.alpha" ? J(x, 0) : p == "decay.beta" ? J(x, 1) : J(x);
  });
  const Observation<J> observation =
      convert_observation<J>(fitted.observations[0], [](const Field&, double x) { return J(x); });
  const Reduction<J> r = reduce(dual, observation);
  const double s_aa = f.covariance[0], s_ab = f.covariance[1], s_bb = f.covariance[4];
  struct Row {
    CorrectionId id;
    double printed_us;
  };
  for (const Row row : {Row{CorrectionId::linear_damping, 0.033}, Row{CorrectionId::quadratic_damping, 0.027},
                        Row{CorrectionId::amplitude_decay, -77.0}}) {
    const J dt = *r.terms[static_cast<int>(row.id)].ratio * r.period_ideal * 1e6;  // us
    const double sigma = std::sqrt(dt.v[0] * dt.v[0] * s_aa + 2 * dt.v[0] * dt.v[1] * s_ab + dt.v[1] * dt.v[1] * s_bb);
    INFO(kCorrections[static_cast<int>(row.id)].id << ": " << dt.a << " +- " << sigma << " us");
    CHECK_THAT(dt.a, WithinAbs(row.printed_us, test::table2_tolerance_us(row.printed_us) + 2 * sigma));
  }
}

TEST_CASE("The fit ends where its stopping rule judged it, not at Ceres's least cost", "[decay_fit]") {
  // Ceres returns the point of least cost, which rounding can make an earlier
  // iterate than the one NewtonDecrement judged (docs/core.md, Stopping). At
  // the fit's result a Gauss-Newton step, computed here from the analytic
  // Jacobian by QR, removes at most 1e-14 of the residual variance, as the rule says.
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const DecayData d = simulate_decay(paper_record(seed, 121));
    const DecayFit f = fit_decay(d, {DecayModel::both});
    if (f.alpha.at_bound || f.beta.at_bound) continue;
    const double p[3] = {f.alpha.value, f.beta.value, f.initial_amplitude.value};
    const Eigen::Index n = static_cast<Eigen::Index>(d.times.size());
    Eigen::VectorXd r(n);
    Eigen::MatrixXd jac(n, 3);
    detail::decay_residuals(d, p, r.data(), jac.data());
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(jac);
    const double decrement = (qr.householderQ().transpose() * r).head<3>().squaredNorm();
    INFO("seed " << seed << ": " << f.termination);
    CHECK(decrement <= 1e-14 * r.squaredNorm() / static_cast<double>(n - 3));
  }
}

TEST_CASE("A record whose sigmas are 4 times too small: chi2 says so, and S scales alpha and beta",
          "[decay_fit][dispersion]") {
  DecayData d = simulate_decay(paper_record(7, 121));
  const DecayFit honest = fit_decay(d);
  for (double& s : d.sigmas) s /= 4.0;  // E[chi2/dof] = 16
  const DecayFit f = fit_decay(d);
  CHECK_FALSE(honest.scaled);
  REQUIRE(f.birge_ratio);
  CHECK(f.scaled);
  CHECK(*f.probability < 0.01);
  CHECK_THAT(*f.birge_ratio, WithinRel(4.0, 0.2));
  // Same residuals, weights 16 times larger: the unscaled sigmas are the
  // honest fit's over 4, and S brings them back to sqrt(chi2/dof) times that.
  for (const auto& [q, h] : {std::pair{f.alpha, honest.alpha}, std::pair{f.beta, honest.beta}}) {
    CHECK_THAT(*q.uncertainty_unscaled, WithinRel(*h.uncertainty / 4.0, 1e-4));
    CHECK_THAT(*q.uncertainty, WithinRel(*f.birge_ratio * *q.uncertainty_unscaled, 1e-9));
  }
}
