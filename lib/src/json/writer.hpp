#pragma once
// What every JSON writer of lib/src/json shares.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "pendulum/estimate.hpp"

#include <ostream>

namespace pendulum {

struct AmplitudeSweep;

/// JSON text as every command prints it (indent -1: one line). Throws
/// std::logic_error at a number that is not finite, which the JSON library
/// would print as null where the API promises a number. A file name that is
/// not UTF-8 prints its bad bytes as U+FFFD instead of failing.
std::string json_text(const nlohmann::ordered_json& j, int indent);

/// The JSON object a period model writes its own results into (its
/// put_fit_results, put_observation_results; lib/src/models/).
struct JsonOut {
  nlohmann::ordered_json& json;
};

/// What the writers of the output and the models' own results share.
namespace writer {

/// The number, or null.
nlohmann::ordered_json optional_number(const std::optional<double>& x);
/// x, or null where it is not finite (unknown: an end of a Monte Carlo
/// interval placed by fewer than two batches).
nlohmann::ordered_json finite_or_null(double x);
/// {"value", "uncertainty", "unit"}, the uncertainty null where unknown.
nlohmann::ordered_json measured(const ValueWithUncertainty& x, const char* unit);
nlohmann::ordered_json measured(const Estimate& x, const char* unit);

/// x with `decimals` decimals, printf's "%.*f" (an ASCII minus: the
/// table's; the report's pendulum::format_fixed prints U+2212).
std::string format_fixed(double x, int decimals);
/// "+- 0.00148" in `format`, or "+- ? (singular fit)" without one.
std::string plus_minus(const std::optional<double>& u, const char* format);
/// "9.8034 +- 0.0015": the value rounded to its uncertainty.
std::string rounded(double value, const std::optional<double>& u);

/// An amplitude sweep's T0, law test and points (sweep_writer.cpp).
nlohmann::ordered_json amplitude_sweep_json(const AmplitudeSweep& s);
/// The same as lines of the result table; `with_chi2` false beside a
/// series' fit, whose chi2 line is the same fit's at one length.
void amplitude_sweep_lines(const AmplitudeSweep& s, bool with_chi2, std::ostream& os);

}  // namespace writer

}  // namespace pendulum
