#pragma once
/// \file argument_ranges.hpp
/// \brief The range of every number the CLI's options and the Python module's
/// arguments take, in one table that both check against, so that they cannot
/// diverge: a value the CLI refuses, Python refuses with the same message
/// (docs/robustness.md, "Numbers in options and arguments").

#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace pendulum {

/// A number's range [low, high] (or [low, high) where `high_open`) in
/// `unit`, and its names.
struct ArgumentRange {
  const char* option;    ///< the CLI's option ("--series-terms"), or the scene key it mirrors
  const char* argument;  ///< the Python module's argument ("series_terms")
  double low, high;
  const char* unit;      ///< "" for a pure number
  const char* expected;  ///< what the message says is expected
  bool high_open = false;
};

namespace ranges {
inline constexpr ArgumentRange negligible_fraction{"--negligible-fraction", "negligible_fraction", 0.0, 1e6, "",
                                                   "a fraction of the period's uncertainty from 0 to 1e6"};
inline constexpr ArgumentRange series_terms{"--series-terms", "series_terms", 1, 1000, "",
                                            "a number of terms of Eq. (8) from 1 to 1000"};
inline constexpr ArgumentRange amplitude_terms{"--terms", "terms", 1, 1000, "",
                                               "a number of terms of Eq. (8) from 1 to 1000"};
/// A scene's length (scene.json's length.value): a laboratory's.
inline constexpr ArgumentRange length{"--length-m", "length_m", 1e-3, 1e3, "m",
                                      "a laboratory pendulum, 1 mm to 1 km long"};
/// reduce RECORDING --length's uncertainty: the scene reader then asks for
/// less than the length.
inline constexpr ArgumentRange length_uncertainty{"--length-uncertainty", "length_uncertainty", 0.0, 1e3, "m",
                                                  "a length's standard uncertainty from 0 to 1 km"};
/// A timing's stated uncertainty or resolution (scene.json's
/// timing.uncertainty and timing.resolution, a table's column): no timer of
/// a pendulum resolves a picosecond, and 1e-200 s squares to 0 (a timing
/// then infinitely precise); the most is a third of the trial (parts.cpp).
inline constexpr ArgumentRange timing_uncertainty{"timing.uncertainty", "timing_uncertainty", 1e-12, std::numeric_limits<double>::infinity(), "s",
                                                  "a time of at least 1 ps (no timer resolves a shorter one)"};
/// Below the length, at most 1 km; a photogate resolves no bob under 1 mm.
inline constexpr ArgumentRange bob_width{"--bob-width-m", "bob_width_m", 1e-3, 1e3, "m",
                                         "a bob's width across the beam from 1 mm to 1 km"};
inline constexpr ArgumentRange stamps_per_period{"--stamps-per-period", "stamps_per_period", 1, 2, "",
                                                 "1 (a timer, a photogate's pendulum mode) or 2 (one a passage)"};
inline constexpr ArgumentRange oscillations{"--oscillations", "oscillations", 1, 1e6, "",
                                            "a number of oscillations from 1 to 1000000"};
/// A site's (scene.json's site.latitude and site.height).
inline constexpr ArgumentRange latitude{"site.latitude", "latitude", -90.0, 90.0, "deg",
                                        "a latitude from -90 to 90 deg"};
inline constexpr ArgumentRange height{"site.height", "height", -12e3, 100e3, "m",
                                      "a height on Earth (-12 km to 100 km)"};
/// A clock's quality factor and semi-amplitude (a clock scene's Q and
/// semi_amplitude, on a circular path, up to pi): a pendulum swings many
/// times before it stops (Feinstein: 100 to 1e6); 1e-9 rad is 2e-4 arc
/// seconds, far below any clock's swing, and keeps k^2 far from underflow.
inline constexpr ArgumentRange quality{"Q", "q", 1.0, 1e15, "", "a quality factor from 1 to 1e15"};
inline constexpr ArgumentRange semi_amplitude{"semi_amplitude", "theta0", 1e-9, 3.141592653589793, "rad",
                                              "an angle from 1e-9 rad to below 180 deg", true};
/// A pendulum's amplitude, in degrees as the amplitude command takes it and
/// in radians as the Python functions and the library take it.
inline constexpr ArgumentRange amplitude_deg{
    "--theta0-deg", "theta0_deg", 0.0, 180.0, "deg",
    "an amplitude from 0 to below 180 deg (at 180 deg and beyond the pendulum goes over the top)", true};
inline constexpr ArgumentRange amplitude{
    "amplitude", "theta0", 0.0, 3.141592653589793, "rad",
    "an amplitude from 0 to below pi rad (at 180 deg and beyond the pendulum goes over the top)", true};
/// A clock's impulse location, from 0 to the semi-amplitude `theta0` (rad):
/// its top is the swing's, so it is made for each swing.
constexpr ArgumentRange impulse_location(double theta0) {
  return {"impulse.location", "location", 0.0, theta0, "rad", "an angle from 0 to the semi-amplitude theta0"};
}

/// Every range above, so that a check over them all (tests/fuzz/fuzz_arguments.cpp)
/// takes a new one without an edit.
inline constexpr const ArgumentRange* all[] = {
    &negligible_fraction, &series_terms, &amplitude_terms, &length,         &length_uncertainty,
    &timing_uncertainty,  &bob_width,    &stamps_per_period, &oscillations, &latitude,
    &height,              &quality,      &semi_amplitude,  &amplitude_deg,  &amplitude};
}  // namespace ranges

/// Whether `value` lies in `range` (a NaN does not): inline, for loops over
/// many values.
constexpr bool accepts(const ArgumentRange& range, double value) {
  return value >= range.low && (range.high_open ? value < range.high : value <= range.high);
}

/// Empty when `value` lies in `range`, else "got VALUE UNIT; expected ..."
/// (a NaN is "NaN", a value is written to 10 digits, never 300).
std::string out_of_range(const ArgumentRange& range, double value);

/// `text` as a decimal number, whole ("16", "+0.5", "1e300", "inf"): not
/// hexadecimal (strtod's "0x10", 16, is no number a lab writes), no spaces;
/// nullopt where it is not one. Options and column specs read numbers so.
std::optional<double> decimal_number(std::string_view text);

}  // namespace pendulum
