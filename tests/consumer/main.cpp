// Calls the installed library through its installed headers: a header-only
// template (amplitude.hpp) and a compiled function that links GeographicLib
// (site.hpp). Exit 0 when both agree with published values.
#include <cmath>
#include <cstdio>

#include <pendulum/amplitude.hpp>
#include <pendulum/site.hpp>

namespace {

bool check(const char* what, double got, double expected, double tolerance, const char* unit) {
  const bool ok = std::abs(got - expected) <= tolerance;
  std::printf("%s %s: got %.17g, expected %.17g +- %g %s\n", ok ? "ok  " : "FAIL", what, got,
              expected, tolerance, unit);
  return ok;
}

}  // namespace

int main() {
  // 90 deg: DeltaT/T0 = 2K(m)/pi - 1 with m = sin^2(45 deg) = 1/2, where
  // K(1/2) = 1.85407 46773 01372 (Abramowitz & Stegun Table 17.1).
  using pendulum::kPi;
  const double expected_amplitude = 2.0 * 1.854074677301372 / kPi - 1.0;
  // WGS84 normal gravity at the equator on the ellipsoid (NIMA TR8350.2,
  // 3rd ed., Table 3.4).
  const double expected_gravity = 9.7803253359;
  // Both checks run and print (&, not &&).
  const bool ok = check("finite_amplitude_agm(pi/2)", pendulum::finite_amplitude_agm(kPi / 2.0),
                        expected_amplitude, 1e-14, "(DeltaT/T0)") &
                  check("normal_gravity(0 deg, 0 m)", pendulum::normal_gravity(0.0, 0.0),
                        expected_gravity, 1e-9, "m/s^2");
  return ok ? 0 : 1;
}
