#pragma once
// Checks that need the corrections: each first-order correction inside its
// theory's range, each period within reach of the pendulum's, and warnings
// about what is legal but suspicious (docs/robustness.md).

#include <string>
#include <vector>

#include "pendulum/parsed_scene.hpp"

namespace pendulum {

/// The words of the suspicion that the trials hold a frequency: the status
/// then names no slip for the ratio of g it makes (status.cpp).
inline constexpr const char* kFrequencyTyped = "a frequency (Hz) typed where trial times belong?";

/// Throws InputError naming the part whose correction leaves its
/// first-order range (|DeltaT/T0| >= its limit in kCorrections) for
/// observation o of a ball on a wire (reduce's rows).
void check_first_order(const Apparatus<double>& app, const Observation<double>& o);

/// check_first_order for every observation. The analysis runs it again on a
/// fitted decay.
void check_first_order(const ParsedScene& scene);

/// Refuses a period no laboratory's g explains and an amplitude in the other
/// angular unit; warns about what is legal but suspicious. Runs
/// check_first_order.
void check_plausibility(ParsedScene& scene);

/// Warnings about corrections skipped for a part a ball's scene does not
/// describe that would not be negligible for typical values: room air (20
/// degC, 101.325 kPa) where the scene gives no air, a steel bob (7850
/// kg/m^3) of the given diameter where it gives no bob mass, a steel and a
/// wooden ball where it gives neither. Negligible as in the analysis: below
/// `negligible_fraction` of the period's uncertainty.
std::vector<std::string> warn_about_skipped_ball_parts(const ParsedScene& scene, double negligible_fraction);

/// A box or cylinder bob in air carries an added mass no row models (Eqs.
/// 54-62 are a sphere's): a warning where its estimate, the potential flow's
/// about an elliptic section across the swing (unmodelled_added_mass), would
/// lengthen some period by more than `negligible_fraction` of its uncertainty.
std::optional<std::string> warn_about_unmodelled_added_mass(const ParsedScene& scene, double negligible_fraction);

/// A body on a string at its own amplitude near its two modes' 3:1
/// resonance, where the slow mode's psi0^4 coefficient (mass.hpp,
/// slow_mode_amplitude_series) grows without bound: a warning where it lies
/// beyond twice what the nonlinear check covered and its term exceeds
/// `negligible_fraction` of a period's relative uncertainty.
std::optional<std::string> warn_about_mode_resonance(const ParsedScene& scene, double negligible_fraction);

}  // namespace pendulum
