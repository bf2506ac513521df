#pragma once
/// \file recordings/swings.hpp
/// \brief From samples or gate events to swings: crossing times, the period
/// with an honest uncertainty, each swing's amplitude, a decay record and a
/// period-against-amplitude curve (docs/recordings.md).
///
/// Method, in order:
///  1. One signal from the channels: the principal axis of the mean-removed
///     rate (or linear-acceleration) vectors, which undoes a tilted phone;
///     |a| - mean|a| for acceleration with gravity (it swings at 2f); the
///     angle about the centre of a circle fitted to a video track.
///  2. Crossings of zero with hysteresis +-h, h = 0.3 of the last half
///     swing's peak (at least 5 noise sigmas): each crossing time is the zero
///     of a least-squares line through the samples between the last one
///     beyond one threshold and the first one beyond the other. A photogate's
///     crossing is the middle of its blocking.
///  3. The period: weighted least squares of the crossing times against their
///     index, t_i = a + b x_i + c x_i^2 + d (-1)^i (x_i = u_i - (u_0 + u_n)/2),
///     u_i = i, or, once every swing has an amplitude, the amplitude-weighted
///     index u_{i+1} = u_i + 1 + DeltaT/T0(theta_i) (Eq. 8), on which the
///     crossings of a decaying swing lie on a line. The period is the mean
///     over the record, b (u_n - u_0)/n per half (or quarter) swing; the
///     quadratic term takes up what drift is left (a length warming up) and,
///     even about the mid-range centre, does not change it (without amplitudes a
///     cubic term e x^3 joins from 12 crossings on, and the mean is b + e X^2,
///     X = (u_n - u_0)/2); the alternating term an offset
///     (with the weighted index, the smooth amplitude's own uncertainty is
///     propagated into the period and added in quadrature)
///     between the two directions (a gyroscope's bias, a photogate off the
///     lowest point). Weights 1/sigma_i^2 with sigma_i proportional to
///     1/(|slope_i| sqrt(samples_i)); the covariance is scaled by the
///     residual variance and, when the residuals' lag-1 autocorrelation rho
///     is positive, by (1 + rho)/(1 - rho) (AR(1) effective sample size).
///  4. Amplitudes: from the peak angular rate by the exact energy relation
///     omega_max = 2 sqrt(g/l) sin(theta0/2) = (4 pi / T0) sin(theta0/2)
///     with T0 = T / (1 + DeltaT/T0(theta0)) (amplitude.hpp, exact), solved
///     together for all swings; from the peak angle; from the tangential
///     linear acceleration at a turning point, g sin theta0 (standard g);
///     none from acceleration with gravity (docs/recordings.md); from a photogate's
///     blocking time dt and the bob's width w: v = w/dt = 2 sqrt(g l)
///     sin(theta0/2).

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pendulum/decay_fit.hpp"
#include "pendulum/recordings/read.hpp"

