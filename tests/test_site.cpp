// The g expected at the site: WGS84 normal gravity through GeographicLib, and
// a measured reference preferred to it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "pendulum/reduce_scene.hpp"
#include "pendulum/json/scene_json.hpp"
#include "pendulum/site.hpp"
#include "scene_files.hpp"

using namespace pendulum;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
// WGS84 (NIMA TR8350.2, 3rd ed., Table 3.4): normal gravity at the equator
// and the pole (m/s^2), Somigliana's constant k and the first eccentricity
// squared.
constexpr double kGammaEquator = 9.7803253359;
constexpr double kGammaPole = 9.8321849378;
constexpr double kSomigliana = 0.00193185265241;
constexpr double kE2 = 0.00669437999013;

// Somigliana's closed form on the ellipsoid (TR8350.2 Eq. 4-1).
double somigliana(double latitude_deg) {
  const double s2 = std::pow(std::sin(latitude_deg * M_PI / 180.0), 2);
  return kGammaEquator * (1.0 + kSomigliana * s2) / std::sqrt(1.0 - kE2 * s2);
}
}  // namespace

TEST_CASE("Normal gravity on the ellipsoid matches WGS84's published values", "[site]") {
  CHECK_THAT(normal_gravity(0.0, 0.0), WithinAbs(kGammaEquator, 1e-9));
  CHECK_THAT(normal_gravity(90.0, 0.0), WithinAbs(kGammaPole, 1e-9));
  CHECK_THAT(normal_gravity(-90.0, 0.0), WithinAbs(kGammaPole, 1e-9));
  for (double lat : {10.0, 30.0, 43.0747, 45.0, 60.0, 80.0}) {
    INFO("latitude " << lat);
    CHECK_THAT(normal_gravity(lat, 0.0), WithinAbs(somigliana(lat), 1e-9));
  }
}

TEST_CASE("Normal gravity falls with height by the free-air gradient", "[site]") {
  // Near the surface d gamma/dh = -3.086e-6 s^-2 (the free-air gradient,
  // 0.3086 mGal/m); over 1 km its change with height stays below 0.1%.
  const double drop = normal_gravity(45.0, 0.0) - normal_gravity(45.0, 1000.0);
  CHECK_THAT(drop, WithinRel(3.086e-3, 2e-3));
}

TEST_CASE("Without a site, g is compared with standard gravity and the Earth's surface range", "[site]") {
  const ExpectedGravity e = earth_surface_gravity();
  CHECK(e.value == 9.80665);  // standard gravity, CGPM 1901
  CHECK(e.source == "earth_surface_range");
  REQUIRE(e.range);
  // The poles at sea level: WGS84's published gamma_p. The equator 4000 m up:
  // gamma_e less the free-air gradient's 0.3086 mGal/m, to its second-order term.
  CHECK_THAT(e.range->second, WithinAbs(kGammaPole, 1e-9));
  CHECK_THAT(e.range->first, WithinAbs(kGammaEquator - 3.086e-6 * kSurfaceHeightHigh, 1e-4));
  CHECK(e.uncertainty == std::max(e.value - e.range->first, e.range->second - e.value));
  const Analysis a = reduce_scene(parse_scene(test::nelson_olsson_text()));
  CHECK(a.expected_g);  // Nelson & Olsson give a site
  CHECK_FALSE(a.surface_g);
}

TEST_CASE("A measured reference g is preferred to normal gravity", "[site]") {
  Site site;
  site.latitude_deg = 43.0;
  site.height = 270.0;
  const auto normal = expected_gravity(site);
  REQUIRE(normal);
  CHECK(normal->source == "normal_gravity_wgs84");
  CHECK(normal->uncertainty == kNormalGravityAnomaly);
  site.reference_g = 9.8026;
  const auto reference = expected_gravity(site);
  REQUIRE(reference);
  CHECK(reference->source == "reference");
  CHECK(reference->value == 9.8026);
  CHECK_FALSE(expected_gravity(Site{}));
}

TEST_CASE("Nelson-Olsson's g agrees with the site's 9.8026 m/s^2 within 1 sigma", "[site][table2]") {
  // Sec. IV: "The experimental values ... agree with this geodesic value within 1 s.d."
  const Analysis a = reduce_scene(parse_scene(test::nelson_olsson_text()));
  REQUIRE(a.expected_g);
  REQUIRE(a.z_score);
  CHECK_THAT(a.expected_g->value, WithinAbs(9.8026, 1e-12));
  CHECK(std::abs(*a.z_score) < 1.0);
  CHECK_THAT(*a.z_score, WithinRel((a.g.value - 9.8026) / *a.g.uncertainty, 1e-12));
}
