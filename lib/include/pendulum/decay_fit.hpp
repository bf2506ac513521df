#pragma once
/// \file decay_fit.hpp
/// \brief Fit of the amplitude-decay law theta0(t) (Nelson & Olsson 1986,
/// Eq. 25) to a record of amplitudes: alpha, beta and the initial amplitude,
/// with Ceres Solver, bounds alpha >= 0 and beta >= 0, and honest
/// uncertainties (docs/decay_fit.md).

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "pendulum/observation.hpp"

namespace pendulum {

/// A decay record in SI units.
struct DecayData {
  std::vector<double> times;       ///< (s), strictly increasing, >= 0
  std::vector<double> amplitudes;  ///< (rad), > 0
  /// Standard uncertainty of each amplitude (rad); empty when none is given,
  /// and then the covariance is scaled by the residual variance.
  std::vector<double> sigmas;
  /// theta0m at t = 0 (rad); fitted when empty, held fixed when given.
  std::optional<double> initial_amplitude;
  /// Whose angle the amplitudes are: a sensor in the bob follows the bob's (observation.hpp).
  AngleOf angle_of = AngleOf::pendulum;
};

/// Which terms of d theta0/dt = -alpha theta0 - beta theta0^2 are fitted.
enum class DecayModel {
  both,            ///< Eq. (25)
  linear_only,     ///< beta = 0: Eq. (33)
  quadratic_only,  ///< alpha = 0: Eq. (46)
};
const char* decay_model_name(DecayModel model);

struct FittedParameter {
  double value = 0.0;
  /// Standard uncertainty; empty for a parameter held fixed (given, or not
  /// in a one-term model) and when the fit's covariance is singular.
  std::optional<double> uncertainty;
  bool at_bound = false;     ///< the fit ended on the bound 0
  bool fitted = false;       ///< varied by the fit
  /// |value| > 2 uncertainty; false for a parameter not fitted.
  bool significant = false;
  /// `uncertainty` before the Birge ratio was applied (DecayFit::scaled).
  std::optional<double> uncertainty_unscaled;
};

struct DecayFit {
  DecayModel model = DecayModel::both;
  /// Why a one-term model was used, or what a two-term fit could not tell
  /// (a term on its bound, the terms not separable, a singular covariance); "" otherwise.
  std::string model_reason;
  FittedParameter alpha;              ///< (1/s)
  FittedParameter beta;               ///< (1/(s rad))
  FittedParameter initial_amplitude;  ///< (rad)
  double correlation_alpha_beta = 0.0;  ///< 0 unless both are fitted
  /// The two-term fit tells linear from quadratic damping: at least one term
  /// is more than two standard uncertainties from 0, so the record rules out
  /// one of the one-term models. False when both one-term models fit as well
  /// (or no two-term fit was made: too few points, or a model forced).
  bool separable = false;
  /// Covariance of (alpha, beta, theta0m) in SI units, row-major.
  std::array<double, 9> covariance{};
  double chi2 = 0.0;  ///< sum of squared weighted residuals
  int dof = 0;        ///< points - fitted parameters
  /// "sigma": residuals weighted by the given sigmas, covariance as is, chi2/dof
  /// tells the fit's quality. "residual_variance": no sigmas, covariance
  /// scaled by s^2 = SSR/dof.
  std::string uncertainty_scaling;
  /// With sigmas: P(chi2' >= chi2) and S = sqrt(chi2/dof) (dispersion.hpp); empty otherwise.
  std::optional<double> probability, birge_ratio;
  /// With sigmas, chi2 improbably large: the covariance is scaled by S^2.
  bool scaled = false;
  double residual_standard_error = 0.0;  ///< sqrt(SSR/dof) of the unweighted residuals (rad)
  int points = 0;
  bool converged = false;
  std::string termination;  ///< Ceres's termination message
  int iterations = 0;
};

struct DecayFitOptions {
  /// Fit this model regardless of what the data support.
  std::optional<DecayModel> model;
};

/// Checks a record; throws InputError naming `path` (e.g. "decay.data") and
/// the offending element for too few points, unsorted or repeated times,
/// non-finite values, non-positive amplitudes or sigmas, or amplitudes that
/// grow over the record.
void validate_decay_data(const DecayData& data, const std::string& path);

/// Fits the decay law to a validated record.
DecayFit fit_decay(const DecayData& data, const DecayFitOptions& options = {});

namespace detail {
/// The fit's residuals r_i = (theta0(t_i) - theta_i)/sigma_i of Eq. (25) at
/// p = (alpha, beta, theta0m) and, when `jacobian` is not null, their
/// analytic Jacobian, column-major n x 3 in the order of p. Evaluated on whole
/// arrays so that Eigen vectorises it; tests check it against ceres::Jet
/// through pendulum::decayed_amplitude.
void decay_residuals(const DecayData& data, const double* p, double* residuals, double* jacobian);
}  // namespace detail

}  // namespace pendulum
