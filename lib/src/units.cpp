#include "pendulum/units.hpp"

#include <array>

#include "pendulum/numeric.hpp"

namespace pendulum {
namespace {

constexpr double kMmHg = 133.322387415;  // Pa, conventional (13.5951 g/cm^3, 9.80665 m/s^2)

constexpr std::array<Unit, 64> kUnits{{
    {"m", Dimension::length, 1.0, 0.0},
    {"cm", Dimension::length, 1e-2, 0.0},
    {"mm", Dimension::length, 1e-3, 0.0},
    {"um", Dimension::length, 1e-6, 0.0},
    {"km", Dimension::length, 1e3, 0.0},
    {"in", Dimension::length, 0.0254, 0.0},
    {"ft", Dimension::length, 0.3048, 0.0},
    {"kg", Dimension::mass, 1.0, 0.0},
    {"g", Dimension::mass, 1e-3, 0.0},
    {"mg", Dimension::mass, 1e-6, 0.0},
    {"s", Dimension::time, 1.0, 0.0},
    {"ms", Dimension::time, 1e-3, 0.0},
    {"min", Dimension::time, 60.0, 0.0},
    {"h", Dimension::time, 3600.0, 0.0},
    {"rad", Dimension::angle, 1.0, 0.0},
    {"mrad", Dimension::angle, 1e-3, 0.0},
    {"deg", Dimension::angle, kRadiansPerDegree, 0.0},
    {"arcmin", Dimension::angle, kRadiansPerDegree / 60.0, 0.0},
    {"arcsec", Dimension::angle, kRadiansPerDegree / 3600.0, 0.0},
    {"Pa", Dimension::pressure, 1.0, 0.0},
    {"hPa", Dimension::pressure, 1e2, 0.0},
    {"kPa", Dimension::pressure, 1e3, 0.0},
    {"mbar", Dimension::pressure, 1e2, 0.0},
    {"bar", Dimension::pressure, 1e5, 0.0},
    {"atm", Dimension::pressure, 101325.0, 0.0},
    {"mmHg", Dimension::pressure, kMmHg, 0.0},
    {"Torr", Dimension::pressure, 101325.0 / 760.0, 0.0},
    {"inHg", Dimension::pressure, kMmHg * 25.4, 0.0},
    {"K", Dimension::temperature, 1.0, 0.0},
    {"degC", Dimension::temperature, 1.0, 273.15},
    {"degF", Dimension::temperature, 5.0 / 9.0, 273.15 - 32.0 * 5.0 / 9.0},
    {"m^3", Dimension::volume, 1.0, 0.0},
    {"cm^3", Dimension::volume, 1e-6, 0.0},
    {"mm^3", Dimension::volume, 1e-9, 0.0},
    {"mL", Dimension::volume, 1e-6, 0.0},
    {"L", Dimension::volume, 1e-3, 0.0},
    {"N/m", Dimension::stiffness, 1.0, 0.0},
    {"N/mm", Dimension::stiffness, 1e3, 0.0},
    {"kN/m", Dimension::stiffness, 1e3, 0.0},
    {"Pa", Dimension::modulus, 1.0, 0.0},
    {"MPa", Dimension::modulus, 1e6, 0.0},
    {"GPa", Dimension::modulus, 1e9, 0.0},
    {"N/m^2", Dimension::modulus, 1.0, 0.0},
    {"kg/mol", Dimension::molar_mass, 1.0, 0.0},
    {"g/mol", Dimension::molar_mass, 1e-3, 0.0},
    {"Pa s", Dimension::viscosity, 1.0, 0.0},
    {"mPa s", Dimension::viscosity, 1e-3, 0.0},
    {"uPa s", Dimension::viscosity, 1e-6, 0.0},
    {"P", Dimension::viscosity, 0.1, 0.0},
    {"cP", Dimension::viscosity, 1e-3, 0.0},
    {"1/s", Dimension::rate, 1.0, 0.0},
    {"1/min", Dimension::rate, 1.0 / 60.0, 0.0},
    {"1/(s rad)", Dimension::rate_per_angle, 1.0, 0.0},
    {"1/(s deg)", Dimension::rate_per_angle, 1.0 / kRadiansPerDegree, 0.0},
    {"m/s^2", Dimension::acceleration, 1.0, 0.0},
    {"cm/s^2", Dimension::acceleration, 1e-2, 0.0},
    {"Gal", Dimension::acceleration, 1e-2, 0.0},
    {"mGal", Dimension::acceleration, 1e-5, 0.0},
    {"s/day", Dimension::daily_rate, 1.0, 0.0},
    {"ms/day", Dimension::daily_rate, 1e-3, 0.0},
    {"kg/m^3", Dimension::density, 1.0, 0.0},
    {"g/cm^3", Dimension::density, 1e3, 0.0},
    {"1/K", Dimension::expansion, 1.0, 0.0},
    {"1/degC", Dimension::expansion, 1.0, 0.0},
}};

/// Spellings people type for a unit of the table (issue 14), and the unit.
struct Alias {
  const char* spelling;
  const char* name;
  Dimension dimension;
};
constexpr Alias kAliases[] = {
    {"sec", "s", Dimension::time},          {"secs", "s", Dimension::time},
    {"degree", "deg", Dimension::angle},    {"degrees", "deg", Dimension::angle},
    {"\xc2\xb0", "deg", Dimension::angle},  // the degree sign
    {"C", "degC", Dimension::temperature},  {"\xc2\xb0" "C", "degC", Dimension::temperature},
    {"F", "degF", Dimension::temperature},  {"\xc2\xb0" "F", "degF", Dimension::temperature},
};

}  // namespace

std::optional<Unit> find_unit(const std::string& name, Dimension dimension) {
  std::string canonical = name;
  for (const auto& a : kAliases) {
    if (a.dimension == dimension && name == a.spelling) canonical = a.name;
  }
  for (const auto& u : kUnits) {
    if (u.dimension == dimension && canonical == u.name) return u;
  }
  return std::nullopt;
}

const char* si_unit(Dimension dimension) {
  switch (dimension) {
    case Dimension::length: return "m";
    case Dimension::mass: return "kg";
    case Dimension::time: return "s";
    case Dimension::angle: return "rad";
    case Dimension::pressure: return "Pa";
    case Dimension::temperature: return "K";
    case Dimension::volume: return "m^3";
    case Dimension::stiffness: return "N/m";
    case Dimension::modulus: return "Pa";
    case Dimension::molar_mass: return "kg/mol";
    case Dimension::viscosity: return "Pa s";
    case Dimension::rate: return "1/s";
    case Dimension::rate_per_angle: return "1/(s rad)";
    case Dimension::acceleration: return "m/s^2";
    case Dimension::daily_rate: return "s/day";
    case Dimension::density: return "kg/m^3";
    case Dimension::expansion: return "1/K";
  }
  return "";
}

const char* dimension_name(Dimension dimension) {
  switch (dimension) {
    case Dimension::length: return "a length";
    case Dimension::mass: return "a mass";
    case Dimension::time: return "a time";
    case Dimension::angle: return "an angle";
    case Dimension::pressure: return "a pressure";
    case Dimension::temperature: return "a temperature";
    case Dimension::volume: return "a volume";
    case Dimension::stiffness: return "a stiffness";
    case Dimension::modulus: return "an elastic modulus";
    case Dimension::molar_mass: return "a molar mass";
    case Dimension::viscosity: return "a dynamic viscosity";
    case Dimension::rate: return "a rate";
    case Dimension::rate_per_angle: return "a rate per angle";
    case Dimension::acceleration: return "an acceleration";
    case Dimension::daily_rate: return "a daily rate";
    case Dimension::density: return "a density";
    case Dimension::expansion: return "a linear expansion coefficient";
  }
  return "";
}

std::string unit_names(Dimension dimension) {
  std::string out;
  for (const auto& u : kUnits) {
    if (u.dimension != dimension) continue;
    if (!out.empty()) out += ", ";
    out += u.name;
  }
  return out;
}

}  // namespace pendulum
