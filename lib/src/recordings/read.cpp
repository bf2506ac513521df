#include "pendulum/recordings/read.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>

#include "pendulum/input_error.hpp"
#include "../text.hpp"
#include "huge_pages.hpp"
#include "../io/mapped_file.hpp"
#include "zip.hpp"

namespace pendulum {

const char* recording_format_name(RecordingFormat format) {
  switch (format) {
    case RecordingFormat::automatic: return "auto";
    case RecordingFormat::phyphox: return "phyphox";
    case RecordingFormat::vernier: return "vernier";
    case RecordingFormat::pasco: return "pasco";
    case RecordingFormat::plain: return "plain";
    case RecordingFormat::tracker: return "tracker";
  }
  return "";
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Messages quote the file's own text (header cells, names): one line.
[[noreturn]] void fail(const std::string& file, std::size_t line, std::size_t column,
                       const std::string& message) {
  throw InputError(file + ":" + std::to_string(line) + ":" + std::to_string(column), one_line(message, 800, true));
}

/// What a header cell names.
enum class Role { time, rate, acceleration, linear_acceleration, angle, omega, x, y, state, period, other };

struct Column {
  std::string name;  ///< as in the file, quotes removed
  Role role = Role::other;
  std::string unit;  ///< text in the last parentheses, lower case
  int run = 0;       ///< PASCO's "Run #n", else 0
  int track = 0;     ///< Tracker's track in an export of several (1, 2, ... by the names above the header), else 0
  bool prefixed = false;  ///< Vernier's "Latest: " or "Run 1: "
};

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\r' || s.front() == '"')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r' || s.back() == '"')) s.remove_suffix(1);
  return s;
}

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

Column classify(std::string_view raw) {
  Column c;
  c.name = std::string(trim(raw));
  std::string s = lower(c.name);
  if (const auto pos = s.find(" run #"); pos != std::string::npos) {
    c.run = std::atoi(s.c_str() + pos + 6);
    s.erase(pos);
  }
  if (const auto colon = s.find(": "); colon != std::string::npos &&
      (starts_with(s, "latest") || starts_with(s, "run "))) {
    c.prefixed = true;
    s.erase(0, colon + 2);
  }
  if (const auto open = s.rfind('('); open != std::string::npos) {
    const auto close = s.find(')', open);
    c.unit = s.substr(open + 1, close == std::string::npos ? std::string::npos : close - open - 1);
    s.erase(open);
  }
  while (!s.empty() && s.back() == ' ') s.pop_back();
  auto axis = [&](std::string_view stem) {
    return s.size() == stem.size() + 2 && starts_with(s, stem) && s[stem.size()] == ' ' &&
           (s.back() == 'x' || s.back() == 'y' || s.back() == 'z');
  };
  if (s == "time" || s == "t") c.role = Role::time;
  else if (axis("gyroscope") || axis("rotation")) c.role = Role::rate;
  else if (axis("linear acceleration")) c.role = Role::linear_acceleration;
  else if (axis("acceleration")) c.role = Role::acceleration;
  else if (s == "angle" || s == "theta" || s == "\xce\xb8") c.role = Role::angle;  // θ
  else if (s == "angular velocity" || s == "omega" || s == "\xcf\x89") c.role = Role::omega;  // ω
  else if (s == "x") c.role = Role::x;
  else if (s == "y") c.role = Role::y;
  else if (s == "gatestate" || s == "gate state" || s == "state") c.role = Role::state;
  else if (s == "period") c.role = Role::period;
  return c;
}

/// Which columns hold what, and their scale to SI.
struct Layout {
  RecordingFormat format = RecordingFormat::automatic;
  SignalKind kind = SignalKind::angular_rate;
  std::size_t time = 0;
  std::vector<std::size_t> channels;
  std::optional<std::size_t> period;
  double time_scale = 1.0;
  double channel_scale = 1.0;
  bool angle_unit_unknown = false;
};

std::optional<double> time_scale(const std::string& unit) {
  if (unit.empty() || unit == "s") return 1.0;
  if (unit == "ms") return 1e-3;
  if (unit == "us" || unit == "\xc2\xb5s" || unit == "\xce\xbcs") return 1e-6;  // µs, μs
  return std::nullopt;
}

/// The first column of `role`, of PASCO run `run` and Tracker track `track` (-1: any).
std::optional<std::size_t> find(const std::vector<Column>& cols, Role role, int run = -1, int track = -1) {
  for (std::size_t j = 0; j < cols.size(); ++j) {
    if (cols[j].role == role && (run < 0 || cols[j].run == run) && (track < 0 || cols[j].track == track)) return j;
  }
  return std::nullopt;
}

std::vector<std::size_t> find_all(const std::vector<Column>& cols, Role role) {
  std::vector<std::size_t> out;
  for (std::size_t j = 0; j < cols.size(); ++j) {
    if (cols[j].role == role) out.push_back(j);
  }
  return out;
}

/// The layout of `format` for these columns, or nullopt if they do not fit it.
std::optional<Layout> layout_for(RecordingFormat format, const std::vector<Column>& cols, bool preamble, int run,
                                 int track) {
  Layout l;
  l.format = format;
  auto angle_scale = [&](const Column& c) {
    if (c.unit == "rad") return 1.0;
    if (c.unit == "deg" || c.unit == "\xc2\xb0") return 3.14159265358979323846 / 180.0;  // °
    l.angle_unit_unknown = true;
    return 1.0;
  };
  switch (format) {
    case RecordingFormat::phyphox: {
      if (cols.empty() || cols[0].role != Role::time || cols[0].unit != "s") return std::nullopt;
      for (auto [role, kind] : {std::pair{Role::rate, SignalKind::angular_rate},
                                {Role::linear_acceleration, SignalKind::linear_acceleration},
                                {Role::acceleration, SignalKind::acceleration}}) {
        l.channels = find_all(cols, role);
        l.kind = kind;
        if (!l.channels.empty()) return l;
      }
      return std::nullopt;
    }
    case RecordingFormat::vernier: {
      const auto t = find(cols, Role::time);
      const auto s = find(cols, Role::state);
      if (!t || !s) return std::nullopt;
      l.time = *t;
      l.channels = {*s};
      l.kind = SignalKind::gate_states;
      l.period = find(cols, Role::period);
      const auto scale = time_scale(cols[*t].unit);
      if (!scale) return std::nullopt;
      l.time_scale = *scale;
      return l;
    }
    case RecordingFormat::pasco: {
      const auto t = find(cols, Role::time, run);
      if (!t) return std::nullopt;
      l.time = *t;
      l.time_scale = time_scale(cols[*t].unit).value_or(1.0);
      if (const auto a = find(cols, Role::angle, run)) {
        l.kind = SignalKind::angle;
        l.channels = {*a};
        l.channel_scale = angle_scale(cols[*a]);
      } else if (const auto w = find(cols, Role::omega, run)) {
        l.kind = SignalKind::angular_rate;
        l.channels = {*w};
        l.channel_scale = cols[*w].unit.find("deg") != std::string::npos || cols[*w].unit[0] == '\xc2'
                              ? 3.14159265358979323846 / 180.0 : 1.0;
      } else if (const auto s = find(cols, Role::state, run)) {
        l.kind = SignalKind::gate_states;
        l.channels = {*s};
        l.period = find(cols, Role::period, run);
      } else {
        return std::nullopt;
      }
      return l;
    }
    case RecordingFormat::tracker: {
      const auto t = find(cols, Role::time);
      if (!t || (!preamble && cols[*t].name != "t")) return std::nullopt;
      l.time = *t;
      if (const auto a = find(cols, Role::angle, -1, track)) {
        l.kind = SignalKind::angle;
        l.channels = {*a};
        l.channel_scale = angle_scale(cols[*a]);
      } else if (const auto w = find(cols, Role::omega, -1, track)) {
        l.kind = SignalKind::angular_rate;
        l.channels = {*w};
      } else if (const auto x = find(cols, Role::x, -1, track), y = find(cols, Role::y, -1, track); x && y) {
        l.kind = SignalKind::position;
        l.channels = {*x, *y};
      } else {
        return std::nullopt;
      }
      return l;
    }
    case RecordingFormat::plain: {
      const auto scale = time_scale(cols.empty() ? std::string() : cols[0].unit);
      if (!scale) return std::nullopt;
      l.kind = SignalKind::blocking_times;
      l.time_scale = *scale;
      return l;
    }
    case RecordingFormat::automatic: break;
  }
  return std::nullopt;
}

Layout detect(RecordingFormat forced, const std::vector<Column>& cols, bool preamble, bool has_header,
              const std::string& file, std::size_t header_line, int run, int track) {
  if (forced != RecordingFormat::automatic) {
    if (auto l = layout_for(forced, cols, preamble, run, track)) return *l;
    fail(file, header_line, 1,
         std::string("the header does not fit a ") + recording_format_name(forced) +
             " export (docs/recordings.md lists the columns each format needs)");
  }
  // The first family whose columns the header has; the most specific first
  // (a PASCO gate file also has what a Vernier one needs).
  if (!has_header || cols.size() == 1) {
    if (auto l = layout_for(RecordingFormat::plain, cols, preamble, run, track)) return *l;
  } else {
    for (auto family : {RecordingFormat::pasco, RecordingFormat::vernier, RecordingFormat::tracker,
                        RecordingFormat::phyphox}) {
      if (auto l = layout_for(family, cols, preamble, run, track)) return *l;
    }
  }
  std::string names;
  for (const auto& c : cols) {
    if (names.size() < 300) names += (names.empty() ? "\"" : ", \"") + one_line(c.name, 40, true) + "\"";
  }
  fail(file, header_line, 1,
       "unrecognised header " + names +
           "; expected a phyphox, Vernier, PASCO or Tracker export or one column of blocking "
           "times (docs/recordings.md), or name the format with --format");
}

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

/// Throws, naming its line and column, if [text, text + size) holds a NUL byte.
void refuse_binary(std::string_view text, std::size_t size, const std::string& file) {
  if (const void* nul = std::memchr(text.data(), '\0', size)) {
    const std::size_t at = static_cast<const char*>(nul) - text.data();
    const std::size_t line = 1 + std::count(text.data(), text.data() + at, '\n');
    const std::size_t bol = text.substr(0, at).rfind('\n');
    fail(file, line, at - (bol == std::string_view::npos ? 0 : bol + 1) + 1,
         "a NUL byte: this is a binary file, not a text export");
  }
}

Recording parse_text(std::string_view text, const std::string& file, RecordingFormat format, const std::string& set);

}  // namespace

