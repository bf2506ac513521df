#pragma once
/// \file recordings/swing_series.hpp
/// \brief A long decay reduced swing by swing (docs/recordings.md, "A long
/// decay, swing by swing"): the recording becomes a series at one length
/// whose observations are groups of its swings, each timed by its own
/// crossings and corrected at its own amplitude.

#include <vector>

#include "pendulum/recordings/swings.hpp"

namespace pendulum {

/// One group of consecutive whole periods of a recording. Groups share no
/// crossing (the half swing between two groups is not timed), so their
/// periods' errors are independent.
struct SwingGroup {
  double start = 0.0;        ///< (s, the file's clock) its first crossing
  double end = 0.0;          ///< (s) its last crossing
  int periods = 0;           ///< whole periods timed
  double period = 0.0;       ///< (s) mean period over the group (fit_crossing_times on its crossings)
  /// (s) with the residual variance and AR(1) factor pooled over the groups' own fits
  double uncertainty = 0.0;
  /// (rad) the amplitude whose exact finite-amplitude factor (N&O Eq. 8,
  /// finite_amplitude_agm) is the mean of its swings' on the smooth curve:
  /// the one amplitude at which a constant swing has the group's mean period.
  double amplitude = 0.0;
  /// (rad) one uncertainty for the amplitudes of all the groups, which share
  /// the smooth curve's error: the common shift of them all that moves the
  /// groups' weighted mean of ln(1 + DeltaT/T0) (weights (T/sigma_T)^2, as
  /// the series weighs them) as much as the curve's coefficients'
  /// covariance does. 0 without it.
  double amplitude_uncertainty = 0.0;
};

/// Whole periods per group: at least 4, and at most 50 groups.
int periods_per_group(int periods);

/// The recording's swings in groups of `periods_per_group(periods)` periods,
/// in time order; empty without smooth amplitudes (SwingAnalysis::
/// smooth_amplitudes) or with fewer than two groups' worth of crossings.
std::vector<SwingGroup> swing_groups(const SwingAnalysis& a);

/// The amplitude theta0 (rad, in [0, pi)) whose exact finite-amplitude
/// correction DeltaT/T0 = 2K(sin(theta0/2))/pi - 1 (N&O Eq. 8) is `factor`
/// (>= 0), by bisection on finite_amplitude_agm to 1e-15 rad.
double amplitude_of_factor(double factor);

/// How far the amplitude's change over the record moves what one mean
/// period corrected at the start amplitude leaves uncorrected, in standard
/// uncertainties of the period: T0 |h(theta_start) - h(theta_end)| / sigma_T
/// (T0 the mean period over the mean exact factor of the two ends).
/// With the decay correction (Eq. 50, which follows theta0^2/16 over the
/// timing) h is the exact factor beyond theta0^2/16, f(theta) - theta^2/16;
/// without it, h = f, the whole exact factor. NaN without amplitudes.
double amplitude_shift_sigmas(const SwingAnalysis& a, bool decay_corrected);

/// The rule (docs/recordings.md, read off the speed-against-error table):
/// swing by swing beyond this shift. One mean period with the decay
/// correction errs by at most 0.087 sigma a sigma of shift there (20 deg), so
/// by less than 2 sigmas up to 20, where swing by swing costs 5 to 12 times
/// its uncertainty (its groups share no crossing).
constexpr double kSwingBySwingShift = 20.0;

}  // namespace pendulum
