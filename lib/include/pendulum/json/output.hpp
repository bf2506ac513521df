#pragma once
/// \file json/output.hpp
/// \brief What the commands print: the result of `reduce` as JSON (an API,
/// docs/output.md) and as a table for people at a terminal, the decay fit,
/// and a batch's summary lines. JSON text in, so that no header below the
/// CLI includes the JSON parser.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pendulum/analysis.hpp"
#include "pendulum/clock_scene.hpp"

namespace pendulum {

struct RecordingSummary;

/// The result document; `input` names the scene file as the user gave it.
/// `indent` as for JSON dumps: -1 is one line.
std::string result_json(const ParsedScene& scene, const Analysis& analysis, const AnalysisOptions& options,
                        const std::string& input, int indent = 2);

/// The same result as an aligned text table for people: corrections in
/// microseconds and mGal, g rounded to its uncertainty, the status.
std::string result_table(const ParsedScene& scene, const Analysis& analysis);

/// The result of an amplitude sweep whose length was not measured
/// (ParsedScene::length_measured): T0 and the law tested, "g": null.
std::string sweep_result_json(const ParsedScene& scene, const AmplitudeSweep& sweep, const std::string& input);
std::string sweep_result_table(const ParsedScene& scene, const AmplitudeSweep& sweep);
/// Why that result is suspect: the reader's findings, periods scattering
/// beyond their stated uncertainties, the law refuted; empty when ok.
std::vector<std::string> sweep_reasons(const ParsedScene& scene, const AmplitudeSweep& sweep);

/// g with its expanded uncertainty as a lab report quotes it after "g = ",
/// both rounded to two significant digits of U (GUM 7.2.6): "9.8034 ± 0.0031
/// m/s² (k = 2.07, 95 %, ν_eff = 31)", with "+-", "m/s^2" and "nu_eff" where
/// not `unicode`; ν_eff as GUM G.4.1 truncates it, "∞" where infinite.
std::string expanded_result(double g, const ExpandedUncertainty& expanded, bool unicode);

/// The document of `pendulum-g fit-decay`: the fit of the scene's decay
/// record, the air's predicted damping beside it, and the warnings.
std::string decay_fit_json(const std::string& input, const ParsedScene& scene, const DecayFit& fit,
                           const std::vector<std::string>& warnings);

/// The same fit as a text table for people (`fit-decay --format table`).
std::string decay_fit_table(const ParsedScene& scene, const DecayFit& fit, const std::vector<std::string>& warnings);

/// The document of `pendulum-g import RECORDING` (docs/recordings.md), no
/// newline: the format, the period, the amplitude range, the `timing` and
/// `decay` parts of a scene, the columns used, the glitches and the notes.
std::string recording_json(const RecordingSummary& summary);

/// How a scene names a recording as `import` read it: the options that
/// changed the reading, written into the scene's reference so that `reduce`
/// reads it the same way.
struct RecordingReference {
  std::string recording;  ///< the file's name as the scene writes it (beside the scene)
  std::string format;     ///< the family forced with --format, empty for auto
  std::string set;        ///< --set, empty for none
  std::string columns;    ///< --columns, empty for none
  std::optional<std::pair<double, double>> range;  ///< --range A:B (s, the file's clock)
  bool whole_record = false;                        ///< --range all
  std::optional<double> bob_width, length;         ///< --bob-width-m, --length-m (m)
};

/// `pendulum-g import RECORDING --format scene`: a whole scene timed by the
/// recording (its `timing` and, where it gives swing amplitudes, `decay`),
/// with what the file cannot tell (the length and its uncertainty, the bob,
/// an amplitude where the recording gives none) as placeholder strings that
/// `reduce` refuses, naming the key to fill. No newline.
std::string recording_scene(const RecordingSummary& summary, const RecordingReference& reference);

/// The forms of a batch summary's line (`pendulum-g batch --format`).
enum class BatchFormat {
  jsonl,  ///< one JSON line, no newline
  csv,    ///< one row, with its newline: the warnings counted, the first given
  /// one row of `--format table` after the file column, no newline: status,
  /// g rounded to its uncertainty, z, the first reason in brief
  table,
};

/// One scene's line in a batch summary (`pendulum-g batch`), in one form:
/// a batch prints one, and each costs its formatting.
struct BatchLine {
  bool ok;               ///< a result exists (status ok or suspect)
  ResultStatus status;
  std::optional<double> g;  ///< (m/s^2), when ok
  std::string text;      ///< the line in the form asked for (BatchFormat)
};
BatchLine batch_line(const std::string& input, const ParsedScene& scene, const Analysis& analysis,
                     BatchFormat format = BatchFormat::jsonl);
/// The line of a scene that failed: its input and the error.
BatchLine batch_failure(const std::string& input, const std::string& error, BatchFormat format = BatchFormat::jsonl);
std::string batch_csv_header();
/// The table's header, its file column `file_width` wide (and 2 spaces).
std::string batch_table_header(std::size_t file_width);

/// The class at a glance: scenes by status, and the mean and sample
/// standard deviation of g over the scenes whose status is ok.
struct ClassSummary {
  int count[3] = {0, 0, 0};  ///< by ResultStatus: ok, suspect, failed
  int ok_g_count = 0;
  std::optional<double> ok_g_mean;                ///< (m/s^2), with one ok scene or more
  std::optional<double> ok_g_standard_deviation;  ///< (m/s^2), with two or more
};
ClassSummary summarise_class(const std::vector<BatchLine>& lines);
/// The same from each scene's status and g (empty when it failed).
ClassSummary summarise_class(const std::vector<std::pair<ResultStatus, std::optional<double>>>& results);
/// The summary's last line: a JSON line with "class": true...
std::string batch_class_json(const ClassSummary& summary);
/// ...or a CSV comment line "# class: ...", with its newline.
std::string batch_class_csv(const ClassSummary& summary);
/// ...or the table's last line "class: ...", with its newline.
std::string batch_class_table(const ClassSummary& summary);

/// The result of `pendulum-g clock` (docs/clock.md) as JSON and as a table;
/// `input` names the scene file as the user gave it.
std::string clock_json(const ClockScene& scene, const ClockAnalysis& analysis, const std::string& input);
std::string clock_table(const ClockScene& scene, const ClockAnalysis& analysis);

}  // namespace pendulum
