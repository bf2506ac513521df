#pragma once
/// \file clock_scene.hpp
/// \brief A clock scene (docs/clock.md): the pendulum, its swing, its Q and
/// its impulse, read from JSON into SI units; and the clock's period model
/// run on it (clock.hpp), as the `clock` command prints it.

#include <optional>
#include <string>
#include <vector>

#include "pendulum/clock.hpp"

namespace pendulum {

/// A value (SI; angles in rad, daily rates in s/day) and its standard
/// uncertainty (0 when the file states none).
struct ClockQuantity {
  double value = 0.0, sigma = 0.0;
};

/// A clock scene as read from its file.
struct ClockScene {
  std::string title, source;
  ClockQuantity g;                       ///< m/s^2
  ClockQuantity length;                  ///< m (given, or from the nominal period, Eq. B-1)
  std::optional<double> nominal_period;  ///< s, when the scene gives it instead of the length
  ClockQuantity semi_amplitude;          ///< rad (beta0 on a cycloidal path)
  ClockQuantity q;                       ///< Q (1)
  ClockQuantity location;                ///< rad, or a fraction of the semi-amplitude
  bool relative_location = false;
  ImpulseDirection direction = ImpulseDirection::away;
  ClockPath path = ClockPath::circular;
  bool damped = false;
  double accuracy = 0.0;  ///< s/day asked of the impulse error; 0: the exact route
};

/// Empty when an impulse of pi/Q of the energy (Feinstein Eq. F-1) keeps the
/// swing of semi-amplitude theta0 (rad) below the top (180 deg; the cusp,
/// 90 deg, on a cycloid), else "got Q; expected ...": a scene's Q and the
/// Python module's q are refused alike.
std::string impulse_over_top(double theta0, double q, ClockPath path);

/// Parses and validates clock scene JSON text (schema "pendulum-g/clock-scene/1").
/// Throws InputError naming the JSON path, the value and what was expected.
ClockScene parse_clock_scene(const std::string& text);

/// What the clock does, for one scene.
struct ClockAnalysis {
  double small_amplitude_period;  ///< T0 (s)
  double free_period;             ///< T at the semi-amplitude, circular error included (s)
  double impulsed_period;         ///< T with one impulse a swing (s)
  double period_sigma;            ///< of every period above, from l, g and the amplitude (s)
  double location;                ///< impulse location (rad)
  double impulsed_amplitude;      ///< semi-amplitude after the impulse (rad), Eq. (F-1)
  ClockQuantity circular_error;   ///< s/day, Eq. (E-2); 0 on a cycloid
  double circular_error_rate;     ///< s/day per rad, Eq. (E-4)
  double impulse_error;           ///< s/day, signed by the direction, Eq. (D-1)
  /// Its uncertainty (s/day); none when a derivative is infinite (an
  /// impulse at the end of the swing with an uncertain location or amplitude).
  std::optional<double> impulse_error_sigma;
  double impulse_error_rate;      ///< s/day per rad of the location, signed, Eq. (D-2); inf at the end
  /// d(impulse error)/d(semi-amplitude) at a fixed impulse location and Q
  /// (s/day per rad, signed; closed-form route of the path): what a change
  /// of amplitude does to a fixed escapement, unlike Eq. (D-2) (docs/clock.md).
  double impulse_error_amplitude_rate;
  ClockChoice choice;             ///< route, its steps and error bounds
  std::optional<double> cancelling_semi_amplitude;  ///< rad, Sec. IX
  std::string cancelling_note;    ///< why there is none, or what was held fixed
  /// rad: where circular plus impulse error stops changing with the amplitude
  /// at a fixed impulse location and Q (amplitude_insensitive_semi_amplitude).
  std::optional<double> insensitive_semi_amplitude;
  std::vector<std::string> warnings;
};

/// Runs the clock's period model on a scene: `route`, or the cheapest route
/// within the scene's accuracy (cheapest_clock_route), the circular error,
/// and the uncertainties propagated to first order (derivatives by
/// ceres::Jet of the closed-form route of the path). Throws InputError for a
/// route that cannot model the scene (a circular route on a cycloid, a
/// cycloid standing for a circle beyond 60 deg).
ClockAnalysis analyse_clock(const ClockScene& scene, std::optional<ClockRoute> route = std::nullopt);

}  // namespace pendulum
