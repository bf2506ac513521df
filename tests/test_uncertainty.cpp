// The budget as the GUM writes it (docs/uncertainty.md): each input's Type,
// distribution and degrees of freedom, Welch-Satterthwaite's effective
// degrees of freedom, the coverage factor from Student's t, and the coverage
// the expanded interval reaches, by simulation.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "pendulum/reduce_scene.hpp"
#include "simulations/decay_simulation.hpp"
#include "pendulum/monte_carlo.hpp"
#include "pendulum/json/output.hpp"
#include "pendulum/json/scene_json.hpp"
#include "pendulum/uncertainty.hpp"
#include "catalogue.hpp"
#include "scene_files.hpp"

using namespace pendulum;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

const BudgetEntry& entry(const Analysis& a, const std::string& input) {
  for (const auto& b : a.budget) {
    if (b.input == input) return b;
  }
  throw std::logic_error("no budget entry " + input);
}

/// A stopwatch experiment: `trials` of 10 oscillations, a length and an amplitude.
nlohmann::json stopwatch_scene(const std::vector<double>& trials, double length, double amplitude_deg) {
  return {{"schema", "pendulum-g/scene/1"},
          {"timing", {{"oscillations_per_trial", 10}, {"unit", "s"}, {"trials", trials}}},
          {"length", {{"value", length}, {"uncertainty", 0.0005}, {"unit", "m"}}},
          {"amplitude", {{"value", amplitude_deg}, {"uncertainty", 0.5}, {"unit", "deg"}}}};
}

}  // namespace

TEST_CASE("Welch-Satterthwaite: GUM Eq. G.2b on GUM H.1.6's components", "[uncertainty]") {
  // GUM H.1.6 (the gauge block): contributions 25, 9.7, 2.9 and 16.6 nm with
  // 18, 25.6, 50 and 2 degrees of freedom. By hand: u_c^2 = 625 + 94.09 +
  // 8.41 + 275.56 = 1003.06 nm^2; sum (c u)^4/nu = 390625/18 + 8852.93/25.6 +
  // 70.7281/50 + 75933.1/2 = 60015.28; nu_eff = 1003.06^2/60015.28 = 16.7646.
  // (GUM rounds u_c to 32 nm before dividing; the formula with u_c^2 as the
  // sum is what the budget computes.)
  const double nu = welch_satterthwaite({{25.0 * 25.0, 18.0}, {9.7 * 9.7, 25.6}, {2.9 * 2.9, 50.0}, {16.6 * 16.6, 2.0}});
  CHECK_THAT(nu, WithinRel(16.76455, 1e-6));
  // One component: its own dof; Type B components (infinite) add variance, not dof.
  CHECK_THAT(welch_satterthwaite({{4.0, 4.0}}), WithinRel(4.0, 1e-15));
  CHECK_THAT(welch_satterthwaite({{4.0, 4.0}, {4.0, kInfiniteDof}}), WithinRel(16.0, 1e-15));
  CHECK(std::isinf(welch_satterthwaite({{1.0, kInfiniteDof}, {2.0, kInfiniteDof}})));
  CHECK(std::isinf(welch_satterthwaite({})));
}

TEST_CASE("The coverage factor is Student's t quantile (GUM Table G.2)", "[uncertainty]") {
  // Two-sided 95 % quantiles of Student's t, as every t table prints them
  // (GUM Table G.2 to two decimals: 12.71, 2.78, 2.23, 2.09, 1.96).
  CHECK_THAT(coverage_factor(1.0), WithinAbs(12.706, 0.0005));
  CHECK_THAT(coverage_factor(4.0), WithinAbs(2.776, 0.0005));
  CHECK_THAT(coverage_factor(10.0), WithinAbs(2.228, 0.0005));
  CHECK_THAT(coverage_factor(20.0), WithinAbs(2.086, 0.0005));
  CHECK_THAT(coverage_factor(kInfiniteDof), WithinAbs(1.960, 0.0005));
  // nu_eff truncated to the integer below (GUM G.4.1): H.1.6's 16.76 takes t(16).
  CHECK(coverage_factor(16.76) == coverage_factor(16.0));
  CHECK_THAT(coverage_factor(16.0, 0.99), WithinAbs(2.921, 0.0005));
}

