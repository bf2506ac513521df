// The reading stages before and after the rows (stages.hpp): decode, lines,
// split, words, content.
#include "stages.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "pendulum/argument_ranges.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/numeric.hpp"
#include "../text.hpp"

namespace pendulum::recording_text {

void fail(const std::string& file, std::size_t line, std::size_t column, const std::string& message) {
  throw InputError(file + ":" + std::to_string(line) + ":" + std::to_string(column), one_line(message, 800, true));
}

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

namespace {

bool ends_with(std::string_view s, std::string_view p) {
  return s.size() >= p.size() && s.substr(s.size() - p.size()) == p;
}

/// Takes the primes (' or ′, a tracker's derivative: X', Y') off the end of
/// `w`, leaving a word; whether there were any.
bool strip_primes(std::string_view& w) {
  bool prime = false;
  for (std::string_view mark : {std::string_view("'"), std::string_view("\xe2\x80\xb2")}) {  // ', ′
    if (ends_with(w, mark) && w.size() > mark.size()) w.remove_suffix(mark.size()), prime = true;
  }
  return prime;
}

}  // namespace

bool generic_names(const std::vector<Column>& cols) {
  return !cols.empty() && std::all_of(cols.begin(), cols.end(), [](const Column& c) {
    std::string_view word = c.word;
    strip_primes(word);
    const bool letter = word == "x" || word == "y";
    return !c.prefixed && c.unit.empty() &&
           ((letter && (c.role == Role::x || c.role == Role::y || c.role == Role::derivative)) ||
            ((c.word == "dx" || c.word == "dy") && c.role == Role::uncertainty));
  });
}

double median_of(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

std::string_view trim_cell(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\r' || s.front() == '"')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r' || s.back() == '"')) s.remove_suffix(1);
  return s;
}

namespace {

std::string_view trim_spaces(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\r' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

bool valid_utf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (n == 0 || i + n > s.size()) return false;
    for (std::size_t k = 1; k < n; ++k) {
      if ((static_cast<unsigned char>(s[i + k]) >> 6) != 2) return false;
    }
    i += n;
  }
  return true;
}

}  // namespace

// --- decode -----------------------------------------------------------------

std::string_view strip_bom(std::string_view text) {
  if (starts_with(text, "\xef\xbb\xbf")) text.remove_prefix(3);
  return text;
}

std::string column_label(const std::string& name, std::size_t index) {
  return name.empty() ? "column " + std::to_string(index) : one_line(name, 40, true);
}

std::string to_utf8(std::string_view cell) {
  if (valid_utf8(cell)) return std::string(cell);
  std::string out;
  for (char ch : cell) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c < 0x80) {
      out += ch;
    } else {
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
    }
  }
  return out;
}

// --- lines ------------------------------------------------------------------

bool is_blank(const char* p, const char* e) {
  for (; p < e; ++p) {
    if (*p != ' ' && *p != '\t' && *p != '\r' && *p != ',' && *p != ';') return false;
  }
  return true;
}

bool is_data(const char* p, const char* e) {
  while (p < e && (*p == ' ' || *p == '"' || *p == '\t')) ++p;
  if (p < e && (*p == '-' || *p == '+')) ++p;
  return p < e && (std::isdigit(static_cast<unsigned char>(*p)) || *p == '.');
}

DataRows data_rows(std::string_view text, const HeaderLines& lines, const std::string& file, const std::string& what) {
  const char* begin = text.data() + lines.data_offset;
  const char* const end = text.data() + text.size();
  if (begin >= end) fail(file, lines.data_line + 1, 1, "no data rows; expected " + what);
  const void* nl = std::memchr(begin, '\n', static_cast<std::size_t>(end - begin));
  return {begin, end, std::string_view(begin, static_cast<std::size_t>((nl ? static_cast<const char*>(nl) : end) - begin))};
}

