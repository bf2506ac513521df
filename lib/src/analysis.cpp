#include "pendulum/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include <Eigen/Dense>
#include <boost/math/special_functions/gamma.hpp>
#include <ceres/jet.h>

#include "pendulum/dispersion.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/interrupt.hpp"
#include "pendulum/models/registry.hpp"
#include "pendulum/period_fit.hpp"
#include "fit_state.hpp"
#include "plausibility.hpp"
#include "text.hpp"

namespace pendulum {

const char* status_name(Status s) {
  switch (s) {
    case Status::applied: return "applied";
    case Status::negligible: return "negligible";
    case Status::skipped: return "skipped";
  }
  return "";
}

const char* result_status_name(ResultStatus s) {
  switch (s) {
    case ResultStatus::ok: return "ok";
    case ResultStatus::suspect: return "suspect";
    case ResultStatus::failed: return "failed";
  }
  return "";
}

std::vector<std::string> review_decay_fit(const DecayFit& fit) {
  std::vector<std::string> warnings;
  if (!fit.converged) warnings.push_back("decay fit: did not converge (" + fit.termination + ")");
  if (fit.uncertainty_scaling == "sigma" && fit.dof > 0) {
    const double reduced = fit.chi2 / fit.dof;
    // chi2/dof has standard deviation sqrt(2/dof) when the sigmas are right.
    if (std::abs(reduced - 1.0) > 4.0 * std::sqrt(2.0 / fit.dof)) {
      std::ostringstream w;
      w << "decay fit: chi2/dof = " << reduced << " with " << fit.dof
        << " degrees of freedom; the stated sigma or the model (Eq. 25) does not fit the data";
      warnings.push_back(w.str());
    }
  }
  const bool inseparable = fit.model == DecayModel::both && fit.alpha.uncertainty && fit.beta.uncertainty &&
                           !fit.separable;
  if (inseparable) {
    warnings.push_back("decay fit: the record cannot tell linear from quadratic damping (correlation of alpha "
                       "and beta " + format_number(fit.correlation_alpha_beta, 6) +
                       "; both one-term models fit it): alpha and beta carry the two-term fit's large, "
                       "correlated uncertainties into the damping rows. A record over which the amplitude "
                       "falls further separates them");
  }
  for (const auto& [name, q] : {std::pair{"alpha", fit.alpha}, std::pair{"beta", fit.beta}}) {
    if (q.fitted && !q.uncertainty) {
      warnings.push_back(std::string("decay fit: the record cannot fix ") + name +
                         " (the fit's covariance is singular): its uncertainty is unknown, and it is "
                         "listed in g.inputs_without_uncertainty, not in the budget");
    }
    if (q.fitted && q.uncertainty && !q.at_bound && !q.significant && !inseparable) {
      warnings.push_back(std::string("decay fit: ") + name +
                         " is not significant (less than two standard uncertainties from 0)");
    }
  }
  return warnings;
}

void use_fitted_decay(ParsedScene& scene, const DecayFit& fit) {
  const AngleOf of = decay_angle_of(scene);  // beta is of this angle
  const bool over_timing = !scene.swing_by_swing;
  scene.apparatus.decay = Decay<double>{fit.alpha.value, fit.beta.value, of, over_timing};
  scene.apparatus_uncertainty.decay =
      Decay<double>{fit.alpha.uncertainty.value_or(0.0), fit.beta.uncertainty.value_or(0.0), of, over_timing};
  if (fit.alpha.uncertainty && fit.beta.uncertainty) {
    scene.input_covariances.push_back({"decay.alpha", "decay.beta", fit.covariance[1]});
  }
  // Type A from the record's points: with stated sigmas the covariance is
  // known (normal); scaled by the residuals' variance it is a t with n - p.
  const InputEvaluation from_record =
      fit.uncertainty_scaling == "sigma" && !fit.scaled
          ? InputEvaluation{"", 'A', Distribution::normal}
          : InputEvaluation{"", 'A', Distribution::student_t, static_cast<double>(fit.dof)};
  for (const char* path : {"decay.alpha", "decay.beta"}) {
    scene.evaluations.push_back(from_record);
    scene.evaluations.back().path = path;
  }
}

std::optional<ParsedScene> scene_with_fitted_decay(const ParsedScene& given, const std::optional<DecayFit>& fit) {
  if (!fit) return std::nullopt;
  ParsedScene fitted = given;
  use_fitted_decay(fitted, *fit);
  return fitted;
}

namespace {

/// One input: a scalar of the apparatus, of one observation, or given once
/// for several observations of a series (ObservationSource::shared).
struct Input {
  std::string path;
  const char* unit;
  double value, sigma;
  std::vector<std::size_t> observations;  ///< the observations it is a field of; none: the apparatus's
  int ordinal;                            ///< place in its owner's zip order
  FieldRole role;
  InputEvaluation evaluation;
};

/// The quantities derived per observation, whose uncertainties are
/// propagated: the model's period, the ideal period, each correction's
/// DeltaT and the cross term's, all in seconds.
constexpr int kModelPeriod = 0, kIdealPeriod = 1, kFirstRow = 2, kCross = kFirstRow + kCorrectionCount;
constexpr int kQuantities = kCross + 1;

template <class T>
std::array<T, kQuantities> derived(const PeriodPrediction<T>& pr) {
  std::array<T, kQuantities> q;
  q[kModelPeriod] = pr.period;
  q[kIdealPeriod] = pr.ideal;
  for (int i = 0; i < kCorrectionCount; ++i) {
    q[kFirstRow + i] = pr.terms[i].ratio ? T(*pr.terms[i].ratio * pr.ideal) : T(0.0);
  }
  q[kCross] = pr.composition.cross * pr.ideal;
  return q;
}

/// The data with the scalar at `ordinal` of its zip order seeded as the
/// derivative direction of a one-component dual number.
using Dual = ceres::Jet<double, 1>;
struct Seeder {
  int seed;
  int ordinal = 0;
  Dual operator()(const Field&, double x) { return ordinal++ == seed ? Dual(x, 0) : Dual(x); }
};

/// The period model fitted to the observations and every input propagated
/// through its optimum (see analyse()).
template <class Model>
class Fit {
 public:
  static constexpr int P = Model::kParameters;
  using Vector = Eigen::Matrix<double, P, 1>;
  using Matrix = Eigen::Matrix<double, P, P>;

