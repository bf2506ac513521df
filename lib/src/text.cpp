#include "text.hpp"

#include <cmath>
#include <sstream>

namespace pendulum {

std::string one_line(const std::string& s, std::size_t max, bool keep_utf8) {
  std::string out;
  for (const unsigned char c : s) {
    if ((c >= 0x20 && c < 0x7f) || (keep_utf8 && c >= 0x80)) {
      out += static_cast<char>(c);
    } else {
      static const char hex[] = "0123456789abcdef";
      out += {'\\', 'x', hex[c >> 4], hex[c & 15]};
    }
  }
  if (out.size() <= max) return out;
  std::size_t cut = max - 3;
  while (cut > 0 && (static_cast<unsigned char>(out[cut]) & 0xc0) == 0x80) --cut;  // a UTF-8 continuation byte
  return out.substr(0, cut) + "...";
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

}  // namespace pendulum
