#pragma once
/// \file period_fit.hpp
/// \brief One Ceres fit of any period model (period_model.hpp) to any number
/// of observations: weighted least squares of the periods, with automatic
/// derivatives. g is projected out (every model's period is g^-1/2 times a
/// function of its other parameters), so Ceres varies the others alone
/// (docs/core.md). The uncertainties are the analysis's (analysis.hpp), which
/// propagates every input through the fit's optimum.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <ceres/ceres.h>

#include "pendulum/amplitude.hpp"
#include "pendulum/apparatus.hpp"
#include "pendulum/detail/newton_decrement.hpp"
#include "pendulum/period_model.hpp"
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

// The fit is defined in this header so that each kind it runs on is
// instantiated where it is called: a registered kind needs no list of
// explicit instantiations (docs/core.md, adding a kind).
namespace detail {

/// The sums of a weighted least-squares problem at one point: J^T J, J^T r
/// and r^T r over the K observations, J with respect to N parameters.
template <int N>
struct NormalSums {
  Eigen::Matrix<double, N, N> jtj = Eigen::Matrix<double, N, N>::Zero();
  Eigen::Matrix<double, N, 1> jtr = Eigen::Matrix<double, N, 1>::Zero();
  double rr = 0.0;
};

/// g projected out (variable projection, Golub & Pereyra 1973). Every period
/// model's period is T = g^-1/2 h(q), q the other parameters: g enters only
/// the ideal period's sqrt(length/g), and the corrections' working frequency
/// comes from the measured period. With s = g^-1/2, the best s for given q
/// is closed form, s = A/B with A = sum w^2 T h, B = sum w^2 h^2, so Ceres
/// varies q alone, on dual numbers of P - 1 components, against the
/// residuals r_k = (s(q) h_k(q) - T_k) w_k, whose derivatives are
/// dr_k = w_k (h_k s' + s h'_k) with s' = (a - 2 s b)/B,
/// a = sum w^2 T h', b = sum w^2 h h'. A step is a scalar pass for each
/// observation's h on dual numbers, then two passes on kLanes observations
/// at a time (vector instructions): one for the four sums, one for r, dr and
/// the normal sums (forming r^T r as C - s A instead would cancel to 1e-7 of
/// it). The columns are padded to whole lanes with observations of weight 0.
///
/// The parameters reach the corrections through the swing's length alone
/// (period_model.hpp), so when none of the corrections the apparatus applies
/// reads the length (reads_length_of the model's rows, asked once per fit), each
/// observation's T/T0 is the same at every step: it is composed once, the
/// scalar pass gives only the length l(q), and the first vector pass takes
/// h = T0(l, g = 1) T/T0 and h' = h l'/(2 l), bound by the square roots and
/// divisions, under which its sums cost nothing.
template <class Model>
class ProjectedPeriods {
 public:
  static constexpr int P = Model::kParameters;
  static constexpr int Q = P - 1;  // the parameters after g
  using Jet = ceres::Jet<double, Q>;