namespace {

/// The end of the line from `p`: its newline, or past a newline inside a
/// quoted cell (RFC 4180: "time\n(s)" is one cell), which opens at a cell's
/// start (after spaces) and closes at a lone quote ("" is one within it). A
/// quote left open over kQuotedLines lines, or to the end, is a stray one:
/// the line then ends at its own newline, as it did before.
const char* line_end(const char* p, const char* end) {
  constexpr int kQuotedLines = 8;
  const void* first = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
  const char* const own = first ? static_cast<const char*>(first) : end;
  if (!std::memchr(p, '"', static_cast<std::size_t>(own - p))) return own;
  bool cell_start = true, quoted = false;
  int newlines = 0;
  for (const char* q = p; q < end; ++q) {
    const char c = *q;
    if (quoted) {
      if (c == '"' && q + 1 < end && q[1] == '"') {
        ++q;
      } else if (c == '"') {
        quoted = false;
      } else if (c == '\n' && ++newlines > kQuotedLines) {
        return own;
      }
    } else if (c == '\n') {
      return q;
    } else if (c == ',' || c == ';' || c == '\t') {
      cell_start = true;
    } else if (c != ' ') {
      quoted = c == '"' && cell_start;
      cell_start = false;
    }
  }
  return quoted ? own : end;
}

}  // namespace

HeaderLines find_header(std::string_view text, const std::string& file) {
  const char* const begin = text.data();
  const char* const end = begin + text.size();
  HeaderLines h;
  const char* p = begin;
  std::size_t line_no = 0;
  while (p < end) {
    const char* e = line_end(p, end);
    ++line_no;
    if (!is_blank(p, e)) {
      if (is_data(p, e)) break;
      if (h.header) h.preamble = true, h.above = h.header, h.above_line = h.header_line;
      h.several_tracks |= starts_with(std::string_view(p, static_cast<std::size_t>(e - p)), "#multi");
      h.header = std::string_view(p, static_cast<std::size_t>(e - p));
      h.header_line = line_no;
    }
    // The lines within a quoted cell count: a later message names the file's own line.
    line_no += static_cast<std::size_t>(std::count(p, e, '\n'));
    p = e + (e < end);
    if (line_no > 100) fail(file, line_no, 1, "no numbers in the first 100 lines; expected a data export");
  }
  h.data_offset = static_cast<std::size_t>(p - begin);
  h.data_line = line_no;
  return h;
}

// --- split ------------------------------------------------------------------

Dialect sniff(std::optional<std::string_view> header, std::string_view first_data) {
  Dialect d;
  const std::string_view probe = header ? *header : first_data;
  for (char c : {'\t', ';', ','}) {
    if (probe.find(c) != std::string_view::npos) {
      d.delimiter = c;
      break;
    }
  }
  // A header of words without one ("# Perioden   t in s", a comment line
  // above "1;3.05"): the rows' tab or semicolon, which no number holds.
  for (char c : {'\t', ';'}) {
    if (!d.delimiter && first_data.find(c) != std::string_view::npos) d.delimiter = c;
  }
  if (!d.delimiter && first_data.find_first_of("\t;") == std::string_view::npos) {
    // Runs of spaces: two or more numbers on the first row so separated.
    const std::string_view row = trim_spaces(first_data);
    if (row.find(' ') != std::string_view::npos) d.delimiter = ' ';
  }
  d.decimal_comma = d.delimiter != ',' && first_data.find(',') != std::string_view::npos;
  return d;
}

std::size_t filled_cells(const std::vector<std::string_view>& cells) {
  std::size_t n = cells.size();
  while (n > 1 && cells[n - 1].empty()) --n;
  return n;
}

std::vector<std::string_view> split_cells_within(std::string_view line, const Dialect& dialect,
                                                 const InputLimits& limits, const std::string& file,
                                                 std::size_t line_no) {
  std::vector<std::string_view> cells = split_cells(line, dialect, limits.columns);
  if (cells.size() > limits.columns) {
    // Empty cells to the end (a spreadsheet's trailing delimiters) are no
    // columns: the line is read up to them. Else refused at the first cell
    // past the limit.
    const auto past = static_cast<std::size_t>(cells[limits.columns].data() - line.data());
    if (line.find_first_not_of(std::string{dialect.delimiter, ' ', '"', '\r'}, past) == std::string_view::npos) {
      cells.resize(limits.columns);
      return cells;
    }
    fail(file, line_no, past + 1, over_limit(limits, Limit::columns));
  }
  return cells;
}

