#include "pendulum/monte_carlo.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <random>
#include <string_view>
#include <utility>

#include <Eigen/Dense>
#include <ceres/jet.h>

#include "grouping.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/interrupt.hpp"
#include "pendulum/models/registry.hpp"
#include "pendulum/numeric.hpp"
#include "pendulum/period_model.hpp"
#include "pendulum/reduction.hpp"

namespace pendulum {

const char* rejection_name(Rejection r) {
  switch (r) {
    case Rejection::outside_domain: return "outside_domain";
    case Rejection::no_convergence: return "no_convergence";
    case Rejection::run_away: return "run_away";
    case Rejection::g_not_positive: return "g_not_positive";
  }
  return "";
}

std::pair<double, double> shortest_interval(const std::vector<double>& sorted, double probability) {
  const std::size_t m = sorted.size();
  const std::size_t q = std::min(m - 1, static_cast<std::size_t>(std::llround(probability * static_cast<double>(m))));
  std::size_t best = 0;
  for (std::size_t r = 1; r + q < m; ++r) {
    if (sorted[r + q] - sorted[r] < sorted[best + q] - sorted[best]) best = r;
  }
  return {sorted[best], sorted[best + q]};
}

namespace {

/// One input drawn: the scalars it moves (the apparatus's zip order, or an
/// observation's: several where a series gives it once), its uncertainty and
/// how it was evaluated.
struct Drawn {
  std::string path;
  double sigma;
  InputEvaluation evaluation;
  /// Its places among the scene's scalars (the apparatus's, then each observation's).
  std::vector<int> slots;
  int partner = -1;  ///< a correlated input's index, drawn jointly
  double correlation = 0.0;
};

/// Seeded deviates: the same seed, the same draws (Marsaglia's polar
/// method, both of its normals used: one logarithm for two and no cosine,
/// and libstdc++'s chi-squared).
class Deviates {
 public:
  explicit Deviates(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return ((engine_() >> 11) + 0.5) * 0x1.0p-53; }  // in (0, 1)
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u, v, s;
    do {
      u = 2.0 * uniform() - 1.0;
      v = 2.0 * uniform() - 1.0;
      s = u * u + v * v;
    } while (s >= 1.0);  // uniform() is never 1/2 exactly, so s > 0
    const double f = std::sqrt(-2.0 * std::log(s) / s);
    spare_ = v * f;
    has_spare_ = true;
    return u * f;
  }
  /// sqrt(nu / chi2_nu): a normal draw times this is Student's t with nu dof.
  double t_scale(double nu) { return 1.0 / std::sqrt(std::chi_squared_distribution<double>(nu)(engine_) / nu); }
  /// A standardised draw of `e`'s distribution: the input is value + sigma x this.
  double draw(const InputEvaluation& e) {
    switch (e.distribution) {
      case Distribution::rectangular: return std::sqrt(3.0) * (2.0 * uniform() - 1.0);
      case Distribution::student_t:  // S1 6.4.9.7: x + (s/sqrt(n)) t_{n-1}
        if (std::isfinite(e.dof)) return normal() * t_scale(e.dof);
        return normal();
      case Distribution::normal: return normal();
    }
    return 0.0;
  }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

/// The exact amplitude method at theta0 (rad), refused outside its domain
/// as choose_amplitude_method refuses it; without its error bound, which
/// g does not read and which costs a second AGM a draw.
AmplitudeChoice exact_amplitude(double theta0) {
  detail::require_amplitude(theta0, ranges::amplitude);
  return {AmplitudeMethod::agm, ReductionOptions{}.series_terms, 0.0};
}

/// One draw's g, or why it gives none.
struct Outcome {
  double g = 0.0;
  std::optional<Rejection> rejected;
};

/// g of a scene whose inputs are shifted: the closed form for one
/// observation with g its only unknown; a series refitted (Gauss-Newton from
/// the analysis's optimum, with its effective-variance weights held, as the
/// estimator is defined by them).
template <class Model>
class Refit {
 public:
  static constexpr int P = Model::kParameters;
  using Jet = ceres::Jet<double, P>;