  Fit(const ParsedScene& scene, const AnalysisOptions& options, Analysis& out)
      : scene_(scene), options_(options), out_(out), k_(scene.observations.size()) {}

  void run() {
    choose_unknowns();
    solve();
    linearise();
    propagate();
    report();
  }

 private:
  void choose_unknowns() {
    fitted_.fill(false);
    fitted_[0] = true;  // g
    for (const std::string& name : scene_.fit) {
      for (int i = 0; i < P; ++i) {
        if (name == Model::kParameterInfo[i].name) fitted_[i] = true;
      }
    }
    free_count_ = static_cast<int>(std::count(fitted_.begin(), fitted_.end(), true));
    amplitude_.resize(k_);
    weights_.resize(k_);
    for (std::size_t k = 0; k < k_; ++k) {
      const double period = scene_.observations[k].period;
      const double sigma = scene_.observation_uncertainties[k].period;
      ReductionOptions reduction = options_.reduction;
      reduction.amplitude_tolerance = options_.amplitude_fraction * sigma / period;
      amplitude_[k] = choose_amplitude_method(reduction, scene_.observations[k].amplitude);
      weights_[k] = 1.0;  // the closed form's, where it cancels; a series's: weigh()
    }
  }

  void solve() {
    std::copy(Model::kDefaults.begin(), Model::kDefaults.end(), p_.begin());
    if (k_ == 1 && free_count_ == 1) {
      p_[0] = Model::solve_g(p_.data(), scene_.observations[0], scene_.apparatus, amplitude_[0]);
      out_.fit.method = "closed_form";
      out_.fit.termination = "closed form of one observation";
      return;
    }
    p_ = Model::start(scene_, fitted_);
    // Effective variance: weights from each observation's own uncertainties
    // (period, length, amplitude) carried to its period at the textbook
    // start, then once more at the optimum.
    const PeriodFitProblem<Model> problem{&scene_.apparatus, &scene_.observations, &amplitude_, &weights_, fitted_};
    weigh();
    // The model cannot reach periods too far apart (a timing of another
    // oscillation count, a pivot misread): bad input, named as such.
    const auto fit = [&] {
      const PeriodFitSolution solution = fit_periods(problem, p_);
      std::copy(solution.parameters.begin(), solution.parameters.end(), p_.begin());
      if (!std::all_of(p_.begin(), p_.end(), [](double x) { return std::isfinite(x); })) throw_cannot_fit();
      return solution;
    };
    fit();
    weigh();
    PeriodFitSolution solution = fit();
    // Paule & Mandel's iteration: tau from the residuals, the weights with
    // it, the fit again, until tau holds still.
    for (int i = 0; i < 50 && length_scatter_applies(); ++i) {
      const std::optional<double> tau = next_length_scatter(i == 0);
      if (!tau || std::abs(*tau - tau_) <= 1e-9 * *tau) break;
      tau_ = *tau;
      weigh();
      solution = fit();
    }
    Model::canonicalise(p_.data());
    out_.fit.method = "ceres_levenberg_marquardt";
    out_.fit.converged = solution.converged;
    out_.fit.termination = solution.termination;
    out_.fit.iterations = solution.iterations;
    if (!solution.converged) out_.warnings.push_back("fit: did not converge (" + solution.termination + ")");
  }

  /// Lengths read without a stated uncertainty (docs/series.md, "Lengths
  /// that scatter"): a simple pendulum's series, each observation its own
  /// length, degrees of freedom left.
  bool length_scatter_applies() const {
    if (!std::is_same_v<Model, SimplePendulum> || static_cast<int>(k_) <= free_count_) return false;
    for (std::size_t k = 0; k < k_; ++k) {
      if (scene_.sources[k].is_shared("length") || scene_.observation_uncertainties[k].length != 0.0) return false;
    }
    return true;
  }

