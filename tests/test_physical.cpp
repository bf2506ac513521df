// The physical pendulum's period model (models/physical_pendulum.hpp) through
// the core's fit: pivot scans and Kater's reversible pendulum, on synthetic
// scenes drawn from the model (pivot_scan_simulation.hpp).

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "pendulum/reduce_scene.hpp"
#include "pendulum/period_fit.hpp"
#include "simulations/pivot_scan_simulation.hpp"
#include "pendulum/json/scene_json.hpp"
#include "reference.hpp"
#include "scene_files.hpp"
#include "simulated_scans.hpp"
// Last: glog (through Ceres, period_fit.hpp) defines CHECK as an abort, and
// Catch's CHECK, defined after it, must be the one the tests use.
#include <catch2/catch.hpp>

using namespace pendulum;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

const ParameterResult& parameter(const Analysis& a, const std::string& name) {
  for (const auto& p : a.fit.parameters) {
    if (name == p.name) return p;
  }
  throw std::logic_error("no parameter " + name);
}

AnalysisOptions exact() {
  AnalysisOptions options;
  options.reduction.amplitude_method = AmplitudeMethod::agm;
  return options;
}

/// Kater's pendulum: k = 0.28 m, one pivot 0.25 m above the centre, the
/// other below it; the centre located to 1 mm (balanced on an edge), the
/// periods to 10 us, 2 deg.
PivotScanSimulation kater(double second_pivot, std::uint64_t seed) {
  PivotScanSimulation sim;
  sim.g = 9.80123;
  sim.radius_of_gyration = 0.28;
  sim.center_of_mass_position = 0.5;
  sim.pivot_positions = {0.25, second_pivot};
  sim.amplitudes = {2.0 * test::kDegree, 2.0 * test::kDegree};
  sim.period_sigma = 1e-5;
  sim.position_sigma = 2e-5;
  sim.amplitude_sigma = 0.1 * test::kDegree;
  sim.center_sigma = 0.001;
  sim.seed = seed;
  return sim;
}

}  // namespace

TEST_CASE("Pivot scan: a noiseless metre stick gives back g, k and the centre", "[physical]") {
  PivotScanSimulation sim = test::metre_stick(1);
  sim.noise = false;
  const Analysis a = reduce_scene(simulate_pivot_scan({}, sim), exact());
  INFO(a.fit.termination);
  CHECK(a.fit.converged);
  CHECK(a.fit.model == std::string("physical_pendulum"));
  CHECK_THAT(a.g.value, WithinRel(sim.g, 1e-12));
  CHECK_THAT(parameter(a, "radius_of_gyration").value, WithinAbs(sim.radius_of_gyration, 1e-12));
  CHECK_THAT(parameter(a, "center_of_mass_position").value, WithinAbs(sim.center_of_mass_position, 1e-12));
  // The curve's minimum is 2 pi sqrt(2k/g) at h = k (d/dh (k^2 + h^2)/h = 0).
  REQUIRE(a.fit.results_of<PhysicalPendulum>());
  const PivotScan& scan = *a.fit.results_of<PhysicalPendulum>();
  REQUIRE(scan.minimum_period);
  CHECK_THAT(scan.minimum_period->value,
             WithinRel(2 * kPi * std::sqrt(2 * sim.radius_of_gyration / sim.g), 1e-12));
  REQUIRE(scan.minimum_pivot_positions.size() == 2);
  CHECK_THAT(scan.minimum_pivot_positions[1].value,
             WithinAbs(sim.center_of_mass_position + sim.radius_of_gyration, 1e-12));
  // Each pivot's conjugate has its period: 2 pi sqrt(l/g) at h' = k^2/h
  // from the body (bodies.hpp) equals the observation's ideal period.
  const double h0 = sim.center_of_mass_position - sim.pivot_positions[0];
  const double conjugate = sim.radius_of_gyration * sim.radius_of_gyration / h0;
  CHECK_THAT(scan.conjugates[0].pivot_distance.value, WithinRel(conjugate, 1e-11));
  CHECK_THAT(scan.conjugates[0].pivot_position->value, WithinAbs(sim.center_of_mass_position + conjugate, 1e-11));
  CHECK_THAT(2 * kPi * std::sqrt(equivalent_length(sim.radius_of_gyration, conjugate) / sim.g),
             WithinRel(a.observations[0].period_ideal.value, 1e-12));
  CHECK_THAT(scan.conjugates[0].equivalent_length.value, WithinRel(h0 + conjugate, 1e-11));
}

