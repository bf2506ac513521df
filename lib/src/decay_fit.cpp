#include "pendulum/decay_fit.hpp"

#include "pendulum/dispersion.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <ceres/ceres.h>

#include "pendulum/detail/newton_decrement.hpp"
#include "decay_kernel.hpp"
#include "text.hpp"
#include "pendulum/numeric.hpp"
#include "pendulum/input_error.hpp"

namespace pendulum {

const char* decay_model_name(DecayModel model) {
  switch (model) {
    case DecayModel::both: return "both";
    case DecayModel::linear_only: return "linear_only";
    case DecayModel::quadratic_only: return "quadratic_only";
  }
  return "";
}

namespace {

enum Index { kAlpha = 0, kBeta = 1, kTheta0 = 2 };

std::string number(double x, int digits = 10) {
  std::ostringstream os;
  os.precision(digits);
  os << x;
  return os.str();
}

/// The record with its weights w_i = 1/sigma_i (1 without sigmas).
struct Record {
  const DecayData& data;
  std::vector<double> w;
  explicit Record(const DecayData& d) : data(d), w(d.times.size(), 1.0) {
    if (!d.sigmas.empty()) {
      for (std::size_t i = 0; i < w.size(); ++i) w[i] = 1.0 / d.sigmas[i];
    }
  }
  kernel::DecaySums sums(const double* p, bool with_jacobian) const {
    return kernel::decay_sums(w.size(), data.times.data(), data.amplitudes.data(), w.data(), p,
                              with_jacobian);
  }
};

}  // namespace

namespace detail {

void decay_residuals(const DecayData& data, const double* p, double* residuals,
                     double* jacobian) {
  const Record rec(data);
  kernel::decay_points(rec.w.size(), data.times.data(), data.amplitudes.data(), rec.w.data(), p,
                       residuals, jacobian);
}

}  // namespace detail

namespace {

/// Eq. (25) over the whole record as one Ceres residual block of four
/// compressed residuals (compress_residuals, newton_decrement.hpp): Ceres's
/// work per iteration no longer grows with the number of points, and the
/// record is read once per evaluation (kernel::decay_sums).
/// Every evaluation computes the Jacobian sums and keeps them, because Ceres
/// asks for the Jacobian at a trial point right after accepting it.
class CompressedDecayCost final : public CompressedCost<3> {
 public:
  explicit CompressedDecayCost(const Record& record) : record_(record) {}

  /// The sums at p, from the last evaluation when it was at p.
  const kernel::DecaySums& sums_at(const double* p) const {
    if (!cached_ || p[0] != cached_p_[0] || p[1] != cached_p_[1] || p[2] != cached_p_[2]) {
      sums_ = record_.sums(p, true);
      cached_p_ = {p[0], p[1], p[2]};
      cached_ = true;
    }
    return sums_;
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    sums_at(parameters[0]);
    Eigen::Matrix3d gram;
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) gram(a, b) = sums_.jtj[a][b];
    }
    const Eigen::Vector3d jtr(sums_.jtr[0], sums_.jtr[1], sums_.jtr[2]);
    return compressed(parameters[0], gram, jtr, sums_.rr, residuals, jacobians);
  }

 private:
  const Record& record_;
  mutable bool cached_ = false;
  mutable std::array<double, 3> cached_p_{};
  mutable kernel::DecaySums sums_;
};

