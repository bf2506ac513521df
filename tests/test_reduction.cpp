// The whole reduction: Nelson & Olsson's Eqs. (5), (90), (91), what is
// skipped, and the propagation of the period's and length's uncertainties.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <string>

#include "pendulum/reduce_scene.hpp"
#include "simulations/decay_simulation.hpp"
#include "pendulum/json/scene_json.hpp"
#include "reference.hpp"
#include "catalogue.hpp"
#include "scene_files.hpp"

using namespace pendulum;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
const CorrectionRow& row(const Analysis& a, const std::string& id) {
  for (const auto& r : a.observations.front().corrections) {
    if (id == r.info.id) return r;
  }
  throw std::logic_error("no correction " + id);
}
}  // namespace

TEST_CASE("Nelson-Olsson: Eqs. (5), (90), (91)", "[reduction][table2]") {
  const Analysis a = reduce_scene(parse_scene(test::nelson_olsson_text()));
  // Eq. (5): g = 9.8007 +- 0.0014 m/s^2 with T0 = T (only T and l enter).
  const TextbookFit* textbook = a.fit.results_of<SimplePendulum>();
  REQUIRE(textbook);
  CHECK(a.fit.results_of<PhysicalPendulum>() == nullptr);  // the fit is the ball's
  CHECK_THAT(textbook->g.value, WithinAbs(9.8007, 0.00005));
  CHECK_THAT(*textbook->g.uncertainty, WithinAbs(0.0014, 0.00005));
  // Eq. (90): T0 = 3.47833 s.
  CHECK_THAT(a.observations.front().period_ideal.value, WithinAbs(3.47833, 0.000005));
  // Eq. (91): g = 9.8034 +- 0.0014 m/s^2, the uncertainty from T and l alone.
  CHECK_THAT(a.g.value, WithinAbs(9.8034, 0.00005));
  CHECK_THAT(*a.g_period_and_length_uncertainty, WithinAbs(0.0014, 0.00005));
  // Every stated uncertainty counts: the amplitude's +-0.3 deg adds to it.
  CHECK(*a.g.uncertainty > *a.g_period_and_length_uncertainty);
  CHECK(a.budget.at(2).input == "amplitude");
}

TEST_CASE("The rows and the amplitude cross term add up to T - T0 (Eqs. 6-7 as a product)", "[reduction]") {
  const Analysis a = reduce_scene(parse_scene(test::nelson_olsson_text()));
  const ObservationResult& o = a.observations.front();
  double sum_t = 0.0;
  REQUIRE(o.corrections.size() == kCorrectionCount);  // the cross term is negligible at 3 deg
  for (const auto& r : o.corrections) {
    REQUIRE(r.delta_T);
    sum_t += *r.delta_T;
  }
  CHECK_THAT(o.total_delta_T, WithinRel(sum_t + o.cross_term_delta_T, 1e-12));
  CHECK_THAT(o.period_measured.value - o.total_delta_T, WithinRel(o.period_ideal.value, 1e-15));
  // The bound at Nelson & Olsson's 3 deg: below 0.03 us, so Table II is unchanged.
  CHECK(std::abs(o.cross_term_delta_T) < 0.03e-6);
  // r_amplitude x (sum of the others): 596.0/3478326 x (473.7 - 596.0)/3478326 of T0.
  CHECK_THAT(o.cross_term_delta_T * 1e6, WithinAbs(-0.021, 0.001));
  // Delta g is linearised, so it matches g - g_uncorrected to second order.
  CHECK_THAT(a.g.value - a.fit.results_of<SimplePendulum>()->g.value, WithinRel(o.total_delta_g, 1e-3));
}

TEST_CASE("Corrections under a tenth of the period's uncertainty are flagged negligible",
          "[reduction]") {
  const Analysis a = reduce_scene(parse_scene(test::nelson_olsson_text()));
  for (const char* id : {"wire_flexibility", "bob_rotation", "double_pendulum", "linear_damping",
                         "quadratic_damping", "wire_stretch", "support_motion"}) {
    INFO(id);
    CHECK(row(a, id).status == Status::negligible);
  }
  for (const char* id : {"finite_amplitude", "bob_radius", "ring", "cap", "cap_screw", "wire_mass",
                         "buoyancy", "amplitude_decay", "added_mass"}) {
    INFO(id);
    CHECK(row(a, id).status == Status::applied);
  }
  const ObservationResult& o = a.observations.front();
  CHECK_THAT(o.negligible_below, WithinRel(0.1 * o.period_measured.uncertainty, 1e-15));
}

