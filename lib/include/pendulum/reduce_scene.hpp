#pragma once
/// \file reduce_scene.hpp
/// \brief What `pendulum-g reduce` gives for a scene: analyse()'s fit and
/// budget, GUM Supplement 1's g where asked for (monte_carlo.hpp), and the
/// verdict on them (judge(), status.hpp). Each layer reads the one below:
/// the analysis knows neither the draws nor the verdict.

#include "pendulum/analysis.hpp"

namespace pendulum {

/// analyse(), then the Monte Carlo that `options` or the scene's
/// "uncertainty" asks for (a warning where it gives no result or does not
/// validate GUM's interval), then judge() into Analysis::status.
Analysis reduce_scene(const ParsedScene& scene, const AnalysisOptions& options = {});

}  // namespace pendulum
