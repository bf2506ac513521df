#pragma once
/// \file site.hpp
/// \brief Where the experiment was done, and the g expected there.

#include <optional>
#include <string>
#include <utility>

namespace pendulum {

/// What a scene's `site` states (SI units, degrees for the latitude).
struct Site {
  std::optional<double> latitude_deg;
  std::optional<double> height;      ///< (m)
  bool height_above_ellipsoid = true;  ///< false: above sea level (the geoid)
  std::optional<double> reference_g;   ///< a measured local g (m/s^2), preferred
  double reference_g_uncertainty = 0.0;
  std::string reference_source;
};

/// The g a measurement is compared with.
struct ExpectedGravity {
  double value;        ///< (m/s^2)
  double uncertainty;  ///< (m/s^2)
  std::string source;  ///< "reference", "normal_gravity_wgs84" or "earth_surface_range"
  std::string note;    ///< what the value leaves out
  /// The lowest and highest g of the range (m/s^2), for "earth_surface_range".
  std::optional<std::pair<double, double>> range;
};

/// Gravity anomalies that normal gravity ignores: typically within
/// +-0.0005 m/s^2 (50 mGal) away from mountains; used as the expected
/// value's uncertainty.
inline constexpr double kNormalGravityAnomaly = 5e-4;

/// Normal gravity of the WGS84 ellipsoid, with its rotation, at geographic
/// latitude `latitude_deg` and height `height` (m) above the ellipsoid
/// (GeographicLib::NormalGravity). Returns |gamma| (m/s^2).
double normal_gravity(double latitude_deg, double height);

/// Heights of the Earth's surface the range below spans (m): sea level to
/// 4000 m, above the highest cities with universities (La Paz, 3640 m).
inline constexpr double kSurfaceHeightHigh = 4000.0;

/// Standard gravity (9.80665 m/s^2) with the range of WGS84 normal gravity
/// over the Earth's surface as its uncertainty: from the equator at
/// kSurfaceHeightHigh to the poles at sea level, the larger distance of an
/// end from standard gravity. What a result without a site is compared with.
ExpectedGravity earth_surface_gravity();

/// The reference g when the site gives one, else normal gravity; empty when
/// the site gives neither.
std::optional<ExpectedGravity> expected_gravity(const Site& site);

}  // namespace pendulum
