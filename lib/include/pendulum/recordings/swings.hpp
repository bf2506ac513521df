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
///     sin(theta0/2). Each peak is a quartic through the middle third of its
///     half swing; a sparse track (fewer than 7 samples there, video at 5-20
///     frames/s) fits a, b, c, d, e of a + b cos phi + c sin phi + d cos 3phi
///     + e sin 3phi across the whole half swing (phi = pi (t - t_mid)/(t_b -
///     t_a), the turning point's phase): the swing's own shape, its third
///     harmonic the finite amplitude's.
///  5. Event stamps (a timer or photogate log of one stamp per period or per
///     passage): each stamp's count from the intervals in half periods (a
///     missed stamp, an interval near 2T, advances the count by two periods;
///     a doubled stamp, near T/2, or a repeat is dropped), then the line
///     fit of stamp against count, t = a + b x + c x^2 (+ h x^3 from 12
///     stamps) with x the count about its mid-range, the mean period b + h
///     X^2 as in step 3; one stamp a passage adds (-1)^n (d + e x + f x^2).
///     One stamp a passage is told by alternation (SwingOptions::
///     stamps_per_period).
///  6. Resolution: no period's uncertainty falls below what the clock's
///     resolution q allows. A uniform quantum gives each time an error of
///     variance q^2/12, so the fit's slope has at least
///     (q/sqrt 12) / sqrt(sum (n_i - mean n)^2) (n_i in periods).
///  7. Glitches: each full period (the time between crossings a period
///     apart: an offset between the directions, which may drift, cancels
///     from it), per its length in the amplitude-weighted index where there
///     are amplitudes and less a quadratic drift in time where there are
///     none, against the median of its 10 neighbours either side, in robust
///     sigmas (from the 40th percentile of the residuals, so that a glitch
///     of more than half the record does not set it; from the 80th where
///     outliers strike most blocks of 10 periods in every third of the
///     record: a logger's hitches are its noise). A stretch of outliers (a
///     jump, a gap, tracking lost, a glitchy end) is reported as a time
///     range with the period without it; where that differs from the whole
///     record's by more than its uncertainty, the difference joins the
///     uncertainty.
///  8. The clean stretch, by default: where step 7 finds glitches, a glitch
///     inside the record, shorter than the stretches on either side of it,
///     whose count of half swings is certain (the time across it over the
///     half swing on each side rounds to the same whole number, of the
///     parity the crossings' directions say, within half a swing) is
///     bridged: its crossings are dropped and the count carried across.
///     Then the longest run of crossings free of the other glitches is
///     analysed alone (steps 1 to 7 on the samples from a quarter interval
///     before its first crossing to a quarter after its last): the release
///     (a glitch at the start), the catch or a glitchy end, and the shorter
///     side of a glitch inside that could not be bridged are cut, each
///     named with its time range. Each cut of 3 periods or more is analysed
///     alone too, and where its T0 (its period, without amplitudes) and the
///     kept stretch's differ by over 5 combined sigmas and 1 % (3 % without
///     amplitudes: a swing's finite amplitude moves a period by 2 % at
///     35 deg), a note says so: a second pendulum, or a wrong column?
///     `--range all` (a scene's `"range":
///     "all"`) keeps the whole record, with step 7's allowance; a typed
///     range wins over both.

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
  /// Crossings' intervals (half swings; quarter swings for acceleration
  /// with gravity) since the previous crossing kept: 1, or more after a
  /// glitch whose count was carried across (step 8).
  long steps = 1;
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
  /// The least uncertainty (s) the clock's resolution allows (step 6);
  /// `uncertainty` is never below it. 0 for a clock of unknown resolution.
  double resolution_floor = 0.0;
};

/// A stretch of the record that does not fit the swing (step 7).
struct Glitch {
  double start = 0.0;  ///< (s, the file's clock) the last good crossing before it
  double end = 0.0;    ///< (s) the first good crossing after it, or the last crossing
  double worst = 0.0;  ///< the largest |interval residual| in it, in robust sigmas
  /// What it is where no interval's residual found it ("the swing grows: a
  /// hand or a drive pumping it", `worst` then in sigmas of its peaks); null
  /// for an outlier stretch.
  const char* cause = nullptr;
};