  Refit(const ParsedScene& scene, const Analysis& analysis) {
    for (int i = 0; i < P; ++i) {
      const ParameterResult& parameter = analysis.fit.parameters[i];
      start_[i] = parameter.value;
      fitted_[i] = parameter.fitted;
      scale_[i] = parameter.uncertainty.value_or(1e-6 * std::abs(parameter.value));
    }
    closed_form_ = scene.observations.size() == 1 && std::count(fitted_.begin(), fitted_.end(), true) == 1;
    for (const ObservationResult& o : analysis.observations) weights_.push_back(1.0 / o.effective_uncertainty);
  }

  Outcome g(const Apparatus<double>& app, const std::vector<Observation<double>>& obs) const {
    if (closed_form_) {
      const double g = Model::solve_g(Model::kDefaults.data(), obs[0], app, exact_amplitude(obs[0].amplitude));
      if (!std::isfinite(g)) return {g, Rejection::outside_domain};
      return g > 0.0 ? Outcome{g, std::nullopt} : Outcome{g, Rejection::g_not_positive};
    }
    const Apparatus<Jet> app_jet = convert_apparatus<Jet>(app, [](const Field&, double x) { return Jet(x); });
    std::vector<Observation<Jet>> obs_jet;
    std::vector<AmplitudeChoice> amplitude;
    for (const auto& o : obs) {
      obs_jet.push_back(convert_observation<Jet>(o, [](const Field&, double x) { return Jet(x); }));
      amplitude.push_back(exact_amplitude(o.amplitude));
    }
    std::array<double, P> p = start_;
    using Matrix = Eigen::Matrix<double, P, P>;
    using Vector = Eigen::Matrix<double, P, 1>;
    // Near the optimum Gauss-Newton converges quadratically: a step below
    // 1e-6 of its parameter's uncertainty leaves an error of order its
    // square, far below any tolerance of S1 7.9, so no further step is
    // evaluated. Measured in uncertainties, a run away (|g| ~ 1e13, its
    // steps 1e-8 of it) never converges, and gives no draw.
    for (int iteration = 0; iteration < 20; ++iteration) {
      std::array<Jet, P> pj;
      for (int i = 0; i < P; ++i) pj[i] = fitted_[i] ? Jet(p[i], i) : Jet(p[i]);
      Matrix h = Matrix::Zero();
      Vector b = Vector::Zero();
      for (std::size_t k = 0; k < obs.size(); ++k) {
        const Jet t = prediction_period<Model>(pj.data(), obs_jet[k], app_jet, amplitude[k]);
        const Vector j = t.v * weights_[k];
        h += j * j.transpose();
        b += j * ((t.a - obs[k].period) * weights_[k]);
      }
      for (int i = 0; i < P; ++i) {
        if (!fitted_[i]) h(i, i) = 1.0;
      }
      const Vector step = h.ldlt().solve(b);
      bool small = true, near = true;
      for (int i = 0; i < P; ++i) {
        p[i] -= step[i];
        if (!(std::abs(step[i]) <= 1e-6 * scale_[i])) small = false;
        // A thousand uncertainties away is another minimum (an offset that
        // absorbs the lengths), not this fit's: P(|t_2| > 1000) ~ 1e-6.
        if (!(std::abs(p[i] - start_[i]) <= 1e3 * scale_[i])) near = false;
      }
      if (small && !near) return {p[0], Rejection::run_away};
      if (small) return p[0] > 0.0 ? Outcome{p[0], std::nullopt} : Outcome{p[0], Rejection::g_not_positive};
    }
    return {p[0], Rejection::no_convergence};
  }

