#include "text.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

namespace pendulum {

std::size_t printable_utf8_length(const std::string& s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = byte(i);
  if (c < 0x80) return 1;
  if (c < 0xc2 || c > 0xf4) return 0;
  const std::size_t want = c < 0xe0 ? 2 : c < 0xf0 ? 3 : 4;
  const unsigned char low = c == 0xe0 ? 0xa0 : c == 0xf0 ? 0x90 : 0x80;
  const unsigned char high = c == 0xed ? 0x9f : c == 0xf4 ? 0x8f : 0xbf;
  if (i + want > s.size() || byte(i + 1) < low || byte(i + 1) > high) return 0;
  if (c == 0xc2 && byte(i + 1) < 0xa0) return 0;  // C1 control
  for (std::size_t k = 2; k < want; ++k) {
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
  }
  return want;
}

std::string lower_case(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string one_line(const std::string& s, std::size_t max, bool keep_utf8) {
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const std::size_t length = c >= 0x80 && keep_utf8 ? printable_utf8_length(s, i) : 0;
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
      ++i;
    } else if (length) {
      out.append(s, i, length);
      i += length;
    } else {
      static const char hex[] = "0123456789abcdef";
      out += {'\\', 'x', hex[c >> 4], hex[c & 15]};
      ++i;
    }
  }
  if (out.size() <= max) return out;
  std::size_t cut = max - 3;
  while (cut > 0 && (static_cast<unsigned char>(out[cut]) & 0xc0) == 0x80) --cut;  // a UTF-8 continuation byte
  return out.substr(0, cut) + "...";
}

std::string spreadsheet_text(const std::string& s) {
  return !s.empty() && std::string_view("=+-@\t\r").find(s.front()) != std::string_view::npos ? "'" + s : s;
}

std::string format_number(double x, int digits) {
  std::ostringstream os;
  os.precision(digits);
  os << x;
  return os.str();
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
