#pragma once
// Private to lib/src/recordings/ (and bench_numbers, which times it against
// std::from_chars and fast_float): the reader's number fast path.
#include <cstdint>
#include <cstring>

namespace pendulum::recording_text {

/// Eight ASCII digits at p as a number, if they are all digits (SWAR: the
/// bytes of one 64-bit word combined pairwise, then by fours; little-endian).
inline bool eight_digits(const char* p, std::uint64_t& out) {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  if ((((v + 0x4646464646464646ULL) | (v - 0x3030303030303030ULL)) & 0x8080808080808080ULL) != 0) return false;
  v -= 0x3030303030303030ULL;
  v = v * 10 + (v >> 8);  // pairs: 2-digit values in bytes 0, 2, 4, 6
  v = ((v & 0x000000FF000000FFULL) * (100 + (1000000ULL << 32)) +
       ((v >> 16) & 0x000000FF000000FFULL) * (1 + (10000ULL << 32))) >> 32;
  out = v;
  return true;
}

/// The body of fast_number; kBounded checks every read against e. Without
/// it each digit run stops after 20 characters, so no read goes more than 58
/// bytes past s: the caller guarantees 64 (most numbers of a large file).
template <bool kBounded>
inline const char* parse_decimal(const char* s, const char* e, char mark, double& v) {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                      1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  auto digit = [&](const char* at, const char* from) {
    return (kBounded ? at < e : at - from < 20) && static_cast<unsigned>(*at - '0') < 10u;
  };
  const char* p = s;
  const bool negative = (!kBounded || p < e) && *p == '-';
  p += negative;
  std::uint64_t m = 0;
  const char* start = p;
  for (; digit(p, start); ++p) m = m * 10 + static_cast<unsigned>(*p - '0');
  int digits = static_cast<int>(p - start), power = 0;
  if ((!kBounded || p < e) && *p == mark) {
    const char* fraction = ++p;
    std::uint64_t chunk;
    if (digits <= 11 && (!kBounded || e - p >= 8) && eight_digits(p, chunk)) m = m * 100000000 + chunk, p += 8;
    for (const char* run = p; digit(p, run); ++p) m = m * 10 + static_cast<unsigned>(*p - '0');
    digits += static_cast<int>(p - fraction);
    power = -static_cast<int>(p - fraction);
  }
  if (digits == 0 || digits > 19) return nullptr;
  if ((!kBounded || p < e) && (*p == 'e' || *p == 'E')) {
    ++p;
    const bool minus = (!kBounded || p < e) && *p == '-';
    p += (!kBounded || p < e) && (*p == '-' || *p == '+');
    const char* first = p;
    int x = 0;
    if (!kBounded && digit(p, first) && digit(p + 1, first) && !digit(p + 2, first)) {
      x = (p[0] - '0') * 10 + (p[1] - '0'), p += 2;  // the common two digits, without a loop
    }
    for (; digit(p, first) && p - first < 6; ++p) x = x * 10 + (*p - '0');
    if (p == first) return nullptr;
    power += minus ? -x : x;
  }
  if (m > (std::uint64_t{1} << 53) || power < -22 || power > 22) return nullptr;
  const double magnitude = power < 0 ? static_cast<double>(m) / kPow10[-power] : static_cast<double>(m) * kPow10[power];
  v = negative ? -magnitude : magnitude;
  return p;
}

/// Reads a decimal number at [s, e) with `mark` as its decimal mark; returns
/// the end of the number, or nullptr when the fast path does not apply.
/// Clinger's fast path: a mantissa m < 2^53 of at most 19 digits and a power
/// p with |p| <= 22 give m * 10^p or m / 10^-p, one correctly rounded
/// operation on exact doubles, hence the same double as std::from_chars
/// (phyphox's 1.234567890E-1 always qualifies). Anything else (more digits,
/// larger powers, "NaN", "inf") is left to std::from_chars.
inline const char* fast_number(const char* s, const char* e, char mark, double& v) {
  return e - s >= 64 ? parse_decimal<false>(s, e, mark, v) : parse_decimal<true>(s, e, mark, v);
}

}  // namespace pendulum::recording_text
