// Elastic corrections: Nelson & Olsson (1986) Sec. III.D and Table II.
#include <catch2/catch.hpp>

#include <cmath>

#include "pendulum/elastic.hpp"
#include "reference.hpp"

using namespace pendulum;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
constexpr double kG = 9.80;                 // m/s^2, working value
constexpr double kYoung = 2.0e11;           // Pa, steel, Sec. III.D.1
constexpr double kWireDiameter = 0.32e-3;   // m, Sec. III.C.2
constexpr double kStiffness = 4e6;          // N/m, Eq. (89)
const double kArea = M_PI * kWireDiameter * kWireDiameter / 4.0;

double us(double ratio) { return ratio * test::kIdealPeriod * 1e6; }
}  // namespace

TEST_CASE("Wire stretch: Eq. (79), +3.4 us", "[elastic][table2]") {
  const double r = wire_stretch(test::kBobMass, kG, kYoung, kArea, test::kAmplitude);
  CHECK_THAT(us(r), WithinAbs(3.4, 0.1));
  CHECK(wire_stretch(test::kBobMass, kG, kYoung, kArea, 0.0) == 0.0);
  // Stiffer wire, smaller correction: ~1/E.
  CHECK_THAT(wire_stretch(test::kBobMass, kG, 2 * kYoung, kArea, test::kAmplitude), WithinRel(r / 2, 1e-15));
}

TEST_CASE("Elastic support: Eq. (87), +1 us", "[elastic][table2]") {
  const double r = support_elastic(test::kBobMass, kG, kStiffness, test::kLength);
  // The paper prints +1 us for 1.2 us (issue 2 allows 0.5 us here).
  CHECK_THAT(us(r), WithinAbs(1.0, 0.5));
  // Eq. (86): the support moves x_m = (mg/K) theta0 = 0.1 um.
  CHECK_THAT(test::kBobMass * kG / kStiffness * test::kAmplitude * 1e6, WithinAbs(0.1, 0.05));
}

TEST_CASE("Coupled support, Eq. (83), reaches Eqs. (87) and (88) in its limits", "[elastic]") {
  const double m = test::kBobMass, l = test::kLength;
  const double omega0 = std::sqrt(kG / l);
  // Elastic rigidity: Omega = sqrt(K/M) = 2000 rad/s >> omega0; the next
  // term of Eq. (85) is O((omega0/Omega)^2) = 1e-6 relative.
  CHECK_THAT(support_coupled(m, 1.0, kStiffness, omega0),
             WithinRel(support_elastic(m, kG, kStiffness, l), 1e-5));
  // Inertial rigidity, Omega -> 0: Eq. (83) gives omega^2 = (1 + m/M) omega0^2
  // exactly, of which Eq. (88) is the first order in m/M.
  const double big_m = 1000.0;
  const double mu = m / big_m;
  const double r = support_coupled(m, big_m, 1e-12, omega0);
  CHECK_THAT(r, WithinRel(1.0 / std::sqrt(1.0 + mu) - 1.0, 1e-9));
  CHECK_THAT(r, WithinRel(support_inertial(m, big_m), 1e-3));
  CHECK(support_inertial(m, big_m) < 0.0);
  CHECK(support_elastic(m, kG, kStiffness, l) > 0.0);
}