TEST_CASE("Kater: the generic fit and Bessel's formula agree to 1e-12", "[physical][kater]") {
  // The second pivot at the first's conjugate, k^2/h1 = 0.3136 m below the
  // centre: equal periods but for the noise; the centre recorded off by
  // N(0, 1 mm).
  const ParsedScene scene = simulate_pivot_scan({}, kater(0.8136, 3));
  const Analysis a = reduce_scene(scene, exact());
  CHECK(a.fit.converged);
  // Bessel on the ideal periods: the measured ones over 2K(sin(A/2))/pi,
  // with K from std::comp_ellint_1 (modulus k), and the recorded centre.
  const double center = *scene.apparatus.body->center_of_mass_position;
  auto ideal = [&](int i) {
    const auto& o = scene.observations[i];
    return o.period * kPi / (2 * std::comp_ellint_1(std::sin(o.amplitude / 2)));
  };
  const double t1 = ideal(0), t2 = ideal(1);
  const double h1 = center - scene.observations[0].length, h2 = scene.observations[1].length - center;
  const double bessel = 8 * kPi * kPi / ((t1 * t1 + t2 * t2) / (h1 + h2) + (t1 * t1 - t2 * t2) / (h1 - h2));
  CHECK_THAT(a.g.value, WithinRel(bessel, 1e-12));
  const PivotScan* scan = a.fit.results_of<PhysicalPendulum>();
  REQUIRE((scan && scan->bessel_g));
  CHECK_THAT(*scan->bessel_g, WithinRel(bessel, 1e-12));
  // Why the method works: the rough centre's sensitivity is Bessel's
  // derivative, dg/dx_c = 2 g^2 (T1^2 - T2^2) / (8 pi^2 (h1 - h2)^2), which
  // T1 ~ T2 makes small.
  const double dgdx = 2 * bessel * bessel * (t1 * t1 - t2 * t2) / (8 * kPi * kPi * (h1 - h2) * (h1 - h2));
  bool found = false;
  for (const auto& b : a.budget) {
    if (b.input != "center_of_mass_position") continue;
    found = true;
    CHECK_THAT(b.sensitivity, WithinRel(dgdx, 1e-6));
  }
  CHECK(found);
  for (const auto& w : a.warnings) CHECK_THAT(w, !Contains("kater:"));
}

TEST_CASE("Kater: a warning when T1 and T2 are too far apart", "[physical][kater]") {
  // h2 = 0.45 m against the conjugate 0.3136 m: T1^2 - T2^2 no longer small.
  const Analysis a = reduce_scene(simulate_pivot_scan({}, kater(0.95, 3)), exact());
  bool warned = false;
  for (const auto& w : a.warnings) warned = warned || w.find("kater: the periods differ") != std::string::npos;
  CHECK(warned);
  CHECK(a.budget.front().input == "center_of_mass_position");
}