 private:
  std::array<double, P> start_;
  std::array<bool, P> fitted_;
  std::array<double, P> scale_;  ///< each parameter's uncertainty, the step's measure
  bool closed_form_;
  std::vector<double> weights_;
};

/// A run's values of g, and the draws that gave none by Rejection.
struct Draws {
  std::vector<double> g;
  std::array<long, kRejectionKinds> rejected{};
};

/// A draw's scene: the scene's apparatus and observations, their drawn
/// scalars written in place, in the sampler's order (the apparatus's, then
/// each observation's).
struct DrawnScene {
  Apparatus<double> apparatus;
  std::vector<Observation<double>> observations;
};

class Sampler {
 public:
  Sampler(const ParsedScene& scene, const Analysis& analysis) : scene_(scene), analysis_(analysis) {
    int at = 0;  // a scalar's place in the order
    zip_apparatus(scene.apparatus, scene.apparatus_uncertainty, [&](const Field& f, const double& x, const double& u) {
      values_.push_back(x);
      add(field_path(f), u, at++);
    });
    // The shape before a body's parts give it anything (derive_from_parts): each draw derives it again.
    zip_apparatus(scene.apparatus, shape_.apparatus, [](const Field&, const double& x, double& y) { y = x; });
    for (std::size_t k = 0; k < scene.observations.size(); ++k) {
      const ObservationSource& source = scene.sources[k];
      zip_observation(scene.observations[k], scene.observation_uncertainties[k],
                      [&](const Field& f, const double& x, const double& u) {
                        if (f.role == FieldRole::period) period_at_.push_back({at, u > 0.0});
                        if (f.role == FieldRole::length && analysis.fit.length_scatter) length_slots_.push_back(at);
                        if (std::string_view(f.path) == "amplitude") amplitudes_.push_back(at);
                        values_.push_back(x);
                        add(source.path_of(f.path), u, at++);
                      });
      shape_.observations.push_back(
          convert_observation<double>(scene.observations[k], [](const Field&, double x) { return x; }));
    }
    for (const auto& c : scene.input_covariances) {
      const int a = find(c.first), b = find(c.second);
      if (a < 0 || b < 0) continue;
      inputs_[a].partner = b;
      inputs_[b].partner = a;
      inputs_[b].correlation = c.covariance / (inputs_[a].sigma * inputs_[b].sigma);
    }
    for (const Drawn& in : inputs_) {
      if (in.evaluation.shared == SharedVariance::pooled_trials) pooled_dof_ = in.evaluation.dof;
    }
    // A fit whose scatter scaled its uncertainty by S (dispersion.hpp): the
    // residuals scatter S^2 times the variance the inputs give them, as the
    // fit weighs them. The excess, (S^2 - 1)/w_k^2, is no input's: it goes
    // to each period (its scale there), as a multivariate t with the fit's
    // n - p degrees of freedom (S^2 = chi2/(n - p) estimates it). Its
    // linear share of g is (S^2 - 1)(J^T W J)^-1, what the scaling added.
    if (analysis.fit.scaled && analysis.fit.birge_ratio && analysis.fit.dof > 0) {
      const double s = *analysis.fit.birge_ratio;
      for (const ObservationResult& o : analysis.observations) {
        excess_.push_back(std::sqrt(s * s - 1.0) * o.effective_uncertainty);
      }
      excess_dof_ = analysis.fit.dof;
    }
  }

  /// `count` values of g, each input but those `held` drawn.
  Draws draw(long count, Deviates& deviates, const std::vector<std::string>& held = {}) const {
    std::vector<double> shift(values_.size(), 0.0);
    std::vector<double> z(inputs_.size());
    std::vector<char> is_held(inputs_.size());
    for (std::size_t i = 0; i < inputs_.size(); ++i) {
      is_held[i] = std::find(held.begin(), held.end(), inputs_[i].path) != held.end();
    }
    DrawnScene drawn = shape_;
    std::vector<double*> scalars;  // drawn's, in the order of values_
    zip_apparatus(scene_.apparatus, drawn.apparatus,
                  [&](const Field&, const double&, double& y) { scalars.push_back(&y); });
    for (std::size_t k = 0; k < scene_.observations.size(); ++k) {
      zip_observation(scene_.observations[k], drawn.observations[k],
                      [&](const Field&, const double&, double& y) { scalars.push_back(&y); });
    }
    Draws out;
    out.g.reserve(count);
    visit_period_model(scene_.model, [&](auto model) {
      const Refit<decltype(model)> refit(scene_, analysis_);
      // Every draw outside the model's domain would loop for ever: a bound.
      for (long attempt = 0; static_cast<long>(out.g.size()) < count && attempt < 10 * count; ++attempt) {
        check_interrupt();
        // Pooled periods share one estimated variance: a multivariate t.
        const double pooled = pooled_dof_ > 0.0 ? deviates.t_scale(pooled_dof_) : 1.0;
        for (std::size_t i = 0; i < inputs_.size(); ++i) {
          const Drawn& in = inputs_[i];
          // Jointly normal with its partner: z_b = rho z_a + sqrt(1 - rho^2) z'.
          if (in.partner >= 0 && in.partner < static_cast<int>(i)) {
            z[i] = in.correlation * z[in.partner] +
                   std::sqrt(std::max(0.0, 1.0 - in.correlation * in.correlation)) * deviates.normal();
          } else {
            z[i] = in.partner >= 0 ? deviates.normal()
                   : in.evaluation.shared == SharedVariance::pooled_trials ? deviates.normal() * pooled
                                          : deviates.draw(in.evaluation);
          }
          const double value = is_held[i] ? 0.0 : in.sigma * z[i];
          for (const int at : in.slots) shift[at] = value;
        }
        add_excess_scatter(deviates, shift);
        draw_length_scatter(shift, deviates);
        set_scalars(shift, scalars, drawn);
        const Outcome g = g_of(refit, drawn);
        if (g.rejected) {
          ++out.rejected[static_cast<int>(*g.rejected)];
        } else {
          out.g.push_back(g.g);
        }
      }
    });
    return out;
  }