std::vector<std::string_view> split_cells(std::string_view line, const Dialect& dialect, std::size_t most) {
  std::vector<std::string_view> out;
  if (dialect.delimiter == ' ') {
    line = trim_spaces(line);
    for (std::size_t start = 0; start < line.size() && out.size() <= most;) {
      std::size_t stop = start;
      if (line[start] == '"') {
        const std::size_t close = line.find('"', start + 1);
        stop = close == std::string_view::npos ? line.size() : close + 1;
      }
      stop = std::min(line.find(' ', stop), line.size());
      const std::string_view cell = trim_cell(line.substr(start, stop - start));
      // "Time (s)" written with spaces: the unit joins its word.
      if (!out.empty() && (starts_with(cell, "(") || starts_with(cell, "["))) {
        const char* first = out.back().data();
        out.back() = std::string_view(first, static_cast<std::size_t>(cell.data() + cell.size() - first));
      } else {
        out.push_back(cell);
      }
      start = stop;
      while (start < line.size() && line[start] == ' ') ++start;
    }
    if (out.empty()) out.emplace_back();
    return out;
  }
  for (std::size_t start = 0;;) {
    std::size_t d = std::string_view::npos;
    if (dialect.delimiter) {
      // A quoted cell may hold the delimiter ("Time, s").
      std::size_t from = start;
      while (from < line.size() && line[from] == ' ') ++from;
      if (from < line.size() && line[from] == '"') {
        const std::size_t close = line.find('"', from + 1);
        from = close == std::string_view::npos ? line.size() : close;
      }
      d = line.find(dialect.delimiter, from);
    }
    out.push_back(trim_cell(line.substr(start, d == std::string_view::npos ? d : d - start)));
    if (d == std::string_view::npos || out.size() > most) return out;
    start = d + 1;
  }
}

// --- words ------------------------------------------------------------------

const char* role_name(Role role) {
  switch (role) {
    case Role::time: return "time";
    case Role::rate: return "angular rate";
    case Role::acceleration: return "acceleration";
    case Role::linear_acceleration: return "linear acceleration";
    case Role::angle: return "angle";
    case Role::omega: return "angular velocity";
    case Role::x: return "x";
    case Role::y: return "y";
    case Role::state: return "gate state";
    case Role::period: return "period";
    case Role::counter: return "counter";
    case Role::uncertainty: return "uncertainty";
    case Role::derivative: return "track derivative";
    case Role::length: return "length";
    case Role::pivot_distance: return "pivot distance";
    case Role::pivot_position: return "pivot position";
    case Role::rod_length: return "rod length";
    case Role::amplitude: return "amplitude";
    case Role::other: return "unknown";
  }
  return "";
}

