#include "pendulum/period_fit.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <Eigen/Dense>
#include <ceres/ceres.h>

#include "pendulum/models/physical_pendulum.hpp"
#include "pendulum/models/simple_pendulum.hpp"

namespace pendulum {

namespace {

/// Every observation's weighted residual in one cost function: one block of
/// K residuals, so that Ceres's cost per observation is the model's alone.
template <class Model>
class PeriodResiduals : public ceres::CostFunction {
 public:
  static constexpr int P = Model::kParameters;
  using Jet = ceres::Jet<double, P>;

  explicit PeriodResiduals(const PeriodFitProblem<Model>& problem)
      : problem_(problem),
        apparatus_jet_(convert_apparatus<Jet>(*problem.apparatus, [](const Field&, double x) { return Jet(x); })) {
    set_num_residuals(static_cast<int>(problem.observations->size()));
    mutable_parameter_block_sizes()->push_back(P);
    observations_jet_.reserve(problem.observations->size());
    for (const auto& o : *problem.observations) {
      observations_jet_.push_back(convert_observation<Jet>(o, [](const Field&, double x) { return Jet(x); }));
    }
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const double* p = parameters[0];
    const auto& obs = *problem_.observations;
    const auto& w = *problem_.weights;
    const auto& amplitude = *problem_.amplitude;
    if (jacobians == nullptr || jacobians[0] == nullptr) {
      for (std::size_t k = 0; k < obs.size(); ++k) {
        const double t = Model::period(p, obs[k], *problem_.apparatus, amplitude[k]);
        residuals[k] = (t - obs[k].period) * w[k];
      }
      return std::isfinite(residuals[0]);
    }
    std::array<Jet, P> pj;
    for (int i = 0; i < P; ++i) pj[i] = Jet(p[i], i);
    for (std::size_t k = 0; k < obs.size(); ++k) {
      const Jet t = Model::period(pj.data(), observations_jet_[k], apparatus_jet_, amplitude[k]);
      residuals[k] = (t.a - obs[k].period) * w[k];
      for (int i = 0; i < P; ++i) jacobians[0][k * P + i] = t.v[i] * w[k];
      if (!std::isfinite(residuals[k])) return false;
    }
    return true;
  }

 private:
  const PeriodFitProblem<Model>& problem_;
  const Apparatus<Jet> apparatus_jet_;
  std::vector<Observation<Jet>> observations_jet_;  ///< constants, converted once
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
  PeriodResiduals<Model> residuals(problem);
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
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 200;
  // To the last digits: the optimum is where the tests and the propagation
  // (implicit-function derivatives) need it.
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-30;
  options.parameter_tolerance = 1e-15;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &ceres_problem, &summary);

  PeriodFitSolution out;
  out.parameters.assign(p.begin(), p.end());
  // (J^T J)^-1 over the fitted parameters from the Jacobian at the optimum.
  const std::size_t k = problem.observations->size();
  std::vector<double> r(k), jacobian(k * P);
  const double* blocks[] = {p.data()};
  double* jacobians[] = {jacobian.data()};
  Eigen::Matrix<double, P, P> jtj = Eigen::Matrix<double, P, P>::Zero();
  if (residuals.Evaluate(blocks, r.data(), jacobians)) {
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, P, Eigen::RowMajor>> j(jacobian.data(), k, P);
    jtj = j.transpose() * j;
  }
  for (int i = 0; i < P; ++i) {
    if (!problem.fitted[i]) jtj.row(i).setZero(), jtj.col(i).setZero(), jtj(i, i) = 1.0;
  }
  const Eigen::LDLT<Eigen::Matrix<double, P, P>> ldlt(jtj);
  if (ldlt.info() == Eigen::Success && ldlt.isPositive() && ldlt.vectorD().minCoeff() > 1e-12 * ldlt.vectorD().maxCoeff()) {
    Eigen::Matrix<double, P, P, Eigen::RowMajor> c = ldlt.solve(Eigen::Matrix<double, P, P>::Identity());
    for (int i = 0; i < P; ++i) {
      if (!problem.fitted[i]) c.row(i).setZero(), c.col(i).setZero();
    }
    out.covariance.assign(c.data(), c.data() + P * P);
  }
  out.chi2 = 2.0 * summary.final_cost;
  out.converged = summary.termination_type == ceres::CONVERGENCE;
  out.termination = summary.message;
  out.iterations = static_cast<int>(summary.iterations.size()) - 1;
  return out;
}

template PeriodFitSolution fit_periods<SimplePendulum>(const PeriodFitProblem<SimplePendulum>&,
                                                        const std::array<double, 2>&);
template PeriodFitSolution fit_periods<PhysicalPendulum>(const PeriodFitProblem<PhysicalPendulum>&,
                                                          const std::array<double, 3>&);

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
