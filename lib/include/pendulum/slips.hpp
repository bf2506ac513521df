#pragma once
/// \file slips.hpp
/// \brief The slips a student makes that scale g by a known factor (a unit,
/// a count of oscillations) or make a bob implausible, in words that name
/// the input to fix. Both the reader's plausibility checks and the verdict
/// (status.hpp) name them.

#include <optional>
#include <string>

#include "pendulum/apparatus.hpp"

namespace pendulum {

/// The slip in the scene that makes g `ratio` times the true g, by
/// g = 4 pi^2 L / T^2: a length unit slip scales g as the length, a period
/// slip by the inverse square (half swings counted: T/2, g x 4). Empty when
/// no slip's ratio is within 15% of `ratio`. The text names the slip and the
/// input to fix, e.g. "the period is half the true one: ...".
std::optional<std::string> name_slip(double ratio);

/// Why the bob's density (its mass over the sphere of its diameter) is
/// implausible, when it is: below 50 kg/m^3, lighter than any solid ball a
/// pendulum swings (a ping-pong ball is about 80), or below the air's. Names
/// a mass in kg written as g (or a diameter in mm written as cm) when a
/// thousand times the density is a solid's (500 to 22590 kg/m^3).
std::optional<std::string> bob_density_slip(const Apparatus<double>& apparatus);

}  // namespace pendulum