/// A stretch cut from the record by default (step 8).
struct Cut {
  double start = 0.0;  ///< (s, the file's clock)
  double end = 0.0;    ///< (s)
  /// "the release", "the catch or a glitchy end", "the shorter side of a
  /// glitch", "a glitch inside, its count carried across"
  std::string why;
  double worst = 0.0;  ///< the largest |period residual| of the glitches in it, in robust sigmas
  /// Periods counted across it, where its crossings were dropped and those
  /// on either side kept (a glitch inside, bridged); 0 where the record was cut.
  double periods_carried = 0.0;
  /// The cut stretch analysed alone, where it holds 3 periods and gives a
  /// period (unset otherwise, and for a bridge): its small-amplitude period
  /// T0 where it and the kept stretch have amplitudes (`small_amplitude`),
  /// else its period, and whether that agrees with the kept stretch's (step
  /// 8): a cut never hides a second pendulum or a wrong column.
  std::optional<PeriodEstimate> period_alone;
  bool small_amplitude = false;
  bool agrees = true;
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
  /// The whole record, glitches, release and catch included (`--range
  /// all`, a scene's `"range": "all"`); by default the clean stretch (step 8).
  bool whole_record = false;
  /// Event stamps: 1 (one per period: a hand timer, a photogate's pendulum
  /// mode) or 2 (one per passage); by default 2 where the intervals alternate
  /// (a gate off the lowest point), else 1.
  std::optional<int> stamps_per_period;
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
  /// 400, a cubic beyond, and a higher order, up to 8, while each term is
  /// beyond 3 sigmas in the swings or the crossings; extrapolated to the crossings);
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
  /// The smooth amplitude curve (rad) at each swing's peak, one per swing
  /// (the index of step 3 takes it): the curve of start_amplitude. Empty
  /// without it.
  std::vector<double> smooth_amplitudes;
  /// That curve: log theta(t) = sum_j coefficients[j] x^j, x = (t - mid) /
  /// half (t in s on the file's clock), and the covariance of its
  /// coefficients (row-major) from the swings' scatter and, for a video
  /// track, its circle's radius (which scales every angle: the constant
  /// term's). Empty coefficients without it.
  struct SmoothCurve {
    double mid = 0.0, half = 1.0;  ///< (s)
    std::vector<double> coefficients, covariance;
  } smooth_curve;
  /// Amplitude of each swing against time from the first crossing (empty
  /// when the recording gives no amplitudes); no sigmas, so the decay fit
  /// scales its covariance by the residual variance.
  DecayData decay;
  /// Stretches that do not fit the swing, in time order (step 7), within
  /// the stretch analysed.
  std::vector<Glitch> glitches;
  /// Step 7's stretches of outliers before they are joined into `glitches`
  /// (one at an end reaching it, ones near each other one): step 8 bridges
  /// each it can on its own.
  std::vector<Glitch> outliers;
  /// The stretch analysed (s, the file's clock): a typed range or the clean
  /// stretch (step 8); unset for the whole record.
  std::optional<std::pair<double, double>> analysed;
  /// What the clean stretch left out, in time order (step 8); empty for a
  /// typed range or the whole record.
  std::vector<Cut> cuts;
  /// The whole record's period, where the clean stretch replaced it (step 8).
  std::optional<PeriodEstimate> whole_record_period;
  /// What the analysis decided or mended, and why it found no amplitudes:
  /// a dropped stamp or a mended count (the text names its data row, from
  /// 1, and its time: a Recording holds no line numbers, so `line` is 0), a
  /// glitch, a fit far beyond its noise, the clock's floor, the range analysed.
  std::vector<RecordingNote> notes;
};

/// Step 3 of the method on given crossings (at least 5): the weighted fit
/// of their times, weights from slope and samples when `samples` > 0. The
/// index runs on by each crossing's `steps` (more than 1 across a bridged
/// glitch). With `amplitudes` (rad, one per swing: crossings.size() - 1) it
/// is u_{i+1} = u_i + steps (1 + DeltaT/T0(theta_i)) instead, and the period is the
/// line's rise from the first crossing to the last per period. `quantum`
/// (s): the clock's resolution, whose floor (step 6) the uncertainty keeps.
/// No weight exceeds 25 times the median (a spurious crossing on a jump
/// would carry the fit).
PeriodEstimate fit_crossing_times(const std::vector<Crossing>& crossings, int crossings_per_period,
                                  const std::vector<double>& amplitudes = {}, double quantum = 0.0);

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
  std::string file;  ///< as printed (printable_name())
  RecordingFormat format = RecordingFormat::automatic;
  SignalKind kind = SignalKind::angular_rate;
  std::size_t rows = 0;     ///< data rows read
  std::size_t dropped = 0;  ///< rows skipped: an empty or NaN cell, a sample out of time order or repeated (noted)
  SwingAnalysis swings;     ///< period, its uncertainty, periods, per-swing data, decay record
  std::string set = {};     ///< the set read (Recording::set); empty for a file of one set
  std::vector<RecordingColumn> columns = {};  ///< how each column was used (Recording::columns)
  std::vector<RecordingNote> notes = {};      ///< what the reader decided and dropped (Recording::notes)
  std::string column_spec = {};  ///< the columns declared ("t:s,theta:deg"), to read the file again alike
  std::vector<std::string> channels = {};  ///< the channels analysed, as the header names them
};

/// Analyses `recording` (analyse_swings) and, where it holds more than one
/// signal (Recording::candidates), each of the others: a zip's set as the
/// reader parsed it (SignalCandidate::recording), a file's other signal read
/// again from `path` with its columns: signals whose periods
/// differ by more than 5 combined standard uncertainties and 10^-3 of the
/// period are refused (InputError naming both and the --columns or --set
/// that picks each: the file cannot say which one is the pendulum's);
/// otherwise a note says they agree.
/// A signal that gives no period is noted and passed over.
SwingAnalysis analyse_candidates(const Recording& recording, const std::string& path, RecordingFormat format,
                                 const SwingOptions& options = {}, const RecordingLimits& limits = {},
                                 const std::string& set = {});

/// Reads the recording at `path` (format from its header unless given) and
/// analyses it (analyse_candidates): the one call a scene reader makes for a `timing` or
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
