#pragma once
/// \file units.hpp
/// \brief Units the scene file may use, and their conversion to SI.
///
/// Every quantity in a scene names its unit; nothing is guessed. A unit
/// belongs to one dimension, so "cm" is refused where a mass is expected.

#include <optional>
#include <string>

namespace pendulum {

enum class Dimension {
  length,
  mass,
  time,
  angle,
  pressure,
  temperature,
  volume,
  stiffness,
  modulus,
  molar_mass,
  viscosity,
  rate,             ///< alpha: 1/time
  rate_per_angle,   ///< beta: 1/(time angle)
  acceleration,     ///< g
  daily_rate,       ///< a clock's gain or loss; "SI" here is s/day
  density,          ///< a body's parts: kg/m^3
  expansion,        ///< linear thermal expansion: 1/K
};

/// A unit: value_SI = factor * value + offset (offset only for temperatures;
/// uncertainties scale by factor alone).
struct Unit {
  const char* name;
  Dimension dimension;
  double factor;
  double offset;
};

/// The unit called `name` if it measures `dimension`; `name` may also be a
/// spelling people type: "sec", "degree(s)", the degree sign, "C" or "\u00b0C"
/// for degC, "F" or "\u00b0F" for degF. The unit returned has the table's name.
std::optional<Unit> find_unit(const std::string& name, Dimension dimension);

/// The SI unit of a dimension, as printed in the output ("m", "kg", "1/(s rad)").
const char* si_unit(Dimension dimension);

/// "a length", "a mass", ... for error messages.
const char* dimension_name(Dimension dimension);

/// The accepted unit names of a dimension, comma-separated.
std::string unit_names(Dimension dimension);

}  // namespace pendulum
