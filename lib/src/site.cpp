#include "pendulum/site.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <GeographicLib/NormalGravity.hpp>

#include "pendulum/numeric.hpp"

namespace pendulum {

double normal_gravity(double latitude_deg, double height) {
  double gamma_north = 0.0, gamma_up = 0.0;
  GeographicLib::NormalGravity::WGS84().Gravity(latitude_deg, height, gamma_north, gamma_up);
  return std::hypot(gamma_north, gamma_up);
}

ExpectedGravity earth_surface_gravity() {
  const double low = normal_gravity(0.0, kSurfaceHeightHigh), high = normal_gravity(90.0, 0.0);
  char note[240];
  std::snprintf(note, sizeof note,
                "no site given: standard gravity, with the range of g on the Earth's surface as its uncertainty "
                "(WGS84 normal gravity, GeographicLib: %.4f m/s^2 at the equator %.0f m up to %.4f m/s^2 at the "
                "poles at sea level)",
                low, kSurfaceHeightHigh, high);
  return ExpectedGravity{kStandardGravity, std::max(kStandardGravity - low, high - kStandardGravity),
                         "earth_surface_range", note, std::pair{low, high}};
}

std::optional<ExpectedGravity> expected_gravity(const Site& site) {
  if (site.reference_g) {
    return ExpectedGravity{*site.reference_g, site.reference_g_uncertainty, "reference",
                           site.reference_source, std::nullopt};
  }
  if (!site.latitude_deg || !site.height) return std::nullopt;
  std::string note =
      "WGS84 normal gravity (GeographicLib); it ignores gravity anomalies, taken as +-0.0005 m/s^2";
  if (!site.height_above_ellipsoid) {
    note += "; the height above sea level is used as height above the ellipsoid (the geoid "
            "undulation, up to +-100 m, moves g by up to +-0.0003 m/s^2)";
  }
  return ExpectedGravity{normal_gravity(*site.latitude_deg, *site.height), kNormalGravityAnomaly,
                         "normal_gravity_wgs84", note, std::nullopt};
}

}  // namespace pendulum
