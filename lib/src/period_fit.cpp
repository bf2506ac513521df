#include "pendulum/period_fit.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <Eigen/Dense>
#include <ceres/ceres.h>

#include "newton_decrement.hpp"
#include "pendulum/models/physical_pendulum.hpp"
#include "pendulum/models/simple_pendulum.hpp"

namespace pendulum {

namespace {

/// The sums of a weighted least-squares problem at one point: J^T J, J^T r
/// and r^T r over the K observations, J with respect to N parameters.
template <int N>
struct NormalSums {
  Eigen::Matrix<double, N, N> jtj = Eigen::Matrix<double, N, N>::Zero();
  Eigen::Matrix<double, N, 1> jtr = Eigen::Matrix<double, N, 1>::Zero();
  double rr = 0.0;
};

/// A swing of constants (its derivatives 0) on dual numbers.
template <class Jet>
Swing<Jet> dual_swing(const Swing<double>& s) {
  return {Jet(s.length), Jet(s.amplitude), Jet(s.omega), Jet(s.trial_duration), s.setting};
}

/// What a fit computes once: the apparatus on dual numbers of N components
/// and, per observation, its measured swing (Model::swing), period, weight
/// and amplitude method. The parameters reach the corrections through the
/// swing's length alone (period_model.hpp), so when none of the corrections
/// the apparatus applies reads the length (corrections_read_length, asked
/// once per fit), each observation's T/T0 is the same at every step and is
/// composed here, once, instead of at every evaluation.
template <class Model, int N>
struct FitData {
  using Jet = ceres::Jet<double, N>;
  struct Row {
    Swing<double> swing;
    double period, weight;  ///< s, 1/s
    const AmplitudeChoice* amplitude;
    double ratio;  ///< T/T0 when `fixed_ratio`
  };
  FitData(const PeriodFitProblem<Model>& problem, const std::array<double, Model::kParameters>& start)
      : apparatus(convert_apparatus<Jet>(*problem.apparatus, [](const Field&, double x) { return Jet(x); })) {
    const auto& obs = *problem.observations;
    const Apparatus<double>& app = *problem.apparatus;
    fixed_ratio = !obs.empty() &&
                  !corrections_read_length(app, Model::swing_at(start.data(), Model::swing(obs[0]), app),
                                           (*problem.amplitude)[0]);
    rows.reserve(obs.size());
    for (std::size_t k = 0; k < obs.size(); ++k) {
      const Swing<double> measured = Model::swing(obs[k]);
      const AmplitudeChoice& amplitude = (*problem.amplitude)[k];
      const double ratio =
          fixed_ratio ? 1.0 + Model::composition(app, Model::swing_at(start.data(), measured, app), amplitude).total
                      : 0.0;
      rows.push_back({measured, obs[k].period, (*problem.weights)[k], &amplitude, ratio});
    }
  }
  Apparatus<Jet> apparatus;
  std::vector<Row> rows;
  bool fixed_ratio;
};

/// g projected out (variable projection, Golub & Pereyra 1973). Every period
/// model's period is T = g^-1/2 h(q), q the other parameters: g enters only
/// the ideal period's sqrt(length/g), and the corrections' working frequency
/// comes from the measured period. With s = g^-1/2, the best s for given q
/// is closed form, s = A/B with A = sum w^2 T h, B = sum w^2 h^2, so Ceres
/// varies q alone, on dual numbers of P - 1 components, against the
/// residuals r_k = (s(q) h_k(q) - T_k) w_k, whose derivatives are
/// dr_k = w_k (h_k s' + s h'_k) with s' = (a - 2 s b)/B,
/// a = sum w^2 T h', b = sum w^2 h h'. One pass evaluates the model and the
/// four sums; a second forms r and dr from the stored h, h' (forming r^T r
/// as C - s A instead would cancel to 1e-7 of it).
template <class Model>
class ProjectedPeriods {
 public:
  static constexpr int P = Model::kParameters;
  static constexpr int Q = P - 1;  // the parameters after g
  using Jet = ceres::Jet<double, Q>;
  using VectorQ = Eigen::Matrix<double, Q, 1>;

  ProjectedPeriods(const PeriodFitProblem<Model>& problem, const std::array<double, P>& start)
      : problem_(problem), data_(problem, start) {}

  struct Point {
    double s;  ///< g^-1/2 at its best for q
    NormalSums<Q> sums;
  };