/// Starting point from the integral form of Eq. (24):
/// ln(theta_i/theta_1) = -alpha (t_i - t_1) - beta * integral of theta dt,
/// a linear least-squares problem in (alpha, beta). The integral is taken
/// between readings as for an exponential (exact for Eq. 33, close for
/// Eq. 25 even on coarse records), or by the trapezoid where a reading is not
/// positive (noisy synthetic tails). A start needs no more than about 200
/// readings: longer records are thinned, which keeps this step's logarithms
/// from costing more than the fit.
std::array<double, 3> initial_guess(const DecayData& data, DecayModel model) {
  const std::size_t n = data.times.size();
  const std::size_t stride = std::max<std::size_t>(1, n / 200);
  double saa = 0, sab = 0, sbb = 0, say = 0, sby = 0, integral = 0;
  const double t0 = data.times[0], log0 = std::log(data.amplitudes[0]);
  std::size_t previous = 0;
  double log_previous = log0;
  const std::size_t steps = (n - 1 + stride - 1) / stride;  // the last reading always counts
  for (std::size_t k = 1; k <= steps; ++k) {
    const std::size_t i = std::min(k * stride, n - 1);
    const double a = data.amplitudes[previous], b = data.amplitudes[i];
    const double h = data.times[i] - data.times[previous];
    const double log_b = b > 0.0 ? std::log(b) : 0.0;
    const bool exponential = a > 0.0 && b > 0.0 && std::abs(a - b) > 1e-8 * a;
    integral += exponential ? h * (a - b) / (log_previous - log_b) : 0.5 * h * (a + b);
    previous = i;
    log_previous = log_b;
    if (b <= 0.0) continue;  // informs the integral only
    const double x_a = -(data.times[i] - t0), x_b = -integral, y = log_b - log0;
    saa += x_a * x_a; sab += x_a * x_b; sbb += x_b * x_b; say += x_a * y; sby += x_b * y;
  }
  double alpha = say / saa, beta = sby / sbb;  // one-term fits
  const double det = saa * sbb - sab * sab;
  if (model == DecayModel::both && det > 1e-12 * saa * sbb) {
    alpha = (say * sbb - sby * sab) / det;
    beta = (sby * saa - say * sab) / det;
  }
  if (model == DecayModel::quadratic_only || !std::isfinite(alpha)) alpha = 0.0;
  if (model == DecayModel::linear_only || !std::isfinite(beta)) beta = 0.0;
  alpha = std::max(alpha, 0.0);
  beta = std::max(beta, 0.0);
  double theta0 = data.initial_amplitude ? *data.initial_amplitude
                                          : data.amplitudes[0] * std::exp((alpha + beta * data.amplitudes[0]) * t0);
  // A decay so fast that its extrapolation to t = 0 overflows (a last
  // reading of 1e-300 deg) starts from the first reading instead.
  if (!std::isfinite(theta0)) theta0 = data.amplitudes[0];
  return {alpha, beta, theta0};
}


struct Solution {
  std::array<double, 3> p;
  ceres::Solver::Summary summary;
  std::optional<std::array<double, 9>> covariance;  ///< (J^T J)^-1 over the free parameters
  double unweighted_squares = 0.0;                  ///< sum of (theta0(t_i) - theta_i)^2
};

/// (J^T J)^-1 over the free parameters from the sums at the optimum, zero rows and columns for the
/// fixed ones; empty when J^T J is numerically singular there (relative
/// eigenvalue of the column-scaled matrix below 1e-12).
std::optional<std::array<double, 9>> covariance(const kernel::DecaySums& sums,
                                                const std::vector<int>& free) {
  const int k = static_cast<int>(free.size());
  Eigen::MatrixXd gram(k, k);
  for (int a = 0; a < k; ++a) {
    for (int b = 0; b < k; ++b) gram(a, b) = sums.jtj[free[a]][free[b]];
  }
  if (!gram.allFinite()) return std::nullopt;
  const Eigen::VectorXd norms = gram.diagonal().cwiseSqrt();
  if ((norms.array() == 0.0).any()) return std::nullopt;
  const Eigen::MatrixXd scaled = norms.cwiseInverse().asDiagonal() * gram * norms.cwiseInverse().asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(scaled);
  if (eig.eigenvalues().minCoeff() <= 1e-12 * eig.eigenvalues().maxCoeff()) return std::nullopt;
  const Eigen::MatrixXd inverse = norms.cwiseInverse().asDiagonal() *
                                  (eig.eigenvectors() * eig.eigenvalues().cwiseInverse().asDiagonal() *
                                   eig.eigenvectors().transpose()) *
                                  norms.cwiseInverse().asDiagonal();
  std::array<double, 9> c{};
  for (int a = 0; a < k; ++a) {
    for (int b = 0; b < k; ++b) c[3 * free[a] + free[b]] = inverse(a, b);
  }
  return c;
}

Solution solve(const DecayData& data, DecayModel model) {
  Solution s;
  s.p = initial_guess(data, model);
  const Record record(data);
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  auto* cost = new CompressedDecayCost(record);
  problem.AddResidualBlock(cost, nullptr, s.p.data());
  std::vector<int> fixed, free;
  for (int i : {kAlpha, kBeta, kTheta0}) {
    const bool is_fixed = (i == kAlpha && model == DecayModel::quadratic_only) ||
                          (i == kBeta && model == DecayModel::linear_only) ||
                          (i == kTheta0 && data.initial_amplitude);
    (is_fixed ? fixed : free).push_back(i);
  }
  if (!fixed.empty()) problem.SetManifold(s.p.data(), new ceres::SubsetManifold(3, fixed));
  for (int i : {kAlpha, kBeta, kTheta0}) problem.SetParameterLowerBound(s.p.data(), i, 0.0);

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.logging_type = ceres::SILENT;
  options.max_num_iterations = 200;
  // The starting point is close: let the first steps be Gauss-Newton's.
  options.initial_trust_region_radius = 1e8;
  // NewtonDecrement decides; Ceres's tolerances only stop a stalled fit.
  options.function_tolerance = 1e-18;
  options.gradient_tolerance = 1e-20;
  options.parameter_tolerance = 1e-15;
  NewtonDecrement<CompressedDecayCost> converged(*cost, static_cast<int>(data.times.size() - free.size()));
  options.callbacks.push_back(&converged);
  ceres::Solve(options, &problem, &s.summary);
  // Ceres returns its least cost, which rounding can put at an earlier
  // point than the one the stopping rule judged (period_fit.hpp): the fit
  // ends where it was judged.
  if (s.summary.termination_type == ceres::USER_SUCCESS) s.p = cost->judged();
  const kernel::DecaySums& sums = cost->sums_at(s.p.data());
  s.covariance = covariance(sums, free);
  s.unweighted_squares = sums.dd;
  return s;
}

