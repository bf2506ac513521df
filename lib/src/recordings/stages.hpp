#pragma once
// The stages of reading a recording's text (docs/recordings.md, "Columns"),
// each a function that can be tested alone (tests/test_recording_stages.cpp):
//   decode  the byte-order mark, a Latin-1 header's ° and µ as UTF-8;
//   lines   the header line, the preamble above it, the first data line;
//   split   the delimiter (tab, semicolon, comma, runs of spaces), the
//           decimal mark, a line's cells;
//   words   a header cell -> its role and unit, from one table of spellings;
//   rows    the numbers, one vector per column;
//   content what a column's numbers say (a counter, a constant, a clock);
//   roles   which columns give the time and the signal (read.cpp);
//   clean   repeated, out-of-order and missing samples, held frames (clean.cpp).

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pendulum/recordings/read.hpp"

namespace pendulum::recording_text {

/// InputError at "file:line:column" (column in bytes, from 1), the message on one line.
[[noreturn]] void fail(const std::string& file, std::size_t line, std::size_t column, const std::string& message);

// --- decode -----------------------------------------------------------------

/// The text without a UTF-8 byte-order mark.
std::string_view strip_bom(std::string_view text);

/// A header cell as a message quotes it: control bytes escaped, cut to 40
/// bytes (a header may be any text: a file named by mistake, a log), or
/// "column N" (`index` from 1) when it is empty.
std::string column_label(const std::string& name, std::size_t index);

/// A header cell as UTF-8: as it is when it is valid UTF-8, otherwise read
/// as Latin-1 (Windows exporters write "°" as 0xB0, "µ" as 0xB5).
std::string to_utf8(std::string_view cell);

// --- lines ------------------------------------------------------------------

/// True if [p, e) holds only spaces, tabs, CR, commas and semicolons.
bool is_blank(const char* p, const char* e);

/// True if the line's first cell starts like a number.
bool is_data(const char* p, const char* e);

struct HeaderLines {
  std::optional<std::string_view> header;  ///< the last non-data line before the data; none: headerless
  std::optional<std::string_view> above;   ///< the line above the header (a preamble)
  std::size_t header_line = 1;
  std::size_t above_line = 1;   ///< where `above` starts (a quoted cell may hold line breaks)
  bool preamble = false;       ///< lines above the header (Tracker's track name, Logger Pro's data set)
  bool several_tracks = false;  ///< Tracker's "#multi:"
  std::size_t data_offset = 0;  ///< byte of the first data line in the text
  std::size_t data_line = 1;
};

/// The header and the first data line; refuses a text with no data rows or
/// no numbers in its first 100 lines.
HeaderLines find_header(std::string_view text, const std::string& file);

/// The data rows after the header: where they begin and end in the text, and
/// the first row, which the dialect is sniffed from.
struct DataRows {
  const char* begin;
  const char* end;
  std::string_view first;
};

/// The data rows of `text` after `lines`; refused as "no data rows;
/// expected `what`" where there are none.
DataRows data_rows(std::string_view text, const HeaderLines& lines, const std::string& file, const std::string& what);

// --- split ------------------------------------------------------------------

/// How the cells of a line are separated: '\t', ';', ',' or ' ' (a run of
/// spaces), or '\0' for one column; and the decimal mark.
struct Dialect {
  char delimiter = '\0';
  bool decimal_comma = false;
  char mark() const { return decimal_comma ? ',' : '.'; }
};

/// Tab, then semicolon, then comma as found in the header (or the first row
/// without one); else the first row's tab or semicolon (a header of spaced
/// words over them); otherwise runs of spaces when the first row has two or
/// more numbers so separated. A comma in the first row is then a decimal comma.
Dialect sniff(std::optional<std::string_view> header, std::string_view first_data);

/// Whether `s` starts with `p`.
bool starts_with(std::string_view s, std::string_view p);

/// The median of `v` (of an even count, the upper of the middle two); NaN
/// when `v` is empty.
double median_of(std::vector<double> v);

/// `s` without the spaces, CRs and quotes around it: a cell's text.
std::string_view trim_cell(std::string_view s);

/// The cells of a line, spaces, CR and quotes trimmed (a quoted cell keeps
/// its delimiters). With runs of spaces, a header's "(s)" or "[deg]" joins
/// the word before it.
/// At most `most` + 1 cells are split.
std::vector<std::string_view> split_cells(std::string_view line, const Dialect& dialect,
                                          std::size_t most = std::string_view::npos);

/// split_cells of the line `line_no` of `file`, refused past limits.columns
/// cells as soon as they are passed: a line of 10^7 cells costs no more.
std::vector<std::string_view> split_cells_within(std::string_view line, const Dialect& dialect,
                                                 const InputLimits& limits, const std::string& file,
                                                 std::size_t line_no);

/// The number of cells up to the last non-empty one (at least 1): a
/// trailing delimiter makes no column.
std::size_t filled_cells(const std::vector<std::string_view>& cells);

// --- words ------------------------------------------------------------------

/// What a column holds.
enum class Role {
  time,                 ///< s, ms, µs
  rate,                 ///< one axis of a gyroscope (rad/s)
  acceleration,         ///< one axis of an accelerometer, gravity included (m/s^2)
  linear_acceleration,  ///< one axis, gravity removed (m/s^2)
  angle,                ///< deg or rad
  omega,                ///< angular velocity about the pivot (rad/s, deg/s)
  x,                    ///< position (m, cm, mm, px)
  y,
  state,                ///< a photogate's state, 0 or 1
  period,               ///< a photogate's period column (s)
  counter,              ///< an event number or row index
  uncertainty,          ///< the uncertainty of another column
  derivative,           ///< a tracker's vx, ax, X', speed: not a swing signal here
  // A table of settings and periods's words (table.cpp); a recording has none.
  length,               ///< a pendulum's length (l, L, Length)
  pivot_distance,       ///< pivot to a rigid body's centre of mass (h)
  pivot_position,       ///< the pivot's place along the body
  rod_length,           ///< a uniform rod's length, pivoted at its end
  amplitude,            ///< the amplitude a timing started at
  other,                ///< a word not in the table
};
/// True for the words only a table of settings uses: a recording reads them as unknown.
constexpr bool table_only(Role role) {
  return role == Role::length || role == Role::pivot_distance || role == Role::pivot_position ||
         role == Role::rod_length || role == Role::amplitude;
}
const char* role_name(Role role);

struct Column {
  std::string name;  ///< as in the file, quotes removed, UTF-8
  Role role = Role::other;
  std::string unit;  ///< normalised ("s", "ms", "us", "deg", "rad", "rad/s", "deg/s", "m", "cm", "mm", "px"), or as written, lower case
  int run = 0;       ///< PASCO's "Run #n", else 0
  int track = 0;     ///< Tracker's track in an export of several (from 1), else 0
  bool prefixed = false;  ///< a "Latest: ", "Run 1: ", "VideoAnalysis: " prefix
  bool known = false;     ///< the word is in the table of spellings
  std::string word;       ///< the word looked up: lower case, without its unit, prefix or suffix
  std::string decided = "header";  ///< "header", "content" or "option"
  /// Frames a second of a time column of frame numbers (`--columns "frame:30fps"`); 0 for times.
  double frame_rate = 0.0;
};

/// Whether a header holds only a fitting program's generic names (x and y,
/// their primes or d's, no unit: "X,Y,X',Y'", "x y dx dy") and no time:
/// names that say where a value goes in a fit, not what it is. A recording
/// or a table with such a header is read by its numbers, as one without a
/// header is (issue 38: "X" stepping by 1/12 s is the time; a table's
/// "x y dx dy" is a length, a period and their uncertainties by place).
bool generic_names(const std::vector<Column>& cols);

/// A header cell's role and unit: case folded; the unit from the last
/// "(...)" or "[...]" or after a comma; a "Word: " prefix, a "_{1}" or "_1"
/// suffix, a PASCO " Run #n" and a trailing prime taken off; the word
/// looked up in the table of spellings (stages.cpp, kSpellings).
Column classify(std::string_view cell);

/// A unit as written ("Degrees", "°", "sec") in its normal spelling, or the
/// text lower-cased when it is not one the reader knows.
std::string normal_unit(std::string_view unit);

/// Whether `unit` is one of the unit spellings normal_unit knows ("cm", "sec", "°").
bool known_unit(std::string_view unit);

/// The factor from a time unit to seconds, or nullopt.
std::optional<double> time_scale(const std::string& unit);
/// The factor from a time column's numbers to seconds: 1/frame_rate for
/// frame numbers, else by its unit (nullopt for a unit that is no time's).
std::optional<double> time_scale(const Column& c);

/// `--columns "t:s,theta:deg"`: one entry per column in file order, a role
/// and an optional unit; "-" or an empty entry leaves a column unused;
/// "frame:30fps" is a time column of frame numbers at 30 frames a second.
/// Refuses an unknown role or unit, naming the entry ("--columns" in `where`).
std::vector<std::optional<Column>> parse_column_spec(const std::string& spec, const std::string& where);

// --- rows -------------------------------------------------------------------

/// The numbers of the data rows, one vector per column (NaN for an empty or
/// "NaN" cell), and the file line of each row.
struct Table {
  std::vector<std::vector<double>> columns;
  std::size_t rows = 0;
  bool any_nan = false;  ///< some cell is empty or NaN (only a row off the fast path can hold one)
  /// (row, line) where the line numbering jumps (blank lines); the first
  /// pair is the first row's.
  std::vector<std::pair<std::size_t, std::size_t>> jumps;
  /// A unit written in a column's cells ("10cm", "0.68s", "7.4%"), normal
  /// form; empty where the cells hold bare numbers.
  std::vector<std::string> cell_units;
  std::size_t line(std::size_t row) const;
};

/// Reads the rows of [p, end), the first on line `line_no`, with `names`
/// (one per column) naming the columns in messages; refuses a truncated or
/// overlong row, a cell that is not a number, mixed delimiters, a row past
/// limits.rows (refused as it is reached; the columns' storage is reserved
/// for at most that many).
Table read_rows(const char* p, const char* end, std::size_t line_no, const Dialect& dialect,
                const std::vector<std::string>& names, const std::string& file, const InputLimits& limits);

// --- content ----------------------------------------------------------------

/// What a column's finite numbers say.
struct ColumnFacts {
  std::size_t finite = 0;
  bool constant = true;     ///< one value throughout (or none)
  bool integers = true;     ///< whole numbers only
  bool counter = false;     ///< whole numbers stepping by one, at most a few larger steps
  /// The whole step of whole numbers that all but one typo's two steps (or
  /// 10 %) take, and more than half, as a count of periods by 2 ("1, 3, 5,
  /// ... periods at t") or a clock in ms by 20; 0 otherwise.
  double stride = 0.0;
  bool increasing = false;  ///< never decreasing, at most a few glitches (clean decides)
  bool ranged = false;      ///< lo and hi were found (examine's `range`)
  double lo = 0.0, hi = 0.0;  ///< 0.5th and 99.5th percentiles
  /// Half the range between the percentiles: the swing's amplitude for an angle.
  double half_range() const { return 0.5 * (hi - lo); }
};
/// Without `range` the percentiles are not found (they take a copy of the
/// column and two partial sorts: most of inferring a long file's roles).
ColumnFacts examine(const std::vector<double>& column, bool range = true);

/// The unit of an angle column whose header gives none, from its swing of
/// +-A = facts.half_range(): "deg" where A > pi/2 (a swing beyond 90 deg is
/// no pendulum's in radians), else "rad"; the note says which and why.
std::pair<std::string, std::string> unitless_angle(const ColumnFacts& facts);

/// Whether one signal the numbers alone found beside a time can be an
/// angle: not whole numbers only (a sensor's raw counts: milli-g, an ADC's
/// or an encoder's steps) and within +-180 as degrees. Needs the range.
bool angle_by_numbers(const ColumnFacts& facts);

/// Why such a signal is read for its period only, with the option that
/// reads it as an angle.
std::string not_an_angle_why(const ColumnFacts& facts);

/// A rough period of a sampled signal, in the time column's own numbers:
/// twice the mean interval between its crossings of the middle of its 5th
/// and 95th percentiles, with hysteresis of a third of that half range (a
/// plausibility check, not a measurement); NaN with fewer than 3 crossings.
double rough_period(const std::vector<double>& time, const std::vector<double>& signal);

/// The median of the positive steps of `time` (NaN without one): event
/// stamps' period, within a factor 2 (one stamp a passage).
double median_step(const std::vector<double>& time);

/// The unit of a time column that gives none, from the period its numbers
/// give (rough_period, median_step): seconds, unless that is over 60 s (a
/// pendulum 900 m long) while in ms (then us) it lies in [0.02, 60] s, as a
/// microcontroller's millisecond clock stamps it; and the column's why.
std::pair<std::string, std::string> unitless_time(double period);

/// True if `b` is, sample for sample, the rate of change of `a` (their
/// correlation over the interior samples beyond 0.9): an angle and its
/// angular velocity, never the x and y of a track (y swings at twice x's
/// frequency, so x's rate and y do not correlate).
bool is_rate_of(const std::vector<double>& t, const std::vector<double>& a, const std::vector<double>& b);

/// True if `y` can be the height of the bob whose horizontal position is `x`
/// at times `t`: on the bob's arc (seen square, or rolled in its plane) y is
/// a function of x, so none of y follows x's rate, the swing a quarter
/// period on. False where that quarter-period part, beyond a polynomial of
/// degree 4 in x, holds over a quarter of y's variance: a third column
/// beside an angle (`t theta extra`: a lagging signal), where that part's
/// amplitude is also over a quarter of x's half range or y swings wider than
/// x (a track's x and y share a unit, and an elliptical swing seen from
/// above puts a few per cent of x into y's quadrature). A y of noise or a
/// tracker's drift has none of it. At most 2^16 samples are used, evenly
/// spread.
bool could_be_track_y(const std::vector<double>& t, const std::vector<double>& x, const std::vector<double>& y);

// --- clean ------------------------------------------------------------------

/// What clean_times keeps.
struct Cleaned {
  bool all = true;                ///< every sample kept (then `keep` is empty)
  std::vector<std::size_t> keep;  ///< otherwise the positions in `time` kept, in order
  double quantum = 0.0;           ///< the clock's resolution when stamps repeat (s), else 0
  std::vector<RecordingNote> notes;
};

/// The samples of `time` (s; time[k] from table row rows[k], or row k when
/// `rows` is empty) in time order: stamps that repeat throughout (a clock printing too few decimals)
/// are kept and their quantum given; a few repeated or out-of-order samples
/// (at most 1 % of the rows) are dropped, each with its line; gaps of more
/// than 1.5 sampling steps are noted when `sampled`. More out of order is
/// refused ("time going backwards"), as is an infinite time.
Cleaned clean_times(const std::vector<double>& time, const std::vector<std::size_t>& rows, const Table& table,
                    bool sampled, const std::string& file);

/// Held frames: a tracker that polls a camera faster than its frames come
/// writes each frame's values again with fresh stamps, a staircase whose
/// steps move every crossing by up to a frame whatever the swing's size.
/// Its runs of rows repeating in every channel (`channels`, sampled at
/// `time`, s) are 2 rows or more (the median) in the swing's fast middle
/// (within half its extent of the median) and, 9 in 10 of them, no longer
/// than twice that where the swing turns: a sensor's rounding (an encoder's steps) repeats
/// where the swing is slow, its runs longest at the turns, and a record at
/// rest adds few runs. Fewer than a tenth of the rows repeating: none. `quantum` is then the median time from one frame to
/// the next (s), the stamps' resolution for a crossing, and the note says
/// so. Nothing is dropped (`all`): a held sample is its frame, late.
Cleaned held_frames(const std::vector<double>& time, const std::vector<std::vector<double>>& channels);

}  // namespace pendulum::recording_text