TEST_CASE("Each input says how its uncertainty was evaluated", "[uncertainty]") {
  const Analysis a = reduce_scene(parse_scene(test::nelson_olsson_text()));
  // Ten trials scattering by more than the 0.01 s resolution: Type A, the
  // mean's t with 9 degrees of freedom; the rest are stated, Type B.
  const BudgetEntry& period = entry(a, "timing.period");
  CHECK(period.evaluation.type == 'A');
  CHECK(period.evaluation.distribution == Distribution::student_t);
  CHECK(period.evaluation.dof == 9.0);
  const BudgetEntry& length = entry(a, "length");
  CHECK(length.evaluation.type == 'B');
  CHECK(length.evaluation.distribution == Distribution::normal);
  CHECK(std::isinf(length.evaluation.dof));
  double shares = 0.0;
  for (const auto& b : a.budget) shares += b.variance_share;
  CHECK_THAT(shares, WithinRel(1.0, 1e-12));
  // g's nu_eff by the formula from the budget's own rows; k and U from it.
  std::vector<VarianceComponent> components;
  for (const auto& b : a.budget) components.push_back({b.contribution * b.contribution, b.evaluation.dof});
  REQUIRE(a.g_expanded);
  CHECK_THAT(a.g_expanded->effective_dof, WithinRel(welch_satterthwaite(components), 1e-12));
  CHECK(a.g_expanded->effective_dof > 9.0);  // the Type B inputs add variance without dof
  CHECK_THAT(a.g_expanded->expanded, WithinRel(a.g_expanded->coverage_factor * *a.g.uncertainty, 1e-15));

  nlohmann::json doc = nlohmann::json::parse(test::nelson_olsson_text());
  SECTION("an amplitude not recorded is rectangular") {
    doc["amplitude"] = "not recorded";
    const Analysis b = reduce_scene(parse_scene(doc.dump()));
    CHECK(entry(b, "amplitude").evaluation.distribution == Distribution::rectangular);
    CHECK(entry(b, "amplitude").evaluation.type == 'B');
  }
  SECTION("a single trial read to a resolution is rectangular") {
    doc["timing"]["trials"] = {347.84};
    const Analysis b = reduce_scene(parse_scene(doc.dump()));
    CHECK(entry(b, "timing.period").evaluation.distribution == Distribution::rectangular);
    CHECK(std::isinf(b.g_expanded->effective_dof));
    CHECK_THAT(b.g_expanded->coverage_factor, WithinAbs(1.960, 0.0005));
  }
  SECTION("equal trials whose resolution is the floor are rectangular, Type B") {
    doc["timing"]["trials"] = {347.84, 347.84, 347.84};
    const Analysis b = reduce_scene(parse_scene(doc.dump()));
    CHECK(entry(b, "timing.period").evaluation.type == 'B');
    CHECK(entry(b, "timing.period").evaluation.distribution == Distribution::rectangular);
  }
}

TEST_CASE("A decay fit's alpha and beta are Type A with the fit's degrees of freedom", "[uncertainty]") {
  const ParsedScene s = parse_scene(test::read_text(std::string(PENDULUM_DATA_DIR) + "/nelson_olsson_1986_decay.json"));
  const Analysis a = reduce_scene(s);
  REQUIRE(a.decay_fit);
  const BudgetEntry& alpha = entry(a, "decay.alpha");
  CHECK(alpha.evaluation.type == 'A');
  if (alpha.evaluation.distribution == Distribution::student_t) CHECK(alpha.evaluation.dof == a.decay_fit->dof);
}

TEST_CASE("Five stopwatch trials: the expanded interval covers g 95 % of the time, k = 2 about 88 %",
          "[uncertainty][coverage]") {
  // The truth: g = 9.81 m/s^2, a 1 m pendulum swung to 5 deg; the model's
  // own period for them (found by reducing the noiseless scene and scaling
  // T by sqrt(g'/g), g going as 1/T^2). Each experiment times 10 oscillations
  // five times with a hand's 0.1 s scatter, and reads the length (+- 0.5 mm)
  // and the amplitude (+- 0.5 deg) once: timing gives about 99 % of u(g)^2.
  constexpr double kTrueG = 9.81, kLength = 1.0, kAmplitude = 5.0, kHand = 0.1;
  double period = 2.0 * kPi * std::sqrt(kLength / kTrueG);
  for (int i = 0; i < 3; ++i) {
    const double g = reduce_scene(parse_scene(stopwatch_scene({10 * period, 10 * period}, kLength, kAmplitude).dump())).g.value;
    period *= std::sqrt(g / kTrueG);
  }
  NormalDeviates noise(20261206);
  constexpr int kExperiments = 2000;
  int covered = 0, covered_by_two = 0;
  double least_dof = kInfiniteDof, most_dof = 0.0;
  for (int e = 0; e < kExperiments; ++e) {
    std::vector<double> trials;
    for (int t = 0; t < 5; ++t) trials.push_back(10 * period + kHand * noise.next());
    const double length = kLength + 0.0005 * noise.next(), amplitude = kAmplitude + 0.5 * noise.next();
    const Analysis a = reduce_scene(parse_scene(stopwatch_scene(trials, length, amplitude).dump()));
    const double error = std::abs(a.g.value - kTrueG);
    covered += error <= a.g_expanded->expanded;
    covered_by_two += error <= 2.0 * *a.g.uncertainty;
    least_dof = std::min(least_dof, a.g_expanded->effective_dof);
    most_dof = std::max(most_dof, a.g_expanded->effective_dof);
  }
  // Binomial standard error of a 95 % rate over 2000: sqrt(0.95 x 0.05/2000) = 0.0049.
  const double rate = double(covered) / kExperiments, rate_two = double(covered_by_two) / kExperiments;
  INFO("expanded: " << rate << ", k = 2: " << rate_two << ", nu_eff " << least_dof << " to " << most_dof);
  // Welch-Satterthwaite never gives fewer than its fewest (the period's 4);
  // a small scatter leaves the Type B rows a larger share, and more.
  CHECK(least_dof >= 4.0);
  CHECK(most_dof > least_dof);
  CHECK_THAT(rate, WithinAbs(0.95, 3 * 0.0049));
  // P(|t_4| < 2) = 0.8839 (t_4's CDF in closed form), binomial error 0.0072.
  CHECK_THAT(rate_two, WithinAbs(0.8839, 3 * 0.0072));
}

