#pragma once
/// \file site.hpp
/// \brief Where the experiment was done, and the g expected there.

#include <optional>
#include <string>

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
  std::string source;  ///< "reference" or "normal_gravity_wgs84"
  std::string note;    ///< what the value leaves out
};

/// Gravity anomalies that normal gravity ignores: typically within
/// +-0.0005 m/s^2 (50 mGal) away from mountains; used as the expected
/// value's uncertainty.
inline constexpr double kNormalGravityAnomaly = 5e-4;

/// Normal gravity of the WGS84 ellipsoid, with its rotation, at geographic
/// latitude `latitude_deg` and height `height` (m) above the ellipsoid
/// (GeographicLib::NormalGravity). Returns |gamma| (m/s^2).
double normal_gravity(double latitude_deg, double height);

/// The reference g when the site gives one, else normal gravity; empty when
/// the site gives neither.
std::optional<ExpectedGravity> expected_gravity(const Site& site);

}  // namespace pendulum