  ProjectedPeriods(const PeriodFitProblem<Model>& problem, const std::array<double, P>& start)
      : problem_(problem),
        apparatus_(convert_apparatus<Jet>(*problem.apparatus, [](const Field&, double x) { return Jet(x); })),
        count_(static_cast<Eigen::Index>(problem.observations->size())) {
    const auto& obs = *problem.observations;
    const auto& amplitude = *problem.amplitude;
    const Apparatus<double>& app = *problem.apparatus;
    if (!obs.empty()) {
      const Swing<double> first = Model::swing_at(start.data(), Model::swing(obs[0]), app);
      fixed_ratio_ = !reads_length_of<double>(
          [&](auto& sink) { visit_model_corrections<Model>(app, first, amplitude[0], sink); });
    }
    settings_.reserve(obs.size());
    columns_.setZero((count_ + kLanes - 1) / kLanes * kLanes, kColumns);
    for (Eigen::Index k = 0; k < count_; ++k) {
      const Swing<double> swing = Model::swing(obs[k]);
      settings_.push_back(swing.setting);
      columns_(k, kLength) = swing.length, columns_(k, kAmplitude) = swing.amplitude;
      columns_(k, kOmega) = swing.omega, columns_(k, kTrialDuration) = swing.trial_duration;
      columns_(k, kPeriod) = obs[k].period;
      columns_(k, kWeight) = (*problem.weights)[k];
      if (fixed_ratio_) {
        columns_(k, kRatio) = 1.0 + Model::composition(app, Model::swing_at(start.data(), swing, app), amplitude[k]).total;
      }
    }
  }

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
    // Whether T/T0 was composed once is decided once per fit, outside the loops.
    const ModelSums m = fixed_ratio_ ? model_sums<true>(p) : model_sums<false>(p);
    Point& pt = point_;
    pt.s = m.big_a / m.big_b;
    const double s = pt.s;
    std::array<double, Q> ds;
    for (int i = 0; i < Q; ++i) ds[i] = (m.a[i] - 2.0 * s * m.b[i]) / m.big_b;
    Lanes rr = Lanes::Zero();
    std::array<Lanes, Q> jtr;
    std::array<std::array<Lanes, Q>, Q> jtj;
    for (int i = 0; i < Q; ++i) {
      jtr[i].setZero();
      for (int l = 0; l < Q; ++l) jtj[i][l].setZero();
    }
    for (Eigen::Index k = 0; k < columns_.rows(); k += kLanes) {
      const Lanes w = lanes(kWeight, k), h = lanes(kH, k);
      const Lanes r = (s * h - lanes(kPeriod, k)) * w;
      rr += r * r;
      std::array<Lanes, Q> j;
      for (int i = 0; i < Q; ++i) {
        j[i] = (lanes(kDh + i, k) * s + ds[i] * h) * w;
        jtr[i] += j[i] * r;
        for (int l = 0; l <= i; ++l) jtj[i][l] += j[i] * j[l];
      }
    }
    pt.sums.rr = rr.sum();
    for (int i = 0; i < Q; ++i) {
      pt.sums.jtr(i) = jtr[i].sum();
      for (int l = 0; l <= i; ++l) pt.sums.jtj(i, l) = pt.sums.jtj(l, i) = jtj[i][l].sum();
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

  /// J^T J over every parameter, g first, at the cached q and its best s:
  /// dr_k/dg = w_k h_k ds/dg with s = g^-1/2, dr_k/dq = w_k s h'_k.
  Eigen::Matrix<double, P, P> full_jtj() const {
    const double s = point_.s;
    const auto w = columns_.col(kWeight);
    // dr/dp_i over the observations: the column it scales times a factor.
    const auto source = [&](int i) { return columns_.col(i == 0 ? kH : kDh + i - 1); };
    const auto factor = [&](int i) { return i == 0 ? -0.5 * s * s * s : s; };
    Eigen::Matrix<double, P, P> jtj;
    for (int i = 0; i < P; ++i) {
      for (int l = 0; l <= i; ++l) {
        jtj(i, l) = jtj(l, i) = factor(i) * factor(l) * (w * w * source(i) * source(l)).sum();
      }
    }
    return jtj;
  }

 private:
  static constexpr Eigen::Index kLanes = 4;
  using Lanes = Eigen::Array<double, kLanes, 1>;

  /// The columns of columns_, one row per observation: the measured swing
  /// (Model::swing), the period, the weight and T/T0 (when fixed_ratio_);
  /// then h and, per parameter after g, h' at the cached q.
  enum Column { kLength, kAmplitude, kOmega, kTrialDuration, kPeriod, kWeight, kRatio, kH, kDh, kColumns = kDh + Q };

  auto lanes(int column, Eigen::Index k) const { return columns_.col(column).template segment<kLanes>(k); }

  /// Observation k's measured swing, on dual numbers of constants.
  Swing<Jet> measured_swing(Eigen::Index k) const {
    const auto row = columns_.row(k);
    return {Jet(row(kLength)), Jet(row(kAmplitude)), Jet(row(kOmega)), Jet(row(kTrialDuration)),
            settings_[static_cast<std::size_t>(k)]};
  }

  struct ModelSums {
    double big_a, big_b;
    std::array<double, Q> a, b;
  };

  /// Each observation's h and h' at p (g = 1) into their columns, and the
  /// sums A, B, a, b. With T/T0 fixed, the lengths on dual numbers first,
  /// then h = T0(l) T/T0 and h' = h l' / (2 l) with the sums.
  template <bool kFixedRatio>
  ModelSums model_sums(const std::array<Jet, P>& p) const {
    auto h = columns_.col(kH);
    auto dh = columns_.template middleCols<Q>(kDh);
    for (Eigen::Index k = 0; k < count_; ++k) {
      const Swing<Jet> swing = Model::swing_at(p.data(), measured_swing(k), apparatus_);
      Jet hk = swing.length;
      if constexpr (!kFixedRatio) {
        hk = ideal_period(swing.length, 1.0) *
             (1.0 + Model::composition(apparatus_, swing, (*problem_.amplitude)[static_cast<std::size_t>(k)]).total);
      }
      h(k) = hk.a;
      dh.row(k) = hk.v.transpose();
    }
    // The padding's h: 0 = T0(1) x 0 when h is T0(l) T/T0 (its T/T0 is 0).
    if constexpr (kFixedRatio) h.tail(columns_.rows() - count_).setOnes();
    Lanes big_a = Lanes::Zero(), big_b = Lanes::Zero();
    std::array<Lanes, Q> a, b;
    for (int i = 0; i < Q; ++i) a[i].setZero(), b[i].setZero();
    for (Eigen::Index k = 0; k < columns_.rows(); k += kLanes) {
      Lanes hk = lanes(kH, k);
      std::array<Lanes, Q> dhk;
      for (int i = 0; i < Q; ++i) dhk[i] = lanes(kDh + i, k);
      if constexpr (kFixedRatio) {
        const Lanes length = hk;
        hk = ideal_period(length, 1.0) * lanes(kRatio, k);
        const Lanes per_length = 0.5 * hk / length;  // dT0/dl = T0/(2 l)
        h.template segment<kLanes>(k) = hk;
        for (int i = 0; i < Q; ++i) {
          dhk[i] *= per_length;
          dh.col(i).template segment<kLanes>(k) = dhk[i];
        }
      }
      const Lanes w = lanes(kWeight, k);
      const Lanes w2 = w * w, w2t = w2 * lanes(kPeriod, k);
      big_a += w2t * hk, big_b += w2 * hk * hk;
      for (int i = 0; i < Q; ++i) a[i] += w2t * dhk[i], b[i] += w2 * hk * dhk[i];
    }
    ModelSums out{big_a.sum(), big_b.sum(), {}, {}};
    for (int i = 0; i < Q; ++i) out.a[i] = a[i].sum(), out.b[i] = b[i].sum();
    return out;
  }

  const PeriodFitProblem<Model>& problem_;
  const Apparatus<Jet> apparatus_;
  const Eigen::Index count_;        ///< observations (the columns' rows without the padding)
  std::vector<Setting> settings_;  ///< each observation's measured swing's setting
  bool fixed_ratio_ = false;
  /// One allocation for every per-observation array of the fit (kColumns).
  mutable Eigen::Array<double, Eigen::Dynamic, kColumns> columns_;
  mutable bool cached_ = false;
  mutable std::array<double, Q> cached_q_{};
  mutable Point point_;
};

/// The projected problem handed to Ceres compressed to Q + 1 residuals
/// (compress_residuals, newton_decrement.hpp), as the decay fit is.
template <class Model>
class CompressedPeriodResiduals final : public CompressedCost<Model::kParameters - 1> {
 public:
  static constexpr int Q = Model::kParameters - 1;