namespace {

/// A bare scene whose only uncertain input is its amplitude, released
/// anywhere in [3, 15] deg (the hand release of docs/scene.md): g(theta0) =
/// 4 pi^2 l/T^2 (2K(sin(theta0/2))/pi)^2, every other correction skipped.
constexpr double kLength = 1.0, kPeriod = 2.01, kLow = 3.0 * kPi / 180.0, kHigh = 15.0 * kPi / 180.0;
double g_at(double theta0) {
  const double factor = 2.0 * std::comp_ellint_1(std::sin(theta0 / 2.0)) / kPi;  // std takes the modulus k
  return 4.0 * kPi * kPi * kLength / (kPeriod * kPeriod) * factor * factor;
}
std::string amplitude_only_scene() {
  return nlohmann::json{{"schema", "pendulum-g/scene/1"},
                        {"timing", {{"oscillations_per_trial", 1}, {"unit", "s"}, {"trials", {kPeriod}}, {"uncertainty", 1e-12}}},
                        {"length", {{"value", kLength}, {"unit", "m"}}},
                        {"amplitude", {{"range", {3, 15}}, {"unit", "deg"}}}}
      .dump();
}

}  // namespace

TEST_CASE("Monte Carlo: g through theta0^2 with theta0 rectangular, against its exact distribution",
          "[uncertainty][monte_carlo]") {
  // theta0 ~ U(a, b) and g increasing and convex in it: g's quantiles are
  // g(a + p (b - a)), its density falls, so the shortest 95 % interval is
  // [g(a), g(a + 0.95 (b - a))]. Mean and standard deviation by Simpson's rule
  // over 2000 intervals of theta0 (error ~1e-16 of g for this smooth g).
  constexpr int kIntervals = 2000;
  double mean = 0.0, square = 0.0;
  for (int i = 0; i <= kIntervals; ++i) {
    const double w = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    const double g = g_at(kLow + (kHigh - kLow) * i / kIntervals);
    mean += w * g / (3.0 * kIntervals);
    square += w * g * g / (3.0 * kIntervals);
  }
  const double deviation = std::sqrt(square - mean * mean);
  const ParsedScene s = parse_scene(amplitude_only_scene());
  Analysis a = reduce_scene(s);
  const std::optional<MonteCarloResult> mc = monte_carlo(s, a, MonteCarloOptions{20261206, 0});
  REQUIRE(mc);
  INFO("draws " << mc->draws << ", tolerance " << mc->tolerance << "; mean " << mc->mean << " (exact " << mean
                << "), u " << mc->standard_uncertainty << " (exact " << deviation << "), [" << mc->low << ", "
                << mc->high << "] (exact [" << g_at(kLow) << ", " << g_at(kLow + 0.95 * (kHigh - kLow)) << "])");
  // The adaptive run holds twice each statistic's standard error within the
  // tolerance delta (S1 7.9.4): 2 delta is four of them.
  CHECK_THAT(mc->mean, WithinAbs(mean, 2 * mc->tolerance));
  CHECK_THAT(mc->standard_uncertainty, WithinAbs(deviation, 2 * mc->tolerance));
  CHECK_THAT(mc->low, WithinAbs(g_at(kLow), 2 * mc->tolerance));
  CHECK_THAT(mc->high, WithinAbs(g_at(kLow + 0.95 * (kHigh - kLow)), 2 * mc->tolerance));
  // GUM's symmetric y +- 1.96 u misplaces both ends: S1 8 fails it, and
  // names the amplitude; the same seed gives the same draws.
  CHECK_FALSE(mc->validated);
  CHECK(mc->bending_input == "amplitude");
  const std::optional<MonteCarloResult> again = monte_carlo(s, a, MonteCarloOptions{20261206, 0});
  CHECK(again->low == mc->low);
  CHECK(again->draws == mc->draws);
}