Recording parse_recording(std::string_view text, const std::string& file, RecordingFormat format,
                          const std::string& set) {
  if (looks_like_zip(text)) {
    fail(file, 1, 1, "a zip archive; expected a text export here (a zip is unpacked when read from its file: read_recording)");
  }
  // A binary file is named as such wherever its NUL byte is. parse_text
  // checks the lines before the data; in the data a NUL fits no cell, so the
  // rows refuse it, and the text is searched for it only then (a search of
  // the whole text up front took 3 % of reading a large file).
  try {
    return parse_text(text, file, format, set);
  } catch (const InputError&) {
    refuse_binary(text, text.size(), file);
    throw;
  }
}

namespace {

Recording parse_text(std::string_view text, const std::string& file, RecordingFormat format, const std::string& set) {
  const std::string_view original = text;
  if (starts_with(text, "\xef\xbb\xbf")) text.remove_prefix(3);  // UTF-8 byte-order mark

  const char* const begin = text.data();
  const char* const end = begin + text.size();
  // Lines: [p, eol), eol at '\n' or end.
  auto line_end = [&](const char* p) {
    const void* nl = std::memchr(p, '\n', end - p);
    return nl ? static_cast<const char*>(nl) : end;
  };
  auto is_blank = [](const char* p, const char* e) {
    for (; p < e; ++p) {
      if (*p != ' ' && *p != '\t' && *p != '\r' && *p != ',' && *p != ';') return false;
    }
    return true;
  };
  // A line is data when its first cell starts like a number.
  auto is_data = [](const char* p, const char* e) {
    while (p < e && (*p == ' ' || *p == '"')) ++p;
    if (p < e && (*p == '-' || *p == '+')) ++p;
    return p < e && (std::isdigit(static_cast<unsigned char>(*p)) || *p == '.');
  };

  // Header: the last non-data line before the first data line; lines before
  // it are a preamble (Tracker's track name).
  const char* p = begin;
  std::size_t line_no = 0;
  std::optional<std::string_view> header, above_header;
  std::size_t header_line = 1;
  bool preamble = false, several_tracks = false;
  while (p < end) {
    const char* e = line_end(p);
    ++line_no;
    if (!is_blank(p, e)) {
      if (is_data(p, e)) break;
      if (header) preamble = true, above_header = header;
      several_tracks |= starts_with(std::string_view(p, e - p), "#multi");
      header = std::string_view(p, e - p);
      header_line = line_no;
    }
    p = e + (e < end);
    if (line_no > 100) fail(file, line_no, 1, "no numbers in the first 100 lines; expected a data export");
  }
  refuse_binary(original, p - original.data(), file);  // the header and what precedes it
  if (p >= end) fail(file, line_no + 1, 1, "no data rows; expected a recording");
  const std::string_view first_data(p, line_end(p) - p);

  // Delimiter: tab, then semicolon, then comma, as found in the header (or
  // the first row when there is none). A comma then is a decimal comma.
  const std::string_view probe = header ? *header : first_data;
  char delimiter = '\0';
  for (char d : {'\t', ';', ','}) {
    if (probe.find(d) != std::string_view::npos) {
      delimiter = d;
      break;
    }
  }
  const bool decimal_comma = delimiter != ',' && first_data.find(',') != std::string_view::npos;

  auto cells = [&](std::string_view line) {
    std::vector<std::string_view> out;
    for (std::size_t start = 0;;) {
      const std::size_t d = delimiter ? line.find(delimiter, start) : std::string_view::npos;
      out.push_back(trim(line.substr(start, d == std::string_view::npos ? d : d - start)));
      if (d == std::string_view::npos) return out;
      start = d + 1;
    }
  };
  std::vector<Column> cols;
  // Tracker's export of several tracks: "#multi:", then each track's name
  // above its first column, then the header (one time column for all).
  std::vector<std::string> tracks;
  if (header) {
    for (std::string_view cell : cells(*header)) cols.push_back(classify(cell));
    while (cols.size() > 1 && cols.back().name.empty()) cols.pop_back();  // a trailing delimiter
    if (several_tracks) {
      if (!above_header || starts_with(*above_header, "#multi")) {
        fail(file, header_line, 1, "a Tracker export of several tracks (#multi:) without their names; expected "
                                   "each track's name on the line above the header, over its first column");
      }
      const std::vector<std::string_view> names = cells(*above_header);
      for (std::size_t j = 0; j < cols.size(); ++j) {
        if (j < names.size() && !names[j].empty()) tracks.emplace_back(names[j]);
        cols[j].track = static_cast<int>(tracks.size());
      }
      // Names out of line with the columns would mix two tracks' x and y.
      for (std::size_t j = 0; j < cols.size(); ++j) {
        const Column& c = cols[j];
        const auto twice = std::find_if(cols.begin(), cols.begin() + j, [&](const Column& b) {
          return b.track == c.track && b.role == c.role;
        });
        const bool unnamed = c.track == 0 && c.role != Role::time && c.role != Role::other;
        if (unnamed || (c.role != Role::other && c.track > 0 && twice != cols.begin() + j)) {
          fail(file, header_line - 1, 1,
               "the track names are out of line with the columns: column " + std::to_string(j + 1) + " (\"" +
                   c.name + "\") " +
                   (unnamed ? std::string("comes before the first name")
                            : "is track \"" + tracks[c.track - 1] + "\"'s second \"" + c.name + "\"") +
                   "; expected each track's name above its first column (Tracker's #multi: export)");
        }
      }
    }
  } else {
    std::size_t n = 1;
    if (delimiter) n += std::count(first_data.begin(), first_data.end(), delimiter);
    cols.resize(n);
  }
  // Which of several Tracker tracks, by its name.
  int track = -1;
  if (!tracks.empty()) {
    std::string listed;
    for (const auto& t : tracks) listed += (listed.empty() ? "\"" : ", \"") + t + "\"";
    if (set.empty() && tracks.size() > 1) {
      fail(file, header_line, 1, "a Tracker export of " + std::to_string(tracks.size()) + " tracks (" + listed +
                                     "); expected the pendulum's chosen by its name (import --set, a scene's set)");
    }
    const auto is_set = [&](const std::string& t) { return lower(t) == lower(set); };
    const auto named = std::find_if(tracks.begin(), tracks.end(), is_set);
    if (!set.empty() && named == tracks.end()) {
      fail(file, header_line, 1, "got the set \"" + set + "\"; expected one of this Tracker export's tracks: " + listed);
    }
    if (!set.empty() && std::count_if(tracks.begin(), tracks.end(), is_set) > 1) {
      fail(file, header_line, 1, "got the set \"" + set + "\", the name of more than one track (" + listed +
                                     "); expected a name of one track (rename the others in Tracker)");
    }
    track = set.empty() ? 1 : static_cast<int>(named - tracks.begin()) + 1;
    const bool positions = find(cols, Role::x, -1, track) && find(cols, Role::y, -1, track);
    if (!find(cols, Role::angle, -1, track) && !find(cols, Role::omega, -1, track) && !positions) {
      std::string own;
      for (const auto& c : cols) {
        if (c.track == track) own += (own.empty() ? "\"" : ", \"") + c.name + "\"";
      }
      fail(file, header_line, 1, "the track \"" + tracks[track - 1] + "\" has the columns " + own +
                                     "; expected its angle (θ), angular velocity (ω) or x and y");
    }
  }
  // A PASCO run other than the first, by its number ("Run #2", "run 2" or "2").
  int run = 1;
  if (!set.empty() && tracks.empty()) {
    const std::string name = lower(set);
    const std::size_t digits = name.find_first_of("0123456789");
    const bool number = digits != std::string::npos && name.find_first_not_of("0123456789", digits) == std::string::npos &&
                        digits < 8 && name.size() - digits < 6;
    const std::string prefix = number ? std::string(trim(name.substr(0, digits))) : std::string();
    if (!number || !(prefix.empty() || prefix == "run #" || prefix == "run")) {
      fail(file, header_line, 1, "got the set \"" + set + "\"; expected a PASCO run (\"Run #2\") or the name of a track in a Tracker "
                                     "export of several (\"#multi:\")");
    }
    run = std::atoi(name.c_str() + digits);
    std::string runs;
    for (const auto& c : cols) {
      if (c.run > 0 && c.role == Role::time) runs += (runs.empty() ? "" : ", ") + std::to_string(c.run);
    }
    if (std::none_of(cols.begin(), cols.end(), [&](const Column& c) { return c.run == run; })) {
      fail(file, header_line, 1, "no column of run " + std::to_string(run) + " in the header; expected a PASCO " +
                                     "export with \"Run #" + std::to_string(run) + "\"" +
                                     (runs.empty() ? std::string() : " (its runs: " + runs + ")"));
    }
  }
  const Layout layout = detect(format, cols, preamble, header.has_value(), file, header_line, run, track);
  const bool holds_sets = layout.format == RecordingFormat::pasco || (layout.format == RecordingFormat::tracker && !tracks.empty());
  if (!set.empty() && !holds_sets) {
    fail(file, header_line, 1, "got the set \"" + set + "\", but this " + recording_format_name(layout.format) +
                                   " export holds a single set; expected a set in a zip archive, a PASCO file or a Tracker export of "
                                   "several tracks");
  }

  Recording rec;
  rec.set = track > 0 ? tracks[static_cast<std::size_t>(track - 1)] : set;  // a track as Tracker names it
  rec.format = layout.format;
  rec.kind = layout.kind;
  for (std::size_t j : layout.channels) rec.channel_names.push_back(cols[j].name);
  rec.channels.resize(layout.channels.size());
  // The columns a row needs: without its time or a channel it is dropped.
  std::vector<std::size_t> needed{layout.time};
  needed.insert(needed.end(), layout.channels.begin(), layout.channels.end());
  const char other_delimiters[] = {'\t', ';', delimiter == ',' ? '\0' : ','};
  const std::size_t ncols = cols.size();
  const char mark = decimal_comma ? ',' : '.';

  // The rows of [p, end), whose first line is line_no, into rec.
  auto parse_rows = [&](const char* p, const char* end, std::size_t line_no) {
    double last_time = -std::numeric_limits<double>::infinity();
    std::size_t last_time_line = 0;
    char buffer[64];
    std::vector<double> cells(ncols);  // this row's values, NaN for an empty or "NaN" cell
    // The common row: plain numbers between single delimiters, read up to its
    // newline, which it returns (no search for the line's end first). Anything
    // else (quotes, spaces, empty or NaN cells, errors) takes the general path.
    auto plain_row = [&](const char* q) -> const char* {
      for (std::size_t j = 0; j + 1 < ncols; ++j) {
        q = fast_number(q, end, mark, cells[j]);
        if (!q || q >= end || *q != delimiter) return nullptr;
        ++q;
      }
      q = fast_number(q, end, mark, cells[ncols - 1]);
      if (!q) return nullptr;
      q += q < end && *q == '\r';
      return q >= end || *q == '\n' ? q : nullptr;
    };
    // The line [p, e) cell by cell, with the errors named.
    auto general_row = [&](const char* p, const char* e) {
      auto column = [&](const char* at) { return static_cast<std::size_t>(at - p) + 1; };
      const char* q = p;
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
                       "' in a file whose header separates columns by '" +
                       (delimiter == '\t' ? std::string("\\t") : std::string(1, delimiter)) + "'");
            }
            fail(file, line_no, column(q),
                 "got \"" + std::string(q, std::min<const char*>(token_end, q + 40)) + "\" in column \"" +
                     cols[j].name + "\"; expected a number");
          };
          if (!stop) {  // the slow path: NaN, long mantissas, large exponents
            stop = s;
            while (!ends_cell(stop)) ++stop;
            std::from_chars_result r{};
            if (decimal_comma) {
              const std::size_t n = std::min<std::size_t>(stop - s, sizeof buffer);
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
          } else if (!ends_cell(stop)) {
            bad_cell(stop);
          }
          num_end = stop;
        }
        q = num_end;
        while (q < e && (*q == ' ' || *q == '"' || *q == '\r')) ++q;
        cells[j] = v;
        if (j + 1 < ncols) {
          if (q >= e || *q != delimiter) {
            fail(file, line_no, column(q),
                 "a truncated row: " + std::to_string(j + 1) + " of " + std::to_string(ncols) +
                     " columns (column \"" + cols[j + 1].name + "\" is missing)");
          }
          ++q;
        } else if (q < e && !(delimiter && *q == delimiter && is_blank(q, e))) {
          fail(file, line_no, column(q),
               "more cells than the " + std::to_string(ncols) +
                   " columns of the header (mixed delimiters, or a decimal comma in a comma-separated file?)");
        }
      }
    };
    for (const char* e = nullptr; p < end; p = e < end ? e + 1 : end, ++line_no) {
      const char* plain = plain_row(p);
      if (plain) {
        e = plain;
      } else {
        e = line_end(p);
        if (is_blank(p, e)) continue;
        general_row(p, e);
      }
      ++rec.rows;
      if (layout.period && !std::isnan(cells[*layout.period])) {
        rec.periods.push_back(cells[*layout.period] * layout.time_scale);
      }
      // The fast path's numbers are never NaN: only a general row can miss one.
      if (!plain && std::any_of(needed.begin(), needed.end(), [&](std::size_t j) { return std::isnan(cells[j]); })) {
        ++rec.dropped;
        continue;
      }
      const double time = cells[layout.time] * layout.time_scale;
      if (!(time > last_time)) {
        fail(file, line_no, 1,
             "time going backwards: " + std::to_string(time) + " s after " + std::to_string(last_time) +
                 " s on line " + std::to_string(last_time_line) + "; expected increasing times");
      }
      if (!std::isfinite(time)) fail(file, line_no, 1, "an infinite time");
      last_time = time;
      last_time_line = line_no;
      rec.time.push_back(time);
      for (std::size_t k = 0; k < rec.channels.size(); ++k) {
        rec.channels[k].push_back(cells[layout.channels[k]] * layout.channel_scale);
      }
    }
  };

  // One allocation per column: rows from the first row's length, 5 % spare.
  // One thread: the reader's figure of merit is the CPU time it takes, and
  // on a shared machine threads add to it (docs/recordings.md, Speed).
  const double bytes_per_row = static_cast<double>(std::max<std::size_t>(first_data.size() + 1, 4));
  const std::size_t guess = static_cast<std::size_t>(1.05 * static_cast<double>(end - p) / bytes_per_row) + 16;
  rec.time.reserve(guess);
  detail::huge_pages(rec.time);
  for (auto& c : rec.channels) {
    c.reserve(guess);
    detail::huge_pages(c);
  }
  parse_rows(p, end, line_no);
  if (layout.angle_unit_unknown) {
    // Tracker writes "θ" without its unit: more than a turn means degrees.
    const auto& a = rec.channels[0];
    const bool degrees = std::any_of(a.begin(), a.end(), [](double x) { return std::fabs(x) > 6.2832; });
    if (degrees) {
      for (double& x : rec.channels[0]) x *= 3.14159265358979323846 / 180.0;
    }
  }
  return rec;
}

}  // namespace

Recording read_recording(const std::string& path, RecordingFormat format, const RecordingLimits& limits,
                         const std::string& set) {
  const InputFile file(path, "a recording file");
  if (file.size() > limits.max_bytes) {
    throw InputError(file.path(), "the file has " + std::to_string(file.size()) + " bytes; expected at most " +
                                      std::to_string(limits.max_bytes) + " (RecordingLimits::max_bytes)");
  }
  // Mapped, not read: no copy of the text (docs/robustness.md says what a
  // copy would cost). A file cut or rewritten while it is read is refused,
  // whatever the parser made of it.
  const detail::MappedFile map(file);
  auto check_unchanged = [&] {
    if (!map.shrank() && !file.changed()) return;
    throw InputError(file.path(), "the file changed while it was read (it had " + std::to_string(file.size()) +
                                      " bytes; is it still being written or synchronised?); expected a "
                                      "complete recording: read it again once it is whole");
  };
  try {
    Recording r = looks_like_zip(map.text()) ? read_zip_recording(map.text(), path, format, set, limits)
                                             : parse_recording(map.text(), path, format, set);
    check_unchanged();
    return r;
  } catch (const InputError&) {
    check_unchanged();
    throw;
  }
}

}  // namespace pendulum