  /// tau for the current fit; the first time, none unless chi2 against the
  /// stated uncertainties alone is above its 99 % quantile (dispersion.hpp).
  std::optional<double> next_length_scatter(bool first) {
    std::vector<double> residual(k_);
    double chi2 = 0.0;
    for (std::size_t k = 0; k < k_; ++k) {
      const auto& o = scene_.observations[k];
      residual[k] = Model::predict(p_.data(), o, scene_.apparatus, amplitude_[k]).period - o.period;
      chi2 += residual[k] * residual[k] / stated_variance_[k];
    }
    const int dof = static_cast<int>(k_) - free_count_;
    if (first) {
      if (!dispersion(chi2, dof).over_dispersed) return std::nullopt;
      chi2_stated_ = chi2;
    }
    return length_scatter(residual, stated_variance_, length_slope_, dof);
  }

  [[noreturn]] static void throw_cannot_fit() {
    throw InputError("observations",
                     "got periods the model cannot fit (no finite parameters reach them); expected timings of one "
                     "pendulum: check each observation's timing.oscillations_per_trial and setting");
  }

  /// w_k = 1 / sqrt(sum over the observation's inputs x of
  /// (d(T_model,k - T_k)/dx sigma_x)^2 + (dT_model,k/dL_k tau)^2) at the
  /// current parameters.
  void weigh() {
    stated_variance_.resize(k_);
    length_slope_.assign(k_, 0.0);
    std::array<Dual, P> p;
    for (int i = 0; i < P; ++i) p[i] = Dual(p_[i]);
    const Apparatus<Dual> app = convert_apparatus<Dual>(scene_.apparatus, [](const Field&, double x) { return Dual(x); });
    for (std::size_t k = 0; k < k_; ++k) {
      double variance = 0.0, largest = 0.0;
      std::string largest_path;
      int ordinal = 0;
      zip_observation(scene_.observations[k], scene_.observation_uncertainties[k],
                      [&](const Field& field, const double&, const double& sigma) {
                        const int seed = ordinal++;
                        // A shared input moves every period alike: no scatter.
                        // An own length's derivative weighs its scatter (tau), stated or not.
                        const bool length = field.role == FieldRole::length;
                        if ((sigma == 0.0 && !length) || scene_.sources[k].is_shared(field.path)) return;
                        const Observation<Dual> o = convert_observation<Dual>(scene_.observations[k], Seeder{seed});
                        const double d = (Model::predict(p.data(), o, app, amplitude_[k]).period - o.period).v[0];
                        if (field.role == FieldRole::length) length_slope_[k] = d;
                        const double share = d * d * sigma * sigma;
                        variance += share;
                        if (!(share <= largest)) largest = share, largest_path = field.path;
                      });
      stated_variance_[k] = variance;
      weights_[k] = 1.0 / std::sqrt(variance + std::pow(length_slope_[k] * tau_, 2));
      // An uncertainty so large that the period's effective one overflows
      // (1e300 m on a pivot) is the input's fault: name it. Not a number:
      // the model has no period at these parameters.
      if (std::isnan(variance)) throw_cannot_fit();
      if (!(std::isfinite(weights_[k]) && weights_[k] > 0.0)) {
        throw InputError(scene_.sources[k].path + largest_path + ".uncertainty",
                         "got an uncertainty so large that the period's effective uncertainty is not a finite "
                         "number; expected an uncertainty of a measurement");
      }
    }
  }

  /// Values and parameter gradients of every derived quantity, the
  /// residuals and their Jacobian, at the optimum.
  void linearise() {
    using JetP = ceres::Jet<double, P>;
    const Apparatus<JetP> app = convert_apparatus<JetP>(scene_.apparatus, [](const Field&, double x) { return JetP(x); });
    std::array<JetP, P> p;
    for (int i = 0; i < P; ++i) p[i] = fitted_[i] ? JetP(p_[i], i) : JetP(p_[i]);
    base_.resize(k_);
    hessian_.setZero();
    out_.fit.chi2 = 0.0;
    for (std::size_t k = 0; k < k_; ++k) {
      const auto& o = scene_.observations[k];
      const Observation<JetP> oj = convert_observation<JetP>(o, [](const Field&, double x) { return JetP(x); });
      const PeriodPrediction<JetP> pr = Model::predict(p.data(), oj, app, amplitude_[k]);
      Base& b = base_[k];
      const auto q = derived(pr);
      for (int j = 0; j < kQuantities; ++j) {
        b.value[j] = q[j].a;
        b.gradient[j] = q[j].v;
      }
      for (int i = 0; i < kCorrectionCount; ++i) {
        const Term<JetP>& t = pr.terms[i];
        b.terms[i] = {t.ratio ? std::optional<double>(t.ratio->a) : std::nullopt, t.method, t.skip_reason,
                      t.error_bound, t.series_terms};
      }
      b.cross_ratio = pr.composition.cross.a;
      b.total_ratio = pr.composition.total.a;
      b.residual = (pr.period.a - o.period) * weights_[k];
      b.jacobian = pr.period.v * weights_[k];
      hessian_ += b.jacobian * b.jacobian.transpose();
      if (k_ > 1) out_.fit.chi2 += b.residual * b.residual;
    }
    // The fitted block of J^T J, inverted where it is regular: judged on
    // its correlation form, which the parameters' units do not affect.
    for (int i = 0; i < P; ++i) {
      if (!fitted_[i]) hessian_(i, i) = 1.0;  // held: decoupled, its derivative masked below
    }
    const Vector d = hessian_.diagonal().cwiseSqrt().cwiseInverse();
    const Matrix normalised = d.asDiagonal() * hessian_ * d.asDiagonal();
    const Eigen::SelfAdjointEigenSolver<Matrix> eigen(normalised);
    singular_ = !(eigen.eigenvalues().minCoeff() > 1e-12 * eigen.eigenvalues().maxCoeff()) || !d.allFinite();
    if (!singular_) inverse_ = hessian_.inverse();
    for (int i = 0; i < P; ++i) {
      if (!fitted_[i]) inverse_.row(i).setZero(), inverse_.col(i).setZero();
    }
  }