  /// The best s and the sums at q; held parameters' rows and columns are the
  /// identity's, so that they stay decoupled (their J^T r is 0).
  const Point& at(const double* q) const {
    if (cached_ && std::equal(q, q + Q, cached_q_.begin())) return point_;
    std::array<Jet, P> p;
    p[0] = Jet(1.0);  // g = 1: the period is h
    for (int i = 0; i < Q; ++i) p[i + 1] = problem_.fitted[i + 1] ? Jet(q[i], i) : Jet(q[i]);
    // Whether T/T0 was composed once is decided once per fit, outside the loop.
    const Sums sums = data_.fixed_ratio ? model_sums<true>(p) : model_sums<false>(p);
    const auto& rows = data_.rows;
    Point& pt = point_;
    pt.s = sums.big_a / sums.big_b;
    const double s = pt.s;
    const VectorQ ds = (sums.a - 2.0 * s * sums.b) / sums.big_b;
    pt.sums = NormalSums<Q>();
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const double r = (s * h_[k].a - rows[k].period) * rows[k].weight;
      const VectorQ j = (h_[k].a * ds + s * h_[k].v) * rows[k].weight;
      pt.sums.jtj.noalias() += j * j.transpose();
      pt.sums.jtr += j * r;
      pt.sums.rr += r * r;
    }
    for (int i = 0; i < Q; ++i) {
      if (!problem_.fitted[i + 1]) {
        pt.sums.jtj.row(i).setZero(), pt.sums.jtj.col(i).setZero(), pt.sums.jtj(i, i) = 1.0, pt.sums.jtr(i) = 0.0;
      }
    }
    std::copy(q, q + Q, cached_q_.begin());
    cached_ = true;
    return point_;
  }

 private:
  struct Sums {
    double big_a = 0.0, big_b = 0.0;
    VectorQ a = VectorQ::Zero(), b = VectorQ::Zero();
  };

  /// Each observation's h and h' at p (g = 1) into h_, and the sums A, B, a, b.
  template <bool kFixedRatio>
  Sums model_sums(const std::array<Jet, P>& p) const {
    Sums sums;
    const auto& rows = data_.rows;
    h_.resize(rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const auto& row = rows[k];
      const Swing<Jet> swing = Model::swing_at(p.data(), dual_swing<Jet>(row.swing), data_.apparatus);
      const Jet ideal = ideal_period(swing.length, 1.0);
      if constexpr (kFixedRatio) {
        h_[k] = ideal * row.ratio;
      } else {
        h_[k] = ideal * (1.0 + Model::composition(data_.apparatus, swing, *row.amplitude).total);
      }
      const double w2 = row.weight * row.weight;
      sums.big_a += w2 * row.period * h_[k].a;
      sums.big_b += w2 * h_[k].a * h_[k].a;
      sums.a += w2 * row.period * h_[k].v;
      sums.b += w2 * h_[k].a * h_[k].v;
    }
    return sums;
  }

  const PeriodFitProblem<Model>& problem_;
  const FitData<Model, Q> data_;
  mutable bool cached_ = false;
  mutable std::array<double, Q> cached_q_{};
  mutable Point point_;
  mutable std::vector<Jet> h_;  ///< each observation's h and h' at the cached q

 public:
  /// J^T J over every parameter, g first, at the cached q and its best s:
  /// dr_k/dg = w_k h_k ds/dg with s = g^-1/2, dr_k/dq = w_k s h'_k.
  Eigen::Matrix<double, P, P> full_jtj() const {
    const double s = point_.s;
    const double ds_dg = -0.5 * s * s * s;
    Eigen::Matrix<double, P, P> jtj = Eigen::Matrix<double, P, P>::Zero();
    for (std::size_t k = 0; k < h_.size(); ++k) {
      Eigen::Matrix<double, P, 1> j;
      j(0) = h_[k].a * ds_dg;
      j.template tail<Q>() = s * h_[k].v;
      jtj.noalias() += data_.rows[k].weight * data_.rows[k].weight * j * j.transpose();
    }
    return jtj;
  }
};

/// The projected problem handed to Ceres "compressed" as in the decay fit
/// (docs/decay_fit.md): with J^T J = R^T R, the Q + 1 residuals
/// q = R^-T J^T r and sqrt(|r|^2 - |q|^2), whose Jacobian is [R; 0], have the
/// same cost, gradient and Gauss-Newton matrix as the K residuals, so the
/// iterates are the same while Ceres's own work no longer grows with K.
template <class Model>
class CompressedPeriodResiduals : public ceres::CostFunction {
 public:
  static constexpr int Q = Model::kParameters - 1;
  using Matrix = Eigen::Matrix<double, Q, Q>;