TEST_CASE("Monte Carlo: GUM's interval where g is linear enough, and the t input that bends Nelson & Olsson's",
          "[uncertainty][monte_carlo]") {
  const ParsedScene s = parse_scene(test::nelson_olsson_text());
  const Analysis a = reduce_scene(s);
  // Every input normal (the ten trials' mean drawn as a normal too): g is
  // linear enough in them at these uncertainties (the amplitude known to
  // +-0.3 deg), and S1 8 validates GUM's interval to the tolerance.
  ParsedScene normal = s;
  normal.evaluations.clear();
  const Analysis an = reduce_scene(normal);
  const std::optional<MonteCarloResult> linear = monte_carlo(normal, an, MonteCarloOptions{7, 0});
  REQUIRE(linear);
  INFO("GUM " << an.g.value << " +- " << an.g_expanded->expanded << "; MC [" << linear->low << ", " << linear->high
              << "], " << linear->draws << " draws, tolerance " << linear->tolerance);
  CHECK(an.g_expanded->coverage_factor == coverage_factor(kInfiniteDof));
  CHECK(linear->validated);
  CHECK_THAT(linear->mean, WithinAbs(an.g.value, linear->tolerance));
  // As read, the period is the mean of ten trials, t with 9 degrees of
  // freedom (S1 6.4.9), whose share Welch-Satterthwaite's nu_eff = 53 gives
  // too little width: the check names it, not the amplitude.
  const std::optional<MonteCarloResult> mc = monte_carlo(s, a, MonteCarloOptions{7, 0});
  REQUIRE(mc);
  INFO("as read: MC [" << mc->low << ", " << mc->high << "], " << mc->draws << " draws");
  CHECK_FALSE(mc->validated);
  CHECK(mc->bending_input == "timing.period");
  // Five trials where the timing dominates: the mean of 5 readings drawn as
  // value + u t_4 (S1 6.4.9) gives GUM's +- t_4 u as its 95 % interval (a
  // normal draw would give +- 1.96 u, 29 % narrower).
  const ParsedScene five = parse_scene(
      stopwatch_scene({20.03, 20.11, 19.95, 20.07, 19.99}, 1.0, 5.0).dump());
  const Analysis b = reduce_scene(five);
  const std::optional<MonteCarloResult> t = monte_carlo(five, b, MonteCarloOptions{11, 0});
  REQUIRE(t);
  INFO("GUM u " << *b.g.uncertainty << ", k " << b.g_expanded->coverage_factor << "; MC [" << t->low << ", "
                << t->high << "], " << t->draws << " draws");
  CHECK_THAT(t->high - t->low, WithinRel(2.0 * b.g_expanded->expanded, 0.02));
}

namespace {

/// A series at `lengths` (+- 0.5 mm), each timed as `trials` of 10
/// oscillations, the amplitude 5 +- 0.5 deg.
nlohmann::json series_scene(const std::vector<double>& lengths, const std::vector<std::vector<double>>& trials) {
  nlohmann::json observations = nlohmann::json::array();
  for (std::size_t k = 0; k < lengths.size(); ++k) {
    observations.push_back({{"length", {{"value", lengths[k]}, {"uncertainty", 0.0005}, {"unit", "m"}}},
                            {"amplitude", {{"value", 5.0}, {"uncertainty", 0.5}, {"unit", "deg"}}},
                            {"timing", {{"oscillations_per_trial", 10}, {"unit", "s"}, {"trials", trials[k]}}}});
  }
  return {{"schema", "pendulum-g/scene/1"}, {"observations", observations}};
}

const std::vector<double> kSeriesLengths{0.4, 0.6, 0.8, 1.0, 1.2};

/// Each length's trials: `count` times 10 periods of g = 9.81 m/s^2 (the
/// ideal period: the truth does not matter here) with `scatter` (s).
std::vector<std::vector<double>> series_trials(int count, double scatter, NormalDeviates& noise) {
  std::vector<std::vector<double>> trials;
  for (const double l : kSeriesLengths) {
    trials.emplace_back();
    for (int t = 0; t < count; ++t) trials.back().push_back(20.0 * kPi * std::sqrt(l / 9.81) + scatter * noise.next());
  }
  return trials;
}

}  // namespace

TEST_CASE("Monte Carlo refits a series: t-distributed periods widen g as t's variance says", "[uncertainty][monte_carlo]") {
  // Ten trials per length: each period is t with 9 degrees of freedom, whose
  // variance is 9/7 of u^2 (S1 6.4.9); the length and amplitude normal. g is
  // linear enough in them here (relative uncertainties ~1e-3), so the draws'
  // variance is the budget's rows, each t row times nu/(nu - 2).
  NormalDeviates noise(40);
  const ParsedScene s = parse_scene(series_scene(kSeriesLengths, series_trials(10, 0.1, noise)).dump());
  const Analysis a = reduce_scene(s);
  double variance = 0.0;
  for (const BudgetEntry& b : a.budget) {
    const double nu = b.evaluation.dof;
    variance += b.contribution * b.contribution * (b.evaluation.distribution == Distribution::student_t ? nu / (nu - 2.0) : 1.0);
  }
  // 10^5 draws place the interval's ends to ~1.1 u M^(-1/3) = 0.024 u,
  // within delta (0.031 u here), so that the check judges.
  constexpr long kDraws = 100000;
  const std::optional<MonteCarloResult> mc = monte_carlo(s, a, MonteCarloOptions{3, kDraws});
  REQUIRE(mc);
  INFO("GUM " << a.g.value << " +- " << *a.g.uncertainty << "; MC " << mc->mean << " +- " << mc->standard_uncertainty
              << ", expected u " << std::sqrt(variance));
  CHECK(mc->draws == kDraws);
  // The standard error of a standard deviation from N draws: u sqrt((1 +
  // kurtosis/2)/(2N)), t_9's excess kurtosis 6/5: 0.0028 of u; four of them.
  CHECK_THAT(mc->standard_uncertainty, WithinRel(std::sqrt(variance), 0.0114));
  CHECK_THAT(mc->mean, WithinAbs(a.g.value, 4.0 * mc->standard_uncertainty / std::sqrt(double(kDraws))));
  // Five periods' t tails are wider than Welch-Satterthwaite's nu_eff gives
  // them: the check names the periods together, as the table groups them.
  CHECK_FALSE(mc->validated);
  CHECK(mc->bending_input == "observations[].timing.period");
  CHECK(mc->bending_name == "5 observations' timing.period");
}

