#include "pendulum/slips.hpp"

#include <cmath>

#include "pendulum/air.hpp"
#include "text.hpp"

namespace pendulum {

namespace {

/// A slip and the ratio it makes g / true g, from g = 4 pi^2 L / T^2.
struct Slip {
  double ratio;
  const char* text;
};
constexpr Slip kSlips[] = {
    // Period T/2: g x 4; period 2T: g / 4.
    {4.0, "the period is half the true one, as when half swings are counted as oscillations (an oscillation is "
          "a full swing, there and back): halve timing.oscillations_per_trial"},
    {0.25, "the period is twice the true one, as when timing.oscillations_per_trial is half the oscillations "
           "timed (an oscillation is a full swing, there and back): double it"},
    // Length x10: g x 10.
    {10.0, "the length is 10 times too long, as when a length in mm is written as cm: fix length.unit"},
    {0.1, "the length is 10 times too short, as when a length in cm is written as mm: fix length.unit"},
    // Length x100: g x 100; period T/10: g x 100.
    {100.0, "the length is 100 times too long, as when a length in cm is written as m (fix length.unit), or the "
            "period 10 times too short, as when one period per trial is typed with oscillations_per_trial 10 "
            "(fix timing.oscillations_per_trial)"},
    {0.01, "the length is 100 times too short, as when a length in m is written as cm (fix length.unit), or the "
           "period 10 times too long, as when trials of 10 oscillations are typed with oscillations_per_trial 1 "
           "(fix timing.oscillations_per_trial)"},
    {1e3, "the length is 1000 times too long, as when a length in mm is written as m: fix length.unit"},
    {1e-3, "the length is 1000 times too short, as when a length in m is written as mm: fix length.unit"},
    // Trials in min written as s: T/60, g x 3600; ms written as s: 1000 T, g / 1e6.
    {3600.0, "the period is 60 times too short, as when trials in min are written as s: fix timing.unit"},
    {1.0 / 3600.0, "the period is 60 times too long, as when trials in s are written as min: fix timing.unit"},
    {1e6, "the period is 1000 times too short, as when trials in s are written as ms: fix timing.unit"},
    {1e-6, "the period is 1000 times too long, as when trials in ms are written as s: fix timing.unit"},
    // A uniform rod (or beam) of length L pivoted at its end: I = m L^2/3, its
    // centre L/2 below, an equivalent length I/(m L/2) = 2L/3, so L for it
    // gives g x 3/2 (Coramik & Inanc 2023's Lego beams came out at x 1.50).
    {1.5, "the lengths are those of a uniform rod or beam pivoted at its end, which swings as a simple pendulum "
          "two thirds as long (its centre L/2 below the pivot, k^2 = L^2/12): give each as rod_length "
          "(a table's column \"rod length\", or --columns \"r:cm,T\"; docs/physical.md) instead of a length"},
    // Inches: 1 m is 39.37 in.
    {1.0 / 0.0254, "the length is 39.37 times too long, as when a length in inches is written as m: fix length.unit "
                   "(\"in\")"},
    {0.01 / 0.0254, "the length is 2.54 times too short, as when a length in inches is written as cm: fix "
                    "length.unit (\"in\")"},
};
/// A slip fits when g's ratio is within this factor of the slip's: hand
/// timing and the corrections move g by a few percent, no slip by less than
/// x1.5 (the rod's), which keeps 1.30 to 1.73 clear of 1.
constexpr double kSlipTolerance = 1.15;

/// Below this a bob is lighter than any solid ball a pendulum swings (a
/// ping-pong ball is about 80 kg/m^3, cork 240, wood 500).
constexpr double kLightestBob = 50.0;     // (kg/m^3)
constexpr double kDensestBob = 22590.0;   // osmium (kg/m^3)
constexpr double kLightestSolid = 500.0;  // wood (kg/m^3)

}  // namespace

std::optional<std::string> bob_density_slip(const Apparatus<double>& app) {
  if (!app.bob || !app.bob->mass) return std::nullopt;
  const double density = *app.bob->mass / app.bob->volume();
  const bool sphere = app.bob->shape == BobShape::sphere;
  const double air = app.air ? air_density(app.air->pressure, app.air->temperature, app.air->molar_mass) : 0.0;
  if (density >= kLightestBob && density > air) return std::nullopt;
  std::string why = "bob.mass: a density of " + format_number(density, 3) +
                    " kg/m^3 (the mass over the " + (sphere ? "sphere of bob.diameter), " : "bob's volume), ");
  why += density <= air ? "less than the air's " + format_number(air, 3) + " kg/m^3: the bob would float"
                        : "lighter than any solid ball a pendulum swings (a ping-pong ball: about 80 kg/m^3), "
                          "which makes buoyancy and added mass implausibly large";
  const double thousandfold = density * 1000.0;
  if (thousandfold >= kLightestSolid && thousandfold <= kDensestBob) {
    why += "; a mass in kg written as g, or a diameter in mm written as cm? Either gives " +
           std::to_string(std::lround(thousandfold)) + " kg/m^3 (steel: 7850): fix bob.mass.unit or bob." +
           (sphere ? "diameter" : "width, height or depth") + ".unit";
  } else {
    why += std::string("; check bob.mass, bob.") + (sphere ? "diameter" : "width, height, depth") + " and their units";
  }
  return why;
}

std::optional<std::string> name_slip(double ratio) {
  if (!(ratio > 0.0) || !std::isfinite(ratio)) return std::nullopt;
  for (const Slip& s : kSlips) {
    if (ratio < s.ratio * kSlipTolerance && ratio > s.ratio / kSlipTolerance) return std::string(s.text);
  }
  return std::nullopt;
}

}  // namespace pendulum
