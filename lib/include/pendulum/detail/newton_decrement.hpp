#pragma once
// pendulum-g's compressed least-squares fits (the decay fit, the period
// fit): their residuals from the normal sums, and their stopping rule.

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <ceres/cost_function.h>
#include <ceres/iteration_callback.h>

namespace pendulum {

/// A least-squares problem of N parameters "compressed": with J^T J = R^T R
/// (N x N), the N + 1 residuals q = R^-T J^T r and sqrt(|r|^2 - |q|^2),
/// whose Jacobian is [R; 0], have the same cost |r|^2, gradient J^T r and
/// Gauss-Newton matrix J^T J as the full problem, so Levenberg-Marquardt
/// takes the same steps while Ceres's own work no longer grows with the
/// number of residuals (docs/decay_fit.md). R is the Cholesky factor of the
/// column-scaled J^T J, whose condition is that of the parameters'
/// correlations alone, with a ridge of 1e-14 on its unit diagonal so that a
/// singular problem (identical observations) still steps; the gradient
/// R^T q = J^T r stays exact. Writes the residuals, and where `jacobian` is
/// given Ceres's row-major (N + 1) x N block; returns |q|^2 (twice the cost
/// a full Gauss-Newton step would remove), or a negative number where the
/// sums are not finite or J^T J is not positive definite.
template <int N>
double compress_residuals(const Eigen::Matrix<double, N, N>& jtj, const Eigen::Matrix<double, N, 1>& jtr, double rr,
                          double* residuals, double* jacobian) {
  using Matrix = Eigen::Matrix<double, N, N>;
  if (!jtj.allFinite() || !jtr.allFinite() || !std::isfinite(rr)) return -1.0;
  Eigen::Matrix<double, N, 1> scale = jtj.diagonal().cwiseSqrt();
  scale = (scale.array() > 0.0).select(scale.cwiseInverse(), 1.0);
  Matrix scaled = scale.asDiagonal() * jtj * scale.asDiagonal();
  scaled.diagonal().array() += 1e-14;
  const Eigen::LLT<Matrix> llt(scaled);
  if (llt.info() != Eigen::Success) return -1.0;
  const Matrix r_factor = Matrix(llt.matrixU()) * scale.cwiseInverse().asDiagonal();
  const Eigen::Matrix<double, N, 1> q = r_factor.transpose().template triangularView<Eigen::Lower>().solve(jtr);
  for (int i = 0; i < N; ++i) residuals[i] = q[i];
  residuals[N] = std::sqrt(std::max(rr - q.squaredNorm(), 0.0));
  if (jacobian) {
    constexpr int kLayout = N == 1 ? Eigen::ColMajor : Eigen::RowMajor;  // one column: the same either way
    Eigen::Map<Eigen::Matrix<double, N + 1, N, kLayout>> jac(jacobian);
    jac.template topRows<N>() = r_factor;
    jac.row(N).setZero();
  }
  return q.squaredNorm();
}

/// A cost of N parameters in one block whose N + 1 residuals are the
/// compressed ones of its normal sums (compress_residuals). It keeps what
/// NewtonDecrement judges: at the last point whose Jacobian Ceres asked for
/// (its current iterate), |q|^2 = r^T J (J^T J)^-1 J^T r, twice the cost a
/// full Gauss-Newton step would still remove, |r|^2, and the point.
template <int N>
class CompressedCost : public ceres::CostFunction {
 public:
  double decrement() const { return decrement_; }
  double rr() const { return rr_; }
  const std::array<double, N>& judged() const { return judged_; }

 protected:
  CompressedCost() {
    set_num_residuals(N + 1);
    mutable_parameter_block_sizes()->push_back(N);
  }

  /// Evaluate's work from the sums at `p`: false where they cannot be compressed.
  bool compressed(const double* p, const Eigen::Matrix<double, N, N>& jtj, const Eigen::Matrix<double, N, 1>& jtr,
                  double rr, double* residuals, double** jacobians) const {
    double* jacobian = jacobians ? jacobians[0] : nullptr;
    const double q2 = compress_residuals<N>(jtj, jtr, rr, residuals, jacobian);
    if (q2 < 0.0) return false;
    if (jacobian) {
      decrement_ = q2;
      rr_ = rr;
      std::copy(p, p + N, judged_.begin());
    }
    return true;
  }

 private:
  mutable double decrement_ = 0.0, rr_ = 0.0;
  mutable std::array<double, N> judged_{};
};

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
