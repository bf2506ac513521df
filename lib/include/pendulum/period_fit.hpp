#pragma once
/// \file period_fit.hpp
/// \brief One Ceres fit of any period model (period_model.hpp) to any number
/// of observations: weighted least squares of the periods, with automatic
/// derivatives. g is projected out (every model's period is g^-1/2 times a
/// function of its other parameters), so Ceres varies the others alone
/// (docs/core.md). The uncertainties are the analysis's (analysis.hpp), which
/// propagates every input through the fit's optimum.

#include <array>
#include <string>
#include <vector>

#include "pendulum/amplitude.hpp"
#include "pendulum/apparatus.hpp"
#include "pendulum/models/physical_pendulum.hpp"
#include "pendulum/models/simple_pendulum.hpp"
#include "pendulum/observation.hpp"

namespace pendulum {

/// The data of a period fit; the pointers outlive the fit.
template <class Model>
struct PeriodFitProblem {
  const Apparatus<double>* apparatus;
  const std::vector<Observation<double>>* observations;
  const std::vector<AmplitudeChoice>* amplitude;  ///< one per observation
  /// 1 / (the period's standard uncertainty) of each observation (1/s).
  const std::vector<double>* weights;
  std::array<bool, Model::kParameters> fitted;  ///< g always; the others are held at `initial`
};

struct PeriodFitSolution {
  std::vector<double> parameters;  ///< SI, in the model's order
  /// (J^T W J)^-1 at the optimum: the parameters' covariance from the
  /// weights alone (row-major, zero rows for held ones); empty when singular
  /// or not asked for (the analysis propagates g's uncertainty itself).
  std::vector<double> covariance;
  bool converged = false;
  std::string termination;  ///< Ceres's message
  int iterations = 0;
};

/// Minimises sum_k [(T_model,k(p) - T_k) w_k]^2 over the fitted parameters:
/// g in closed form for given others, the others by Levenberg-Marquardt from
/// `initial` (g's start is not used), until a Gauss-Newton step would remove
/// less than 1e-14 of the residual variance (the tests recover noiseless
/// parameters to 1e-12). The covariance only `with_covariance`.
template <class Model>
PeriodFitSolution fit_periods(const PeriodFitProblem<Model>& problem,
                              const std::array<double, Model::kParameters>& initial, bool with_covariance = false);

extern template PeriodFitSolution fit_periods<SimplePendulum>(const PeriodFitProblem<SimplePendulum>&,
                                                               const std::array<double, 2>&, bool);
extern template PeriodFitSolution fit_periods<PhysicalPendulum>(const PeriodFitProblem<PhysicalPendulum>&,
                                                                 const std::array<double, 3>&, bool);

/// A weighted straight line y = slope x + intercept (intercept 0 when
/// `with_intercept` is false) with the effective-variance weights
/// sigma_y^2 + slope^2 sigma_x^2 (one refinement of the slope), and the
/// parameters' covariance.
struct StraightLine {
  double slope, intercept;
  double var_slope, var_intercept, cov;
};
StraightLine fit_straight_line(const std::vector<double>& x, const std::vector<double>& y,
                               const std::vector<double>& sigma_x, const std::vector<double>& sigma_y,
                               bool with_intercept);

}  // namespace pendulum
