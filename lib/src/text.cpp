#include "text.hpp"

#include <cmath>
#include <sstream>

namespace pendulum {

std::string one_line(const std::string& s, std::size_t max) {
  std::string out;
  for (const unsigned char c : s) {
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static const char hex[] = "0123456789abcdef";
      out += {'\\', 'x', hex[c >> 4], hex[c & 15]};
    }
  }
  return out.size() > max ? out.substr(0, max - 3) + "..." : out;
}

std::string printable(const std::string& s, std::size_t max) {
  std::string out = s;
  for (char& c : out) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  }
  return out.size() > max ? out.substr(0, max - 3) + "..." : out;
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
