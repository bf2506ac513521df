#include "pendulum/argument_ranges.hpp"

#include <charconv>
#include <cmath>

#include "text.hpp"

namespace pendulum {

std::string out_of_range(const ArgumentRange& range, double value) {
  if (accepts(range, value)) return "";
  const std::string unit = *range.unit ? std::string(" ") + range.unit : "";
  // "NaN", not the "-nan" printf may write.
  return "got " + (std::isnan(value) ? std::string("NaN") : format_number(value)) + unit + "; expected " +
         range.expected;
}

std::optional<double> decimal_number(std::string_view text) {
  if (text.size() > 1 && text.front() == '+' && text[1] != '-') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  // 1e400, beyond a double, is refused too (strtod gives infinity).
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace pendulum
