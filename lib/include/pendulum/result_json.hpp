#pragma once
/// \file result_json.hpp
/// \brief The output of `pendulum-g reduce`: JSON (an API, docs/output.md)
/// and a table for people at a terminal.

#include <string>

#include <nlohmann/json.hpp>

#include "pendulum/analysis.hpp"

namespace pendulum {

/// The result document; `input` names the scene file as the user gave it.
nlohmann::ordered_json result_to_json(const ParsedScene& scene, const Analysis& analysis,
                              const AnalysisOptions& options, const std::string& input);

/// The decay fit as JSON (the body of `pendulum-g fit-decay`); `given` are
/// alpha and beta stated beside the record, if any.
nlohmann::ordered_json decay_fit_to_json(const DecayFit& fit, const std::optional<Decay<double>>& given);

/// The air's predicted damping, compared with the alpha and beta in use.
nlohmann::ordered_json drag_to_json(const DragPrediction<double>& drag, const Decay<double>& decay);

/// One scene's line in a batch summary (`pendulum-g batch`): g, its
/// uncertainty, the largest budget entry, the expected g and the z-score.
nlohmann::ordered_json batch_summary(const std::string& input, const ParsedScene& scene,
                                     const Analysis& analysis);

/// The summary line of a scene that failed: its input and the error.
nlohmann::ordered_json batch_failure(const std::string& input, const std::string& error);

/// The CSV header and one row for a summary line.
std::string batch_csv_header();
std::string batch_csv_row(const nlohmann::ordered_json& summary);

/// The same result as an aligned text table (microseconds, 1e-5 m/s^2).
std::string result_to_table(const ParsedScene& scene, const Analysis& analysis);

}  // namespace pendulum
