#include "pendulum/period_fit.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <Eigen/Dense>
#include <ceres/ceres.h>

#include "newton_decrement.hpp"
#include "pendulum/models/simple_pendulum.hpp"

namespace pendulum {

namespace {

/// The sums of a weighted least-squares problem at one point: J^T J, J^T r
/// and r^T r over the K observations.
template <int P>
struct NormalSums {
  Eigen::Matrix<double, P, P> jtj = Eigen::Matrix<double, P, P>::Zero();
  Eigen::Matrix<double, P, 1> jtr = Eigen::Matrix<double, P, 1>::Zero();
  double rr = 0.0;
};

/// Every observation's weighted residual r_k = (T_model,k - T_k) w_k in one
/// cost function, handed to Ceres "compressed" as in the decay fit
/// (docs/decay_fit.md): with J^T J = R^T R, the P + 1 residuals
/// q = R^-T J^T r and sqrt(|r|^2 - |q|^2), whose Jacobian is [R; 0], have the
/// same cost, gradient and Gauss-Newton matrix as the K residuals, so the
/// iterates are the same while Ceres's own work no longer grows with K. The
/// sums at a point are computed once (a trial step's residuals and the
/// accepted point's Jacobian are the same evaluation).
template <class Model>
class CompressedPeriodResiduals : public ceres::CostFunction {
 public:
  static constexpr int P = Model::kParameters;
  using Jet = ceres::Jet<double, P>;
  using Matrix = Eigen::Matrix<double, P, P>;

  explicit CompressedPeriodResiduals(const PeriodFitProblem<Model>& problem)
      : problem_(problem),
        apparatus_jet_(convert_apparatus<Jet>(*problem.apparatus, [](const Field&, double x) { return Jet(x); })) {
    set_num_residuals(P + 1);
    mutable_parameter_block_sizes()->push_back(P);
    observations_jet_.reserve(problem.observations->size());
    for (const auto& o : *problem.observations) {
      observations_jet_.push_back(convert_observation<Jet>(o, [](const Field&, double x) { return Jet(x); }));
    }
  }

  /// The sums at p; held parameters' rows and columns are the identity's, so
  /// that they stay decoupled (their J^T r is 0).
  const NormalSums<P>& sums(const double* p) const {
    if (cached_ && std::equal(p, p + P, cached_p_.begin())) return sums_;
    std::array<Jet, P> pj;
    for (int i = 0; i < P; ++i) pj[i] = Jet(p[i], i);
    const auto& obs = *problem_.observations;
    NormalSums<P> s;
    for (std::size_t k = 0; k < obs.size(); ++k) {
      const Jet t = Model::period(pj.data(), observations_jet_[k], apparatus_jet_, (*problem_.amplitude)[k]);
      const double w = (*problem_.weights)[k];
      const double r = (t.a - obs[k].period) * w;
      const Eigen::Matrix<double, P, 1> j = t.v * w;
      s.jtj.noalias() += j * j.transpose();
      s.jtr += j * r;
      s.rr += r * r;
    }
    for (int i = 0; i < P; ++i) {
      if (!problem_.fitted[i]) s.jtj.row(i).setZero(), s.jtj.col(i).setZero(), s.jtj(i, i) = 1.0, s.jtr(i) = 0.0;
    }
    std::copy(p, p + P, cached_p_.begin());
    cached_ = true;
    sums_ = s;
    return sums_;
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const NormalSums<P>& s = sums(parameters[0]);
    if (!s.jtj.allFinite() || !s.jtr.allFinite() || !std::isfinite(s.rr)) return false;
    // R from the Cholesky factor of the column-scaled J^T J, with a ridge of
    // 1e-14 on its unit diagonal so that a singular problem (identical
    // observations) still steps; the gradient R^T q = J^T r stays exact.
    Eigen::Matrix<double, P, 1> scale = s.jtj.diagonal().cwiseSqrt();
    scale = (scale.array() > 0.0).select(scale.cwiseInverse(), 1.0);
    Matrix scaled = scale.asDiagonal() * s.jtj * scale.asDiagonal();
    scaled.diagonal().array() += 1e-14;
    const Eigen::LLT<Matrix> llt(scaled);
    if (llt.info() != Eigen::Success) return false;
    const Matrix r_factor = Matrix(llt.matrixU()) * scale.cwiseInverse().asDiagonal();
    const Eigen::Matrix<double, P, 1> q = r_factor.transpose().template triangularView<Eigen::Lower>().solve(s.jtr);
    for (int i = 0; i < P; ++i) residuals[i] = q[i];
    residuals[P] = std::sqrt(std::max(s.rr - q.squaredNorm(), 0.0));
    if (jacobians && jacobians[0]) {
      decrement_ = q.squaredNorm();
      rr_ = s.rr;
      Eigen::Map<Eigen::Matrix<double, P + 1, P, Eigen::RowMajor>> jac(jacobians[0]);
      jac.template topRows<P>() = r_factor;
      jac.row(P).setZero();
    }
    return true;
  }

 private:
  const PeriodFitProblem<Model>& problem_;
  const Apparatus<Jet> apparatus_jet_;
  std::vector<Observation<Jet>> observations_jet_;  ///< constants, converted once
  mutable bool cached_ = false;
  mutable std::array<double, P> cached_p_{};
  mutable NormalSums<P> sums_;
  mutable double decrement_ = 0.0, rr_ = 0.0;

