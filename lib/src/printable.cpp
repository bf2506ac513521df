#include "pendulum/printable.hpp"

#include <string_view>

namespace pendulum {

namespace {

/// The length of the well-formed UTF-8 sequence at s[i] (1 to 4; RFC 3629:
/// no overlong forms, no surrogates, nothing above U+10FFFF), 0 if none or
/// if it is a C1 control (U+0080 to U+009F: a terminal takes U+009B as CSI,
/// as it does ESC [).
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

}  // namespace

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

}  // namespace pendulum