TEST_CASE("Pivot scans: +-1 sigma holds the truth 68% of the time", "[physical][coverage]") {
  // 400 scans (seeds 1000-1399). If the propagated uncertainties are right,
  // each count inside +-1 sigma is Binomial(400, 0.6827): mean 273.1,
  // standard deviation 9.3; the test allows 3.5 standard deviations. The
  // mean chi2 is dof = 15 with a standard error of sqrt(2 dof / 400) = 0.27.
  const int n = 400;
  int g_in = 0, g_unscaled_in = 0, k_in = 0, c_in = 0;
  double chi2 = 0.0;
  for (int s = 0; s < n; ++s) {
    const PivotScanSimulation sim = test::metre_stick(1000 + s);
    const Analysis a = reduce_scene(simulate_pivot_scan({}, sim));
    REQUIRE(a.fit.converged);
    g_in += std::abs(a.g.value - sim.g) <= *a.g.uncertainty;
    g_unscaled_in += std::abs(a.g.value - sim.g) <= *a.g_uncertainty_unscaled;
    const ParameterResult& k = parameter(a, "radius_of_gyration");
    k_in += std::abs(k.value - sim.radius_of_gyration) <= *k.uncertainty;
    const ParameterResult& c = parameter(a, "center_of_mass_position");
    c_in += std::abs(c.value - sim.center_of_mass_position) <= *c.uncertainty;
    chi2 += a.fit.chi2 / n;
  }
  INFO("g " << g_in << ", k " << k_in << ", centre " << c_in << " of " << n << "; mean chi2 " << chi2);
  CHECK(std::abs(g_in - 273.1) <= 3.5 * 9.3);
  CHECK(std::abs(k_in - 273.1) <= 3.5 * 9.3);
  CHECK(std::abs(c_in - 273.1) <= 3.5 * 9.3);
  CHECK_THAT(chi2, WithinAbs(15.0, 5 * 0.27));
  // The Birge ratio, applied only where chi2 is improbable, leaves honest
  // coverage as it was: within one binomial standard deviation.
  INFO("unscaled " << g_unscaled_in);
  CHECK(g_in - g_unscaled_in <= 9.3);
}

TEST_CASE("Pivot scans whose sigmas are 3 times too small: the scaled sigma covers g 60% of the time",
          "[physical][coverage][dispersion]") {
  // 400 scans (seeds 1000-1399), every stated sigma divided by 3: unscaled
  // +-1 sigma holds g 26% of the time, scaled P(|t_15| < 1) = 0.67.
  const int n = 400;
  const test::Coverage c = test::coverage_of_g(
      [](int s) { return simulate_pivot_scan({}, test::metre_stick(1000 + s)); }, n, test::metre_stick(0).g, 3.0);
  CHECK(c.scaled >= 0.6 * n);
  CHECK(c.unscaled < 0.35 * n);
}

TEST_CASE("A pivot scan at chi2/dof near 60 is suspect, with the scatter's sigma", "[physical][dispersion]") {
  ParsedScene scene = simulate_pivot_scan({}, test::metre_stick(11));
  test::understate(scene, std::sqrt(60.0));
  const Analysis a = reduce_scene(scene);
  INFO(a.fit.chi2 / a.fit.dof);
  REQUIRE(a.fit.birge_ratio);
  CHECK(a.fit.chi2 / a.fit.dof > 30.0);
  CHECK(a.status == ResultStatus::suspect);
  REQUIRE_FALSE(a.status_reasons.empty());
  CHECK_THAT(a.status_reasons.back(), Catch::Matchers::Contains("a pivot position misread"));
  CHECK_THAT(*a.g.uncertainty, WithinRel(*a.fit.birge_ratio * *a.g_uncertainty_unscaled, 0.01));
  CHECK_THAT(*parameter(a, "radius_of_gyration").uncertainty,
             WithinRel(*a.fit.birge_ratio * *parameter(a, "radius_of_gyration").uncertainty_unscaled, 0.01));
}

TEST_CASE("The pivot scan's textbook curve is in the fit, Kater's is Bessel's formula on the measured periods",
          "[physical][textbook]") {
  const ParsedScene scene = simulate_pivot_scan({}, kater(0.8136, 3));
  const Analysis a = reduce_scene(scene);
  const PivotScan* scan = a.fit.results_of<PhysicalPendulum>();
  REQUIRE((scan && scan->textbook));
  const auto& t = *scan->textbook;
  // Bessel's 8 pi^2/g = (T1^2 + T2^2)/(h1 + h2) + (T1^2 - T2^2)/(h1 - h2), on the periods as measured.
  const double c = *scene.apparatus.body->center_of_mass_position;
  const double T1 = scene.observations[0].period, T2 = scene.observations[1].period;
  const double h1 = std::abs(scene.observations[0].length - c), h2 = std::abs(scene.observations[1].length - c);
  const double bessel = 8.0 * kPi * kPi / ((T1 * T1 + T2 * T2) / (h1 + h2) + (T1 * T1 - T2 * T2) / (h1 - h2));
  CHECK_THAT(t.g.value, WithinRel(bessel, 1e-12));
  REQUIRE(t.g.uncertainty);
  CHECK(*t.g.uncertainty > 0.0);
  REQUIRE(t.center_of_mass_position);
  CHECK(*t.center_of_mass_position == c);
}

