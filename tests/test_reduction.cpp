// The whole reduction: Nelson & Olsson's Eqs. (5), (90), (91), what is
// skipped, and the propagation of the period's and length's uncertainties.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

#include "pendulum/analysis.hpp"
#include "reference.hpp"
#include "scene_files.hpp"

using namespace pendulum;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
const CorrectionRow& row(const Analysis& a, const std::string& id) {
  for (const auto& r : a.corrections) {
    if (id == r.info.id) return r;
  }
  throw std::logic_error("no correction " + id);
}
}  // namespace

TEST_CASE("Nelson-Olsson: Eqs. (5), (90), (91)", "[reduction][table2]") {
  const Analysis a = analyse(parse_scene(test::nelson_olsson_text()));
  // Eq. (5): g = 9.8007 +- 0.0014 m/s^2 with T0 = T.
  CHECK_THAT(a.g_uncorrected.value, WithinAbs(9.8007, 0.00005));
  CHECK_THAT(a.g_uncorrected.uncertainty, WithinAbs(0.0014, 0.00005));
  // Eq. (90): T0 = 3.47833 +- 0.00017 s.
  CHECK_THAT(a.period_ideal.value, WithinAbs(3.47833, 0.000005));
  CHECK_THAT(a.period_ideal.uncertainty, WithinAbs(0.00017, 0.000005));
  // Eq. (91): g = 9.8034 +- 0.0014 m/s^2.
  CHECK_THAT(a.g.value, WithinAbs(9.8034, 0.00005));
  CHECK_THAT(a.g.uncertainty, WithinAbs(0.0014, 0.00005));
}

TEST_CASE("Corrections add linearly (Eqs. 6-7)", "[reduction]") {
  const Analysis a = analyse(parse_scene(test::nelson_olsson_text()));
  double sum_t = 0.0, sum_g = 0.0;
  for (const auto& r : a.corrections) {
    REQUIRE(r.delta_T);
    sum_t += *r.delta_T;
    sum_g += *r.delta_g;
  }
  CHECK_THAT(a.total_delta_T, WithinRel(sum_t, 1e-12));
  CHECK_THAT(a.total_delta_g, WithinRel(sum_g, 1e-12));
  CHECK_THAT(a.period_measured.value - a.total_delta_T, WithinRel(a.period_ideal.value, 1e-15));
  // Delta g is linearised, so it matches g - g_uncorrected to second order.
  CHECK_THAT(a.g.value - a.g_uncorrected.value, WithinRel(a.total_delta_g, 1e-3));
}

TEST_CASE("Corrections under a tenth of the period's uncertainty are flagged negligible",
          "[reduction]") {
  const Analysis a = analyse(parse_scene(test::nelson_olsson_text()));
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
  CHECK_THAT(a.negligible_below, WithinRel(0.1 * a.period_measured.uncertainty, 1e-15));
}

TEST_CASE("A bare scene computes only what it has", "[reduction]") {
  auto doc = nlohmann::json::parse(test::nelson_olsson_text());
  for (const char* part : {"ring", "cap", "cap_screw", "wire", "support", "decay"}) doc.erase(part);
  doc["air"] = "vacuum";
  const Analysis a = analyse(parse_scene(doc.dump()));
  for (const auto& r : a.corrections) {
    const std::string id = r.info.id;
    const bool present = id == "finite_amplitude" || id == "bob_radius" || id == "bob_rotation";
    INFO(id);
    CHECK((r.status != Status::skipped) == present);
    CHECK(r.delta_T.has_value() == present);
    if (!present) CHECK_FALSE(r.reason.empty());
  }
  CHECK(row(a, "buoyancy").reason == "the scene is in vacuum");
}

TEST_CASE("The budget's derivatives match finite differences of the reduction", "[reduction][jet]") {
  ParsedScene s = parse_scene(test::nelson_olsson_text());
  const Analysis a = analyse(s);
  REQUIRE(a.budget.size() == 2);
  double quadrature = 0.0;
  for (const auto& b : a.budget) quadrature += b.contribution * b.contribution;
  CHECK_THAT(std::sqrt(quadrature), WithinRel(a.g.uncertainty, 1e-14));

  auto g_at = [&](double period, double length) {
    ParsedScene t = s;
    t.value.period = period;
    t.value.length = length;
    return analyse(t).g.value;
  };
  const double hp = 1e-6 * s.value.period, hl = 1e-6 * s.value.length;
  const double dg_dt = (g_at(s.value.period + hp, s.value.length) -
                        g_at(s.value.period - hp, s.value.length)) / (2 * hp);
  const double dg_dl = (g_at(s.value.period, s.value.length + hl) -
                        g_at(s.value.period, s.value.length - hl)) / (2 * hl);
  CHECK(a.budget[0].input == "timing.trials");
  CHECK_THAT(a.budget[0].sensitivity, WithinRel(dg_dt, 1e-6));
  CHECK(a.budget[1].input == "length");
  CHECK_THAT(a.budget[1].sensitivity, WithinRel(dg_dl, 1e-6));
  // Close to the ideal pendulum's -2g/T and g/l.
  CHECK_THAT(a.budget[0].sensitivity, WithinRel(-2 * a.g.value / a.period_ideal.value, 1e-3));
  CHECK_THAT(a.budget[1].sensitivity, WithinRel(a.g.value / s.value.length, 1e-3));
}

TEST_CASE("Amplitude methods differ by their truncation only", "[reduction]") {
  const ParsedScene s = parse_scene(test::nelson_olsson_text());
  AnalysisOptions small, exact;
  small.reduction.amplitude_method = AmplitudeMethod::small_angle;
  exact.reduction.amplitude_method = AmplitudeMethod::agm;
  const CorrectionRow exact_row = row(analyse(s, exact), "finite_amplitude");
  const CorrectionRow small_row = row(analyse(s, small), "finite_amplitude");
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
  const CorrectionRow automatic = row(analyse(s), "finite_amplitude");
  CHECK(automatic.method == "small_angle");
  CHECK(*automatic.error_bound_delta_T < 0.01 * s.uncertainty.period);
  // A timing 100 times better leaves 0.0169 us: theta0^2/16 (0.23 us) and
  // Eq. (8) with 1 term (omitted A_2 m^2 T0 = 0.23 us) no longer fit; with 2
  // terms the omitted tail is A_3 m^3 T0 / (1 - m) = 1.1e-4 us.
  s.uncertainty.period /= 100.0;
  const CorrectionRow tight = row(analyse(s), "finite_amplitude");
  CHECK(tight.method == "series");
  CHECK(tight.series_terms == 2);
  CHECK(*tight.error_bound_delta_T < 0.01 * s.uncertainty.period);
  // No stated uncertainty: nothing is known to be small enough but the
  // exact method.
  s.uncertainty.period = 0.0;
  CHECK(row(analyse(s), "finite_amplitude").method == "agm");
}