TEST_CASE("A bare scene computes only what it has", "[reduction]") {
  auto doc = nlohmann::json::parse(test::nelson_olsson_text());
  for (const char* part : {"ring", "cap", "cap_screw", "wire", "support", "decay"}) doc.erase(part);
  doc["air"] = "vacuum";
  const Analysis a = reduce_scene(parse_scene(doc.dump()));
  for (const auto& r : a.observations.front().corrections) {
    const std::string id = r.info.id;
    const bool present = id == "finite_amplitude" || id == "bob_radius" || id == "bob_rotation";
    INFO(id);
    CHECK((r.status != Status::skipped) == present);
    CHECK(r.delta_T.has_value() == present);
    if (!present) CHECK_FALSE(r.reason.empty());
  }
  CHECK(row(a, "buoyancy").reason == "the scene is in vacuum");
}

// A fit composes T/T0 once per observation when no applied correction reads
// the swing's length (period_fit.hpp): a correction marked as not reading it
// must not change with it. Each row is checked in every scene that applies it,
// Nelson & Olsson's and tests/valid_scenes.json's, and must apply in one: a new
// correction's part comes with a valid scene that has it.
// The support's Eq. (87), m g/(2 K l) with the working g = omega^2 l, reads
// the length but leaves m omega^2/(2 K): marked as reading it, the safe side.
// An angle of the body's (a sensor in the bob) reaches the amplitude and the
// damping rows as the pendulum's theta = c psi, c from the length
// (pendulum_over_body_angle): only where a bob on a string is, whose
// bob_radius row reads the length, so a fit still composes at every step.
TEST_CASE("The corrections marked reads_length are those that change with the swing's length", "[reduction][fit]") {
  std::array<int, kCorrectionCount> applied{};
  const SceneFiles files{std::string(PENDULUM_TESTS_DIR), true};
  for (const std::string& text : test::valid_scene_texts()) {
    const ParsedScene s = parse_scene(text, files);
    const Observation<double>& o = s.observations.front();
    const AmplitudeChoice amplitude = cheapest_amplitude_method(o.amplitude, 0.0);
    const Swing<double> swing = Swing<double>::of(o, 0.0);
    Swing<double> longer = swing;
    longer.length *= 1.25;
    const Terms<double> at = correction_terms(s.apparatus, swing, amplitude);
    const Terms<double> at_longer = correction_terms(s.apparatus, longer, amplitude);
    const bool body_angle = o.amplitude_of == AngleOf::body || (s.apparatus.decay && s.apparatus.decay->angle_of == AngleOf::body);
    const bool through_c = body_angle && pendulum_over_body_angle(s.apparatus, swing.length) != 1.0;
    CHECK_FALSE((through_c && !at[static_cast<int>(CorrectionId::bob_radius)].ratio));
    bool reads_length = false;
    for (int i = 0; i < kCorrectionCount; ++i) {
      INFO(s.title << ": " << kCorrections[i].id);
      REQUIRE(at[i].ratio.has_value() == at_longer[i].ratio.has_value());
      if (!at[i].ratio) continue;
      ++applied[i];
      reads_length |= kCorrections[i].reads_length;
      const bool changes = *at[i].ratio != *at_longer[i].ratio;
      if (!kCorrections[i].reads_length) {
        CHECK_FALSE((changes && !through_c));
      } else if (kCorrections[i].correction != CorrectionId::support_motion) {
        CHECK(changes);
      }
    }
    CHECK(corrections_read_length(s.apparatus, swing, amplitude) == reads_length);
  }
  for (int i = 0; i < kCorrectionCount; ++i) {
    INFO(kCorrections[i].id);
    CHECK(applied[i] > 0);
  }
  const ParsedScene s = parse_scene(test::nelson_olsson_text());
  const Swing<double> swing = Swing<double>::of(s.observations.front(), 0.0);
  Apparatus<double> damped_only;  // the amplitude and the damping rows read no length
  damped_only.decay = s.apparatus.decay;
  CHECK_FALSE(corrections_read_length(damped_only, swing, cheapest_amplitude_method(swing.amplitude, 0.0)));
}