  /// What a length measured to the bob's top (or bottom) gains from a
  /// change of the bob (`seeded`, the apparatus with one input seeded): the
  /// change of its knot-to-centre distance, which the reader added (value 0,
  /// its derivative that input's).
  Dual knot_to_center_change(std::size_t k, const Apparatus<Dual>& seeded) const {
    const double sign = scene_.sources[k].knot_to_center_sign;
    if (sign == 0.0 || !seeded.bob) return Dual(0.0);
    return sign * (seeded.bob->knot_to_center() - scene_.apparatus.bob->knot_to_center());
  }

  /// d(parameters)/d(input) through the optimum: -(J^T J)^-1 J^T dr/dx.
  Vector parameter_derivative(const Vector& jt_dr) const { return -inverse_ * jt_dr; }

  void gather_inputs() {
    for (std::size_t k = 0; k < k_; ++k) {
      int ordinal = 0;
      zip_observation(scene_.observations[k], scene_.observation_uncertainties[k],
                      [&](const Field& f, const double& v, const double& u) {
                        const ObservationSource& source = scene_.sources[k];
                        const int at = ordinal++;
                        if (!source.is_shared(f.path)) {
                          if (tau_ > 0.0 && f.role == FieldRole::length) add_length_scatter(k, f, v, at);
                          return add_input(source.path + f.path, f, v, u, {k}, at);
                        }
                        const int known = find_input(f.path);
                        if (known >= 0) return inputs_[known].observations.push_back(k);
                        // Said once, by its first observation.
                        const auto& missing = out_.inputs_without_uncertainty;
                        if (std::find(missing.begin(), missing.end(), f.path) == missing.end()) {
                          add_input(f.path, f, v, u, {k}, at);
                        }
                      });
    }
    int ordinal = 0;
    zip_apparatus(scene_.apparatus, scene_.apparatus_uncertainty,
                  [&](const Field& f, const double& v, const double& u) { add_input(field_path(f), f, v, u, {}, ordinal++); });
  }

  /// Observation k's share of the lengths' scatter: its length moved by tau,
  /// Type A from the fit's n - p residuals.
  void add_length_scatter(std::size_t k, const Field& f, double value, int ordinal) {
    const std::string path = scene_.sources[k].path + "length_scatter";
    inputs_.push_back({path, f.unit, value, tau_, {k}, ordinal, f.role,
                       InputEvaluation{path, 'A', Distribution::student_t, static_cast<double>(k_) - free_count_,
                                       SharedVariance::length_scatter}});
  }

  void add_input(std::string path, const Field& f, double value, double sigma, std::vector<std::size_t> observations,
                 int ordinal) {
    if (sigma > 0.0) {
      InputEvaluation evaluation = evaluation_of(scene_.evaluations, path);
      inputs_.push_back({std::move(path), f.unit, value, sigma, std::move(observations), ordinal, f.role,
                         std::move(evaluation)});
    } else {
      out_.inputs_without_uncertainty.push_back(std::move(path));
    }
  }