TEST_CASE("Monte Carlo of a series scaled by its Birge ratio draws the excess scatter as a multivariate t",
          "[uncertainty][monte_carlo]") {
  // One trial per length, its stated uncertainty 0.01 s against a 0.05 s
  // scatter: chi2/dof ~ 25 and the fit scales its uncertainty by S. With only
  // the periods uncertain and g linear in them, g - g_fit is u z +
  // sqrt(S^2 - 1) u t_4 (u the stated periods' share of u(g), z normal, t_4
  // the excess with the fit's n - p degrees of freedom). Its 97.5 % quantile
  // q solves P(u z + c t_4 <= q) = integral of Phi((q - c t)/u) f_4(t) dt =
  // 0.975, f_4(t) = (3/8)(1 + t^2/4)^(-5/2): Simpson's rule over |t| < 400
  // (t_4's tail beyond holds 4e-10) and bisection.
  NormalDeviates noise(41);
  nlohmann::json doc = series_scene(kSeriesLengths, series_trials(1, 0.05, noise));
  // Each length stated to 1 nm: a scatter of the periods, not of lengths
  // read without an uncertainty (those would fit tau, docs/series.md).
  for (auto& o : doc["observations"]) {
    o["timing"]["uncertainty"] = 0.01;
    o["length"]["uncertainty"] = 1e-9;
    o["amplitude"].erase("uncertainty");
  }
  const ParsedScene s = parse_scene(doc.dump());
  const Analysis a = reduce_scene(s);
  REQUIRE(a.fit.scaled);
  REQUIRE_FALSE(a.fit.length_scatter);
  const std::optional<MonteCarloResult> mc = monte_carlo(s, a, MonteCarloOptions{5, 40000});
  REQUIRE(mc);
  const double u = *a.g_uncertainty_unscaled, c = std::sqrt(std::pow(*a.fit.birge_ratio, 2) - 1.0) * u;
  const auto below = [&](double q) {
    constexpr int kSteps = 400000;
    constexpr double kSpan = 400.0, h = 2.0 * kSpan / kSteps;
    double p = 0.0;
    for (int i = 0; i <= kSteps; ++i) {
      const double t = -kSpan + i * h, w = (i == 0 || i == kSteps) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      p += w * 0.5 * std::erfc(-(q - c * t) / (u * std::sqrt(2.0))) * 0.375 * std::pow(1.0 + t * t / 4.0, -2.5);
    }
    return p * h / 3.0;
  };
  double low = 0.0, high = 10.0 * (u + c);
  for (int i = 0; i < 60; ++i) (below(0.5 * (low + high)) < 0.975 ? low : high) = 0.5 * (low + high);
  INFO("S " << *a.fit.birge_ratio << ", u(g) " << *a.g.uncertainty << ", MC [" << mc->low << ", " << mc->high
            << "], expected half-width " << low);
  // The interval's ends from 40000 draws are good to ~1 %.
  CHECK_THAT((mc->high - mc->low) / 2.0, WithinRel(low, 0.03));
}

namespace {

/// Six lengths, one trial of ten oscillations each stated to 0.01 s and
/// scattering `scatter` (s) about g = 9.81 m/s^2; lengths +- 0.5 mm, the
/// amplitude as given (deg).
nlohmann::json scattered_series(double scatter, double amplitude, double amplitude_sigma, NormalDeviates& noise) {
  nlohmann::json observations = nlohmann::json::array();
  for (const double l : {0.4, 0.6, 0.8, 1.0, 1.2, 1.4}) {
    observations.push_back(
        {{"length", {{"value", l}, {"uncertainty", 0.0005}, {"unit", "m"}}},
         {"amplitude", {{"value", amplitude}, {"uncertainty", amplitude_sigma}, {"unit", "deg"}}},
         {"timing",
          {{"oscillations_per_trial", 10},
           {"unit", "s"},
           {"uncertainty", 0.01},
           {"trials", {20.0 * kPi * std::sqrt(l / 9.81) + scatter * noise.next()}}}}});
  }
  return {{"schema", "pendulum-g/scene/1"}, {"observations", observations}};
}

}  // namespace