 private:
  /// The lengths' fitted scatter (analysis.cpp, Paule & Mandel) where it
  /// was fitted instead of a Birge ratio: each length, stated without
  /// uncertainty, moved by tau times one normal deviate, tau itself t-scaled
  /// with the fit's dof.
  void draw_length_scatter(std::vector<double>& shift, Deviates& deviates) const {
    if (length_slots_.empty()) return;
    const double tau = *analysis_.fit.length_scatter * deviates.t_scale(analysis_.fit.dof);
    for (const int at : length_slots_) shift[at] = tau * deviates.normal();
  }

  void add(std::string path, double sigma, int at) {
    if (!(sigma > 0.0)) return;
    const int known = find(path);
    if (known >= 0) return inputs_[known].slots.push_back(at);
    InputEvaluation evaluation = evaluation_of(scene_.evaluations, path);
    inputs_.push_back({std::move(path), sigma, std::move(evaluation), {at}});
  }

  /// The Birge ratio's excess added to each period's drawn shift: one
  /// chi-square draw for all of them (one variance, estimated once).
  void add_excess_scatter(Deviates& deviates, std::vector<double>& shift) const {
    if (excess_.empty()) return;
    const double scale = deviates.t_scale(excess_dof_);
    for (std::size_t k = 0; k < excess_.size(); ++k) {
      const auto [at, drawn] = period_at_[k];  // a period without an uncertainty is no input: its shift is this alone
      shift[at] = (drawn ? shift[at] : 0.0) + excess_[k] * scale * deviates.normal();
    }
  }
  int find(const std::string& path) const {
    for (std::size_t i = 0; i < inputs_.size(); ++i) {
      if (inputs_[i].path == path) return static_cast<int>(i);
    }
    return -1;
  }

  /// The scene's scalars shifted, written into `drawn` through `scalars`; a
  /// body's shape restored first, and what its drawn parts give derived
  /// again; a length to the bob's top or bottom moves with the bob's drawn
  /// size, as the budget's does (analysis.cpp).
  void set_scalars(const std::vector<double>& shift, const std::vector<double*>& scalars, DrawnScene& drawn) const {
    Apparatus<double>& app = drawn.apparatus;
    if (app.body) *app.body = *shape_.apparatus.body;  // its parts' sizes unchanged: no scalar moves
    for (std::size_t at = 0; at < values_.size(); ++at) *scalars[at] = values_[at] + shift[at];
    // An amplitude drawn below zero is the same swing to the other side.
    for (const int at : amplitudes_) *scalars[at] = std::abs(*scalars[at]);
    if (app.body) derive_from_parts(*app.body);
    for (std::size_t k = 0; k < drawn.observations.size(); ++k) {
      const double sign = scene_.sources[k].knot_to_center_sign;
      if (sign != 0.0 && app.bob) {
        drawn.observations[k].length += sign * (app.bob->knot_to_center() - scene_.apparatus.bob->knot_to_center());
      }
    }
  }

