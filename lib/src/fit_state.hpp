#pragma once
/// \file fit_state.hpp
/// \brief What a period model's own results read of its fit at the optimum
/// (Model::report, docs/core.md): the scene, the parameters, which were
/// fitted, and their covariances.

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <Eigen/Dense>
#include <ceres/jet.h>

#include "pendulum/analysis_options.hpp"
#include "pendulum/estimate.hpp"
#include "pendulum/parsed_scene.hpp"

namespace pendulum {

template <int P>
struct FitState {
  using Matrix = Eigen::Matrix<double, P, P>;
  const ParsedScene& scene;
  const AnalysisOptions& options;
  std::array<double, P> p;       ///< the optimum (SI, g first), canonicalised
  std::array<bool, P> fitted;    ///< which parameters the fit varied
  Matrix covariance;             ///< of the parameters, every input propagated
  Matrix inverse;                ///< (J^T W J)^-1 of the weighted residuals
  bool singular;                 ///< J^T J singular: no uncertainties

  std::optional<double> deviation(double variance) const {
    if (singular) return std::nullopt;
    return std::sqrt(std::max(variance, 0.0));
  }

  /// A function of the parameters with its uncertainty from their covariance.
  template <class F>
  Estimate derived_estimate(F&& f) const {
    using JetP = ceres::Jet<double, P>;
    std::array<JetP, P> q;
    for (int i = 0; i < P; ++i) q[i] = JetP(p[i], i);
    const JetP v = f(q.data());
    return {v.a, deviation(v.v.dot(covariance * v.v))};
  }
};

}  // namespace pendulum
