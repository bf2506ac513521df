#pragma once
// Checks that need the corrections: each first-order correction inside its
// theory's range, each period within reach of the pendulum's, and warnings
// about what is legal but suspicious (docs/robustness.md).

#include "pendulum/parsed_scene.hpp"

namespace pendulum {

/// Throws InputError naming the part whose correction leaves its
/// first-order range (|DeltaT/T0| >= its limit in kCorrections) for any
/// observation. The analysis runs it again on a fitted decay.
void check_first_order(const ParsedScene& scene);

/// Refuses a period no laboratory's g explains and an amplitude in the other
/// angular unit; warns about what is legal but suspicious. Runs
/// check_first_order.
void check_plausibility(ParsedScene& scene);

}  // namespace pendulum