  void propagate() {
    gather_inputs();
    variance_.assign(k_, {});
    covariance_.setZero();
    covariance_pl_.setZero();
    Matrix observations_total = Matrix::Zero();
    std::vector<Matrix> observation_own(k_, Matrix::Zero());
    std::array<Dual, P> p;
    for (int i = 0; i < P; ++i) p[i] = Dual(p_[i]);
    const Apparatus<Dual> app = convert_apparatus<Dual>(scene_.apparatus, [](const Field&, double x) { return Dual(x); });

    // The correlated inputs keep their total derivatives for the cross terms.
    for (const auto& c : scene_.input_covariances) {
      const int a = find_input(c.first), b = find_input(c.second);
      if (a >= 0 && b >= 0) pairs_.push_back({a, b, c.covariance, {}, {}});
    }
    std::vector<std::array<double, kQuantities>> partial(k_);
    std::vector<double> residual_partial(k_);
    std::vector<std::size_t> every(k_);
    for (std::size_t k = 0; k < k_; ++k) every[k] = k;
    for (std::size_t j = 0; j < inputs_.size(); ++j) {
      check_interrupt();
      const Input& in = inputs_[j];
      const bool of_apparatus = in.observations.empty();
      const std::vector<std::size_t>& touched = of_apparatus ? every : in.observations;
      const Apparatus<Dual> seeded_app =
          of_apparatus ? convert_apparatus<Dual>(scene_.apparatus, Seeder{in.ordinal}) : app;
      Vector jt_dr = Vector::Zero();
      for (const std::size_t k : touched) {
        Observation<Dual> o = convert_observation<Dual>(scene_.observations[k], Seeder{of_apparatus ? -1 : in.ordinal});
        if (of_apparatus) o.length += knot_to_center_change(k, seeded_app);
        const PeriodPrediction<Dual> pr = Model::predict(p.data(), o, seeded_app, amplitude_[k]);
        const auto q = derived(pr);
        for (int i = 0; i < kQuantities; ++i) partial[k][i] = q[i].v[0];
        residual_partial[k] = (pr.period - o.period).v[0] * weights_[k];
        jt_dr += base_[k].jacobian * residual_partial[k];
      }
      const Vector dp = parameter_derivative(jt_dr);
      sensitivities_.push_back(dp);
      const Matrix outer = dp * dp.transpose() * (in.sigma * in.sigma);
      covariance_ += outer;
      if (in.role != FieldRole::other) covariance_pl_ += outer;
      if (!of_apparatus) {
        observations_total += outer;
        for (const std::size_t k : touched) observation_own[k] += outer;
      }
      Pair* pair = nullptr;
      for (auto& pr : pairs_) {
        if (pr.a == static_cast<int>(j) || pr.b == static_cast<int>(j)) pair = &pr;
      }
      if (pair) (pair->a == static_cast<int>(j) ? pair->da : pair->db).assign(k_, {});
      for (const std::size_t k : touched) {
        for (int i = 0; i < kQuantities; ++i) {
          const double total = partial[k][i] + base_[k].gradient[i].dot(dp);
          variance_[k][i] += total * total * in.sigma * in.sigma;
          if (pair) (pair->a == static_cast<int>(j) ? pair->da : pair->db)[k][i] = total;
        }
      }
    }
    // An observation's inputs move the others' quantities through the
    // parameters alone.
    for (std::size_t k = 0; k < k_; ++k) {
      const Matrix others = observations_total - observation_own[k];
      for (int i = 0; i < kQuantities; ++i) {
        variance_[k][i] += base_[k].gradient[i].dot(others * base_[k].gradient[i]);
      }
    }
    for (const Pair& pr : pairs_) {
      const Vector& da = sensitivities_[pr.a];
      const Vector& db = sensitivities_[pr.b];
      covariance_ += (da * db.transpose() + db * da.transpose()) * pr.covariance;
      if (pr.da.empty() || pr.db.empty()) continue;
      for (std::size_t k = 0; k < k_; ++k) {
        for (int i = 0; i < kQuantities; ++i) variance_[k][i] += 2.0 * pr.da[k][i] * pr.db[k][i] * pr.covariance;
      }
    }
  }

  int find_input(const std::string& path) const {
    for (std::size_t j = 0; j < inputs_.size(); ++j) {
      if (inputs_[j].path == path) return static_cast<int>(j);
    }
    return -1;
  }

  std::optional<double> deviation(double variance) const {
    if (singular_) return std::nullopt;
    return std::sqrt(std::max(variance, 0.0));
  }

  void report() {
    const double g = p_[0];
    report_parameters();
    const ParameterResult& fitted_g = out_.fit.parameters[0];
    out_.g = {g, fitted_g.uncertainty};
    out_.g_uncertainty_unscaled = fitted_g.uncertainty_unscaled;
    out_.g_period_and_length_uncertainty = deviation(covariance_pl_(0, 0));
    // Periods whose uncertainty is their scatter: the periods' share carries S as g's does.
    if (scene_.period_uncertainty_from_scatter && out_.fit.scaled && out_.g_period_and_length_uncertainty &&
        fitted_g.uncertainty_from_observations) {
      out_.g_period_and_length_uncertainty = scaled_uncertainty(
          *out_.g_period_and_length_uncertainty, *fitted_g.uncertainty_from_observations, *out_.fit.birge_ratio);
    }
    report_observations(g);
    report_budget();
    out_.fit.model = Model::kName;
    Model::report(FitState<P>{scene_, options_, p_, fitted_, covariance_, inverse_, singular_}, out_);
    if (singular_) {
      out_.warnings.push_back(
          "fit: the observations cannot separate the unknowns (their covariance is singular), so no "
          "uncertainty is given; add observations at other lengths, or fit fewer unknowns");
    }
  }

