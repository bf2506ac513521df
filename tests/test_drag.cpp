// Theoretical damping constants: Nelson & Olsson (1986) Sec. III.C.4.
#include <catch2/catch.hpp>

#include "pendulum/drag.hpp"
#include "pendulum/json/scene_json.hpp"
#include "reference.hpp"
#include "scene_files.hpp"

using namespace pendulum;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("Drag constants of the Nelson-Olsson pendulum (Sec. III.C.4)", "[drag]") {
  const ParsedScene scene = parse_scene(test::nelson_olsson_text());
  const auto p = predict_drag(scene.apparatus, scene.observations[0]);
  REQUIRE(p);
  // Sec. III.C.2: the ball's largest Reynolds number is 1100, the wire's 6.
  CHECK_THAT(p->reynolds_sphere, WithinAbs(1100.0, 50.0));
  REQUIRE(p->reynolds_wire);
  CHECK_THAT(*p->reynolds_wire, WithinAbs(6.0, 0.5));
  // Text after Eq. (64): C'_D = 0.61, b = 0.49e-4 kg/s, c = 1.04e-3 kg/m.
  // The paper's b uses the rounded C_H = 0.50; the unrounded 0.503 gives
  // 0.497e-4 (docs/deviations.md), so b is checked both ways.
  CHECK_THAT(p->c_d_prime, WithinAbs(0.61, 0.005));
  const auto& air = *scene.apparatus.air;
  const double rho = air_density(air.pressure, air.temperature, air.molar_mass);
  const double delta = penetration_depth(air.viscosity, test::kOmega0, rho);
  CHECK_THAT(sphere_linear_drag(air.viscosity, test::kBobRadius, 0.50, delta), WithinAbs(0.49e-4, 0.005e-4));
  CHECK_THAT(p->b_sphere, WithinAbs(0.497e-4, 0.0005e-4));
  CHECK_THAT(p->c_sphere, WithinAbs(1.04e-3, 0.005e-3));
  // Text after Eq. (67): the wire's b = 0.93e-4 kg/s and c = 0.28e-3 kg/m.
  CHECK_THAT(*p->b_wire, WithinAbs(0.93e-4, 0.005e-4));
  CHECK_THAT(*p->c_wire, WithinAbs(0.28e-3, 0.005e-3));
  // Totals: b = 1.42e-4 kg/s, c = 1.32e-3 kg/m.
  CHECK_THAT(p->b, WithinAbs(1.42e-4, 0.005e-4));
  CHECK_THAT(p->c, WithinAbs(1.32e-3, 0.005e-3));
}

TEST_CASE("Measured drag from alpha and beta: b = 4.27e-4 kg/s, c = 1.18e-3 kg/m", "[drag]") {
  // Eqs. (26)-(27) inverted, with the fitted alpha and beta of Eqs. (28)-(29)
  // (text after Eq. 68). The text prints c = (3/2)(pi m/omega0) beta, which
  // gives 7.1e-3 kg/m; Eq. (27) gives the 1.18e-3 it states (docs/deviations.md).
  const double b = 2.0 * test::kBobMass * test::kAlpha;
  CHECK_THAT(b, WithinAbs(4.27e-4, 0.005e-4));
  CHECK_THAT(alpha_from_linear_drag(b, test::kBobMass), WithinRel(test::kAlpha, 1e-15));
  const double c = 1.18e-3;
  CHECK_THAT(beta_from_quadratic_drag(c, test::kOmega0, test::kLength, test::kBobMass),
             WithinRel(test::kBeta, 0.005 / 1.18));
}

TEST_CASE("No air, no drag prediction, a wire without diameter has no quadratic drag", "[drag]") {
  ParsedScene scene = parse_scene(test::nelson_olsson_text());
  scene.apparatus.wire->diameter.reset();
  const auto p = predict_drag(scene.apparatus, scene.observations[0]);
  REQUIRE(p);
  CHECK(p->b_wire);
  CHECK_FALSE(p->c_wire);
  scene.apparatus.air.reset();
  CHECK_FALSE(predict_drag(scene.apparatus, scene.observations[0]));
}
