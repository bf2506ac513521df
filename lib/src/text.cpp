#include "text.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

namespace pendulum {

std::string lower_case(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string format_number(double x, int digits) {
  std::ostringstream os;
  os.precision(digits);
  os << x;
  return os.str();
}

std::string uncertainty_not_below_value(const std::string& u, const std::string& value) {
  return "got " + u + "; expected an uncertainty smaller than the value (" + value + ")";
}

std::string format_percent(double fraction) {
  const double percent = 100.0 * fraction;
  if (std::abs(percent) < 10.0) return format_number(percent, 2) + "%";
  std::ostringstream os;
  os << std::fixed;
  os.precision(0);
  os << percent << "%";
  return os.str();
}

int decimals_for_uncertainty(double u, int most) {
  if (!(u > 0.0) || !std::isfinite(u)) return 5;
  return std::clamp(1 - static_cast<int>(std::floor(std::log10(u))), 0, most);
}

CorrectionDecimals correction_decimals(double delta_T, const std::optional<double>& delta_T_uncertainty, double delta_g) {
  auto decimals = [](double u) { return u > 0.0 && std::isfinite(u) ? std::min(decimals_for_uncertainty(u, 9), 4) : 4; };
  if (!delta_T_uncertainty) return {4, 4};
  const double u_us = *delta_T_uncertainty * 1e6;
  const double g_per_us = delta_T != 0.0 ? std::abs(delta_g * 1e5 / (delta_T * 1e6)) : 1.0;
  return {decimals(u_us), decimals(u_us * g_per_us)};
}

}  // namespace pendulum
