#include "pendulum/site.hpp"

#include <cmath>

#include <GeographicLib/NormalGravity.hpp>

namespace pendulum {

double normal_gravity(double latitude_deg, double height) {
  double gamma_north = 0.0, gamma_up = 0.0;
  GeographicLib::NormalGravity::WGS84().Gravity(latitude_deg, height, gamma_north, gamma_up);
  return std::hypot(gamma_north, gamma_up);
}

std::optional<ExpectedGravity> expected_gravity(const Site& site) {
  if (site.reference_g) {
    return ExpectedGravity{*site.reference_g, site.reference_g_uncertainty, "reference",
                           site.reference_source};
  }
  if (!site.latitude_deg || !site.height) return std::nullopt;
  std::string note =
      "WGS84 normal gravity (GeographicLib); it ignores gravity anomalies, taken as +-0.0005 m/s^2";
  if (!site.height_above_ellipsoid) {
    note += "; the height above sea level is used as height above the ellipsoid (the geoid "
            "undulation, up to +-100 m, moves g by up to +-0.0003 m/s^2)";
  }
  return ExpectedGravity{normal_gravity(*site.latitude_deg, *site.height), kNormalGravityAnomaly,
                         "normal_gravity_wgs84", note};
}

}  // namespace pendulum
