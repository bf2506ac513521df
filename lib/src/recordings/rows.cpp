// The rows stage (stages.hpp): the numbers of a recording, one vector per
// column, read in one pass with Clinger's fast path (number.hpp) and
// std::from_chars behind it, no allocation per cell.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "huge_pages.hpp"
#include "pendulum/interrupt.hpp"
#include "number.hpp"
#include "stages.hpp"

namespace pendulum::recording_text {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

std::size_t Table::line(std::size_t row) const {
  const auto after = std::upper_bound(jumps.begin(), jumps.end(), row,
                                      [](std::size_t r, const std::pair<std::size_t, std::size_t>& j) { return r < j.first; });
  if (after == jumps.begin()) return row + 1;
  const auto& [first, line] = *(after - 1);
  return line + (row - first);
}

Table read_rows(const char* p, const char* end, std::size_t line_no, const Dialect& dialect,
                const std::vector<std::string>& names, const std::string& file, const InputLimits& limits) {
  const std::size_t ncols = names.size();
  const char delimiter = dialect.delimiter;
  const bool spaces = delimiter == ' ';
  const char mark = dialect.mark();
  const char other_delimiters[] = {'\t', ';', delimiter == ',' ? '\0' : ','};
  Table table;
  table.columns.resize(ncols);
  table.cell_units.resize(ncols);
  {
    // One allocation per column: rows from the first row's length, 5 % spare.
    const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
    const std::size_t first = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - p) : static_cast<std::size_t>(end - p);
    const double bytes_per_row = static_cast<double>(std::max<std::size_t>(first + 1, 4));
    const std::size_t guess = std::min(static_cast<std::size_t>(1.05 * static_cast<double>(end - p) / bytes_per_row) + 16,
                                       limits.rows + 1);
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
        // A unit after the number ("10cm", "0.68s", "7.38%"): the column's, the same in every cell.
        auto cell_unit = [&](const char* at) {
          const char* token_end = at;
          while (!ends_cell(token_end)) ++token_end;
          const std::string_view u(at, static_cast<std::size_t>(token_end - at));
          if (u.empty() || !(u == "%" || known_unit(u))) return at;
          const std::string normal = u == "%" ? std::string("%") : normal_unit(u);
          std::string& unit = table.cell_units[j];
          if (!unit.empty() && unit != normal) {
            fail(file, line_no, column(at),
                 "got the unit \"" + std::string(u) + "\" in column \"" + names[j] + "\" whose cells above are in " +
                     unit + "; expected one unit in each column");
          }
          unit = normal;
          return token_end;
        };
        auto bad_cell = [&](const char* bad) {
          const char* token_end = s;
          while (!ends_cell(token_end)) ++token_end;
          // `bad` is the end of the text when a cell is a lone sign there.
          if (bad < e && std::find(std::begin(other_delimiters), std::end(other_delimiters), *bad) !=
                             std::end(other_delimiters)) {
            fail(file, line_no, column(bad),
                 std::string("mixed delimiters: found '") + (*bad == '\t' ? "\\t" : std::string(1, *bad)) +
                     "' in a file whose header " +
                     (spaces ? std::string("separates columns by runs of spaces")
                     : delimiter == '\0'
                         ? std::string("names one column")
                         : "separates columns by '" + (delimiter == '\t' ? std::string("\\t") : std::string(1, delimiter)) +
                               "'"));
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
          if (r.ec == std::errc() && r.ptr != stop && cell_unit(r.ptr) == stop) r.ptr = stop;
          if (r.ec != std::errc() || r.ptr != stop) bad_cell(r.ec != std::errc() ? s : r.ptr);
          // No sensor reads infinity: a logger's overflow mark, not a sample.
          if (std::isinf(v)) {
            fail(file, line_no, column(q),
                 "got \"" + std::string(q, std::min<const char*>(stop, q + 40)) + "\" in column \"" + names[j] +
                     "\"; expected a finite number (an empty cell or NaN marks a missing sample)");
          }
        } else if (!ends_cell(stop)) {
          const char* after = cell_unit(stop);
          if (after == stop) bad_cell(stop);
          stop = after;
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
    check_interrupt();
    if (table.rows == limits.rows && !is_blank(p, line_end(p))) fail(file, line_no, 1, over_limit(limits, Limit::rows));
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
