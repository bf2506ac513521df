#pragma once
/// \file amplitude_sweep.hpp
/// \brief One pendulum timed at several amplitudes: its small-amplitude
/// period T0 from the exact law T = T0 2K(sin^2(theta0/2))/pi (Nelson &
/// Olsson Eq. 8, Kelley Eq. 17), and the law tested (docs/series.md,
/// "Amplitude sweeps").

#include <optional>
#include <string>
#include <vector>

#include "pendulum/estimate.hpp"

namespace pendulum {

/// One timing of a sweep.
struct SweepPoint {
  double amplitude;        ///< theta0 (rad), 0 <= theta0 < pi
  double amplitude_sigma;  ///< (rad), 0 where not stated
  double period;           ///< measured (s), > 0
  double period_sigma;     ///< (s), > 0: stated, or the floor of a scatter to come
};

struct AmplitudeSweep {
  /// T0 (s) and its standard uncertainty, with its degrees of freedom
  /// (infinite for stated uncertainties, n - 1 from the scatter or where
  /// the Birge ratio was applied).
  Estimate t0;
  double t0_dof;
  /// chi2 of the exact law, n - 1 degrees of freedom; its upper-tail
  /// probability, empty where the uncertainties are the scatter (no verdict).
  double chi2 = 0.0;
  int dof = 0;
  std::optional<double> probability;
  /// The periods' uncertainties are their scatter about the law: a variance
  /// common to every period, added to the stated floors (and each
  /// amplitude's carried to its period) until chi2 = n - 1.
  bool sigma_from_scatter = false;
  /// T0's uncertainty over the one the stated uncertainties alone give: the
  /// scatter's, or the Birge ratio where chi2 is improbably large; 1 otherwise.
  double scale = 1.0;
  /// Per point: T0 F(theta0_i), the effective uncertainty (period's and
  /// amplitude's, carried to the period, times `scale`) and the residual
  /// (measured - law) / that.
  std::vector<double> law, effective_sigma, residual;
  /// The quadratic T = a (1 + c theta0^2) fitted with the same weights, c
  /// (1/rad^2) against the one the exact law gives at these amplitudes (1/16
  /// at small ones); empty below three distinct amplitudes.
  std::optional<Estimate> coefficient;
  double quadratic_t0 = 0.0;  ///< the quadratic's a (s), with `coefficient`
  double coefficient_law = 0.0;
  /// Two-sided probability of so large a |c - c_law|, c's uncertainty from
  /// the quadratic's own scatter: Student's t at its n - 2 degrees of freedom.
  std::optional<double> coefficient_probability;
  double low = 0.0, high = 0.0;  ///< the amplitudes' range (rad)
};

/// Two-sided probability below which the periods do not rise with the
/// amplitude as the law says (the same bar as an over-dispersed chi2).
inline constexpr double kSweepLawProbability = 0.01;

/// How many of `amplitudes` differ by more than 1e-6 of the largest (their
/// rounding: 10 deg written in radians to 10 digits is still 10 deg).
std::size_t distinct_amplitudes(std::vector<double> amplitudes);

/// Fits T0 by weighted least squares with effective variances (the
/// amplitude's uncertainty carried through dT/dtheta0 at the fit, iterated),
/// closed form since T is linear in T0. `sigma_from_scatter`: the points'
/// period_sigma is a floor, the scatter beyond it a variance of its own.
/// The law is tested where three amplitudes differ by more than 1e-6 of the
/// largest. Needs two points or more.
AmplitudeSweep fit_amplitude_sweep(const std::vector<SweepPoint>& points, bool sigma_from_scatter);

/// Whether the law is refuted: the coefficient's probability below kSweepLawProbability.
inline bool sweep_law_refuted(const AmplitudeSweep& s) {
  return s.coefficient_probability && *s.coefficient_probability < kSweepLawProbability;
}

/// What a refuted law says: the coefficient found against the law's, and
/// the slips that make it.
std::string sweep_law_finding(const AmplitudeSweep& s);

}  // namespace pendulum
