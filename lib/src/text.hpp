#pragma once
// Numbers and strings in messages: one line of printable ASCII.

#include <cstddef>
#include <string>

namespace pendulum {

/// `s` fit for a one-line message: ASCII only, control and non-ASCII bytes
/// as \xNN, cut to `max` characters.
std::string one_line(const std::string& s, std::size_t max);

/// Text from a file (a header cell, a name in an archive) fit for a one-line
/// message: control bytes as '?', UTF-8 kept (a header's θ or µs), cut to
/// `max` characters with "...".
std::string printable(const std::string& s, std::size_t max);

/// `x` with `digits` significant digits.
std::string format_number(double x, int digits = 10);

/// A fraction as a percentage for a message: "5.3%", "8%", "120%" (two
/// significant digits below 10%, whole percents above, never "1e+02%").
std::string format_percent(double fraction);

}  // namespace pendulum