  void report_parameters() {
    FitReport& fit = out_.fit;
    fit.dof = static_cast<int>(k_) - free_count_;
    const Dispersion d = dispersion(fit.chi2, fit.dof);
    fit.probability = d.probability;
    fit.birge_ratio = d.birge_ratio;
    // Periods whose uncertainty is the scatter about the fit: S applied wherever it is above the floor.
    // With the lengths' scatter fitted, S = 1 by construction: nothing to scale.
    fit.scaled = (scene_.period_uncertainty_from_scatter ? d.birge_ratio && *d.birge_ratio > 1.0 : d.over_dispersed) &&
                 !singular_ && tau_ == 0.0;
    if (tau_ > 0.0) report_length_scatter();
    std::vector<int> free;
    for (int i = 0; i < P; ++i) {
      const ParameterInfo& info = Model::kParameterInfo[i];
      std::optional<double> from_periods;
      // (J^T W J)^-1 of the weighted residuals: what ceres::Covariance gives.
      if (fitted_[i] && k_ > 1 && !singular_) from_periods = std::sqrt(inverse_(i, i));
      const std::optional<double> stated = fitted_[i] ? deviation(covariance_(i, i)) : std::nullopt;
      // The scatter tests the observations' own uncertainties, (J^T W J)^-1: S scales that share.
      const std::optional<double> supported =
          fit.scaled && stated ? std::optional<double>(scaled_uncertainty(*stated, *from_periods, *d.birge_ratio))
                               : stated;
      fit.parameters.push_back({info.name, info.unit, p_[i], supported, from_periods, fitted_[i], stated});
      if (fitted_[i]) free.push_back(i);
    }
    if (!singular_) {
      for (int a : free) {
        for (int b : free) {
          fit.correlation.push_back(covariance_(a, b) / std::sqrt(covariance_(a, a) * covariance_(b, b)));
        }
      }
    }
  }

  void report_length_scatter() {
    FitReport& fit = out_.fit;
    fit.length_scatter = tau_;
    fit.chi2_stated = chi2_stated_;
    const Dispersion stated = dispersion(*chi2_stated_, fit.dof);
    out_.warnings.push_back(
        "fit: the lengths scatter by " + format_number(tau_ * 1e3, 2) +
        " mm beyond their stated uncertainty (none stated): against the periods' uncertainties alone " +
        dispersion_finding(stated, "the observations scatter about the fit") +
        "; taken as each length's own unknown error (a tape read to the bob's centre), it weighs the periods "
        "as the textbook line T^2 against L does, and its share is in g's uncertainty (the budget's "
        "length_scatter rows)");
  }

  void report_observations(double g) {
    for (std::size_t k = 0; k < k_; ++k) {
      const Base& b = base_[k];
      const auto& o = scene_.observations[k];
      const double sigma = scene_.observation_uncertainties[k].period;
      ObservationResult r;
      r.path = scene_.sources[k].path;
      r.length = o.length;
      r.amplitude = o.amplitude;
      r.trials = scene_.sources[k].trial_count;
      r.oscillations_per_trial = o.oscillations_per_trial;
      r.period_measured = {o.period, sigma};
      r.period_model = b.value[kModelPeriod];
      r.period_ideal = {b.value[kIdealPeriod], deviation(variance_[k][kIdealPeriod])};
      if (k_ > 1) {
        r.residual = b.residual;  // in effective standard uncertainties
        r.effective_uncertainty = 1.0 / weights_[k];
      }
      r.negligible_below = options_.negligible_fraction * sigma;
      r.amplitude_of = o.amplitude_of;
      if (o.amplitude_of == AngleOf::body) {
        const Swing<double> s = Model::swing_at(p_.data(), Model::swing(o), scene_.apparatus);
        r.amplitude_pendulum = pendulum_over_body_angle(scene_.apparatus, s.length) * o.amplitude;
      }
      for (int i = 0; i < kCorrectionCount; ++i) {
        const Term<double>& term = b.terms[i];
        CorrectionRow row;
        row.info = kCorrections[i];
        row.method = term.method;
        row.series_terms = term.series_terms;
        if (!term.ratio) {
          row.reason = term.skip_reason;
        } else {
          row.ratio = term.ratio;
          row.delta_T = b.value[kFirstRow + i];
          row.delta_g = 2.0 * g * *term.ratio;
          row.delta_T_uncertainty = deviation(variance_[k][kFirstRow + i]);
          if (term.error_bound) row.error_bound_delta_T = *term.error_bound * b.value[kIdealPeriod];
          set_status(row, r.negligible_below);
        }
        r.corrections.push_back(std::move(row));
      }
      r.cross_term_delta_T = b.value[kCross];
      if (r.cross_term_delta_T != 0.0 && std::abs(r.cross_term_delta_T) >= r.negligible_below) {
        CorrectionRow row;
        row.info = kAmplitudeCrossTerm;
        row.method = "product";
        row.ratio = b.cross_ratio;
        row.delta_T = r.cross_term_delta_T;
        row.delta_g = 2.0 * g * b.cross_ratio;
        row.delta_T_uncertainty = deviation(variance_[k][kCross]);
        set_status(row, r.negligible_below);
        r.corrections.push_back(std::move(row));
      }
      r.total_delta_T = b.value[kModelPeriod] - b.value[kIdealPeriod];
      r.total_delta_g = 2.0 * g * b.total_ratio;
      // Periods whose uncertainty is the scatter about the fit cannot single one
      // out: in that scatter a residual is at most sqrt(n - p) of it (under 3 to
      // n - p = 9), while against the printed digits' floor every one is far off.
      if (r.residual && std::abs(*r.residual) > 3.0 && !scene_.period_uncertainty_from_scatter) {
        out_.warnings.push_back(r.path + "timing: the period " + format_number(o.period, 7) + " s is " +
                                format_number(std::abs(*r.residual), 2) + " of its standard uncertainties from the model's " +
                                format_number(r.period_model, 7) + " s; a miscounted oscillation, a length misread, or an "
                                "uncertainty too small?");
      }
      out_.observations.push_back(std::move(r));
    }
  }

