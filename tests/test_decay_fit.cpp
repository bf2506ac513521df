// The fit of the decay law, Eq. (25): derivatives, recovery, coverage of the
// uncertainties, the limits alpha -> 0 and beta -> 0, model choice, bad data,
// and the bundled record.
#include <catch2/catch.hpp>
#include <ceres/jet.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>

#include "pendulum/analysis.hpp"
#include "pendulum/decay_simulation.hpp"
#include "pendulum/scene_json.hpp"
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
      alpha_in += std::abs(f.alpha.value - test::kAlpha) <= *f.alpha.uncertainty;
      beta_in += std::abs(f.beta.value - test::kBeta) <= *f.beta.uncertainty;
    }
    INFO((weighted ? "given sigma" : "residual variance") << ": alpha " << alpha_in << ", beta "
                                                          << beta_in << " of " << n);
    CHECK(std::abs(alpha_in - 273.1) <= 3.5 * 9.3);
    CHECK(std::abs(beta_in - 273.1) <= 3.5 * 9.3);
  }
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
  // 20 s of a 17.5 deg decay, read to 0.3 deg.
  const DecayFit short_record = fit_decay(simulate_decay(paper_record(7, 21, 20.0)));
  CHECK(short_record.model != DecayModel::both);
  CHECK_THAT(short_record.model_reason, Contains("cannot be told apart"));
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
  const Analysis a = analyse(scene);
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