namespace {

/// The words exporters write for each role, lower case, without their unit,
/// prefix or suffix (classify). A new exporter's spelling is one line here.
/// `axis`: the word is followed by " x", " y" or " z" (phyphox).
struct Spelling {
  const char* word;
  Role role;
  bool axis = false;
};
const Spelling kSpellings[] = {
    {"time", Role::time},  // phyphox, Vernier, PASCO, Logger Pro, OpenCV scripts
    {"t", Role::time},     // Tracker
    {"elapsed time", Role::time},
    {"timestamp", Role::time},
    {"tempo", Role::time},   // Portuguese, Italian
    {"tiempo", Role::time},  // Spanish
    {"tijd", Role::time},    // Dutch
    {"zeit", Role::time},    // German
    {"temps", Role::time},   // French
    {"hoek", Role::angle},   // Dutch
    {"winkel", Role::angle},  // German
    {"\xc3\xa2ngulo", Role::angle},  // ângulo, Portuguese
    {"angulo", Role::angle},  // Spanish, Portuguese without the accent
    {"\xc3\xa1ngulo", Role::angle},  // ángulo, Spanish
    {"gyroscope", Role::rate, true},            // phyphox's Gyroscope
    {"rotation", Role::rate, true},             // phyphox's Pendulum experiment (raw data)
    {"linear acceleration", Role::linear_acceleration, true},  // phyphox
    {"acceleration", Role::acceleration, true},  // phyphox's Acceleration with g
    {"angle", Role::angle},                      // PASCO, OpenCV scripts, Logger Pro
    {"angular position", Role::angle},
    {"theta", Role::angle},
    {"\xce\xb8", Role::angle},  // θ (Tracker)
    {"\xce\x98", Role::angle},  // Θ
    {"angular velocity", Role::omega},  // PASCO
    {"omega", Role::omega},
    {"\xcf\x89", Role::omega},  // ω (Tracker)
    {"\xce\xa9", Role::omega},  // Ω
    {"x", Role::x},  // Tracker, Logger Pro's video analysis
    {"x position", Role::x},
    {"position x", Role::x},
    {"y", Role::y},
    {"y position", Role::y},
    {"position y", Role::y},
    {"gatestate", Role::state},  // Vernier
    {"gate state", Role::state},
    {"state", Role::state},  // PASCO
    // A light sensor under the swing: a gate whose beam is the light, dark while the bob passes.
    {"light intensity", Role::state},  // PASCO's light sensor
    {"light", Role::state},
    {"illuminance", Role::state},
    {"lichtintensit\xc3\xa4t", Role::state},  // Lichtintensität
    {"period", Role::period},  // Vernier's pendulum timing
    {"n", Role::counter},  // timers
    {"count", Role::counter},
    {"counter", Role::counter},
    {"index", Role::counter},
    {"event", Role::counter},
    {"#", Role::counter},
    {"no.", Role::counter},
    {"frame", Role::counter},
    {"sample", Role::counter},
    {"error", Role::uncertainty},
    {"uncertainty", Role::uncertainty},
    {"sigma", Role::uncertainty},
    {"\xcf\x83", Role::uncertainty},  // σ
    {"dt", Role::uncertainty},
    {"dx", Role::uncertainty},
    {"dy", Role::uncertainty},
    {"d\xce\xb8", Role::uncertainty},  // dθ
    {"\xce\xb4\xce\xb8", Role::uncertainty},  // δθ
    {"vx", Role::derivative},  // Tracker's velocity and acceleration
    {"vy", Role::derivative},
    {"v", Role::derivative},
    {"ax", Role::derivative},
    {"ay", Role::derivative},
    {"a", Role::derivative},
    {"velocity", Role::derivative},
    {"speed", Role::derivative},
    {"p", Role::derivative},  // Tracker's momentum
    {"px", Role::derivative},
    {"py", Role::derivative},
    {"\xce\xb1", Role::derivative},  // α, Tracker's angular acceleration
    // Tables of settings and periods (table.cpp; docs/series.md, "Tables").
    {"l", Role::length},
    {"length", Role::length},
    {"pendulum length", Role::length},
    {"string length", Role::length},
    {"h", Role::pivot_distance},
    {"pivot distance", Role::pivot_distance},
    {"distance", Role::pivot_distance},
    {"pivot position", Role::pivot_position},
    {"pivot", Role::pivot_position},
    {"position", Role::pivot_position},
    {"hole", Role::pivot_position},
    {"rod length", Role::rod_length},
    {"beam length", Role::rod_length},
    {"rod_length", Role::rod_length},
    {"l_rod", Role::rod_length},  // the output's heading, L_rod (m)
    {"amplitude", Role::amplitude},
    {"theta0", Role::amplitude},
    {"\xce\xb8" "0", Role::amplitude},  // θ0
    // The same in Dutch and German lab tables.
    {"lengte", Role::length},
    {"l\xc3\xa4nge", Role::length},  // länge
    {"laenge", Role::length},
    {"tijd", Role::time},
    {"zeit", Role::time},
    {"periode", Role::period},
    {"trillingstijd", Role::period},
    {"periodendauer", Role::period},
    {"hoek", Role::angle},
    {"winkel", Role::angle},
};

/// Unit spellings, lower case, and their normal form.
const std::pair<const char*, const char*> kUnits[] = {
    {"s", "s"},          {"sec", "s"},          {"second", "s"},        {"seconds", "s"},
    {"ms", "ms"},        {"us", "us"},          {"\xc2\xb5s", "us"},    {"\xce\xbcs", "us"},  // µs, μs
    {"deg", "deg"},      {"degree", "deg"},     {"degrees", "deg"},     {"\xc2\xb0", "deg"},  // °
    {"rad", "rad"},      {"radian", "rad"},     {"radians", "rad"},
    // Degrees as German, Dutch, Spanish and Portuguese write them (a gradian is "gon" there).
    {"grad", "deg"},     {"graden", "deg"},     {"grados", "deg"},      {"graus", "deg"},
    {"rad/s", "rad/s"},  {"deg/s", "deg/s"},    {"\xc2\xb0/s", "deg/s"}, {"degrees/s", "deg/s"},
    {"m", "m"},          {"cm", "cm"},          {"mm", "mm"},           {"px", "px"},
    {"pixel", "px"},     {"pixels", "px"},      {"m/s^2", "m/s^2"},     {"m/s\xc2\xb2", "m/s^2"},  // m/s²
};

}  // namespace

std::string normal_unit(std::string_view unit) {
  const std::string u = lower_case(trim_spaces(unit));
  for (const auto& [spelt, normal] : kUnits) {
    if (u == spelt) return normal;
  }
  return u;
}