  /// g of the drawn scene, through every correction with the exact
  /// amplitude factor.
  template <class Model>
  Outcome g_of(const Refit<Model>& refit, const DrawnScene& drawn) const {
    // A draw the model cannot reach (an angle past 180 deg) gives no g.
    try {
      return refit.g(drawn.apparatus, drawn.observations);
    } catch (const std::domain_error&) {
      return {std::numeric_limits<double>::quiet_NaN(), Rejection::outside_domain};
    }
  }

  const ParsedScene& scene_;
  const Analysis& analysis_;
  std::vector<Drawn> inputs_;
  std::vector<double> values_;  ///< the scene's scalars: the apparatus's, then each observation's
  std::vector<int> amplitudes_;  ///< the observations' amplitudes among them
  DrawnScene shape_;  ///< the scene with no body's parts derived: where each draw's starts
  /// Each observation's period: its place among the scalars, and whether it is drawn as an input.
  std::vector<std::pair<int, bool>> period_at_;
  /// Each period's excess scatter sqrt(S^2 - 1)/w_k (s), and its dof; none unscaled.
  std::vector<double> excess_;
  double excess_dof_ = 0.0;
  double pooled_dof_ = 0.0;  ///< of the pooled periods' one variance; 0 where none is pooled
  std::vector<int> length_slots_;  ///< where the lengths' scatter was fitted
};

/// delta of S1 7.9.2: u = c 10^l with c of two digits, delta = 10^l / 2.
double numerical_tolerance(double u) { return 0.5 * std::pow(10.0, std::floor(std::log10(u)) - 1.0); }

struct Summary {
  double mean, deviation, low, high;
};

/// `values` ascending (-0 before +0, which std::sort leaves in either
/// order): a radix sort of their bits, each double made an unsigned key in
/// its order, in passes of 11 bits, a pass skipped where every key has the
/// same digit (the draws' leading bits). 10^6 draws take a fraction of a
/// comparison sort's time, and a run sorts each draw two or three times.
void sort_draws(std::vector<double>& values) {
  constexpr int kDigitBits = 11;
  constexpr std::size_t kDigits = std::size_t{1} << kDigitBits;
  const std::size_t n = values.size();
  std::vector<std::uint64_t> keys(n), sorted(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t bits;
    std::memcpy(&bits, &values[i], sizeof bits);
    keys[i] = bits >> 63 ? ~bits : bits | (std::uint64_t{1} << 63);
  }
  std::vector<std::size_t> start(kDigits);
  for (int shift = 0; shift < 64; shift += kDigitBits) {
    std::fill(start.begin(), start.end(), 0);
    for (const std::uint64_t k : keys) ++start[(k >> shift) & (kDigits - 1)];
    if (start[(keys.empty() ? 0 : keys[0] >> shift) & (kDigits - 1)] == n) continue;
    std::size_t sum = 0;
    for (std::size_t& s : start) sum += std::exchange(s, sum);
    for (const std::uint64_t k : keys) sorted[start[(k >> shift) & (kDigits - 1)]++] = k;
    keys.swap(sorted);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t bits = keys[i] >> 63 ? keys[i] & ~(std::uint64_t{1} << 63) : ~keys[i];
    std::memcpy(&values[i], &bits, sizeof bits);
  }
}

Summary summarise(std::vector<double> values) {
  sort_draws(values);
  double mean = 0.0, ss = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double d = values[i] - mean;
    mean += d / static_cast<double>(i + 1);
    ss += d * (values[i] - mean);
  }
  const auto [low, high] = shortest_interval(values, kCoverageProbability);
  return {mean, std::sqrt(ss / static_cast<double>(values.size() - 1)), low, high};
}

/// A run's draws and the summaries of its batches (in drawn order), whose
/// spread measures the ends' sampling error.
struct Run {
  Draws draws;
  std::vector<Summary> batches;
};

/// S1 7.9.4: batches of 10^4 until twice the standard deviation of each
/// batch statistic's mean (g, u(g), both ends) is within the tolerance.
Run adaptive_draws(const Sampler& sampler, Deviates& deviates) {
  constexpr long kBatch = 10000;
  Run run;
  std::vector<double>& all = run.draws.g;
  std::vector<Summary>& batches = run.batches;
  while (static_cast<long>(all.size()) < kMostDraws) {
    const Draws batch = sampler.draw(kBatch, deviates);
    for (int i = 0; i < kRejectionKinds; ++i) run.draws.rejected[i] += batch.rejected[i];
    if (batch.g.size() < 2) break;
    batches.push_back(summarise(batch.g));
    all.insert(all.end(), batch.g.begin(), batch.g.end());
    const double h = static_cast<double>(batches.size());
    if (batches.size() < 2) continue;
    const double delta = numerical_tolerance(summarise(all).deviation);
    bool stable = true;
    for (double Summary::*statistic : {&Summary::mean, &Summary::deviation, &Summary::low, &Summary::high}) {
      double mean = 0.0, ss = 0.0;
      for (const Summary& b : batches) mean += b.*statistic / h;
      for (const Summary& b : batches) ss += (b.*statistic - mean) * (b.*statistic - mean);
      if (2.0 * std::sqrt(ss / (h * (h - 1.0))) > delta) stable = false;
    }
    if (stable) break;
  }
  return run;
}

/// A fixed number of draws, cut into ten batches for their ends' spread.
Run fixed_draws(const Sampler& sampler, Deviates& deviates, long count) {
  constexpr long kBatches = 10;
  Run run{sampler.draw(count, deviates), {}};
  const std::vector<double>& g = run.draws.g;
  const std::size_t m = g.size() / kBatches;
  for (std::size_t b = 0; m >= 2 && b < kBatches; ++b) {
    run.batches.push_back(summarise(std::vector<double>(g.begin() + b * m, g.begin() + (b + 1) * m)));
  }
  return run;
}

/// The standard uncertainty of the ends of all the draws' shortest interval:
/// each end's spread over the batches, s_b, carried from a batch's m draws
/// to all M as (m/M)^(1/3). A shortest interval's end settles as M^(-1/3),
/// not as a quantile's M^(-1/2): where g's density is smooth at the ends
/// the interval's length is flat about its minimum, and its place wanders
/// (the shorth's cube-root rate, Kim & Pollard 1990). An end at the edge of
/// g's range settles faster, and is overstated. Infinite from fewer than
/// two batches.
std::pair<double, double> end_uncertainty(const std::vector<Summary>& batches) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  const double h = static_cast<double>(batches.size());
  if (batches.size() < 2) return {kNone, kNone};
  const auto spread = [&](double Summary::*end) {
    double mean = 0.0, ss = 0.0;
    for (const Summary& b : batches) mean += b.*end / h;
    for (const Summary& b : batches) ss += (b.*end - mean) * (b.*end - mean);
    return std::sqrt(ss / (h - 1.0)) * std::cbrt(1.0 / h);  // m/M = 1/h
  };
  return {spread(&Summary::low), spread(&Summary::high)};
}