TEST_CASE("The bundled physical scenes are what their generator writes, and give back their truth",
          "[physical][data]") {
  for (const std::string name : {"metre_stick", "kater"}) {
    const std::string file_name = name == "kater" ? "kater_reversible_pendulum.json" : "metre_stick_pivot_scan.json";
    int status = 0;
    const std::string text = test::command_output(std::string(PENDULUM_MAKE_PHYSICAL_SCENES) + " " + name, status);
    REQUIRE(status == 0);
    // Trials are rounded; another libm may move one by a unit, so the scenes
    // are compared as read.
    const ParsedScene generated = parse_scene(text);
    const ParsedScene file = parse_scene(test::read_text(std::string(PENDULUM_DATA_DIR) + "/" + file_name));
    REQUIRE(generated.observations.size() == file.observations.size());
    for (std::size_t k = 0; k < file.observations.size(); ++k) {
      const double unit = name == "kater" ? 1e-4 / 50 / 3 : 0.01 / 10 / 5;
      CHECK_THAT(file.observations[k].period, WithinAbs(generated.observations[k].period, unit + 1e-12));
      CHECK(file.observations[k].length == generated.observations[k].length);
    }
    // The truth: the site's normal gravity within 3 of the fit's standard
    // uncertainties; the metre stick's k and centre those of its parts.
    const Analysis a = reduce_scene(file);
    INFO(name);
    REQUIRE(a.expected_g);
    CHECK(std::abs(a.g.value - a.expected_g->value) < 3 * *a.g.uncertainty);
    if (name == "metre_stick") {
      const ParameterResult& k = parameter(a, "radius_of_gyration");
      CHECK(std::abs(k.value - *file.body_from_parts->radius_of_gyration) < 3 * *k.uncertainty);
    } else {
      const PivotScan* scan = a.fit.results_of<PhysicalPendulum>();
      REQUIRE((scan && scan->bessel_g));
      CHECK_THAT(*scan->bessel_g, WithinRel(a.g.value, 1e-12));
    }
  }
}

namespace {

/// A brass-weighted steel rod as a scene of one pivot: the body in parts,
/// k and the centre from them, the closed form of one observation.
std::string rod_scene(const std::string& extra) {
  return R"({
    "pivot_position": {"value": 0.05, "uncertainty": 0.0002, "unit": "m"},
    "amplitude": {"value": 3, "uncertainty": 0.5, "unit": "deg"},
    "timing": {"oscillations_per_trial": 20, "unit": "s", "resolution": 0.01, "trials": [37.58, 37.6, 37.59]},
    "body": {"parts": [
      {"shape": "cylinder", "radius": {"value": 6, "unit": "mm"}, "length": {"value": 1.2, "unit": "m"},
       "axis": "body", "density": {"value": 7850, "unit": "kg/m^3"}, "position": {"value": 0.6, "unit": "m"}},
      {"shape": "cylinder", "radius": {"value": 30, "unit": "mm"}, "inner_radius": {"value": 6, "unit": "mm"},
       "length": {"value": 40, "unit": "mm"}, "axis": "body", "density": {"value": 8.5, "unit": "g/cm^3"},
       "position": {"value": 1.0, "unit": "m"}}]})" +
         extra + "}";
}

}  // namespace