bool known_unit(std::string_view unit) {
  const std::string u = lower_case(trim_spaces(unit));
  return std::any_of(std::begin(kUnits), std::end(kUnits), [&](const auto& k) { return u == k.first; });
}

std::optional<double> time_scale(const std::string& unit) {
  if (unit.empty() || unit == "s") return 1.0;
  if (unit == "ms") return 1e-3;
  if (unit == "us") return 1e-6;
  return std::nullopt;
}

std::optional<double> time_scale(const Column& c) {
  if (c.frame_rate > 0.0) return 1.0 / c.frame_rate;
  return time_scale(c.unit);
}

Column classify(std::string_view raw) {
  Column c;
  c.name = to_utf8(trim_cell(raw));
  std::string s = lower_case(c.name);
  // A line break within a quoted cell ("time\r\n(s)") is a space between its words.
  std::size_t kept = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\r' && i + 1 < s.size() && s[i + 1] == '\n') continue;
    s[kept++] = s[i] == '\r' || s[i] == '\n' ? ' ' : s[i];
  }
  s.resize(kept);
  // A header written as a comment ("# winkel in grad"): its words after the mark ("#" alone is a counter's).
  if (s.size() > 1 && s.front() == '#' && s.find_first_not_of("# ") != std::string::npos &&
      std::isalpha(static_cast<unsigned char>(s[s.find_first_not_of("# ")]))) {
    s.erase(0, s.find_first_not_of("# "));
  }
  if (const auto pos = s.find(" run #"); pos != std::string::npos) {
    c.run = std::atoi(s.c_str() + pos + 6);
    s.erase(pos);
  }
  // "Latest: ", "Run 1: " (Vernier), "VideoAnalysis: " (Logger Pro).
  if (const auto colon = s.find(": "); colon != std::string::npos && colon > 0 && colon < 40) {
    c.prefixed = true;
    s.erase(0, colon + 2);
  }
  const auto unit_in = [&](char open, char close) {
    const auto at = s.rfind(open);
    if (at == std::string::npos) return false;
    const auto end = s.find(close, at);
    c.unit = s.substr(at + 1, end == std::string::npos ? std::string::npos : end - at - 1);
    s.erase(at);
    return true;
  };
  if (!unit_in('(', ')') && !unit_in('[', ']')) {
    if (const auto comma = s.rfind(','); comma != std::string::npos) {
      c.unit = s.substr(comma + 1);
      s.erase(comma);
    } else if (const auto slash = s.find('/'); slash != std::string::npos && slash > 0 && known_unit(s.substr(slash + 1))) {
      // "Time/s", "AngVel/rad/s": the quantity over its unit, as ISO 80000 writes a table's heading.
      c.unit = s.substr(slash + 1);
      s.erase(slash);
    } else if (const auto in = s.find(" in "); in != std::string::npos && in > 0) {
      // "t in s", "winkel in grad", "t in s  5 Perioden": the unit after "in", the words around it kept.
      const std::size_t from = in + 4, to = std::min(s.find(' ', from), s.size());
      if (known_unit(s.substr(from, to - from))) {
        c.unit = s.substr(from, to - from);
        s = s.substr(0, in) + s.substr(to);
      }
    }
  }
  c.unit = normal_unit(c.unit);
  std::string_view w = trim_spaces(s);
  c.word = std::string(w);
  // "t_{1}", "x_1": a tracker's numbered object.
  if (const auto u = w.rfind('_'); u != std::string_view::npos && u > 0) {
    std::string_view tail = w.substr(u + 1);
    if (!tail.empty() && tail.front() == '{' && tail.back() == '}') tail = tail.substr(1, tail.size() - 2);
    if (!tail.empty() && std::all_of(tail.begin(), tail.end(), [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)); })) {
      w = trim_spaces(w.substr(0, u));
    }
  }
  const bool prime = strip_primes(w);
  for (const Spelling& sp : kSpellings) {
    const std::size_t n = std::strlen(sp.word);
    const bool match = sp.axis ? w.size() == n + 2 && starts_with(w, sp.word) && w[n] == ' ' &&
                                     (w.back() == 'x' || w.back() == 'y' || w.back() == 'z')
                               : w == sp.word;
    if (match) {
      c.role = prime ? Role::derivative : sp.role;
      c.known = true;
      break;
    }
  }
  return c;
}