 public:
  /// At the last point whose Jacobian Ceres asked for: |q|^2 = r^T J
  /// (J^T J)^-1 J^T r, twice the cost a full Gauss-Newton step would still
  /// remove, and |r|^2 (NewtonDecrement).
  double decrement() const { return decrement_; }
  double rr() const { return rr_; }
};

}  // namespace

template <class Model>
PeriodFitSolution fit_periods(const PeriodFitProblem<Model>& problem,
                              const std::array<double, Model::kParameters>& initial) {
  constexpr int P = Model::kParameters;
  std::array<double, P> p = initial;
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem ceres_problem(problem_options);
  CompressedPeriodResiduals<Model> residuals(problem);
  ceres_problem.AddResidualBlock(&residuals, nullptr, p.data());
  std::vector<int> held;
  for (int i = 0; i < P; ++i) {
    if (!problem.fitted[i]) held.push_back(i);
  }
  if (static_cast<int>(held.size()) == P) {
    ceres_problem.SetParameterBlockConstant(p.data());
  } else if (!held.empty()) {
    ceres_problem.SetManifold(p.data(), new ceres::SubsetManifold(P, held));
  }
  // g stays positive: the model's sqrt(l/g) has no meaning below.
  ceres_problem.SetParameterLowerBound(p.data(), 0, 1e-6 * initial[0]);

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;  // on the P + 1 compressed residuals
  options.max_num_iterations = 200;
  // NewtonDecrement decides; Ceres's tolerances, at the last digits, only
  // stop a stalled fit.
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-30;
  options.parameter_tolerance = 1e-15;
  options.logging_type = ceres::SILENT;
  int free = 0;
  for (int i = 0; i < P; ++i) free += problem.fitted[i];
  NewtonDecrement<CompressedPeriodResiduals<Model>> converged(
      residuals, static_cast<int>(problem.observations->size()) - free);
  options.callbacks.push_back(&converged);
  ceres::Solver::Summary summary;
  ceres::Solve(options, &ceres_problem, &summary);

  PeriodFitSolution out;
  out.parameters.assign(p.begin(), p.end());
  // (J^T J)^-1 over the fitted parameters at the optimum, judged singular
  // on its column-scaled form, which the parameters' units do not affect.
  const Eigen::Matrix<double, P, P> jtj = residuals.sums(p.data()).jtj;
  const Eigen::Matrix<double, P, 1> scale = jtj.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, P, P>> eigen(scale.asDiagonal() * jtj * scale.asDiagonal());
  if (scale.allFinite() && eigen.eigenvalues().minCoeff() > 1e-12 * eigen.eigenvalues().maxCoeff()) {
    Eigen::Matrix<double, P, P, Eigen::RowMajor> c = jtj.inverse();
    for (int i = 0; i < P; ++i) {
      if (!problem.fitted[i]) c.row(i).setZero(), c.col(i).setZero();
    }
    out.covariance.assign(c.data(), c.data() + P * P);
  }
  out.chi2 = 2.0 * summary.final_cost;
  out.converged = summary.termination_type == ceres::CONVERGENCE || summary.termination_type == ceres::USER_SUCCESS;
  out.termination = summary.message;
  out.iterations = static_cast<int>(summary.iterations.size()) - 1;
  return out;
}

template PeriodFitSolution fit_periods<SimplePendulum>(const PeriodFitProblem<SimplePendulum>&,
                                                        const std::array<double, 2>&);

StraightLine fit_straight_line(const std::vector<double>& x, const std::vector<double>& y,
                               const std::vector<double>& sigma_x, const std::vector<double>& sigma_y,
                               bool with_intercept) {
  StraightLine line{0.0, 0.0, 0.0, 0.0, 0.0};
  // Effective variance: the slope of the unweighted-in-x fit first, then
  // once more with sigma_y^2 + slope^2 sigma_x^2. Points stated without
  // uncertainty take the smallest variance of the others; with none stated
  // at all, the line is exact (variances 0).
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<double> var(x.size());
    double smallest = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      var[i] = sigma_y[i] * sigma_y[i] + line.slope * line.slope * sigma_x[i] * sigma_x[i];
      if (var[i] > 0.0 && (smallest == 0.0 || var[i] < smallest)) smallest = var[i];
    }
    const double scale = smallest > 0.0 ? 1.0 : 0.0;
    double s = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double w = smallest > 0.0 ? 1.0 / std::max(var[i], smallest) : 1.0;
      s += w;
      sx += w * x[i];
      sy += w * y[i];
      sxx += w * x[i] * x[i];
      sxy += w * x[i] * y[i];
    }
    if (with_intercept) {
      const double det = s * sxx - sx * sx;
      line.slope = (s * sxy - sx * sy) / det;
      line.intercept = (sxx * sy - sx * sxy) / det;
      line.var_slope = scale * s / det;
      line.var_intercept = scale * sxx / det;
      line.cov = -scale * sx / det;
    } else {
      line.slope = sxy / sxx;
      line.var_slope = scale / sxx;
    }
  }
  return line;
}

}  // namespace pendulum