TEST_CASE("Monte Carlo of a Birge-scaled series puts the excess scatter on the periods, not on every input",
          "[uncertainty][monte_carlo]") {
  NormalDeviates noise(42);
  SECTION("g linear in its inputs: the draws' u is the scaled budget's, the excess's share as t_5's variance") {
    // Periods stated to 1e-3 s (and lengths to 0.5 mm) against a 6e-3 s
    // scatter, six lengths and g fitted alone: n - p = 5 and S = 2.3 with
    // this seed (0.03 s gave S = 1.2, not scaled). The draws' variance is the budget's
    // rows (all normal) plus the excess (S^2 - 1) u_obs^2 (u_obs the share
    // the fit's weights give, uncertainty_from_observations) times t_5's
    // variance 5/3. Drawing every observation's own inputs S times wider
    // made it S^2 u_obs^2 5/3 instead.
    const ParsedScene s = parse_scene(scattered_series(0.06, 5.0, 0.5, noise).dump());
    const Analysis a = reduce_scene(s);
    REQUIRE(a.fit.scaled);
    REQUIRE(a.fit.dof == 5);
    const double s2 = std::pow(*a.fit.birge_ratio, 2), u_obs = *a.fit.parameters[0].uncertainty_from_observations;
    double variance = (s2 - 1.0) * u_obs * u_obs * 5.0 / 3.0;
    for (const BudgetEntry& b : a.budget) variance += b.contribution * b.contribution;
    constexpr long kDraws = 100000;
    const std::optional<MonteCarloResult> mc = monte_carlo(s, a, MonteCarloOptions{13, kDraws});
    REQUIRE(mc);
    INFO("S " << std::sqrt(s2) << ", GUM u " << *a.g.uncertainty << "; MC u " << mc->standard_uncertainty
              << ", expected " << std::sqrt(variance));
    // A standard deviation from N draws: relative standard error
    // sqrt((2 + kurtosis)/(4N)), t_5's excess kurtosis 6 at most: 0.45 %; four of them.
    CHECK_THAT(mc->standard_uncertainty, WithinRel(std::sqrt(variance), 4.0 * std::sqrt(8.0 / (4.0 * kDraws))));
  }
  SECTION("the amplitude keeps its own uncertainty: g's curvature bias is g sigma^2/8, not g S^2 sigma^2/8") {
    // The amplitude 3 +- 2 deg at every length: g goes as f(theta0)^2, f =
    // 2K(sin(theta0/2))/pi, so each draw's g is g_fit f(theta)^2/f(theta0)^2
    // to first order in the periods, and the mean E[f(theta)^2]/f(theta0)^2
    // - 1 ~ sigma^2/8 of g (1.5e-3 m/s^2 here), by Simpson's rule over
    // theta0 + sigma z, |z| < 10. Widened S
    // times (S = 2.4) it was S^2 times that. The periods' own curvature (g
    // as 1/T^2) adds 3 u^2/(4 g), u the draws' deviation (~1e-5 m/s^2).
    const ParsedScene s = parse_scene(scattered_series(0.06, 3.0, 2.0, noise).dump());
    const Analysis a = reduce_scene(s);
    REQUIRE(a.fit.scaled);
    const double theta0 = 3.0 * kPi / 180.0, sigma = 2.0 * kPi / 180.0;
    const auto f2 = [](double theta) { return std::pow(2.0 * std::comp_ellint_1(std::sin(theta / 2.0)) / kPi, 2); };
    constexpr int kIntervals = 4000;
    double mean = 0.0;
    for (int i = 0; i <= kIntervals; ++i) {
      const double z = -10.0 + 20.0 * i / kIntervals, w = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      mean += w * f2(theta0 + sigma * z) * std::exp(-0.5 * z * z) / std::sqrt(2.0 * kPi) * (20.0 / kIntervals) / 3.0;
    }
    constexpr long kDraws = 40000;
    const std::optional<MonteCarloResult> mc = monte_carlo(s, a, MonteCarloOptions{17, kDraws});
    REQUIRE(mc);
    const double expected = a.g.value * mean / f2(theta0) + 0.75 * std::pow(mc->standard_uncertainty, 2) / a.g.value;
    INFO("S " << *a.fit.birge_ratio << ", g " << a.g.value << "; MC mean " << mc->mean << " +- "
              << mc->standard_uncertainty / std::sqrt(double(kDraws)) << ", expected " << expected << " (bias "
              << expected - a.g.value << ")");
    CHECK_THAT(mc->mean, WithinAbs(expected, 4.0 * mc->standard_uncertainty / std::sqrt(double(kDraws))));
  }
}