namespace {

/// "30fps" (any case, spaces allowed) as 30; 0 for anything else.
double frame_rate(const std::string& text) {
  const std::string rate = lower_case(trim_spaces(text));
  if (rate.size() < 4 || rate.compare(rate.size() - 3, 3, "fps") != 0) return 0.0;
  const std::string number(trim_spaces(std::string_view(rate).substr(0, rate.size() - 3)));
  const double f = decimal_number(number).value_or(0.0);
  return std::isfinite(f) && f > 0.0 && f <= 1e6 ? f : 0.0;
}

}  // namespace

std::vector<std::optional<Column>> parse_column_spec(const std::string& spec, const std::string& where) {
  struct Name {
    const char* word;
    Role role;
  };
  static const Name kNames[] = {{"t", Role::time},        {"time", Role::time},      {"theta", Role::angle},
                                {"angle", Role::angle},   {"omega", Role::omega},    {"x", Role::x},
                                {"y", Role::y},           {"n", Role::counter},      {"count", Role::counter},
                                {"state", Role::state},   {"period", Role::period},  {"gyro", Role::rate},
                                {"a", Role::acceleration}, {"linear_a", Role::linear_acceleration},
                                {"frame", Role::time}};
  std::vector<std::optional<Column>> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = spec.find(',', start);
    const std::string entry(trim_spaces(std::string_view(spec).substr(start, comma == std::string::npos ? comma : comma - start)));
    if (entry.empty() || entry == "-") {
      out.emplace_back();
    } else {
      const std::size_t colon = entry.find(':');
      const std::string word = lower_case(entry.substr(0, colon));
      const std::string unit = colon == std::string::npos ? std::string() : normal_unit(entry.substr(colon + 1));
      const Name* name = std::find_if(std::begin(kNames), std::end(kNames), [&](const Name& n) { return word == n.word; });
      if (name == std::end(kNames)) {
        throw InputError(where, "got the column \"" + one_line(entry, 40) +
                                    "\"; expected a role: t (time), frame (frame numbers: frame:30fps), theta (angle), "
                                    "omega, x, y, n (counter), state, period, gyro, a, linear_a, or - for a column not used");
      }
      Column c;
      c.role = name->role;
      c.known = true;
      c.unit = unit;
      c.decided = "option";
      if (word == "frame") {
        c.frame_rate = frame_rate(colon == std::string::npos ? std::string() : entry.substr(colon + 1));
        c.unit = "frame";
        if (!(c.frame_rate > 0.0)) {
          throw InputError(where, "got the column \"" + one_line(entry, 40) +
                                      "\"; expected frame numbers with their frame rate, e.g. \"frame:30fps\"");
        }
      }
      const bool fits = unit.empty() || c.frame_rate > 0.0 ||
                        (c.role == Role::time || c.role == Role::period ? time_scale(unit).has_value()
                         : c.role == Role::angle                        ? unit == "deg" || unit == "rad"
                         : c.role == Role::omega || c.role == Role::rate ? unit == "rad/s" || unit == "deg/s"
                         : c.role == Role::x || c.role == Role::y         ? unit == "m" || unit == "cm" || unit == "mm" || unit == "px"
                                                                           : false);
      if (!fits) {
        throw InputError(where, "got the unit \"" + one_line(entry.substr(colon + 1), 20) + "\" for " + role_name(c.role) +
                                    "; expected " +
                                    (c.role == Role::time || c.role == Role::period ? "s, ms or us"
                                     : c.role == Role::angle                        ? "deg or rad"
                                     : c.role == Role::omega || c.role == Role::rate ? "rad/s or deg/s"
                                     : c.role == Role::x || c.role == Role::y         ? "m, cm, mm or px"
                                                                                       : "no unit"));
      }
      out.push_back(c);
    }
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

// --- content ----------------------------------------------------------------

ColumnFacts examine(const std::vector<double>& column, bool range) {
  ColumnFacts f;
  std::vector<double> values;
  if (range) values.reserve(column.size());
  std::size_t steps = 0, unit_steps = 0, decreases = 0, bad_steps = 0, votes = 0;
  double last = std::numeric_limits<double>::quiet_NaN(), candidate = 0.0;  // the majority step (Boyer-Moore)
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : column) {
    if (!std::isfinite(v)) continue;
    if (range) values.push_back(v);
    ++f.finite;
    lo = std::min(lo, v), hi = std::max(hi, v);
    f.integers &= v == std::floor(v);
    if (!std::isnan(last)) {
      ++steps;
      const double d = v - last;
      unit_steps += d == 1.0;
      if (votes == 0) candidate = d;
      if (d == candidate) {
        ++votes;
      } else {
        --votes;
      }
      decreases += d < 0.0;
      bad_steps += !(d >= 1.0 && d == std::floor(d));
    }
    last = v;
  }
  if (f.finite == 0) return f;
  f.constant = lo == hi;
  // A few glitches (a missed or doubled stamp, an out-of-order sample) leave a counter or a clock what it is.
  const std::size_t few = steps / 100;
  f.counter = f.integers && steps > 0 && bad_steps <= few && unit_steps * 10 >= steps * 9;
  f.increasing = !f.constant && decreases <= few;
  const std::size_t typos = std::max<std::size_t>(2, steps / 10);  // one typed count moves two steps
  if (f.integers && candidate >= 1.0 && bad_steps <= typos) {
    // The majority step, where all steps but one typo's two (or 10 %) are it.
    std::size_t agree = 0;
    last = std::numeric_limits<double>::quiet_NaN();
    for (double v : column) {
      if (!std::isfinite(v)) continue;
      if (!std::isnan(last)) agree += v - last == candidate;
      last = v;
    }
    if (2 * agree > steps && agree + typos >= steps) f.stride = candidate;
  }
  if (!range) return f;
  f.ranged = true;
  const std::size_t k = values.size() / 200;
  std::nth_element(values.begin(), values.begin() + k, values.end());
  f.lo = values[k];
  std::nth_element(values.begin(), values.end() - 1 - k, values.end());
  f.hi = values[values.size() - 1 - k];
  return f;
}