namespace pendulum {

/// One crossing of the swing signal through zero (or one gate passage).
struct Crossing {
  double time = 0.0;   ///< (s)
  double slope = 0.0;  ///< signal's rate of change at the crossing (signal unit/s); 0 for gate events
  int samples = 0;     ///< samples in the line fit; 0 for gate events
};

/// The half (or, for acceleration with gravity, quarter) swing between two
/// consecutive crossings.
struct RecordedSwing {
  double start = 0.0;   ///< (s)
  double end = 0.0;     ///< (s)
  double peak_time = 0.0;  ///< (s) of the largest |signal|, or the gate passage
  /// theta0 (rad); NaN where the recording cannot give it.
  double amplitude = 0.0;
};

/// The period and how well the crossings determine it.
struct PeriodEstimate {
  double value = 0.0;        ///< (s)
  double uncertainty = 0.0;  ///< standard uncertainty (s)
  int periods = 0;           ///< whole periods spanned by the crossings
  double residual_rms = 0.0;  ///< weighted rms of the crossing-time residuals (s)
  double lag1_correlation = 0.0;  ///< of the standardised residuals
  double inflation = 1.0;    ///< variance factor for autocorrelation, >= 1
  /// The part of `uncertainty` (s) from the smooth amplitude in the
  /// amplitude-weighted index, added in quadrature; 0 without it.
  double amplitude_uncertainty = 0.0;
};

/// One point of the period-against-amplitude curve: one full period.
struct PeriodPoint {
  double time = 0.0;       ///< (s) of its middle, from the first crossing
  double amplitude = 0.0;  ///< (rad), mean of its swings; NaN if unknown
  double period = 0.0;     ///< (s)
};

struct SwingOptions {
  double hysteresis_fraction = 0.3;   ///< h as a fraction of the last peak
  std::optional<double> bob_width;    ///< (m): a photogate's amplitudes need it
  /// (m) pivot to bob centre: a photogate's amplitudes use sqrt(g l) = 2 pi l / T0
  /// from it; without it g is taken as standard gravity.
  std::optional<double> length;
  /// Only the samples or events with time in [first, second] (s, the file's
  /// own clock) are analysed: `import --range`, a scene's `"range"`.
  std::optional<std::pair<double, double>> range;
};

struct SwingAnalysis {
  std::vector<Crossing> crossings;
  int crossings_per_period = 2;
  /// Unit vector of the swing axis in the sensor's frame (rate and linear
  /// acceleration), zeros otherwise.
  std::array<double, 3> axis{};
  double noise = 0.0;  ///< noise sigma of the signal (signal unit), 0 for gate events
  std::vector<RecordedSwing> swings;
  PeriodEstimate period;
  /// Small-amplitude period T0 (s) the amplitudes were solved with; NaN
  /// when the recording gives no amplitudes.
  double small_amplitude_period = 0.0;
  std::vector<PeriodPoint> period_curve;
  /// Amplitude (rad) at the first and the last crossing, the start and end of
  /// the timing, from the smooth amplitude curve (a polynomial in time fitted
  /// to log theta over the swings: a line below 100 swings, a quadratic below
  /// 400, a cubic beyond; extrapolated to the crossings);
  /// NaN without amplitudes. The scene's `amplitude` is the start one.
  double start_amplitude = 0.0;
  double end_amplitude = 0.0;
  /// Standard uncertainty (rad) of start_amplitude where the recording
  /// measures the angle itself (an angle, a video track): the smooth curve's
  /// at the first crossing (its coefficients' covariance from the swings'
  /// scatter) and, for a video track, its circle's radius, which scales
  /// every angle. NaN for the other families, whose amplitudes rest on
  /// what no recording gives (a gyroscope's scale, g for an acceleration, the
  /// bob's speed through a beam taken as constant): docs/recordings.md.
  double start_amplitude_uncertainty = 0.0;
  /// Amplitude of each swing against time from the first crossing (empty
  /// when the recording gives no amplitudes); no sigmas, so the decay fit
  /// scales its covariance by the residual variance.
  DecayData decay;
};

/// Step 3 of the method on given crossings (at least 5): the weighted fit
/// of their times, weights from slope and samples when `samples` > 0.
/// With `amplitudes` (rad, one per swing: crossings.size() - 1) the index is
/// u_{i+1} = u_i + 1 + DeltaT/T0(theta_i) instead of i, and the period is the
/// line's rise from the first crossing to the last per period.
PeriodEstimate fit_crossing_times(const std::vector<Crossing>& crossings, int crossings_per_period,
                                  const std::vector<double>& amplitudes = {});

/// Analyses a parsed recording. `file` names it in errors (InputError): no
/// oscillation, fewer than three swings, an amplitude beyond 180 deg.
SwingAnalysis analyse_swings(const Recording& recording, const std::string& file,
                             const SwingOptions& options = {});

/// Step 1's swing signal of a sampled recording, one value per sample of
/// `recording.time`, zero on average: the one analyse_swings finds the
/// crossings on (rad/s for a rate, m/s^2 for an acceleration, rad for an
/// angle or a track). For gate states, 1 where the beam is blocked and 0
/// where it is open, one value per event; empty for bare blocking times.
/// For drawing (the report).
std::vector<double> swing_signal(const Recording& recording);

/// Everything `pendulum-g import` and a scene's recording hook need.
struct RecordingSummary {
  std::string file;
  RecordingFormat format = RecordingFormat::automatic;
  SignalKind kind = SignalKind::angular_rate;
  std::size_t rows = 0;     ///< data rows read
  std::size_t dropped = 0;  ///< rows skipped for an empty or NaN cell
  SwingAnalysis swings;     ///< period, its uncertainty, periods, per-swing data, decay record
  std::string set = {};     ///< the set read (Recording::set); empty for a file of one set
  std::vector<RecordingColumn> columns = {};  ///< how each column was used (Recording::columns)
  std::vector<RecordingNote> notes = {};      ///< what the reader decided and dropped (Recording::notes)
  std::string column_spec = {};  ///< the columns declared ("t:s,theta:deg"), to read the file again alike
};

/// Reads the recording at `path` (format from its header unless given) and
/// analyses it: the one call a scene reader makes for a `timing` or
/// `decay.data` that names a recording. Throws InputError naming the file
/// (and line and column for a bad row). `set`: the CSV to read in a zip
/// archive, a PASCO run or a Tracker track (read_recording); `columns`
/// declares the columns' roles and units (parse_recording).
RecordingSummary analyse_recording(const std::string& path,
                                   RecordingFormat format = RecordingFormat::automatic,
                                   const SwingOptions& options = {},
                                   const RecordingLimits& limits = {}, const std::string& set = {},
                                   const std::string& columns = {});

}  // namespace pendulum
