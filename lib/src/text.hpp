#pragma once
// Numbers and strings in messages: one line of printable ASCII.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "pendulum/printable.hpp"

namespace pendulum {

/// `s` with its ASCII letters in lower case (headers, set and file names are
/// matched in any case; other bytes are kept).
std::string lower_case(std::string_view s);

/// `x` with `digits` significant digits.
std::string format_number(double x, int digits = 10);

/// The refusal of an uncertainty as large as its value, which might then be
/// 0: "got 80 cm; expected an uncertainty smaller than the value (75 cm)".
/// `u` and `value` as the input wrote them, each with its unit.
std::string uncertainty_not_below_value(const std::string& u, const std::string& value);

/// A fraction as a percentage for a message: "5.3%", "8%", "120%" (two
/// significant digits below 10%, whole percents above, never "1e+02%").
std::string format_percent(double fraction);

/// Decimals that show `u` to two significant digits, as a lab report rounds
/// a value to its uncertainty, at most `most`; 5 where u is not a positive
/// finite number.
int decimals_for_uncertainty(double u, int most);

/// Decimals of a correction's row in the pages' and the terminal's tables:
/// dT and u(dT) in us, dg in 1e-5 m/s^2, each by its uncertainty to two
/// significant digits (dg's scales as dT's), at most the 4 (0.1 ns) that a
/// row without one shows. Arguments in SI (s, s, m/s^2).
struct CorrectionDecimals {
  int delta_T, delta_g;
};
CorrectionDecimals correction_decimals(double delta_T, const std::optional<double>& delta_T_uncertainty, double delta_g);

}  // namespace pendulum