  void set_status(CorrectionRow& row, double negligible_below) const {
    row.status = std::abs(*row.delta_T) < negligible_below ? Status::negligible : Status::applied;
    if (row.status == Status::negligible) {
      row.reason = "|delta_T| below " + format_number(options_.negligible_fraction, 6) +
                   " of the period's uncertainty (" + format_number(negligible_below, 6) + " s)";
    }
  }

  /// Parameter i's effective degrees of freedom (GUM G.4), its variance's
  /// components as variance_components() forms them.
  double effective_dof(int i) const {
    std::vector<InputShare> shares;
    for (std::size_t j = 0; j < inputs_.size(); ++j) {
      const InputEvaluation& e = inputs_[j].evaluation;
      shares.push_back({std::pow(sensitivities_[j](i) * inputs_[j].sigma, 2), e.dof, e.shared});
    }
    std::vector<PairShare> pairs;
    for (const Pair& pr : pairs_) {
      pairs.push_back({static_cast<std::size_t>(pr.a), static_cast<std::size_t>(pr.b),
                       2.0 * sensitivities_[pr.a](i) * sensitivities_[pr.b](i) * pr.covariance});
    }
    VarianceComponent birge{0.0, kInfiniteDof};
    const ParameterResult& p = out_.fit.parameters[i];
    if (out_.fit.scaled && p.uncertainty && p.uncertainty_unscaled) {
      birge = {*p.uncertainty * *p.uncertainty - *p.uncertainty_unscaled * *p.uncertainty_unscaled,
               static_cast<double>(out_.fit.dof)};
    }
    return welch_satterthwaite(variance_components(shares, pairs, birge));
  }

  void report_budget() {
    const double combined = covariance_(0, 0);  // the stated uncertainties' u_c^2
    for (std::size_t j = 0; j < inputs_.size(); ++j) {
      const Input& in = inputs_[j];
      const double s = sensitivities_[j](0), contribution = std::abs(s) * in.sigma;
      out_.budget.push_back({in.path, in.unit, in.value, in.sigma, s, contribution, in.evaluation,
                             combined > 0.0 ? contribution * contribution / combined : 0.0});
    }
    for (int i = 0; i < P; ++i) {
      ParameterResult& p = out_.fit.parameters[i];
      if (p.uncertainty) p.degrees_of_freedom = effective_dof(i);
    }
    if (const std::optional<double>& u = out_.g.uncertainty) {
      const double nu = out_.fit.parameters[0].degrees_of_freedom, k = coverage_factor(nu);
      out_.g_expanded = ExpandedUncertainty{nu, k, kCoverageProbability, k * *u};
    }
    std::stable_sort(out_.budget.begin(), out_.budget.end(),
                     [](const BudgetEntry& x, const BudgetEntry& y) { return x.contribution > y.contribution; });
    if (!pairs_.empty()) {
      const Pair& pr = pairs_.front();
      const Input &a = inputs_[pr.a], &b = inputs_[pr.b];
      out_.budget_correlation = BudgetCorrelation{a.path, b.path, pr.covariance / (a.sigma * b.sigma),
                                                  2.0 * sensitivities_[pr.a](0) * sensitivities_[pr.b](0) * pr.covariance};
    }
    if (singular_) out_.budget.clear();
  }

  struct Base {
    std::array<double, kQuantities> value;
    std::array<Vector, kQuantities> gradient;  ///< with respect to the parameters
    Terms<double> terms;
    double cross_ratio, total_ratio;
    double residual;
    Vector jacobian;  ///< of the residual
  };
  struct Pair {
    int a, b;
    double covariance;
    std::vector<std::array<double, kQuantities>> da, db;  ///< total derivatives of the quantities
  };