namespace {
// An independent propagation: central differences of the double-precision
// reduction in each input, step 1e-3 of its uncertainty.
struct Propagated {
  double g, period_ideal;
};
/// Visits every scalar of the scene's one observation and its apparatus
/// with its uncertainty: f(path, value, uncertainty).
template <class S, class F>
void each_input(S& s, F&& f) {
  zip_observation(s.observations[0], s.observation_uncertainties[0],
                  [&](const Field& field, auto& x, const double& u) { f(std::string(field.path), x, u); });
  zip_apparatus(s.apparatus, s.apparatus_uncertainty,
                [&](const Field& field, auto& x, const double& u) { f(std::string(field.path), x, u); });
}

Propagated finite_difference_uncertainty(const ParsedScene& s) {
  double var_g = 0.0, var_t0 = 0.0;
  each_input(s, [&](const std::string& path, const double&, const double& u) {
    if (u == 0.0) return;
    auto shifted = [&](double h) {
      ParsedScene t = s;
      each_input(t, [&](const std::string& p, double& x, const double&) {
        if (p == path) x += h;
      });
      return reduce(t.apparatus, t.observations[0]);
    };
    const double h = 1e-3 * u;
    const auto up = shifted(h), down = shifted(-h);
    const double dg = (up.g - down.g) / (2 * h), dt0 = (up.period_ideal - down.period_ideal) / (2 * h);
    var_g += dg * dg * u * u;
    var_t0 += dt0 * dt0 * u * u;
  });
  return {std::sqrt(var_g), std::sqrt(var_t0)};
}
}  // namespace

TEST_CASE("The propagated uncertainties match finite differences", "[reduction][budget]") {
  // The exact amplitude method on both sides (default ReductionOptions).
  const ParsedScene s = parse_scene(test::nelson_olsson_text());
  AnalysisOptions exact;
  exact.reduction.amplitude_method = AmplitudeMethod::agm;
  const Analysis a = reduce_scene(s, exact);
  const Propagated fd = finite_difference_uncertainty(s);
  CHECK_THAT(*a.g.uncertainty, WithinRel(fd.g, 1e-6));
  CHECK_THAT(*a.observations.front().period_ideal.uncertainty, WithinRel(fd.period_ideal, 1e-6));
  // The budget adds in quadrature to the total.
  double quadrature = 0.0;
  for (const auto& b : a.budget) quadrature += b.contribution * b.contribution;
  CHECK_THAT(std::sqrt(quadrature), WithinRel(*a.g.uncertainty, 1e-14));
  // Every input the file gives an uncertainty for is in the budget, largest first.
  CHECK(a.budget.size() == 8);
  for (std::size_t i = 1; i < a.budget.size(); ++i) CHECK(a.budget[i - 1].contribution >= a.budget[i].contribution);
  // Close to the ideal pendulum's -2g/T and g/l.
  for (const auto& b : a.budget) {
    if (b.input == "timing.period") {
      CHECK_THAT(b.sensitivity, WithinRel(-2 * a.g.value / a.observations.front().period_ideal.value, 1e-3));
    }
    if (b.input == "length") CHECK_THAT(b.sensitivity, WithinRel(a.g.value / s.observations[0].length, 1e-3));
  }
}

TEST_CASE("Monte Carlo agrees with the linear propagation", "[reduction][budget]") {
  // 4000 scenes with every input drawn from N(value, uncertainty), seeded.
  // The sample standard deviation of g has a relative standard error of
  // 1/sqrt(2 x 4000) = 1.1%; the test allows 4.5%, which also covers the
  // curvature of the amplitude correction (relative sigma^2/(2 theta^2) = 0.5%).
  const ParsedScene s = parse_scene(test::nelson_olsson_text());
  const Analysis a = reduce_scene(s);
  NormalDeviates noise(20261122);
  const int n = 4000;
  double sum = 0.0, sum2 = 0.0;
  for (int k = 0; k < n; ++k) {
    ParsedScene t = s;
    each_input(t, [&](const std::string&, double& x, const double& u) { x += u * noise.next(); });
    const double g = reduce(t.apparatus, t.observations[0]).g;
    sum += g;
    sum2 += g * g;
  }
  const double mean = sum / n, sd = std::sqrt((sum2 - n * mean * mean) / (n - 1));
  const double sigma = *a.g.uncertainty;
  INFO("Monte Carlo: " << mean << " +- " << sd << "; propagated " << a.g.value << " +- " << sigma);
  CHECK_THAT(sd, WithinRel(sigma, 0.045));
  CHECK_THAT(mean, WithinAbs(a.g.value, 4 * sigma / std::sqrt(double(n))));
}