/// GUM's y +- U against the draws' shortest interval (S1 8.2): d_low, d_high.
std::pair<double, double> disagreement(double y, double expanded, const Summary& s) {
  return {std::abs(y - expanded - s.low), std::abs(y + expanded - s.high)};
}

}  // namespace

double expanded_without(const Analysis& a, const std::vector<std::string>& without) {
  const auto held = [&](const std::string& path) { return std::find(without.begin(), without.end(), path) != without.end(); };
  std::vector<InputShare> shares;
  std::vector<std::string> paths;
  for (const BudgetEntry& b : a.budget) {
    if (held(b.input)) continue;
    shares.push_back({b.contribution * b.contribution, b.evaluation.dof, b.evaluation.shared});
    paths.push_back(b.input);
  }
  std::vector<PairShare> pairs;
  if (const std::optional<BudgetCorrelation>& c = a.budget_correlation) {
    const auto first = std::find(paths.begin(), paths.end(), c->first), second = std::find(paths.begin(), paths.end(), c->second);
    if (first != paths.end() && second != paths.end()) {
      pairs.push_back({static_cast<std::size_t>(first - paths.begin()), static_cast<std::size_t>(second - paths.begin()),
                       c->variance});
    }
  }
  VarianceComponent birge{0.0, kInfiniteDof};
  if (a.fit.scaled && a.g.uncertainty && a.g_uncertainty_unscaled) {
    birge = {*a.g.uncertainty * *a.g.uncertainty - *a.g_uncertainty_unscaled * *a.g_uncertainty_unscaled,
             static_cast<double>(a.fit.dof)};
  }
  const std::vector<VarianceComponent> components = variance_components(shares, pairs, birge);
  double variance = 0.0;
  for (const VarianceComponent& c : components) variance += c.variance;
  return coverage_factor(welch_satterthwaite(components)) * std::sqrt(variance);
}

