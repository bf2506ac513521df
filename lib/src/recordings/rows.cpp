// The rows stage (stages.hpp): the numbers of a recording, one vector per
// column, read in one pass with Clinger's fast path and std::from_chars
// behind it, no allocation per cell.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "stages.hpp"
#include "huge_pages.hpp"

namespace pendulum::recording_text {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

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

}  // namespace

std::size_t Table::line(std::size_t row) const {
  const auto after = std::upper_bound(jumps.begin(), jumps.end(), row,
                                      [](std::size_t r, const std::pair<std::size_t, std::size_t>& j) { return r < j.first; });
  if (after == jumps.begin()) return row + 1;
  const auto& [first, line] = *(after - 1);
  return line + (row - first);
}

Table read_rows(const char* p, const char* end, std::size_t line_no, const Dialect& dialect,
                const std::vector<std::string>& names, const std::string& file) {
  const std::size_t ncols = names.size();
  const char delimiter = dialect.delimiter;
  const bool spaces = delimiter == ' ';
  const char mark = dialect.mark();
  const char other_delimiters[] = {'\t', ';', delimiter == ',' ? '\0' : ','};
  Table table;
  table.columns.resize(ncols);
  {
    // One allocation per column: rows from the first row's length, 5 % spare.
    const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
    const std::size_t first = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - p) : static_cast<std::size_t>(end - p);
    const double bytes_per_row = static_cast<double>(std::max<std::size_t>(first + 1, 4));
    const std::size_t guess = static_cast<std::size_t>(1.05 * static_cast<double>(end - p) / bytes_per_row) + 16;
    for (auto& c : table.columns) {
      c.reserve(guess);
      detail::huge_pages(c);
    }
  }
  auto line_end = [&](const char* q) {
    const void* nl = std::memchr(q, '\n', static_cast<std::size_t>(end - q));
    return nl ? static_cast<const char*>(nl) : end;
  };
  char buffer[64];
  // The common row: plain numbers between single delimiters, read up to its
  // newline, which it returns (no search for the line's end first). Anything
  // else (quotes, runs of spaces, empty or NaN cells, errors) takes the general path.
  auto plain_row = [&](const char* q) -> const char* {
    double v;
    std::size_t j = 0;
    for (; j + 1 < ncols; ++j) {
      q = fast_number(q, end, mark, v);
      if (!q || q >= end || *q != delimiter) break;
      table.columns[j].push_back(v);
      ++q;
    }
    if (j + 1 == ncols && (q = fast_number(q, end, mark, v))) {
      q += q < end && *q == '\r';
      if (q >= end || *q == '\n') {
        table.columns[j].push_back(v);
        return q;
      }
    }
    for (std::size_t k = 0; k < j; ++k) table.columns[k].pop_back();
    return nullptr;
  };
  // The line [p, e) cell by cell, with the errors named.
  auto general_row = [&](const char* p, const char* e) {
    auto column = [&](const char* at) { return static_cast<std::size_t>(at - p) + 1; };
    const char* q = p;
    if (spaces) {
      while (q < e && *q == ' ') ++q;
    }
    for (std::size_t j = 0; j < ncols; ++j) {
      // One cell: optional spaces and quotes around a number, "NaN" or nothing.
      while (q < e && (*q == ' ' || *q == '"')) ++q;
      double v = kNaN;
      const char* num_end = q;
      if (q < e && *q != delimiter && *q != '\r') {
        const char* s = q + (*q == '+');
        const char* stop = fast_number(s, e, mark, v);
        auto ends_cell = [&](const char* at) {
          return at >= e || *at == delimiter || *at == '"' || *at == ' ' || *at == '\r';
        };
        auto bad_cell = [&](const char* bad) {
          const char* token_end = s;
          while (!ends_cell(token_end)) ++token_end;
          // `bad` is the end of the text when a cell is a lone sign there.
          if (bad < e && std::find(std::begin(other_delimiters), std::end(other_delimiters), *bad) !=
                             std::end(other_delimiters)) {
            fail(file, line_no, column(bad),
                 std::string("mixed delimiters: found '") + (*bad == '\t' ? "\\t" : std::string(1, *bad)) +
                     "' in a file whose header separates columns by " +
                     (spaces ? std::string("runs of spaces")
                             : "'" + (delimiter == '\t' ? std::string("\\t") : std::string(1, delimiter)) + "'"));
          }
          fail(file, line_no, column(q),
               "got \"" + std::string(q, std::min<const char*>(token_end, q + 40)) + "\" in column \"" + names[j] +
                   "\"; expected a number");
        };
        if (!stop) {  // the slow path: NaN, long mantissas, large exponents
          stop = s;
          while (!ends_cell(stop)) ++stop;
          std::from_chars_result r{};
          if (dialect.decimal_comma) {
            const std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(stop - s), sizeof buffer);
            std::copy(s, s + n, buffer);
            std::replace(buffer, buffer + n, ',', '.');
            r = std::from_chars(buffer, buffer + n, v);
            r.ptr = s + (r.ptr - buffer);
          } else {
            r = std::from_chars(s, stop, v);
          }
          if (r.ec == std::errc::result_out_of_range) {
            fail(file, line_no, column(q), "a number out of the range of double");
          }
          if (r.ec != std::errc() || r.ptr != stop) bad_cell(r.ec != std::errc() ? s : r.ptr);
          // No sensor reads infinity: a logger's overflow mark, not a sample.
          if (std::isinf(v)) {
            fail(file, line_no, column(q),
                 "got \"" + std::string(q, std::min<const char*>(stop, q + 40)) + "\" in column \"" + names[j] +
                     "\"; expected a finite number (an empty cell or NaN marks a missing sample)");
          }
        } else if (!ends_cell(stop)) {
          bad_cell(stop);
        }
        num_end = stop;
      }
      q = num_end;
      while (q < e && (*q == ' ' || *q == '"' || *q == '\r')) ++q;
      table.columns[j].push_back(v);
      table.any_nan |= std::isnan(v);
      if (j + 1 < ncols) {
        // Runs of spaces: the spaces just skipped were the delimiter.
        if (spaces ? q >= e || q == num_end : q >= e || *q != delimiter) {
          fail(file, line_no, column(q),
               "a truncated row: " + std::to_string(j + 1) + " of " + std::to_string(ncols) + " columns (column \"" +
                   names[j + 1] + "\" is missing)");
        }
        q += !spaces;
      } else if (q < e && !(delimiter && *q == delimiter && is_blank(q, e))) {
        fail(file, line_no, column(q),
             "more cells than the " + std::to_string(ncols) +
                 " columns of the header (mixed delimiters, or a decimal comma in a comma-separated file?)");
      }
    }
  };
  std::size_t expected_line = 0;  // the line the next row has without a jump
  for (const char* e = nullptr; p < end; p = e < end ? e + 1 : end, ++line_no) {
    const char* plain = plain_row(p);
    if (plain) {
      e = plain;
    } else {
      e = line_end(p);
      if (is_blank(p, e)) continue;
      general_row(p, e);
    }
    if (line_no != expected_line) table.jumps.emplace_back(table.rows, line_no);
    expected_line = line_no + 1;
    ++table.rows;
  }
  return table;
}

}  // namespace pendulum::recording_text
