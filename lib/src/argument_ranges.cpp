#include "pendulum/argument_ranges.hpp"

#include <cmath>

#include "text.hpp"

namespace pendulum {

std::string out_of_range(const ArgumentRange& range, double value) {
  if (value >= range.low && (range.high_open ? value < range.high : value <= range.high)) return "";
  const std::string unit = *range.unit ? std::string(" ") + range.unit : "";
  // "NaN", not the "-nan" printf may write.
  return "got " + (std::isnan(value) ? std::string("NaN") : format_number(value)) + unit + "; expected " +
         range.expected;
}

}  // namespace pendulum