DecayFit report(const DecayData& data, DecayModel model, const Solution& s,
                std::string reason) {
  // Eq. (25) could not be evaluated (an overflow on an extreme record): no
  // fit to report, and the record is to blame.
  if (s.summary.termination_type == ceres::FAILURE || !(s.summary.final_cost >= 0.0) ||
      !std::isfinite(s.summary.final_cost)) {
    // Ceres's own words, its first line only (the rest names its internals).
    const std::string message = s.summary.message.substr(0, s.summary.message.find('\n'));
    throw InputError("decay.data", "the fit of Eq. (25) failed (" + one_line(message, 200) +
                                       "); expected a record the decay law can be evaluated on");
  }
  DecayFit f;
  const int n = static_cast<int>(data.times.size());
  const bool weighted = !data.sigmas.empty();
  f.model = model;
  f.model_reason = std::move(reason);
  f.points = n;
  f.converged = s.summary.termination_type == ceres::USER_SUCCESS ||
                s.summary.termination_type == ceres::CONVERGENCE;
  f.termination = s.summary.termination_type == ceres::USER_SUCCESS
                      ? "converged: a Gauss-Newton step would change chi2 by less than 1e-14 of "
                        "the residual variance"
                      : s.summary.message;
  f.iterations = static_cast<int>(s.summary.iterations.size()) - 1;
  f.chi2 = 2.0 * s.summary.final_cost;
  const int fitted = 1 + (model == DecayModel::both) + !data.initial_amplitude;
  f.dof = n - fitted;
  f.uncertainty_scaling = weighted ? "sigma" : "residual_variance";
  f.residual_standard_error = f.dof > 0 ? std::sqrt(s.unweighted_squares / f.dof) : 0.0;
  const double unscaled = weighted ? 1.0 : (f.dof > 0 ? f.chi2 / f.dof : 0.0);
  double scale = unscaled;
  if (weighted) {
    const Dispersion d = dispersion(f.chi2, f.dof);
    f.probability = d.probability;
    f.birge_ratio = d.birge_ratio;
    f.scaled = d.over_dispersed;
    scale = d.applied_scale() * d.applied_scale();
  }
  if (s.covariance) {
    for (int i = 0; i < 9; ++i) f.covariance[i] = (*s.covariance)[i] * scale;
  }
  auto fill = [&](FittedParameter& q, int i, bool is_fitted) {
    q.value = s.p[i];
    q.fitted = is_fitted;
    if (!is_fitted) return;
    q.at_bound = s.p[i] == 0.0;
    if (s.covariance) {
      q.uncertainty_unscaled = std::sqrt(std::max((*s.covariance)[4 * i] * unscaled, 0.0));
      q.uncertainty = std::sqrt(std::max(f.covariance[4 * i], 0.0));
      q.significant = std::abs(q.value) > 2.0 * *q.uncertainty;
    }
  };
  fill(f.alpha, kAlpha, model != DecayModel::quadratic_only);
  fill(f.beta, kBeta, model != DecayModel::linear_only);
  fill(f.initial_amplitude, kTheta0, !data.initial_amplitude);
  if (model == DecayModel::both && f.alpha.uncertainty && f.beta.uncertainty &&
      *f.alpha.uncertainty > 0.0 && *f.beta.uncertainty > 0.0) {
    f.correlation_alpha_beta = f.covariance[kAlpha * 3 + kBeta] / (*f.alpha.uncertainty * *f.beta.uncertainty);
  }
  return f;
}

}  // namespace