  explicit CompressedPeriodResiduals(const ProjectedPeriods<Model>& projected) : projected_(projected) {}

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const NormalSums<Q>& s = projected_.at(parameters[0]).sums;
    return this->compressed(parameters[0], s.jtj, s.jtr, s.rr, residuals, jacobians);
  }

 private:
  const ProjectedPeriods<Model>& projected_;
};

}  // namespace detail

/// Minimises sum_k [(T_model,k(p) - T_k) w_k]^2 over the fitted parameters:
/// g in closed form for given others, the others by Levenberg-Marquardt from
/// `initial` (g's start is not used), until a Gauss-Newton step would remove
/// less than 1e-14 of the residual variance (the tests recover noiseless
/// parameters to 1e-12). The covariance only `with_covariance`.
template <class Model>
PeriodFitSolution fit_periods(const PeriodFitProblem<Model>& problem,
                              const std::array<double, Model::kParameters>& initial, bool with_covariance = false) {
  constexpr int P = Model::kParameters;
  constexpr int Q = P - 1;
  static_assert(Q >= 1, "a period model has parameters besides g");
  static_assert(is_period_model<Model>(), "Model has every piece of a period model (period_model.hpp)");
  std::array<double, Q> q;
  std::copy(initial.begin() + 1, initial.end(), q.begin());
  const detail::ProjectedPeriods<Model> projected(problem, initial);
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
    detail::CompressedPeriodResiduals<Model> residuals(projected);
    ceres_problem.AddResidualBlock(&residuals, nullptr, q.data());
    if (!held.empty()) ceres_problem.SetManifold(q.data(), new ceres::SubsetManifold(Q, held));
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_QR;  // on the Q + 1 compressed residuals
    options.max_num_iterations = 200;
    // Near the optimum a Gauss-Newton step lowers the cost by less than the
    // rounding of the periods moves it (u T w per residual, u = 2^-53); a
    // monotonic trust region then rejects such steps at random and shrinks
    // until its parameter tolerance ends the fit (10 iterations instead of 3
    // on a 10-pivot scan). Measured against the cost a few steps back, they
    // pass.
    options.use_nonmonotonic_steps = true;
    // NewtonDecrement decides; Ceres's tolerances, at the last digits, only
    // stop a stalled fit.
    options.function_tolerance = 1e-16;
    options.gradient_tolerance = 1e-30;
    options.parameter_tolerance = 1e-15;
    options.logging_type = ceres::SILENT;
    const int free = Q - static_cast<int>(held.size()) + 1;
    NewtonDecrement<detail::CompressedPeriodResiduals<Model>> converged(
        residuals, static_cast<int>(problem.observations->size()) - free);
    options.callbacks.push_back(&converged);
    ceres::Solver::Summary summary;
    ceres::Solve(options, &ceres_problem, &summary);
    out.converged =
        summary.termination_type == ceres::CONVERGENCE || summary.termination_type == ceres::USER_SUCCESS;
    out.termination = summary.message;
    out.iterations = static_cast<int>(summary.iterations.size()) - 1;
    // Ceres returns the point of least cost, which the same rounding can make
    // an earlier one than the point the stopping rule judged (up to 3e-5 of
    // a standard uncertainty away in the tests): the fit ends where it was judged.
    if (summary.termination_type == ceres::USER_SUCCESS) q = residuals.judged();
  }
  const typename detail::ProjectedPeriods<Model>::Point& best = projected.at(q.data());
  out.parameters.assign(P, 0.0);
  out.parameters[0] = 1.0 / (best.s * best.s);
  std::copy(q.begin(), q.end(), out.parameters.begin() + 1);
  if (!with_covariance) return out;
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

}  // namespace pendulum