TEST_CASE("One pivot of a body in parts: the closed form is Eq. (56) solved for g", "[physical]") {
  const ParsedScene scene = parse_scene(rod_scene(""));
  CHECK(scene.model == kind_of<PhysicalPendulum>());
  const Analysis a = reduce_scene(scene, exact());
  CHECK(a.fit.method == "closed_form");
  // Independently: the body's k and centre (bodies.hpp), then
  // g = 4 pi^2 l (2K/pi)^2 / T^2 with K from std::comp_ellint_1.
  const double steel = 7850 * kPi * 0.006 * 0.006 * 1.2, brass = 8500 * kPi * (0.03 * 0.03 - 0.006 * 0.006) * 0.04;
  const auto b = body_properties(std::vector<Part<double>>{
      make_part(cylinder(0.006, 0.0, 1.2, CylinderAxis::body_axis), steel, 0.6),
      make_part(cylinder(0.03, 0.006, 0.04, CylinderAxis::body_axis), brass, 1.0)});
  const double T = (37.58 + 37.6 + 37.59) / 3 / 20, A = 3 * test::kDegree;
  const double factor = 2 * std::comp_ellint_1(std::sin(A / 2)) / kPi;
  const double l = equivalent_length(b.radius_of_gyration, b.center - 0.05);
  CHECK_THAT(a.g.value, WithinRel(4 * kPi * kPi * l * factor * factor / (T * T), 1e-13));
}

