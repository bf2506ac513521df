// Finite-amplitude correction: exact AGM method, Eq. (8) series, theta^2/16.
#include <catch2/catch.hpp>
#include <ceres/jet.h>

#include <cmath>

#include "pendulum/amplitude.hpp"
#include "reference.hpp"

using namespace pendulum;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

TEST_CASE("AGM at 90 deg matches the lemniscate constant", "[amplitude]") {
  // K(k = sin 45 deg) = Gamma(1/4)^2 / (4 sqrt(pi)) (Whittaker & Watson,
  // 22.8), so T/T0 = 2K/pi = Gamma(1/4)^2 / (2 pi^{3/2}); tgamma is
  // accurate to a few ulp.
  const double pi = std::acos(-1.0);
  const double expected = std::pow(std::tgamma(0.25), 2) / (2.0 * std::pow(pi, 1.5)) - 1.0;
  CHECK_THAT(finite_amplitude_agm(pi / 2.0), WithinRel(expected, 1e-14));
}

TEST_CASE("AGM agrees with std::comp_ellint_1 where no digits cancel", "[amplitude]") {
  // 2K(k)/pi - 1 from libstdc++ (k = sin(theta0/2)); above 30 deg the
  // subtraction loses under two digits.
  for (double deg : {30.0, 60.0, 90.0, 120.0, 150.0, 170.0, 179.0}) {
    const double theta0 = deg * test::kDegree;
    const double expected = 2.0 * std::comp_ellint_1(std::sin(theta0 / 2.0)) / M_PI - 1.0;
    INFO("theta0 = " << deg << " deg");
    CHECK_THAT(finite_amplitude_agm(theta0), WithinRel(expected, 1e-13));
  }
}

TEST_CASE("AGM agrees with the converged Eq. (8) series", "[amplitude]") {
  // Independent route: 60 terms of Eq. (8) converge to double precision for
  // k^2 = sin^2(theta0/2) <= 0.23 (theta0 <= 57 deg).
  for (double theta0 : {1e-3, 1e-2, 0.1, 0.5, 1.0}) {
    INFO("theta0 = " << theta0 << " rad");
    CHECK_THAT(finite_amplitude_agm(theta0),
               WithinRel(finite_amplitude_series(theta0, 60), 2e-15));
  }
}

TEST_CASE("AGM keeps full relative accuracy at tiny amplitudes", "[amplitude]") {
  // Eq. (8) in powers of theta: theta^2/16 + 11 theta^4/3072 + 173 theta^6/737280
  // (Kelley 1993, Eq. 10); the next term is 1.7e-5 theta^8.
  for (double theta0 : {1e-12, 1e-8, 1e-5, 1e-3}) {
    const double t2 = theta0 * theta0;
    const double expected = t2 / 16.0 + 11.0 * t2 * t2 / 3072.0 + 173.0 * t2 * t2 * t2 / 737280.0;
    INFO("theta0 = " << theta0 << " rad");
    CHECK_THAT(finite_amplitude_agm(theta0), WithinRel(expected, 1e-15));
  }
  CHECK(finite_amplitude_agm(0.0) == 0.0);
}

TEST_CASE("AGM is finite and increasing up to 180 deg", "[amplitude]") {
  double previous = 0.0;
  for (double deg = 1.0; deg < 180.0; deg += 1.0) {
    const double r = finite_amplitude_agm(deg * test::kDegree);
    REQUIRE(std::isfinite(r));
    CHECK(r > previous);
    previous = r;
  }
  // theta0 -> pi: K ~ ln(4/kc), so the correction grows without bound.
  const double near_top = finite_amplitude_agm(179.9999 * test::kDegree);
  CHECK(std::isfinite(near_top));
  CHECK(near_top > 7.0);
}

TEST_CASE("Finite amplitude reproduces Table II: +596 us at 3 deg", "[amplitude][table2]") {
  const double dt_us = finite_amplitude_agm(test::kAmplitude) * test::kIdealPeriod * 1e6;
  CHECK_THAT(dt_us, WithinAbs(596.0, test::table2_tolerance_us(596.0)));
  // theta^2/16 is what the paper used: the two differ by
  // (11 theta^4/3072 + 173 theta^6/737280) T0 = 0.0936 us.
  const double small_us = finite_amplitude_small_angle(test::kAmplitude) * test::kIdealPeriod * 1e6;
  const double t2 = test::kAmplitude * test::kAmplitude;
  CHECK_THAT(dt_us - small_us,
             WithinAbs((11.0 / 3072.0 * t2 * t2 + 173.0 / 737280.0 * t2 * t2 * t2) * test::kIdealPeriod * 1e6, 1e-8));
}

TEST_CASE("Series terms and the small-angle form", "[amplitude]") {
  const double theta0 = 0.3;
  const double k2 = std::pow(std::sin(theta0 / 2.0), 2);
  CHECK_THAT(finite_amplitude_series(theta0, 1), WithinRel(k2 / 4.0, 1e-15));
  CHECK_THAT(finite_amplitude_series(theta0, 2), WithinRel(k2 / 4.0 + 9.0 / 64.0 * k2 * k2, 1e-15));
  CHECK(finite_amplitude_small_angle(theta0) == theta0 * theta0 / 16.0);
}

TEST_CASE("AGM derivative through ceres::Jet matches a central difference", "[amplitude][jet]") {
  for (double theta0 : {1e-4, 0.05, 1.0, 2.5}) {
    const ceres::Jet<double, 1> x(theta0, 0);
    const double derivative = finite_amplitude_agm(x).v[0];
    const double h = 1e-6 * theta0;
    const double numeric = (finite_amplitude_agm(theta0 + h) - finite_amplitude_agm(theta0 - h)) / (2 * h);
    INFO("theta0 = " << theta0);
    CHECK_THAT(derivative, WithinRel(numeric, 1e-7));
  }
  // d/dtheta (theta^2/16) = theta/8 at small amplitude.
  const ceres::Jet<double, 1> tiny(1e-6, 0);
  CHECK_THAT(finite_amplitude_agm(tiny).v[0], WithinRel(1e-6 / 8.0, 1e-10));
}