TEST_CASE("A decay fit's alpha-beta correlation enters the budget", "[reduction][budget]") {
  const ParsedScene s = parse_scene(test::read_text(std::string(PENDULUM_DATA_DIR) + "/nelson_olsson_1986_decay.json"));
  const Analysis a = reduce_scene(s);
  REQUIRE(a.budget_correlation);
  CHECK(a.budget_correlation->correlation < -0.9);
  double quadrature = a.budget_correlation->variance;
  for (const auto& b : a.budget) quadrature += b.contribution * b.contribution;
  CHECK_THAT(std::sqrt(quadrature), WithinRel(*a.g.uncertainty, 1e-12));
}

TEST_CASE("Amplitude methods differ by their truncation only", "[reduction]") {
  const ParsedScene s = parse_scene(test::nelson_olsson_text());
  AnalysisOptions small, exact;
  small.reduction.amplitude_method = AmplitudeMethod::small_angle;
  exact.reduction.amplitude_method = AmplitudeMethod::agm;
  const CorrectionRow exact_row = row(reduce_scene(s, exact), "finite_amplitude");
  const CorrectionRow small_row = row(reduce_scene(s, small), "finite_amplitude");
  CHECK(small_row.method == "small_angle");
  CHECK(exact_row.method == "agm");
  // 11 theta^4 / 3072 T0 = 0.094 us at 3 deg (Eq. 8, second term).
  const double difference_us = (*exact_row.delta_T - *small_row.delta_T) * 1e6;
  CHECK_THAT(difference_us, WithinAbs(0.094, 0.001));
  // Each bound covers the true error: theta^2/16's bound is (9/64) m^2 T0
  // with m = sin^2(1.5 deg), 0.23 us (amplitude_error_bound).
  REQUIRE(small_row.error_bound_delta_T);
  CHECK(*small_row.error_bound_delta_T * 1e6 >= difference_us);
  CHECK_THAT(*small_row.error_bound_delta_T * 1e6, WithinRel(0.2296, 1e-3));
  CHECK(*exact_row.error_bound_delta_T <= 1e-15 * *exact_row.delta_T * 1.0000001);
}

TEST_CASE("The automatic amplitude method is the cheapest within 1% of the period's uncertainty",
          "[reduction]") {
  ParsedScene s = parse_scene(test::nelson_olsson_text());
  // Nelson-Olsson: sigma_T = 169 us, so the budget is 1.69 us; theta0^2/16
  // is within 0.23 us at 3 deg.
  const CorrectionRow automatic = row(reduce_scene(s), "finite_amplitude");
  CHECK(automatic.method == "small_angle");
  double& sigma_t = s.observation_uncertainties[0].period;
  CHECK(*automatic.error_bound_delta_T < 0.01 * sigma_t);
  // A timing 100 times better leaves 0.0169 us: theta0^2/16 (0.23 us) and
  // Eq. (8) with 1 term (omitted A_2 m^2 T0 = 0.23 us) no longer fit; with 2
  // terms the omitted tail is A_3 m^3 T0 / (1 - m) = 1.1e-4 us.
  sigma_t /= 100.0;
  const CorrectionRow tight = row(reduce_scene(s), "finite_amplitude");
  CHECK(tight.method == "series");
  CHECK(tight.series_terms == 2);
  CHECK(*tight.error_bound_delta_T < 0.01 * sigma_t);
  // No stated uncertainty: nothing is known to be small enough but the
  // exact method.
  sigma_t = 0.0;
  CHECK(row(reduce_scene(s), "finite_amplitude").method == "agm");
}