TEST_CASE("Temperature: every length of the body scales by (1 + w C)/(1 + w C_ref), Eq. (41)", "[physical]") {
  // The same swing read at 20 degC and at 35 degC of a steel body (Kelley's
  // table, 1.1e-5 /K): l and so g grow by (1 + 35 w)/(1 + 20 w).
  const Analysis cold = reduce_scene(parse_scene(rod_scene(
      R"(, "temperature": {"value": 20, "unit": "degC"}, "reference_temperature": {"value": 20, "unit": "degC"},
          "material": "steel")")), exact());
  const Analysis warm = reduce_scene(parse_scene(rod_scene(
      R"(, "temperature": {"value": 35, "uncertainty": 0.5, "unit": "degC"},
          "reference_temperature": {"value": 20, "unit": "degC"}, "material": "steel")")), exact());
  const double w = 1.1e-5;
  CHECK_THAT(warm.g.value / cold.g.value, WithinRel((1 + 35 * w) / (1 + 20 * w), 1e-14));
  // The temperature's share of g: dg/dC = g w/(1 + w C) (K = degC steps).
  bool found = false;
  for (const auto& e : warm.budget) {
    if (e.input != "temperature") continue;
    found = true;
    CHECK_THAT(e.sensitivity, WithinRel(warm.g.value * w / (1 + 35 * w), 1e-9));
    CHECK(e.uncertainty == 0.5);
  }
  CHECK(found);
}

TEST_CASE("Pivot scan of a body in parts, k held and the centre fitted, gives back g", "[physical]") {
  // The metre stick's k as its parts give it (held), its centre fitted; the
  // start's line then runs through the origin in k^2 + h^2.
  PivotScanSimulation sim = test::metre_stick(5);
  sim.noise = false;
  Apparatus<double> app;
  app.body.emplace().radius_of_gyration = sim.radius_of_gyration;
  ParsedScene scene = simulate_pivot_scan(app, sim);
  scene.apparatus_uncertainty.body->radius_of_gyration = 0.0;
  scene.fit = {"center_of_mass_position"};
  const Analysis a = reduce_scene(scene, exact());
  CHECK(a.fit.converged);
  CHECK_THAT(a.g.value, WithinRel(sim.g, 1e-12));
  CHECK_THAT(parameter(a, "center_of_mass_position").value, WithinAbs(sim.center_of_mass_position, 1e-12));
  CHECK_FALSE(parameter(a, "radius_of_gyration").fitted);
  // Held, it is reported as the k the model used: the body's, not the default.
  CHECK(parameter(a, "radius_of_gyration").value == sim.radius_of_gyration);
}

TEST_CASE("Pivot scans: every fit ends by its own stopping rule in a few steps, below the cost's rounding",
          "[physical]") {
  // Near the optimum a Gauss-Newton step lowers the cost by less than the
  // rounding of the periods moves it (docs/core.md, Stopping); a monotonic
  // trust region then rejects such steps until Ceres's parameter tolerance
  // ends the fit (seed 32 took 10 iterations). Ten pivots 1 ms apart, as
  // bench_pivot_scan_fit's smallest. And the fit returns the point its rule
  // judged, not Ceres's least cost, which the same rounding can make an
  // earlier point: started there, a fit takes no step.
  int longest = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    PivotScanSimulation sim = test::metre_stick(seed);
    sim.pivot_positions.resize(10);
    sim.amplitudes.resize(10);
    sim.period_sigma = 1e-3;
    const ParsedScene scene = simulate_pivot_scan({}, sim);
    const Analysis a = reduce_scene(scene, exact());
    INFO("seed " << seed << ": " << a.fit.termination);
    CHECK(a.fit.converged);
    CHECK_THAT(a.fit.termination, Contains("SOLVER_TERMINATE_SUCCESSFULLY"));
    longest = std::max(longest, a.fit.iterations);

    const std::vector<AmplitudeChoice> amplitude(scene.observations.size(), {AmplitudeMethod::agm, 0, 0.0});
    const std::vector<double> weights(scene.observations.size(), 1.0 / sim.period_sigma);
    const PeriodFitProblem<PhysicalPendulum> problem{&scene.apparatus, &scene.observations, &amplitude, &weights,
                                                      {true, true, true}};
    const PeriodFitSolution first = fit_periods(problem, physical_start(scene, {true, true, true}));
    std::array<double, 3> optimum;
    std::copy(first.parameters.begin(), first.parameters.end(), optimum.begin());
    CHECK(fit_periods(problem, optimum).iterations == 0);
  }
  // 3 at most were measured over these seeds with non-monotonic steps; 5
  // leaves two for another platform's rounding, half a stall's 10.
  CHECK(longest <= 5);
}

namespace {

/// Rods of lengths `lengths` (m), each pivoted at its end and timed once at
/// 4 deg, in gravity g, with their ideal periods from the closed form
/// T = 2 pi sqrt(2L/(3g)) 2K(sin(A/2))/pi (Kelley Eqs. 45, 56), K from
/// std::comp_ellint_1, independent of the library's AGM.
std::string rod_series(const std::vector<double>& lengths, double g) {
  auto digits = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", x);
    return std::string(text);
  };
  const double A = 4 * test::kDegree, factor = 2 * std::comp_ellint_1(std::sin(A / 2)) / kPi;
  std::string observations;
  for (double L : lengths) {
    const double T = 2 * kPi * std::sqrt(2 * L / (3 * g)) * factor;
    observations += std::string(observations.empty() ? "" : ",") + R"({"rod_length": {"value": )" +
                    digits(L) + R"(, "uncertainty": 0.0005, "unit": "m"}, "timing": {"unit": "s",
                    "oscillations_per_trial": 1, "resolution": 1e-9, "trials": [)" + digits(T) + "]}}";
  }
  return R"({"amplitude": {"value": 4, "uncertainty": 0.5, "unit": "deg"}, "observations": [)" + observations + "]}";
}

}  // namespace

