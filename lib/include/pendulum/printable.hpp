#pragma once
/// \file printable.hpp
/// \brief Text from outside (file names, header cells, option values, titles)
/// made safe for a terminal and a spreadsheet (docs/robustness.md, "Text from
/// outside").

#include <cstddef>
#include <string>

namespace pendulum {

/// Bytes of an option's value quoted in an option error, of a whole option
/// error, of a scene's title in a table: a 100 KB value is not echoed whole.
inline constexpr std::size_t kShownValueBytes = 80;
inline constexpr std::size_t kShownOptionErrorBytes = 200;
inline constexpr std::size_t kShownTitleBytes = 200;

/// `s` fit for a terminal and a one-line message: control bytes (C1 ones
/// too) as \xNN, and the bytes of other characters than ASCII too unless
/// `keep_utf8` (a recording's header says θ or µs; bytes that are not UTF-8
/// are escaped all the same), cut to at most `max` bytes with "..." (at a
/// character's start). The one function every such text goes through.
std::string one_line(const std::string& s, std::size_t max, bool keep_utf8 = false);

/// `s` as a CSV cell a spreadsheet shows as text: a leading =, +, -, @, tab
/// or carriage return (which start a formula) gets a ' before it (OWASP's
/// "CSV injection"). For text cells only: a number's minus stays.
std::string spreadsheet_text(const std::string& s);

}  // namespace pendulum
