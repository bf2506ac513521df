#pragma once
/// \file dispersion.hpp
/// \brief Whether a fit's residuals scatter as its stated uncertainties say
/// (chi2 against its degrees of freedom), and the uncertainty the scatter
/// supports when they do not: the Birge ratio S = sqrt(chi2/dof) (the PDG's
/// scale factor), applied when chi2 is improbably large (docs/output.md,
/// "Fits that scatter more than their uncertainties").

#include <optional>
#include <string>
#include <vector>

namespace pendulum {

/// chi2 whose upper-tail probability is below this is over-dispersed: the
/// result is suspect and its uncertainty scaled by S. Chosen on coverage
/// (tests/tools/chi2_coverage.cpp, docs/output.md): it leaves honest fits'
/// coverage as it was, where PDG's rule (scale whenever S > 1) raises it.
inline constexpr double kOverDispersedProbability = 0.01;

struct Dispersion {
  double chi2 = 0.0;
  int dof = 0;
  /// P(chi2' >= chi2) for `dof` degrees of freedom; empty at dof 0.
  std::optional<double> probability;
  /// S = sqrt(chi2/dof); empty at dof 0.
  std::optional<double> birge_ratio;
  /// probability < kOverDispersedProbability and S > 1: the scatter exceeds
  /// the stated uncertainties, and S is applied.
  bool over_dispersed = false;
  /// S where over_dispersed, else 1.
  double applied_scale() const { return over_dispersed ? *birge_ratio : 1.0; }
};

Dispersion dispersion(double chi2, int dof);

/// A standard uncertainty sigma whose share sigma_scatter comes from the
/// points the fit's chi2 tests (their own, independent uncertainties),
/// the share scaled by `scale`: sqrt(sigma^2 + (scale^2 - 1) sigma_scatter^2).
/// What every point shares (an apparatus's input, a length read once) is
/// not tested by the scatter about the fit, and is left as it is.
double scaled_uncertainty(double sigma, double sigma_scatter, double scale);

/// "the observations scatter about the fit 7.69 times as much as their
/// stated uncertainties allow (chi2/dof = 59.1, chi2 = 887 for 15 degrees
/// of freedom, probability 2e-132)", `points` saying what scatters about what.
/// Paule & Mandel's extra variance, in length space: the standard deviation
/// tau (m) of an unknown error common in size to every observation's length
/// for which chi2 = sum_k r_k^2 / (v_k + (s_k tau)^2) equals `dof`; r_k is
/// observation k's residual (s), v_k its stated variance (s^2), s_k its
/// period's derivative by its length, dT_k/dL_k (s/m). 0 where the stated
/// variances give chi2 <= dof already; empty where no tau reaches dof (the
/// observations whose s_k is 0 alone scatter more).
std::optional<double> length_scatter(const std::vector<double>& residual, const std::vector<double>& variance,
                                     const std::vector<double>& slope, int dof);

std::string dispersion_finding(const Dispersion& d, const std::string& points);

}  // namespace pendulum
