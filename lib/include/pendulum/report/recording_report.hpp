#pragma once
/// \file recording_report.hpp
/// \brief What a report shows of a recording (docs/report.md): the swing
/// signal with the detected crossings, the amplitude of each swing against
/// time with the decay fit of Nelson & Olsson (1986) Eq. (25), and the period
/// against the amplitude with the exact finite-amplitude period, Eq. (8).
///
/// Built from the analysis result (`RecordingSummary`, what
/// `analyse_recording()` returns and a scene's recording hook keeps), not
/// from a file: `make_recording_record(summary)` is the one call a scene
/// report makes. The samples themselves are optional: without them there is
/// no signal plot.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pendulum/recordings/swings.hpp"
#include "pendulum/report/decay_record.hpp"
#include "pendulum/report/svg_plot.hpp"

namespace pendulum::report {

/// A sampled signal reduced for drawing.
struct SignalTrace {
  std::vector<double> time, value;
};

/// The least and the greatest sample of each of `columns` equal slices of
/// [time.front(), time.back()], in the order they were sampled, with the
/// first and the last sample: every slice's extremes are drawn, so a slice
/// that holds a crossing of zero spans zero, and no peak is lost. Give at
/// least as many slices as the plot has pixel columns. A record of at most
/// 2 `columns` samples is returned whole. Throws std::invalid_argument when
/// the lengths differ or columns is 0.
SignalTrace decimate_signal(const std::vector<double>& time, const std::vector<double>& value, std::size_t columns);

/// The report data of an analysed recording, in SI units (angles in rad).
struct RecordingRecord {
  std::string input;        ///< the file as the user named it, "/set" after it for a set
  std::string format;       ///< the family read: "phyphox", ...
  std::string signal;       ///< what the signal is, in words
  std::size_t rows = 0, dropped = 0;
  PeriodEstimate period;
  /// The period is printed no finer than this (s): the crossing fit's own
  /// floor where it has one (PeriodEstimate::resolution_floor: the clock's
  /// q^2/12 a crossing through the fitted slope); else the clock's
  /// resolution (Recording::time_quantum, 1 us where the reader sets none,
  /// the finest stamp a lab logger writes) spread over the periods,
  /// sqrt(2) dt / N, since each end crossing is known no better than dt.
  double period_resolution = 0.0;
  int crossings_per_period = 2;
  std::vector<double> crossings;  ///< (s), as recorded
  /// Each crossing time's standard uncertainty (s): the fit's residual rms
  /// over the square root of its normalised weight (recordings/swings.hpp).
  std::vector<double> crossing_sigmas;
  double small_amplitude_period;  ///< T0 (s); NaN without amplitudes
  double start_amplitude, end_amplitude;  ///< (rad); NaN without amplitudes
  /// The signal as drawn (decimated), its axis label and the number of
  /// samples it came from; empty without samples or for gate events.
  std::optional<SignalTrace> trace;
  std::string trace_label;
  std::size_t samples = 0;
  /// Each swing's amplitude (rad) at its peak time (s, as recorded).
  std::vector<double> swing_times, swing_amplitudes;
  /// The decay fit of Eq. (25) on those, times as recorded; empty when it
  /// does not apply, and decay_note says why.
  std::optional<DecayRecord> decay;
  std::string decay_note;
  /// One point per full period (time as recorded).
  std::vector<PeriodPoint> periods;
  /// The stretch analysed (s, as recorded) where it is not the whole record
  /// (a typed range, or the clean stretch), what the clean stretch left out
  /// or bridged, and the whole record's period it replaced
  /// (SwingAnalysis::analysed, cuts, whole_record_period).
  std::optional<std::pair<double, double>> analysed;
  std::vector<Cut> cuts;
  std::optional<PeriodEstimate> whole_record_period;
};

/// The report data of `summary`; `samples`, when given, is the recording it
/// was analysed from, for the signal plot (decimated here).
RecordingRecord make_recording_record(const RecordingSummary& summary, const Recording* samples = nullptr);

/// At most this many crossing ticks on the signal plot: 4 px apart or more.
inline constexpr std::size_t kMaxCrossingTicks = 150;

/// The signal with every detected crossing marked (every n-th beyond
/// kMaxCrossingTicks, said in the legend and the description); empty without
/// a trace.
std::optional<Figure> signal_figure(const RecordingRecord& r, const std::string& id);

/// Each swing's amplitude in degrees against time, with the decay fit, its
/// +-1 sigma band and the residuals when the fit applies; empty without
/// amplitudes.
std::optional<Figure> amplitude_figure(const RecordingRecord& r, const std::string& id);

/// The period of each full swing (averaged over m consecutive ones, down to
/// at most 200 points; the mean is the time from the first crossing to the
/// last over m, so its error bar is sqrt(sigma_first^2 + sigma_last^2) / m)
/// against its amplitude, with the exact period
/// T0 f(theta0), f = 1 + DeltaT/T0(theta0) (Eq. 8, finite_amplitude_agm),
/// T0 = sum T_i f_i / sum f_i^2 fitted to the plotted periods, and the
/// residuals; empty without amplitudes.
std::optional<Figure> period_amplitude_figure(const RecordingRecord& r, const std::string& id);

/// The plots the record allows, by name: signal, amplitude, period-amplitude.
std::vector<std::string> recording_plot_names(const RecordingRecord& r);

/// One plot as a standalone SVG file. Throws InputError naming the file and
/// what it lacks, or the plots it has.
std::string recording_plot_svg(const RecordingRecord& r, const std::string& name);

}  // namespace pendulum::report