  explicit CompressedPeriodResiduals(const ProjectedPeriods<Model>& projected) : projected_(projected) {
    set_num_residuals(Q + 1);
    mutable_parameter_block_sizes()->push_back(Q);
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const NormalSums<Q>& s = projected_.at(parameters[0]).sums;
    if (!s.jtj.allFinite() || !s.jtr.allFinite() || !std::isfinite(s.rr)) return false;
    // R from the Cholesky factor of the column-scaled J^T J, with a ridge of
    // 1e-14 on its unit diagonal so that a singular problem (identical
    // observations) still steps; the gradient R^T q = J^T r stays exact.
    Eigen::Matrix<double, Q, 1> scale = s.jtj.diagonal().cwiseSqrt();
    scale = (scale.array() > 0.0).select(scale.cwiseInverse(), 1.0);
    Matrix scaled = scale.asDiagonal() * s.jtj * scale.asDiagonal();
    scaled.diagonal().array() += 1e-14;
    const Eigen::LLT<Matrix> llt(scaled);
    if (llt.info() != Eigen::Success) return false;
    const Matrix r_factor = Matrix(llt.matrixU()) * scale.cwiseInverse().asDiagonal();
    const Eigen::Matrix<double, Q, 1> q = r_factor.transpose().template triangularView<Eigen::Lower>().solve(s.jtr);
    for (int i = 0; i < Q; ++i) residuals[i] = q[i];
    residuals[Q] = std::sqrt(std::max(s.rr - q.squaredNorm(), 0.0));
    if (jacobians && jacobians[0]) {
      decrement_ = q.squaredNorm();
      rr_ = s.rr;
      // Ceres's row-major (Q + 1) x Q block (one column: the same either way).
      constexpr int kLayout = Q == 1 ? Eigen::ColMajor : Eigen::RowMajor;
      Eigen::Map<Eigen::Matrix<double, Q + 1, Q, kLayout>> jac(jacobians[0]);
      jac.template topRows<Q>() = r_factor;
      jac.row(Q).setZero();
    }
    return true;
  }

  /// At the last point whose Jacobian Ceres asked for: |q|^2 = r^T J
  /// (J^T J)^-1 J^T r, twice the cost a full Gauss-Newton step would still
  /// remove, and |r|^2 (NewtonDecrement).
  double decrement() const { return decrement_; }
  double rr() const { return rr_; }

 private:
  const ProjectedPeriods<Model>& projected_;
  mutable double decrement_ = 0.0, rr_ = 0.0;
};

}  // namespace

template <class Model>
PeriodFitSolution fit_periods(const PeriodFitProblem<Model>& problem,
                              const std::array<double, Model::kParameters>& initial) {
  constexpr int P = Model::kParameters;
  constexpr int Q = P - 1;
  static_assert(Q >= 1, "a period model has parameters besides g");
  std::array<double, Q> q;
  std::copy(initial.begin() + 1, initial.end(), q.begin());
  const ProjectedPeriods<Model> projected(problem, initial);
  PeriodFitSolution out;
  std::vector<int> held;
  for (int i = 0; i < Q; ++i) {
    if (!problem.fitted[i + 1]) held.push_back(i);
  }
  if (static_cast<int>(held.size()) == Q) {
    // g alone: its closed form.
    out.converged = true;
    out.termination = "g alone: closed form of the weighted least squares";
  } else {
    ceres::Problem::Options problem_options;
    problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem ceres_problem(problem_options);
    CompressedPeriodResiduals<Model> residuals(projected);
    ceres_problem.AddResidualBlock(&residuals, nullptr, q.data());
    if (!held.empty()) ceres_problem.SetManifold(q.data(), new ceres::SubsetManifold(Q, held));
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_QR;  // on the Q + 1 compressed residuals
    options.max_num_iterations = 200;
    // NewtonDecrement decides; Ceres's tolerances, at the last digits, only
    // stop a stalled fit.
    options.function_tolerance = 1e-16;
    options.gradient_tolerance = 1e-30;
    options.parameter_tolerance = 1e-15;
    options.logging_type = ceres::SILENT;
    const int free = Q - static_cast<int>(held.size()) + 1;
    NewtonDecrement<CompressedPeriodResiduals<Model>> converged(
        residuals, static_cast<int>(problem.observations->size()) - free);
    options.callbacks.push_back(&converged);
    ceres::Solver::Summary summary;
    ceres::Solve(options, &ceres_problem, &summary);
    out.converged =
        summary.termination_type == ceres::CONVERGENCE || summary.termination_type == ceres::USER_SUCCESS;
    out.termination = summary.message;
    out.iterations = static_cast<int>(summary.iterations.size()) - 1;
  }
  const typename ProjectedPeriods<Model>::Point& best = projected.at(q.data());
  out.parameters.assign(P, 0.0);
  out.parameters[0] = 1.0 / (best.s * best.s);
  std::copy(q.begin(), q.end(), out.parameters.begin() + 1);
  out.chi2 = best.sums.rr;
  // (J^T J)^-1 over the fitted parameters at the optimum, g included,
  // judged singular on its column-scaled form, which the parameters' units
  // do not affect.
  Eigen::Matrix<double, P, P> jtj = projected.full_jtj();
  for (int i = 0; i < P; ++i) {
    if (!problem.fitted[i]) jtj.row(i).setZero(), jtj.col(i).setZero(), jtj(i, i) = 1.0;
  }
  const Eigen::Matrix<double, P, 1> scale = jtj.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, P, P>> eigen(scale.asDiagonal() * jtj * scale.asDiagonal());
  if (scale.allFinite() && eigen.eigenvalues().minCoeff() > 1e-12 * eigen.eigenvalues().maxCoeff()) {
    Eigen::Matrix<double, P, P, Eigen::RowMajor> c = jtj.inverse();
    for (int i = 0; i < P; ++i) {
      if (!problem.fitted[i]) c.row(i).setZero(), c.col(i).setZero();
    }
    out.covariance.assign(c.data(), c.data() + P * P);
  }
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