std::optional<MonteCarloResult> monte_carlo(const ParsedScene& scene, const Analysis& analysis,
                                            const MonteCarloOptions& options) {
  if (!analysis.g_expanded || analysis.budget.empty()) return std::nullopt;
  const Sampler sampler(scene, analysis);
  Deviates deviates(options.seed);
  const Run run = options.draws > 0 ? fixed_draws(sampler, deviates, options.draws) : adaptive_draws(sampler, deviates);
  const std::vector<double>& draws = run.draws.g;
  if (draws.size() < 2) return std::nullopt;
  const Summary s = summarise(draws);
  MonteCarloResult r;
  r.options = options;
  r.draws = static_cast<long>(draws.size());
  r.rejected_by_reason = run.draws.rejected;
  for (const long n : r.rejected_by_reason) r.rejected_draws += n;
  r.mean = s.mean;
  r.standard_uncertainty = s.deviation;
  r.low = s.low;
  r.high = s.high;
  r.tolerance = numerical_tolerance(s.deviation);
  std::tie(r.d_low, r.d_high) = disagreement(analysis.g.value, analysis.g_expanded->expanded, s);
  std::tie(r.low_uncertainty, r.high_uncertainty) = end_uncertainty(run.batches);
  // Judged where the ends are placed within the tolerance: as the ends'
  // uncertainty goes as M^(-1/3), (u/delta)^3 times the draws would (up to
  // two significant digits: the estimate is not better).
  const double worst = std::max(r.low_uncertainty, r.high_uncertainty);
  r.judged = worst <= r.tolerance;
  if (!r.judged && std::isfinite(worst)) {
    const double needed = static_cast<double>(r.draws) * std::pow(worst / r.tolerance, 3);
    const double step = std::pow(10.0, std::floor(std::log10(needed)) - 1.0);
    r.draws_to_judge = static_cast<long>(std::ceil(needed / step) * step);
  }
  r.validated = r.judged && r.d_low <= r.tolerance && r.d_high <= r.tolerance;
  // The input that bends g: among the three largest fields (one row, or
  // one field of every observation of a series), the first whose removal
  // (held at its values, and out of GUM's budget) restores agreement.
  std::vector<std::string> paths;
  std::vector<double> contributions;
  for (const BudgetEntry& b : analysis.budget) paths.push_back(b.input), contributions.push_back(b.contribution);
  const std::vector<BudgetGroup> groups = group_budget(paths, contributions);
  for (std::size_t i = 0; r.judged && !r.validated && i < groups.size() && i < 3; ++i) {
    std::vector<std::string> held;
    for (const std::size_t row : groups[i].rows) held.push_back(paths[row]);
    Deviates again(options.seed);
    const Summary without = summarise(sampler.draw(r.draws, again, held).g);
    // Judged to the run's own tolerance: the smaller u of the rest would ask
    // for more draws than the run made.
    const auto [d_low, d_high] = disagreement(analysis.g.value, expanded_without(analysis, held), without);
    if (d_low <= r.tolerance && d_high <= r.tolerance) {
      r.bending_input = held.size() == 1 ? held.front() : "observations[]." + groups[i].field;
      r.bending_name = group_name(groups[i], paths);
      r.bending_distribution = distribution_name(analysis.budget[groups[i].rows.front()].evaluation.distribution);
      break;
    }
  }
  return r;
}

}  // namespace pendulum