void validate_decay_data(const DecayData& data, const std::string& path) {
  const std::size_t n = data.times.size();
  auto at = [&](const char* key, std::size_t i) {
    return path + "." + key + "[" + std::to_string(i) + "]";
  };
  if (data.amplitudes.size() != n) {
    throw InputError(path + ".amplitudes", "got " + std::to_string(data.amplitudes.size()) +
                                               " amplitudes; expected one per time (" +
                                               std::to_string(n) + ")");
  }
  const std::size_t minimum = data.initial_amplitude ? 2 : 3;
  if (n < minimum) {
    throw InputError(path + ".times", "got " + std::to_string(n) + " points; expected at least " +
                                          std::to_string(minimum) +
                                          " (one more than the fitted parameters of the simplest model)");
  }
  if (!data.sigmas.empty() && data.sigmas.size() != n) {
    throw InputError(path + ".sigmas", "got " + std::to_string(data.sigmas.size()) +
                                           " sigmas; expected one per time (" + std::to_string(n) + ")");
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(data.times[i]) || data.times[i] < 0.0) {
      throw InputError(at("times", i), "got " + number(data.times[i]) + "; expected a finite time >= 0");
    }
    if (i > 0 && !(data.times[i] > data.times[i - 1])) {
      throw InputError(at("times", i), "got " + number(data.times[i]) + " after " +
                                           number(data.times[i - 1]) +
                                           "; expected strictly increasing times (no repeats)");
    }
    if (!std::isfinite(data.amplitudes[i]) || data.amplitudes[i] <= 0.0 ||
        data.amplitudes[i] >= kPi) {
      throw InputError(at("amplitudes", i), "got " + number(data.amplitudes[i]) +
                                                " rad; expected a positive amplitude below 180 deg");
    }
    if (!data.sigmas.empty() && (!std::isfinite(data.sigmas[i]) || data.sigmas[i] <= 0.0)) {
      throw InputError(at("sigmas", i), "got " + number(data.sigmas[i]) + "; expected a positive uncertainty");
    }
  }
  if (data.initial_amplitude && !(*data.initial_amplitude > 0.0 && std::isfinite(*data.initial_amplitude))) {
    throw InputError(path + ".initial_amplitude", "expected a positive amplitude");
  }
  // The least-squares slope of ln(theta) against t must be negative.
  double mt = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) {
    mt += data.times[i] / n;
    my += std::log(data.amplitudes[i]) / n;
  }
  double sty = 0;
  for (std::size_t i = 0; i < n; ++i) sty += (data.times[i] - mt) * (std::log(data.amplitudes[i]) - my);
  if (!(sty < 0.0)) {
    throw InputError(path + ".amplitudes",
                     "the amplitudes do not decrease over the record; expected a decay");
  }
}

DecayFit fit_decay(const DecayData& data, const DecayFitOptions& options) {
  const int n = static_cast<int>(data.times.size());
  auto fit = [&](DecayModel model, std::string reason) {
    return report(data, model, solve(data, model), std::move(reason));
  };
  auto separable = [](const DecayFit& f) {
    return f.model == DecayModel::both && f.alpha.uncertainty && f.beta.uncertainty &&
           (f.alpha.significant || f.beta.significant);
  };
  if (options.model) {
    DecayFit f = fit(*options.model, "chosen by the user");
    f.separable = separable(f);
    return f;
  }

  const int full_parameters = 2 + !data.initial_amplitude;
  if (n <= full_parameters) {
    // No degree of freedom for both: the one-term model with the lower chi2.
    const DecayFit lin = fit(DecayModel::linear_only, "");
    const DecayFit quad = fit(DecayModel::quadratic_only, "");
    DecayFit best = lin.chi2 <= quad.chi2 ? lin : quad;
    best.model_reason = std::to_string(n) +
                        " points leave no degree of freedom for both alpha and beta; the one-term model "
                        "with the lower chi2 is used";
    return best;
  }
  // Both terms, always: dropping one that ends on its bound 0, or that the
  // record cannot tell from the other, and quoting the other's one-term
  // uncertainty as if the model were known put it 6-20 sigma from the truth
  // on short records (issue 14). The two-term covariance at the optimum,
  // bound or not, is what the record says about each term.
  DecayFit full = fit(DecayModel::both, "");
  if (!full.alpha.uncertainty || !full.beta.uncertainty) {
    full.model_reason = "the two-term fit's covariance is singular: the record cannot fix alpha and beta";
    return full;
  }
  full.separable = separable(full);
  const std::string bound = full.alpha.at_bound  ? "alpha reached its bound 0"
                            : full.beta.at_bound ? "beta reached its bound 0"
                                                 : "";
  if (full.separable) {
    if (!bound.empty()) {
      full.model_reason = bound + (full.alpha.at_bound ? ": the data show no linear damping"
                                                       : ": the data show no quadratic damping") +
                          "; both terms keep the two-term fit's uncertainties";
    }
    return full;
  }
  full.model_reason = "the record cannot tell linear from quadratic damping (correlation of alpha and beta " +
                      number(full.correlation_alpha_beta, 6) + ", neither term two standard uncertainties from 0" +
                      (bound.empty() ? "" : "; " + bound) +
                      "): both terms are reported with the two-term fit's correlated uncertainties";
  return full;
}

}  // namespace pendulum
