#pragma once
// The stopping rule of pendulum-g's compressed least-squares fits (the decay
// fit, the period fit).

#include <algorithm>

#include <ceres/iteration_callback.h>

namespace pendulum {

/// Stops when a full Gauss-Newton step would lower the sum of squares by
/// less than 1e-14 of the residual variance s^2 = |r|^2/dof: the parameters
/// are then within about 1e-7 of their standard uncertainties from the
/// optimum, whatever the scale of the residuals. (Ceres's own relative
/// function tolerance stops too early on large sums, or never on noise.)
/// `Cost` is a compressed least-squares cost: decrement() = |q|^2 and rr() =
/// |r|^2 at the last point whose Jacobian Ceres asked for.
template <class Cost>
class NewtonDecrement final : public ceres::IterationCallback {
 public:
  NewtonDecrement(const Cost& cost, int dof) : cost_(cost), dof_(std::max(dof, 1)) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    return cost_.decrement() <= 1e-14 * cost_.rr() / dof_ ? ceres::SOLVER_TERMINATE_SUCCESSFULLY
                                                          : ceres::SOLVER_CONTINUE;
  }

 private:
  const Cost& cost_;
  int dof_;
};

}  // namespace pendulum
