#pragma once
/// \file uncertainty.hpp
/// \brief The budget as the GUM (JCGM 100:2008) writes it: how each input's
/// standard uncertainty was evaluated (Type A or B, its distribution, its
/// degrees of freedom), the effective degrees of freedom of the combined
/// uncertainty (Welch-Satterthwaite, GUM G.4) and the coverage factor from
/// Student's t (GUM G.3). docs/uncertainty.md.

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace pendulum {

/// What an input's uncertainty describes (GUM 4.3.7, 4.3.9; S1 6.4).
enum class Distribution {
  normal,       ///< a stated standard uncertainty
  rectangular,  ///< a resolution, a range, an amplitude not recorded: (b - a)/sqrt(12)
  student_t,    ///< the mean of n readings: s/sqrt(n) with n - 1 degrees of freedom (S1 6.4.9)
};
const char* distribution_name(Distribution d);

inline constexpr double kInfiniteDof = std::numeric_limits<double>::infinity();

/// An input's variance is its own, or one several inputs share.
enum class SharedVariance {
  none,
  pooled_trials,   ///< a series' trial scatter pooled over its observations
  length_scatter,  ///< a series' lengths' scatter tau, fitted from its residuals
};

/// How one input's standard uncertainty was evaluated (GUM 4.2, 4.3).
struct InputEvaluation {
  std::string path;  ///< the input's JSON path, as the budget names it
  char type = 'B';   ///< 'A': from the scatter of repeated readings; 'B': otherwise
  Distribution distribution = Distribution::normal;
  double dof = kInfiniteDof;  ///< A: n - 1; B: infinite (GUM G.4.2: the bounds are taken as certain)
  /// Where its variance is one estimated from several inputs together:
  /// theirs are one component of Welch-Satterthwaite's sum, with `dof`
  /// theirs together.
  SharedVariance shared = SharedVariance::none;
};

/// The evaluation `path` was given, or Type B, normal, infinite dof.
InputEvaluation evaluation_of(const std::vector<InputEvaluation>& given, const std::string& path);

/// One independent component of u_c^2: its variance (c_i u_i)^2 and dof.
struct VarianceComponent {
  double variance;
  double dof;
};

/// nu_eff = u_c^4 / sum_i (c_i u_i)^4 / nu_i (GUM Eq. G.2b), u_c^2 the sum of
/// the components; infinite when every component's dof is, or u_c is 0.
double welch_satterthwaite(const std::vector<VarianceComponent>& components);

/// One input's share of a result's variance: (c_i u_i)^2 and how u_i was evaluated.
struct InputShare {
  double variance;
  double dof;
  SharedVariance shared;  ///< InputEvaluation::shared
};

/// A correlated pair of `InputShare`s (a decay fit's alpha and beta): their
/// indices and the cross term 2 c_a c_b u(a, b), which may be negative.
struct PairShare {
  std::size_t a, b;
  double cross;
};

/// The independent components of a result's variance, as Welch-Satterthwaite
/// takes them (GUM G.4): each input's share with its dof; the shares of
/// one shared Estimate as one, with their dof (one variance estimated once); a
/// correlated pair's two shares and cross term as one, with the smaller dof
/// (one fit gave both); and `birge`, the variance a Birge ratio added, as
/// one with the fit's dof (S^2 is chi2/dof), where it is positive. Both the
/// analysis's nu_eff and the Monte Carlo's GUM interval without an input
/// are formed here, so that holding an input out changes nu_eff by that
/// input alone.
std::vector<VarianceComponent> variance_components(const std::vector<InputShare>& inputs,
                                                   const std::vector<PairShare>& pairs, VarianceComponent birge);

/// The coverage probability of the expanded uncertainty.
inline constexpr double kCoverageProbability = 0.95;

/// k_p = t_p(nu): the two-sided Student's t quantile for `probability`
/// (GUM G.3.4) with nu truncated to the integer below (GUM G.4.1, note 1);
/// the normal quantile for infinite nu, and for nu beyond 1e6 (where t and the
/// normal agree to 2e-6). nu must be >= 1.
double coverage_factor(double dof, double probability = kCoverageProbability);

}  // namespace pendulum