  const ParsedScene& scene_;
  const AnalysisOptions& options_;
  Analysis& out_;
  const std::size_t k_;
  std::array<bool, P> fitted_;
  int free_count_ = 0;
  std::vector<AmplitudeChoice> amplitude_;
  std::vector<double> weights_;
  /// The lengths' fitted scatter (m), 0 where none; each period's variance
  /// from its stated inputs (s^2) and dT/dL (s/m), at the last weigh().
  double tau_ = 0.0;
  std::optional<double> chi2_stated_;
  std::vector<double> stated_variance_, length_slope_;
  std::array<double, P> p_;
  std::vector<Base> base_;
  Matrix hessian_, inverse_ = Matrix::Zero();
  bool singular_ = false;
  std::vector<Input> inputs_;
  std::vector<Vector> sensitivities_;
  std::vector<Pair> pairs_;
  Matrix covariance_, covariance_pl_;
  std::vector<std::array<double, kQuantities>> variance_;
};

}  // namespace

std::optional<AmplitudeSweep> amplitude_sweep_of(const ParsedScene& scene) {
  const auto& obs = scene.observations;
  if (!scene.series || scene.swing_by_swing || obs.empty()) return std::nullopt;
  const double length = obs.front().length;
  std::vector<double> amplitudes;
  for (const auto& o : obs) {
    if (o.setting != Setting::length || std::abs(o.length - length) > 1e-9 * length) return std::nullopt;
    amplitudes.push_back(o.amplitude);
  }
  if (distinct_amplitudes(amplitudes) < (scene.length_measured ? 3u : 2u)) return std::nullopt;
  std::vector<SweepPoint> points;
  for (std::size_t k = 0; k < obs.size(); ++k) {
    const auto& u = scene.observation_uncertainties[k];
    points.push_back({obs[k].amplitude, u.amplitude, obs[k].period, u.period});
  }
  return fit_amplitude_sweep(points, scene.period_uncertainty_from_scatter);
}

Analysis analyse(const ParsedScene& given, const AnalysisOptions& options) {
  if (!given.length_measured) {
    throw InputError("length", "\"" + std::string(kLengthNotMeasured) + "\": an amplitude sweep without its length "
                               "gives its small-amplitude period (pendulum-g reduce), not g; expected the length "
                               "for g and everything that needs it");
  }
  Analysis out;
  if (given.decay_data) {
    out.decay_fit = fit_decay(*given.decay_data);
    out.decay_given = given.apparatus.decay;
    out.warnings = review_decay_fit(*out.decay_fit);
  }
  const std::optional<ParsedScene> fitted = scene_with_fitted_decay(given, out.decay_fit);
  if (fitted) check_first_order(*fitted);  // alpha and beta from the fit, too
  const ParsedScene& scene = fitted ? *fitted : given;
  if (scene.apparatus.decay && scene.observations.size() == 1) {
    out.drag = predict_drag(scene.apparatus, scene.observations[0]);
  }
  visit_period_model(scene.model, [&](auto model) { Fit<decltype(model)>(scene, options, out).run(); });
  out.amplitude_sweep = amplitude_sweep_of(scene);
  for (auto& w : visit_period_model(scene.model, [&](auto model) {
         return decltype(model)::skipped_part_warnings(scene, options.negligible_fraction);
       })) {
    out.warnings.push_back(std::move(w));
  }

  if (scene.site) out.expected_g = expected_gravity(*scene.site);
  if (!out.expected_g) out.surface_g = earth_surface_gravity();
  const auto z_against = [&](const ExpectedGravity& expected) -> std::optional<double> {
    if (!out.g.uncertainty) return std::nullopt;
    const double combined = std::hypot(*out.g.uncertainty, expected.uncertainty);
    const double z = (out.g.value - expected.value) / combined;
    if (combined > 0.0 && std::isfinite(z)) return z;
    return std::nullopt;
  };
  if (out.expected_g) out.z_score = z_against(*out.expected_g);
  if (out.surface_g) out.surface_z = z_against(*out.surface_g);

  // An uncertainty so large that the propagated ones overflow (1e300 on a
  // rate, say) is the input's fault: name the input that contributes most.
  bool finite_uncertainties = !out.g.uncertainty || std::isfinite(*out.g.uncertainty);
  for (const auto& o : out.observations) {
    if (o.period_ideal.uncertainty && !std::isfinite(*o.period_ideal.uncertainty)) finite_uncertainties = false;
    for (const auto& row : o.corrections) {
      if (row.delta_T_uncertainty && !std::isfinite(*row.delta_T_uncertainty)) finite_uncertainties = false;
    }
  }
  if (!finite_uncertainties && !out.budget.empty()) {
    const auto worst = std::max_element(out.budget.begin(), out.budget.end(), [](const auto& x, const auto& y) {
      return !(std::abs(x.sensitivity) * x.uncertainty >= std::abs(y.sensitivity) * y.uncertainty);
    });
    std::ostringstream why;
    why << "got " << worst->uncertainty << " " << worst->unit
        << "; expected an uncertainty small enough for g's uncertainty to stay finite";
    throw InputError(worst->input + ".uncertainty", why.str());
  }

  // A non-finite number here is a bug, not an input error: never print it.
  auto check = [](double x, const std::string& what) {
    if (!std::isfinite(x)) throw std::logic_error("non-finite " + what);
  };
  check(out.g.value, "g");
  for (const auto& o : out.observations) {
    check(o.period_ideal.value, "ideal period");
    check(o.period_model, "model period");
    for (const auto& row : o.corrections) {
      if (row.delta_T) check(*row.delta_T, row.info.id);
    }
  }
  return out;
}

}  // namespace pendulum