TEST_CASE("Series of five lengths: the expanded interval covers g 95 % of the time", "[uncertainty][coverage]") {
  // The truth: g = 9.81 m/s^2; at each length the model's own period (each
  // noiseless observation reduced, T scaled by sqrt(g'/g) three times: g goes
  // as 1/T^2). Each experiment times 10 oscillations five times per length
  // with a hand's 0.1 s scatter and reads each length (+- 0.5 mm) and
  // amplitude (+- 0.5 deg) once. Each length's own s (4 dof) as its weight
  // covered 85.8 % (rms of (g - truth)/u 1.54): E[1/s^2] is twice 1/sigma^2;
  // the scatter pooled over the lengths (20 dof) is what covers.
  constexpr double kTrueG = 9.81, kHand = 0.1;
  std::vector<double> period;
  for (const double l : kSeriesLengths) period.push_back(2.0 * kPi * std::sqrt(l / kTrueG));
  for (int i = 0; i < 3; ++i) {
    for (std::size_t k = 0; k < period.size(); ++k) {
      const nlohmann::json one = stopwatch_scene({10 * period[k], 10 * period[k]}, kSeriesLengths[k], 5.0);
      period[k] *= std::sqrt(reduce_scene(parse_scene(one.dump())).g.value / kTrueG);
    }
  }
  NormalDeviates noise(20261207);
  constexpr int kExperiments = 1000;
  int covered = 0, pooled = 0;
  for (int e = 0; e < kExperiments; ++e) {
    std::vector<double> lengths;
    std::vector<std::vector<double>> trials;
    for (std::size_t k = 0; k < period.size(); ++k) {
      lengths.push_back(kSeriesLengths[k] + 0.0005 * noise.next());
      trials.emplace_back();
      for (int t = 0; t < 5; ++t) trials.back().push_back(10 * period[k] + kHand * noise.next());
    }
    nlohmann::json doc = series_scene(lengths, trials);
    for (auto& o : doc["observations"]) o["amplitude"]["value"] = 5.0 + 0.5 * noise.next();
    const ParsedScene s = parse_scene(doc.dump());
    pooled += evaluation_of(s.evaluations, "observations[0].timing.period").shared == SharedVariance::pooled_trials;
    const Analysis a = reduce_scene(s);
    covered += std::abs(a.g.value - kTrueG) <= a.g_expanded->expanded;
  }
  // Bartlett's test refutes equal scatter 1 % of the time when it is equal.
  CHECK(pooled >= 0.97 * kExperiments);
  // Binomial standard error of a 95 % rate over 1000: sqrt(0.95 x 0.05/1000) = 0.0069.
  const double rate = double(covered) / kExperiments;
  INFO("expanded: " << rate << ", pooled " << pooled);
  CHECK_THAT(rate, WithinAbs(0.95, 3 * 0.0069));
}

TEST_CASE("Monte Carlo refits a physical pendulum: Kater's, every input normal", "[uncertainty][monte_carlo]") {
  // The two pivots' periods drawn as normals too (their t_2 has no
  // variance): the draws' u is GUM's, and their mean is g plus the amplitude's
  // curvature, g sigma_theta^2/8 (g goes as (1 + theta0^2/8) near 0 with
  // theta0 = 1 +- 0.2 deg at both pivots).
  ParsedScene s = parse_scene(test::read_text(std::string(PENDULUM_DATA_DIR) + "/kater_reversible_pendulum.json"));
  s.evaluations.clear();
  const Analysis a = reduce_scene(s);
  constexpr long kDraws = 40000;
  const std::optional<MonteCarloResult> mc = monte_carlo(s, a, MonteCarloOptions{9, kDraws});
  REQUIRE(mc);
  const double sigma = 0.2 * kPi / 180.0, curvature = a.g.value * sigma * sigma / 8.0;
  INFO("GUM " << a.g.value << " +- " << *a.g.uncertainty << "; MC " << mc->mean << " +- " << mc->standard_uncertainty
              << "; curvature " << curvature);
  CHECK_THAT(mc->standard_uncertainty, WithinRel(*a.g.uncertainty, 0.02));
  CHECK_THAT(mc->mean, WithinAbs(a.g.value + curvature, 4.0 * mc->standard_uncertainty / std::sqrt(double(kDraws))));
}

TEST_CASE("Monte Carlo: too few draws judge nothing, and name no input", "[uncertainty][monte_carlo]") {
  // Nelson & Olsson's scene, every input normal: g's distribution is near
  // normal, u = 0.0016 m/s^2 and delta = 5e-5 m/s^2. The ends of a shortest
  // interval of M draws scatter as ~1.1 u M^(-1/3) (docs/uncertainty.md), so
  // 1000 draws place them to ~2e-4 m/s^2, four times delta.
  ParsedScene s = parse_scene(test::nelson_olsson_text());
  s.evaluations.clear();
  const Analysis a = reduce_scene(s);
  const std::optional<MonteCarloResult> few = monte_carlo(s, a, MonteCarloOptions{3, 1000});
  REQUIRE(few);
  INFO("ends +- " << few->low_uncertainty << ", " << few->high_uncertainty << "; tolerance " << few->tolerance);
  CHECK_FALSE(few->judged);
  CHECK_FALSE(few->validated);
  CHECK(few->bending_input.empty());
  CHECK(std::max(few->low_uncertainty, few->high_uncertainty) > few->tolerance);
  CHECK(few->draws_to_judge > 1000);
  AnalysisOptions options;
  options.monte_carlo = MonteCarloOptions{3, 1000};
  const Analysis said = reduce_scene(s, options);
  const auto unjudged = std::find_if(said.warnings.begin(), said.warnings.end(), [](const std::string& w) {
    return w.find("too few to judge GUM's interval") != std::string::npos;
  });
  CHECK(unjudged != said.warnings.end());

  // The ends' stated uncertainty against their spread over 40 independent
  // runs of 2000 draws: a standard deviation from 40 has a relative standard
  // error of 1/sqrt(78) = 11 %, and the stated one is the mean of 40 batch
  // estimates (each ~25 % from 10 batches): three of each, 0.39.
  double sum = 0.0, square = 0.0, stated = 0.0;
  constexpr int kRuns = 40;
  for (int run = 0; run < kRuns; ++run) {
    const std::optional<MonteCarloResult> r = monte_carlo(s, a, MonteCarloOptions{100u + run, 2000});
    sum += r->low;
    square += r->low * r->low;
    stated += r->low_uncertainty / kRuns;
  }
  const double spread = std::sqrt((square - sum * sum / kRuns) / (kRuns - 1));
  INFO("low end: spread over runs " << spread << ", stated " << stated << "; a quantile's 2.67 u/sqrt(M) "
                                    << 2.67 * *a.g.uncertainty / std::sqrt(2000.0));
  CHECK_THAT(stated, WithinRel(spread, 0.39));
}

