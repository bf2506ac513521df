#pragma once
/// \file output.hpp
/// \brief What the commands print: the result of `reduce` as JSON (an API,
/// docs/output.md) and as a table for people at a terminal, the decay fit,
/// and a batch's summary lines. JSON text in, so that no header below the
/// CLI includes the JSON parser.

#include <string>
#include <vector>

#include "pendulum/analysis.hpp"
#include "pendulum/clock_scene.hpp"

namespace pendulum {

/// The result document; `input` names the scene file as the user gave it.
/// `indent` as for JSON dumps: -1 is one line.
std::string result_json(const ParsedScene& scene, const Analysis& analysis, const AnalysisOptions& options,
                        const std::string& input, int indent = 2);

/// The same result as an aligned text table (microseconds, 1e-5 m/s^2).
std::string result_table(const ParsedScene& scene, const Analysis& analysis);

/// The document of `pendulum-g fit-decay`: the fit of the scene's decay
/// record, the air's predicted damping beside it, and the warnings.
std::string decay_fit_json(const std::string& input, const ParsedScene& scene, const DecayFit& fit,
                           const std::vector<std::string>& warnings);

/// One scene's line in a batch summary (`pendulum-g batch`), as a JSON line
/// and as a CSV row.
struct BatchLine {
  bool ok;
  std::string json;  ///< one line, no newline
  std::string csv;   ///< one row, with its newline
};
BatchLine batch_line(const std::string& input, const ParsedScene& scene, const Analysis& analysis);
/// The line of a scene that failed: its input and the error.
BatchLine batch_failure(const std::string& input, const std::string& error);
std::string batch_csv_header();

/// The result of `pendulum-g clock` (docs/clock.md) as JSON and as a table;
/// `input` names the scene file as the user gave it.
std::string clock_json(const ClockScene& scene, const ClockAnalysis& analysis, const std::string& input);
std::string clock_table(const ClockScene& scene, const ClockAnalysis& analysis);

}  // namespace pendulum