TEST_CASE("A series of rods pivoted at an end: each its own body, l = 2L/3 (Kelley Eq. 45)", "[physical][rods]") {
  const std::vector<double> lengths = {0.3, 0.5, 0.7, 0.9};
  const ParsedScene scene = parse_scene(rod_series(lengths, 9.81));
  CHECK(scene.model == kind_of<PhysicalPendulum>());
  const Analysis a = reduce_scene(scene, exact());
  INFO(a.fit.termination);
  CHECK(a.fit.converged);
  for (const ParameterResult& p : a.fit.parameters) CHECK(p.fitted == (std::string(p.name) == "g"));
  CHECK_THAT(a.g.value, WithinRel(9.81, 1e-10));
  REQUIRE(a.fit.results_of<PhysicalPendulum>());
  const PivotScan& scan = *a.fit.results_of<PhysicalPendulum>();
  // One body's minimum and k mean nothing for several rods.
  CHECK_FALSE(scan.minimum_period);
  REQUIRE(scan.textbook);
  CHECK_FALSE(scan.textbook->radius_of_gyration);
  // Without the finite-amplitude factor the textbook line's g is low by factor^2.
  const double factor = 2 * std::comp_ellint_1(std::sin(4 * test::kDegree / 2)) / kPi;
  const double gt = 9.81 / (factor * factor);
  CHECK_THAT(scan.textbook->g.value, WithinRel(gt, 1e-12));
  // Its uncertainty, the line T^2 h = a (h^2 + k^2) through the origin with
  // h = L/2, k^2 = L^2/12 (x = L^2/3, y = T^2 L/2, a = 4 pi^2/g): slope
  // sum c y, c = x/sum x^2, and y - a x moves by 2 T h dT + (T^2/2 - 2aL/3) dL.
  const double a_slope = 4 * kPi * kPi / gt, sigma_t = 1e-9 / std::sqrt(12.0), sigma_l = 0.0005;
  double sxx = 0.0, variance = 0.0;
  for (double L : lengths) sxx += std::pow(L * L / 3, 2);
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    const double L = lengths[i], T = scene.observations[i].period, c = L * L / 3 / sxx;
    variance += c * c * (std::pow(2 * T * (L / 2) * sigma_t, 2) + std::pow((T * T / 2 - 2 * a_slope * L / 3) * sigma_l, 2));
  }
  REQUIRE(scan.textbook->g.uncertainty);
  CHECK_THAT(*scan.textbook->g.uncertainty, WithinRel(gt * std::sqrt(variance) / a_slope, 1e-9));
  REQUIRE(scan.conjugates.size() == lengths.size());
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    CHECK_THAT(scan.conjugates[i].equivalent_length.value, WithinRel(2 * lengths[i] / 3, 1e-14));
    CHECK_THAT(scan.conjugates[i].pivot_distance.value, WithinRel(lengths[i] / 6, 1e-14));
  }
  // In air, the rods' buoyancy is skipped with a reason that fits rods (no parts to give).
  const ParsedScene aired = parse_scene(R"({"air": {"pressure": {"value": 100.44, "unit": "kPa"}, "temperature":
      {"value": 25.5, "unit": "degC"}, "molar_mass": {"value": 0.02896, "unit": "kg/mol"}, "viscosity": {"value":
      1.853e-05, "unit": "Pa s"}}, )" + rod_series(lengths, 9.81).substr(1));
  const Analysis in_air = reduce_scene(aired, exact());
  bool warned = false;
  for (const auto& w : in_air.warnings) warned |= w.find("the rods' densities are not known") != std::string::npos;
  CHECK(warned);
  // The rods' lengths' uncertainty is in g's budget (g grows with each L).
  bool found = false;
  for (const auto& e : a.budget) found |= e.input.find("rod_length") != std::string::npos && e.sensitivity > 0.0;
  CHECK(found);
}

TEST_CASE("A rod pivoted at its end is the thin rod of its parts hung at its end", "[physical][rods]") {
  // The same rod both ways: rod_length, and a body of one thin_rod part with
  // a pivot_position at its end (bodies.hpp, derive_from_parts).
  const std::string timing = R"("amplitude": {"value": 6, "unit": "deg"},
      "timing": {"oscillations_per_trial": 1, "unit": "s", "resolution": 0.001, "trials": [1.3412, 1.3405, 1.3409]})";
  const Analysis rod = reduce_scene(parse_scene(R"({"rod_length": {"value": 0.66, "unit": "m"}, )" + timing + "}"), exact());
  const Analysis parts = reduce_scene(parse_scene(
      R"({"pivot_position": {"value": 0, "unit": "m"}, "body": {"parts": [{"shape": "thin_rod",
          "length": {"value": 0.66, "unit": "m"}, "mass": {"value": 0.2, "unit": "kg"},
          "position": {"value": 0.33, "unit": "m"}}]}, )" + timing + "}"), exact());
  CHECK(rod.fit.method == "closed_form");
  CHECK_THAT(rod.g.value, WithinRel(parts.g.value, 1e-14));
}