TEST_CASE("Monte Carlo ends placed by fewer than two batches: null in JSON",
          "[uncertainty][monte_carlo]") {
  // end_uncertainty is infinite from fewer than two batches of kept draws
  // (monte_carlo.cpp): the writer refused the infinity (require_finite: an
  // internal error, exit 3).
  const ParsedScene s = parse_scene(test::nelson_olsson_text());
  Analysis a = reduce_scene(s);
  a.monte_carlo = monte_carlo(s, a, MonteCarloOptions{3, 1000});
  REQUIRE(a.monte_carlo);
  a.monte_carlo->low_uncertainty = a.monte_carlo->high_uncertainty = std::numeric_limits<double>::infinity();
  a.monte_carlo->judged = a.monte_carlo->validated = false;
  a.monte_carlo->draws_to_judge = 0;
  const auto doc = nlohmann::json::parse(result_json(s, a, AnalysisOptions{}, "scene.json"));
  const auto& mc = doc.at("g").at("monte_carlo");
  CHECK(mc.at("coverage_interval_uncertainty_m_s2") == nlohmann::json::array({nullptr, nullptr}));
  CHECK(mc.at("draws_to_judge").is_null());
}

TEST_CASE("Monte Carlo counts the draws it drops", "[uncertainty][monte_carlo]") {
  // An amplitude of 170 +- 10 deg (normal): a draw past 180 deg is no swing,
  // P(z > 1) = 0.158655 of the attempts (the normal's tail), each counted
  // outside the model's domain, and the warning says so.
  nlohmann::json doc = stopwatch_scene({40.1, 40.2, 40.0}, 1.0, 170.0);
  doc["amplitude"]["uncertainty"] = 10.0;
  ParsedScene s = parse_scene(doc.dump());
  s.evaluations.clear();
  AnalysisOptions options;
  options.monte_carlo = MonteCarloOptions{5, 20000};
  const Analysis a = reduce_scene(s, options);
  REQUIRE(a.monte_carlo);
  const MonteCarloResult& mc = *a.monte_carlo;
  const double attempts = double(mc.draws + mc.rejected_draws);
  INFO("rejected " << mc.rejected_draws << " of " << attempts);
  CHECK(mc.draws == 20000);
  CHECK(mc.rejected_by_reason[static_cast<int>(Rejection::outside_domain)] == mc.rejected_draws);
  // Binomial standard error of 0.1587 over ~24000 attempts: 0.0024; four of them.
  CHECK_THAT(mc.rejected_draws / attempts, WithinAbs(0.158655, 4 * 0.0024));
  const auto said = std::find_if(a.warnings.begin(), a.warnings.end(), [](const std::string& w) {
    return w.find("gave no g and were dropped") != std::string::npos;
  });
  CHECK(said != a.warnings.end());
}

TEST_CASE("GUM's interval without an input is the analysis's own with none held out", "[uncertainty][monte_carlo]") {
  // One function forms nu_eff for both: the pooled periods one component,
  // a Birge ratio's share one with the fit's dof, a decay fit's alpha and
  // beta one. Summing the rows one by one gave each pooled row the pool's
  // dof (nu_eff far too large) and dropped the Birge share.
  NormalDeviates noise(43);
  const auto same = [](const ParsedScene& s) {
    const Analysis a = reduce_scene(s);
    REQUIRE(a.g_expanded);
    CHECK_THAT(expanded_without(a, {}), WithinRel(a.g_expanded->expanded, 1e-12));
  };
  SECTION("pooled trials") {
    const ParsedScene s = parse_scene(series_scene(kSeriesLengths, series_trials(5, 0.1, noise)).dump());
    REQUIRE(evaluation_of(s.evaluations, "observations[0].timing.period").shared == SharedVariance::pooled_trials);
    same(s);
  }
  SECTION("a Birge-scaled fit") {
    const ParsedScene s = parse_scene(scattered_series(0.03, 5.0, 0.5, noise).dump());
    REQUIRE(reduce_scene(s).fit.scaled);
    same(s);
  }
  SECTION("a decay fit's correlated alpha and beta") {
    same(parse_scene(test::read_text(std::string(PENDULUM_DATA_DIR) + "/nelson_olsson_1986_decay.json")));
  }
  SECTION("the lengths' fitted scatter, one estimate over every observation") {
    nlohmann::json doc = scattered_series(0.03, 5.0, 0.5, noise);
    for (auto& o : doc["observations"]) o["length"].erase("uncertainty");
    const ParsedScene s = parse_scene(doc.dump());
    REQUIRE(reduce_scene(s).fit.length_scatter);
    same(s);
  }
}