std::pair<std::string, std::string> unitless_angle(const ColumnFacts& facts) {
  const double a = facts.half_range();
  if (a > kPi / 2.0) {
    return {"deg", "swings by +-" + format_number(a, 3) + ", over 90 deg if radians: read as degrees"};
  }
  return {"rad", "swings by +-" + format_number(a, 3) + ", " + format_number(degrees(a), 3) +
                     " deg if radians: read as radians (if it is degrees, say so with --columns or \"columns\")"};
}

double rough_period(const std::vector<double>& time, const std::vector<double>& signal) {
  // The middle and the half range from at most 4096 samples evenly spread.
  const std::size_t stride = std::max<std::size_t>(1, signal.size() / 4096);
  std::vector<double> some;
  for (std::size_t k = 0; k < signal.size(); k += stride) {
    if (std::isfinite(signal[k])) some.push_back(signal[k]);
  }
  if (some.size() < 8) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t q = some.size() / 20;
  std::nth_element(some.begin(), some.begin() + q, some.end());
  const double lo = some[q];
  std::nth_element(some.begin(), some.end() - 1 - q, some.end());
  const double hi = some[some.size() - 1 - q];
  const double middle = 0.5 * (lo + hi), h = (hi - lo) / 6.0;
  int side = 0, crossings = 0;
  double first = 0.0, last = 0.0;
  for (std::size_t k = 0; k < signal.size() && k < time.size(); ++k) {
    const int now = signal[k] > middle + h ? 1 : signal[k] < middle - h ? -1 : 0;
    if (now == 0 || now == side || !std::isfinite(time[k])) continue;
    if (side != 0) (crossings++ == 0 ? first : last) = time[k];
    side = now;
  }
  return crossings >= 3 ? 2.0 * (last - first) / (crossings - 1) : std::numeric_limits<double>::quiet_NaN();
}

