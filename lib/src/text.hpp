#pragma once
// Numbers and strings in messages: one line of printable ASCII.

#include <cstddef>
#include <string>

namespace pendulum {

/// `s` fit for a one-line message: control bytes as \xNN, and the bytes of
/// other characters than ASCII too unless `keep_utf8` (a recording's header
/// says θ or µs; bytes that are not UTF-8 are escaped all the same), cut to
/// at most `max` bytes with "..." (at a character's start).
std::string one_line(const std::string& s, std::size_t max, bool keep_utf8 = false);

/// The length of the well-formed UTF-8 sequence at s[i] (1 to 4; RFC 3629:
/// no overlong forms, no surrogates, nothing above U+10FFFF), 0 if none or
/// if it is a C1 control (U+0080 to U+009F: a terminal takes U+009B as CSI,
/// as it does ESC [).
std::size_t printable_utf8_length(const std::string& s, std::size_t i);

/// `x` with `digits` significant digits.
std::string format_number(double x, int digits = 10);

/// A fraction as a percentage for a message: "5.3%", "8%", "120%" (two
/// significant digits below 10%, whole percents above, never "1e+02%").
std::string format_percent(double fraction);

}  // namespace pendulum