double median_step(const std::vector<double>& time) {
  std::vector<double> steps;
  for (std::size_t k = 1; k < time.size(); ++k) {
    if (std::isfinite(time[k] - time[k - 1]) && time[k] > time[k - 1]) steps.push_back(time[k] - time[k - 1]);
  }
  if (steps.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
  return steps[steps.size() / 2];
}

std::pair<std::string, std::string> unitless_time(double period) {
  // A period of 60 s is a pendulum 900 m long: none a student times.
  constexpr double kShortest = 0.02, kLongest = 60.0;
  if (!(period > kLongest)) return {"s", "no unit given, read as seconds"};
  for (auto [unit, scale] : {std::pair{"ms", 1e-3}, {"us", 1e-6}}) {
    if (period * scale >= kShortest && period * scale <= kLongest) {
      const double km = length_for_period(period, kStandardGravity) / 1000.0;
      return {unit, std::string("no unit given, read as ") + (scale == 1e-3 ? "milliseconds" : "microseconds") +
                        ": as seconds its swing would take " + format_number(std::round(period), 12) +
                        " s (a pendulum " + format_number(std::round(km), 12) + " km long), as " + unit + " " +
                        format_number(period * scale, 3) +
                        " s (if it is seconds, say so with --columns or \"columns\", e.g. \"t:s,...\")"};
    }
  }
  return {"s", "no unit given, read as seconds"};
}

bool angle_by_numbers(const ColumnFacts& facts) { return !facts.integers && facts.half_range() <= 180.0; }

std::string not_an_angle_why(const ColumnFacts& facts) {
  return (facts.integers ? std::string("whole numbers only (a sensor's raw counts?)")
                         : "swings by +-" + format_number(facts.half_range(), 3) + ", over 180 deg as degrees") +
         ": no angle, so it times the swing without measuring it (if it is an angle, say so with --columns or "
         "\"columns\", e.g. \"t:s,theta:deg\")";
}

bool is_rate_of(const std::vector<double>& t, const std::vector<double>& a, const std::vector<double>& b) {
  double n = 0.0, su = 0.0, sv = 0.0, suu = 0.0, svv = 0.0, suv = 0.0;
  for (std::size_t k = 1; k + 1 < t.size(); ++k) {
    const double dt = t[k + 1] - t[k - 1];
    const double u = (a[k + 1] - a[k - 1]) / dt, v = b[k];
    if (!(dt > 0.0) || !std::isfinite(u) || !std::isfinite(v)) continue;
    n += 1.0, su += u, sv += v, suu += u * u, svv += v * v, suv += u * v;
  }
  if (n < 8.0) return false;
  const double cuu = suu - su * su / n, cvv = svv - sv * sv / n, cuv = suv - su * sv / n;
  return cuu > 0.0 && cvv > 0.0 && std::fabs(cuv) / std::sqrt(cuu * cvv) > 0.9;
}

bool could_be_track_y(const std::vector<double>& t, const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = std::min({t.size(), x.size(), y.size()});
  if (n < 16) return true;
  struct Sample {
    double x, rate, y;
  };
  std::vector<Sample> at;
  const std::size_t stride = std::max<std::size_t>(1, n / 65536);
  for (std::size_t k = 1; k + 1 < n; k += stride) {
    const Sample v{x[k], (x[k + 1] - x[k - 1]) / (t[k + 1] - t[k - 1]), y[k]};
    if (std::isfinite(v.x) && std::isfinite(v.rate) && std::isfinite(v.y)) at.push_back(v);
  }
  if (at.size() < 16) return true;
  double mean = 0.0, spread = 0.0, rate_spread = 0.0, y_mean = 0.0, lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const Sample& v : at) mean += v.x / at.size(), y_mean += v.y / at.size(), lo = std::min(lo, v.y), hi = std::max(hi, v.y);
  for (const Sample& v : at) spread = std::max(spread, std::fabs(v.x - mean)), rate_spread = std::max(rate_spread, std::fabs(v.rate));
  if (!(spread > 0.0) || !(rate_spread > 0.0)) return true;
  // Scaled to [-1, 1], so that the normal equations stay well conditioned.
  using Row = Eigen::Matrix<double, 6, 1>;
  const auto row = [&](const Sample& v) {
    const double u = (v.x - mean) / spread;
    return Row(1.0, u, u * u, u * u * u, u * u * u * u, v.rate / rate_spread);
  };
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  Row right = Row::Zero();
  double yy = 0.0;
  for (const Sample& v : at) {
    const Row r = row(v);
    normal += r * r.transpose(), right += r * v.y, yy += (v.y - y_mean) * (v.y - y_mean);
  }
  // The sums of squares left by the polynomial alone and with the rate.
  const auto ssr = [&](int terms) {
    const Eigen::VectorXd c = normal.topLeftCorner(terms, terms).ldlt().solve(right.head(terms));
    double s = 0.0;
    for (const Sample& v : at) s += std::pow(v.y - row(v).head(terms).dot(c), 2);
    return s;
  };
  // The quarter-period part: its share of y's variance, and its amplitude
  // against x's (a track's x and y share a unit; an elliptical swing seen
  // from above puts a few per cent of x's amplitude into y's quadrature,
  // itself most of a small y's variance).
  const double quadrature = ssr(5) - ssr(6);
  const double amplitude = std::sqrt(2.0 * quadrature / at.size()), y_half = 0.5 * (hi - lo);
  return !(quadrature > 0.25 * yy && (amplitude > 0.25 * spread || y_half > spread));
}

}  // namespace pendulum::recording_text
