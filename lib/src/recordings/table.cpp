// Tables of settings and periods (table.hpp; docs/series.md, "Tables"): the
// recording reader's stages read the text (stages.hpp), then each column's
// role and unit is decided from the option, the header or the numbers, the
// units are checked against the physics (T^2 against L), and the rows at one
// setting become one observation.
#include "pendulum/recordings/table.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>

#include "pendulum/amplitude.hpp"
#include "pendulum/dispersion.hpp"
#include "pendulum/argument_ranges.hpp"
#include "pendulum/files.hpp"
#include "pendulum/straight_line.hpp"
#include "zip.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/numeric.hpp"
#include "../text.hpp"
#include "stages.hpp"

namespace pendulum {

namespace {

using namespace recording_text;

constexpr double kStandardGravity = 9.80665;  // m/s^2, the scale of a T^2-against-L check only

enum class Kind { unused, setting, time, amplitude };

/// A column a student derived from the others (their working, not a
/// measurement): compared with what the row's own numbers give, not read.
enum class Derived { none, period_squared, g };

/// How one column is read.
struct Use {
  Kind kind = Kind::unused;
  bool uncertainty = false;
  Setting setting = Setting::length;
  std::string unit;  ///< normal form; empty until given or decided
  int oscillations = 0;
  bool trial = false;  ///< one of several trials' columns: a row's trials are its repeats
  Derived derived = Derived::none;
  std::string decided = "header";
  std::string why;
};

bool same(const Use& a, const Use& b) {
  return a.kind == b.kind && a.uncertainty == b.uncertainty && !(a.trial && b.trial);
}

std::string quantity_name(const Use& u) {
  std::string q = u.kind == Kind::setting  ? std::string(setting_key(u.setting))
                  : u.kind == Kind::time   ? (u.oscillations > 1 ? "time of " + std::to_string(u.oscillations) + " oscillations"
                                                                 : std::string("period"))
                  : u.kind == Kind::amplitude ? std::string("amplitude")
                                              : std::string("unused");
  std::replace(q.begin(), q.end(), '_', ' ');
  return u.uncertainty ? "uncertainty of the " + q : q;
}

/// N of a time of N oscillations written in a header word: "t10", "10t",
/// "t_{10}", "time of 10", "10 periods", "time for 20 swings".
int oscillations_in(std::string_view word) {
  std::string w;
  for (char c : word) {
    if (c != ' ' && c != '_' && c != '{' && c != '}') w += c;
  }
  const std::size_t d0 = w.find_first_of("0123456789");
  if (d0 == std::string::npos) return 0;
  const std::size_t d1 = std::min(w.find_first_not_of("0123456789", d0), w.size());
  if (d1 - d0 > 5) return 0;
  const std::string before = w.substr(0, d0), after = w.substr(d1);
  const int n = std::stoi(w.substr(d0, d1 - d0));
  // English, Dutch ("tijd 10 slingeringen") and German ("Zeit 5 Perioden").
  const bool count_word = after == "oscillations" || after == "swings" || after == "periods" || after == "osc" ||
                          after == "slingeringen" || after == "trillingen" || after == "perioden" ||
                          after == "schwingungen";
  const bool time_word = before == "t" || before == "time" || before == "timeof" || before == "timefor" ||
                         before == "tijd" || before == "tijdvoor" || before == "zeit" || before == "zeitf\xc3\xbcr";
  if (!(n >= 1 && ((time_word && (after.empty() || count_word)) || (before.empty() && (after == "t" || count_word))))) {
    return 0;
  }
  return n;
}

/// What a word names, as the spellings table gives it.
std::optional<Use> quantity_of(std::string_view word) {
  if (word.empty()) return std::nullopt;
  Use u;
  const Column c = classify(word);
  switch (c.role) {
    case Role::length: u.kind = Kind::setting, u.setting = Setting::length; break;
    case Role::pivot_distance: u.kind = Kind::setting, u.setting = Setting::pivot_distance; break;
    case Role::pivot_position:
    case Role::x: u.kind = Kind::setting, u.setting = Setting::pivot_position; break;
    case Role::rod_length: u.kind = Kind::setting, u.setting = Setting::rod_length; break;
    case Role::time:
    case Role::period: u.kind = Kind::time; break;
    case Role::angle:
    case Role::amplitude: u.kind = Kind::amplitude; break;
    default:
      if (const int n = oscillations_in(c.word)) {
        u.kind = Kind::time, u.oscillations = n;
        break;
      }
      return std::nullopt;
  }
  return u;
}

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

/// Words that say how a period was timed: "T tracker", "period (phyphox)",
/// "T_stopwatch" are period columns, told apart by the method (issue 39:
/// Tracker's and phyphox's periods side by side).
constexpr const char* kTimingMethods[] = {"tracker", "phyphox", "stopwatch", "photogate", "gate",  "video",
                                          "phone",   "sensor",  "manual",    "hand",      "timer", "camera",
                                          "app",     "logger",  "pasco",     "vernier",   "arduino"};

bool is_timing_method(std::string_view word) {
  return std::any_of(std::begin(kTimingMethods), std::end(kTimingMethods), [&](const char* m) { return word == m; });
}

/// A period's word and a timing method's (kTimingMethods), in either order,
/// underscores and brackets as spaces ("t tracker", "phyphox period");
/// `unit` joins them where it is a method, not a unit ("T (video)").
bool method_qualified_period(std::string word, const std::string& unit) {
  if (is_timing_method(unit)) word += " " + unit;
  for (char& ch : word) {
    if (ch == '_' || ch == '(' || ch == ')' || ch == '[' || ch == ']') ch = ' ';
  }
  int periods = 0, methods = 0, others = 0;
  for (std::size_t at = 0; at < word.size();) {
    const std::size_t end = std::min(word.find(' ', at), word.size());
    const std::string token = word.substr(at, end - at);
    at = end + 1;
    if (token.empty()) continue;
    const Role role = classify(token).role;
    if (role == Role::period || role == Role::time) ++periods;
    else if (is_timing_method(token)) ++methods;
    else ++others;
  }
  return periods == 1 && methods >= 1 && others == 0;
}



/// A quantity named in an uncertainty's word, a plot's axes too: "x" the
/// setting, "y" the period (matplotlib's xerr, yerr; dx, dy).
std::optional<Use> axis_quantity(const std::string& word) {
  Use u;
  if (word == "x") u.kind = Kind::setting;
  else if (word == "y") u.kind = Kind::time;
  else return quantity_of(word);
  return u;
}

/// Whether a header word names one trial of several: "trial1", "Trial 2",
/// "1st run", "run #3", "meting 2", "Versuch 1".
bool is_trial_word(std::string_view word) {
  std::string w;
  for (char c : word) {
    if (!std::isdigit(static_cast<unsigned char>(c)) && c != ' ' && c != '_' && c != '#' && c != '.') w += c;
  }
  for (const char* ordinal : {"st", "nd", "rd", "th"}) {
    if (starts_with(w, ordinal) && word.find_first_of("0123456789") == 0) w.erase(0, 2);
  }
  static const char* const kTrials[] = {"trial", "run", "attempt", "try", "meting", "versuch", "messung", "poging"};
  return std::any_of(std::begin(kTrials), std::end(kTrials), [&](const char* t) { return w == t; });
}

/// An uncertainty column's word ("σT", "dT", "u(T)", "sigma_l", "err h", or
/// "σ" alone): the quantity it is the uncertainty of; a Use of Kind::unused
/// for "the column before"; nullopt when the word is no uncertainty's.
std::optional<Use> uncertainty_of(const Column& c) {
  static const char* const kPrefixes[] = {"sigma_", "sigma ", "sigma", "\xcf\x83_", "\xcf\x83 ", "\xcf\x83",
                                          "\xce\xb4", "\xce\x94", "u_", "u(", "err_", "err ", "error_", "error ",
                                          "err", "uncertainty of ", "uncertainty in ", "uncertainty on ",
                                          "uncertainty_", "uncertainty ", "error of ", "error in ", "error on ",
                                          "unc_", "unc ", "unc", "delta_", "delta ", "delta", "fout in ", "fout ",
                                          "onzekerheid in ", "onzekerheid ", "fehler der ", "fehler des ", "fehler ",
                                          "unsicherheit der ", "unsicherheit des ", "unsicherheit ", "+-",
                                          "\xc2\xb1", "d"};
  const std::string& w = c.word;
  static const char* const kAlone[] = {"sigma", "\xcf\x83", "error", "err", "uncertainty", "unc", "delta", "fout",
                                       "fehler", "u", "+-", "\xc2\xb1"};
  for (const char* alone : kAlone) {
    if (w == alone) {
      // "u(T)" without a unit: the header's "(t)" was taken for one.
      if (auto q = quantity_of(c.unit)) return q;
      return Use{};
    }
  }
  // A plot's axes, matplotlib's names: "xerr" the setting's, "yerr" the period's.
  for (const char* suffix : {"err", "_err", " err", "error", "_error", " error"}) {
    const std::size_t n = std::strlen(suffix);
    if (w.size() <= n || w.compare(w.size() - n, n, suffix) != 0) continue;
    if (auto q = axis_quantity(w.substr(0, w.size() - n))) return q;
  }
  for (const char* prefix : kPrefixes) {
    if (!starts_with(w, prefix)) continue;
    std::string rest = w.substr(std::strlen(prefix));
    while (!rest.empty() && (rest.back() == ')' || rest.back() == ' ')) rest.pop_back();
    if (starts_with(rest, "the ")) rest.erase(0, 4);  // "uncertainty in the period"
    if (auto q = axis_quantity(rest)) return q;
  }
  return std::nullopt;
}

/// A column's role from its header cell.
Use from_header(const Column& c) {
  Use u;
  for (const char* word : {"t^2", "t\xc2\xb2", "period^2", "period\xc2\xb2", "t squared", "period squared"}) {
    if (c.word == word) {
      u.derived = Derived::period_squared, u.unit = c.unit;
      u.why = "the periods squared (a student's working): not read";
      return u;
    }
  }
  if (c.word == "g" || c.word == "gravity") {
    u.derived = Derived::g, u.unit = c.unit;
    u.why = "each row's g (a student's working): not read";
    return u;
  }
  if (const int n = oscillations_in(c.word)) {
    u.kind = Kind::time, u.oscillations = n, u.unit = c.unit;
    u.why = "the time of " + std::to_string(n) + " oscillations by the header";
    return u;
  }
  if (is_trial_word(c.word)) {
    u.kind = Kind::time, u.trial = true, u.unit = c.unit;
    u.why = "one trial's time by the header: a row's trials are its repeats";
    return u;
  }
  if (auto q = uncertainty_of(c)) {
    q->uncertainty = true;
    // "u(T)": the unit of the quantity named, not one of its own.
    q->unit = quantity_of(c.unit) ? std::string() : c.unit;
    return *q;
  }
  if (auto q = quantity_of(c.word)) {
    q->unit = c.unit;
    return *q;
  }
  if (method_qualified_period(c.word, c.unit)) {
    u.kind = Kind::time;
    u.unit = is_timing_method(c.unit) ? std::string() : c.unit;
    u.why = "a period by the header, its timing method named";
    return u;
  }
  u.why = c.role == Role::counter ? "a counter or index" : c.name.empty() ? "not needed" : "a word the reader does not know";
  return u;
}

/// The root mean square of `v`, scaled by the power of two nearest its
/// largest size so that a stated 1e-200 s does not square to 0 (a timing
/// then claimed exact); the scaling is exact, so other values' rms keeps
/// every bit.
double rms(const std::vector<double>& v) {
  double largest = 0.0, sum = 0.0;
  for (double x : v) largest = std::max(largest, std::fabs(x));
  if (!(largest > 0.0)) return largest;
  int exponent = 0;
  (void)std::frexp(largest, &exponent);
  for (double x : v) sum += std::pow(std::ldexp(x, -exponent), 2) / static_cast<double>(v.size());
  return std::ldexp(std::sqrt(sum), exponent);
}

/// The column (from 1) where cell `j` of the line `line_no` of `text`
/// starts: a message points at the cell. Found only for a message, so the
/// lines are counted then.
std::size_t cell_column(std::string_view text, std::size_t line_no, const Dialect& dialect, std::size_t j) {
  std::size_t start = 0;
  for (std::size_t n = 1; n < line_no && start != std::string_view::npos; ++n) {
    start = text.find('\n', start);
    if (start != std::string_view::npos) ++start;
  }
  if (start == std::string_view::npos) return 1;
  const std::string_view line = text.substr(start, text.find('\n', start) - start);
  const std::vector<std::string_view> cells = split_cells(line, dialect, j);
  return j < cells.size() ? static_cast<std::size_t>(cells[j].data() - line.data()) + 1 : 1;
}

/// True if `u` reads as the uncertainty of `v`: never negative, not all zero
/// and below a third of v's typical size.
bool reads_as_uncertainty(const std::vector<double>& u, const std::vector<double>& v) {
  std::vector<double> size;
  for (double x : v) size.push_back(std::fabs(x));
  const double typical = median_of(size);
  const double top = *std::max_element(u.begin(), u.end());
  return std::all_of(u.begin(), u.end(), [](double x) { return x >= 0.0; }) && top > 0.0 && top < typical / 3.0;
}

struct Scale {
  const char* name;
  double factor;
};
constexpr Scale kLengthUnits[] = {{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}, {"in", 0.0254}, {"ft", 0.3048}};
constexpr Scale kTimeUnits[] = {{"s", 1.0}, {"ms", 1e-3}, {"min", 60.0}};
constexpr Scale kAngleUnits[] = {{"deg", kRadiansPerDegree}, {"rad", 1.0}};

template <std::size_t N>
std::optional<double> factor_of(const Scale (&units)[N], const std::string& unit) {
  for (const Scale& s : units) {
    if (unit == s.name) return s.factor;
  }
  return std::nullopt;
}

template <std::size_t N>
std::string names_of(const Scale (&units)[N]) {
  std::string out;
  for (const Scale& s : units) out += (out.empty() ? "" : ", ") + std::string(s.name);
  return out;
}

/// 4 pi^2 L / T^2 of each row (m/s^2), the settings in m and the periods in s.
std::vector<double> row_g(const std::vector<double>& l, const std::vector<double>& t) {
  std::vector<double> g(l.size());
  for (std::size_t i = 0; i < l.size(); ++i) g[i] = gravity_for_period(l[i], t[i]);
  return g;
}

/// k^2 = h (l - h) of each row (m^2), l = g0 T^2 / (4 pi^2) the equivalent
/// length: the body's radius of gyration squared, the same at every pivot.
std::vector<double> row_k2(const std::vector<double>& h, const std::vector<double>& t) {
  std::vector<double> k2(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double l = length_for_period(t[i], kStandardGravity);
    k2[i] = h[i] * (l - h[i]);
  }
  return k2;
}

/// Whether the settings (m) and periods (s) read as a length series of a
/// lab's pendulum: a median length of 0.1 to 5 m (never "135 m"), and a g
/// whose median is 4 to 25 m/s^2 and every row's within a factor 2.5 of it
/// (a short row beside lengths taped to the top of the bob runs low).
bool fits_length(const std::vector<double>& l, const std::vector<double>& t) {
  const std::vector<double> g = row_g(l, t);
  const double m = median_of(g), length = median_of(l);
  return length >= 0.1 && length <= 5.0 && m >= 4.0 && m <= 25.0 &&
         std::all_of(g.begin(), g.end(), [&](double x) { return x > m / 2.5 && x < 2.5 * m; });
}

/// Whether the settings (m) and periods (s) read as rods pivoted at an end:
/// as lengths, 2/3 of them (the rod's equivalent length, Kelley Eq. 45).
bool fits_rod_length(const std::vector<double>& l, const std::vector<double>& t) {
  std::vector<double> equivalent(l);
  for (double& x : equivalent) x *= 2.0 / 3.0;
  return fits_length(equivalent, t);
}

/// Whether the settings (m) and periods (s) read as pivot distances: every
/// k^2 positive, the largest less than twice the smallest.
bool fits_pivot_distance(const std::vector<double>& h, const std::vector<double>& t) {
  const std::vector<double> k2 = row_k2(h, t);
  const auto [lo, hi] = std::minmax_element(k2.begin(), k2.end());
  return *lo > 0.0 && *hi < 2.0 * *lo;
}

/// Whether positions (m) span a body whose periods are these: 5 cm to twice
/// the longest equivalent length.
bool fits_pivot_position(const std::vector<double>& x, const std::vector<double>& t) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  const double l = length_for_period(*std::max_element(t.begin(), t.end()), kStandardGravity);
  return *hi - *lo >= 0.05 && *hi - *lo <= 2.0 * l;
}

/// How a setting column without a unit gets one, a row per setting in
/// kSettingInfo's order: whether its values (m) fit the periods (s), and
/// what only the right unit gives.
struct UnitCheck {
  Setting setting;
  bool (*fits)(const std::vector<double>& x, const std::vector<double>& t);
  const char* alone;  ///< the note's reason: "in that unit alone ..."
};
constexpr UnitCheck kUnitChecks[] = {
    {Setting::length, fits_length, "in that unit alone 4 pi^2 L/T^2 is a g near the Earth's"},
    {Setting::pivot_distance, fits_pivot_distance, "in that unit alone the pivots give one radius of gyration"},
    {Setting::pivot_position, fits_pivot_position, "in that unit alone the positions span a body of these periods"},
    {Setting::rod_length, fits_rod_length, "in that unit alone 4 pi^2 (2L/3)/T^2 is a g near the Earth's"},
};
constexpr bool unit_checks_follow_settings() {
  if (std::size(kUnitChecks) != std::size(kSettingInfo)) return false;
  for (std::size_t i = 0; i < std::size(kUnitChecks); ++i) {
    if (kUnitChecks[i].setting != kSettingInfo[i].setting) return false;
  }
  return true;
}
static_assert(unit_checks_follow_settings(), "kUnitChecks has a row for each setting, in kSettingInfo's order");

const UnitCheck& unit_check(Setting s) { return kUnitChecks[static_cast<int>(s)]; }

/// The step of the printed digits of `v`: 10^-k for the fewest decimals k
/// (0 to 6) that write every value ("12.74" and "12.7" give 0.01).
double printed_resolution(const std::vector<double>& v) {
  double step = 1.0;
  for (int k = 0; k < 6; ++k, step /= 10.0) {
    const bool whole = std::all_of(v.begin(), v.end(), [&](double x) {
      const double n = x / step;
      return std::fabs(n - std::round(n)) <= 1e-6 * std::max(1.0, std::fabs(n));
    });
    if (whole) return step;
  }
  return step;
}

std::vector<double> scaled(const std::vector<double>& v, double f) {
  std::vector<double> out(v);
  for (double& x : out) x *= f;
  return out;
}

/// Whether a length column in `unit` may be in `s`: `unit` itself, or, for
/// "" (a unit the numbers decide), a metric one (in and ft only if said).
bool unit_allowed(const Scale& s, const std::string& unit) {
  const std::string name = s.name;
  return unit.empty() ? name == "m" || name == "cm" || name == "mm" : unit == name;
}

/// Whether `l` in `unit` ("" for any of m, cm, mm: a unit from the numbers)
/// reads as the lengths of the periods t (s).
bool lengths_fit(const std::vector<double>& l, const std::string& unit, const std::vector<double>& t) {
  return std::any_of(std::begin(kLengthUnits), std::end(kLengthUnits), [&](const Scale& s) {
    return unit_allowed(s, unit) && fits_length(scaled(l, s.factor), t);
  });
}

/// Counts students time: the N of a time of N swings taken from the numbers.
constexpr int kSwingCounts[] = {2, 3, 4, 5, 6, 8, 10, 12, 15, 20, 25, 30, 40, 50, 100};

/// The N of times of N swings that no header or option names ("trial1",
/// "1st run (second)"): the count whose times/N beside the lengths in
/// `unit` ("" any metric one) give the g nearest the Earth's; 0 when no
/// count makes them a pendulum's.
int swings_in(const std::vector<double>& l, const std::string& unit, const std::vector<double>& times) {
  int best = 0;
  double nearest = HUGE_VAL;
  for (const int n : kSwingCounts) {
    const std::vector<double> t = scaled(times, 1.0 / n);
    for (const Scale& s : kLengthUnits) {
      if (!unit_allowed(s, unit) || !fits_length(scaled(l, s.factor), t)) continue;
      const double miss = std::fabs(std::log(median_of(row_g(scaled(l, s.factor), t)) / kStandardGravity));
      if (miss < nearest) nearest = miss, best = n;
    }
  }
  return best;
}

/// The sizes |x| of signed values (a release to either side).
std::vector<double> sizes(const std::vector<double>& v) {
  std::vector<double> out(v);
  for (double& x : out) x = std::fabs(x);
  return out;
}

/// y = slope x + intercept fitted unweighted (fit_straight_line with equal
/// uncertainties), and the residual sum of squares of t about its curve
/// `at` (t itself where the line is in t).
template <class At>
std::pair<StraightLine, double> unweighted_line(const std::vector<double>& x, const std::vector<double>& y,
                                                const std::vector<double>& t, At at) {
  const StraightLine line = fit_straight_line(x, y, std::vector<double>(x.size(), 0.0), std::vector<double>(x.size(), 1.0), true);
  double rss = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) rss += std::pow(t[i] - at(line, i), 2);
  return {line, rss};
}

/// T = a + b x^2 fitted unweighted to the sizes x and periods t: c = b/a,
/// its standard uncertainty from the scatter about the line (n - 2 degrees
/// of freedom), and that scatter's sum of squares; empty below four points.
struct QuadraticRise {
  double c, sigma_c, rss;
};
std::optional<QuadraticRise> quadratic_rise(const std::vector<double>& x, const std::vector<double>& t) {
  const std::size_t n = x.size();
  if (n < 4) return std::nullopt;
  std::vector<double> u(n);
  for (std::size_t i = 0; i < n; ++i) u[i] = x[i] * x[i];
  const auto [line, rss] = unweighted_line(u, t, t, [&](const StraightLine& l, std::size_t i) { return l.intercept + l.slope * u[i]; });
  if (!std::isfinite(line.slope) || !std::isfinite(line.intercept)) return std::nullopt;
  const double var_b = rss / static_cast<double>(n - 2) * line.var_slope;
  return QuadraticRise{line.slope / line.intercept, std::sqrt(var_b) / line.intercept, rss};
}

/// The residual sum of squares of the periods t about a pivot scan's curve
/// through them: T^2 h = (4 pi^2/g)(k^2 + h^2) is a line in h^2 (Kelley
/// Eq. 55), fitted unweighted, whatever the unit of h.
double pivot_scan_rss(const std::vector<double>& h, const std::vector<double>& t) {
  std::vector<double> x(h.size()), y(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) x[i] = h[i] * h[i], y[i] = t[i] * t[i] * h[i];
  return unweighted_line(x, y, t, [&](const StraightLine& l, std::size_t i) {
           return std::sqrt(std::max((l.intercept + l.slope * x[i]) / h[i], 0.0));
         }).second;
}

/// Whether a headerless first column reads as release angles beside these
/// periods rather than as a setting: no length in any unit (nor times of N
/// swings beside one), sizes up to 90 spanning a factor 3 or more, periods
/// within 25 % of each other (the exact law rises 18 % from 0 to 90 deg)
/// that do not fall as the size grows, and that the quadratic in the size
/// follows better than a pivot scan's curve in it (a pivot scan about its
/// least period is as flat, but U-shaped).
bool reads_as_amplitudes(const std::vector<double>& a, const std::vector<double>& t) {
  const std::vector<double> x = sizes(a);
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  const auto [t_lo, t_hi] = std::minmax_element(t.begin(), t.end());
  if (!(*hi <= 90.0 && *hi >= 3.0 * *lo && *t_lo > 0.0 && *t_hi <= 1.25 * *t_lo)) return false;
  if (lengths_fit(a, "", t) || swings_in(a, "", t) > 0) return false;
  const auto rise = quadratic_rise(x, t);
  if (!rise) return true;
  return rise->c >= 0.0 && (!(*lo > 0.0) || rise->rss <= pivot_scan_rss(x, t));
}

/// The unit of a sweep's amplitudes between 0.35 and 1.6, where their size
/// alone cannot say (docs/series.md, "Amplitude sweeps"): radians where the
/// periods rise with them, beyond 3 sigmas, as the law says in radians
/// (within a factor 3 of c = 1/16 per rad^2; in degrees the law's rise is
/// 3283 times smaller); empty where the rise does not decide.
std::string sweep_angle_unit(const std::vector<double>& a, const std::vector<double>& t) {
  const auto rise = quadratic_rise(sizes(a), t);
  if (!rise || !(rise->c > 3.0 * rise->sigma_c)) return "";
  const double law = 1.0 / 16.0;
  return rise->c > law / 3.0 && rise->c < 3.0 * law ? "rad" : "";
}

/// Whether d = b - a at every row, to the printed digits' rounding, and d
/// is positive (b - a = d also makes a = b - d: the caller prefers as the
/// period a column whose name is no stamp's, then the least).
bool is_difference(const std::vector<double>& d, const std::vector<double>& b, const std::vector<double>& a) {
  if (d.empty()) return false;
  const double step = std::max({printed_resolution(d), printed_resolution(b), printed_resolution(a)});
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (!(d[i] > 0.0) || !(std::fabs(b[i] - a[i] - d[i]) <= 1.5 * step)) return false;
  }
  return true;
}

/// Whether the first data row separates its cells by tabs and by single
/// spaces both ("0.6<TAB>1.54 0.01 0.4", a course template's): read as runs of spaces.
bool tabs_and_spaces(std::string_view text) {
  try {
    const HeaderLines lines = find_header(text, "");
    if (lines.header) return false;
    const std::string_view row = trim_cell(data_rows(text, lines, "", "").first);
    return row.find('\t') != std::string_view::npos && row.find(' ') != std::string_view::npos &&
           row.find_first_of(",;") == std::string_view::npos;
  } catch (const InputError&) {
    return false;  // the reader proper says what is wrong
  }
}

/// Whether a header row holds units alone ("(m)", "[s]", or empty cells):
/// the names are on the line above it.
bool units_row(const std::vector<Column>& cols) {
  const bool all = std::all_of(cols.begin(), cols.end(), [](const Column& c) {
    return c.name.empty() || (c.word.empty() && !c.unit.empty());
  });
  return all && std::any_of(cols.begin(), cols.end(), [](const Column& c) { return !c.unit.empty(); });
}

/// The roles of a headerless table's columns from the units its cells
/// carry ("10cm,0.68s,0.63s,7.38%,8.50"): the first length the setting, the
/// first time the periods (a second, a theory's, unused), the first angle
/// the amplitude; a percentage or a bare number (a per-row g) unused.
std::vector<Use> roles_by_cell_units(const std::vector<std::string>& units) {
  std::vector<Use> use(units.size());
  bool setting = false, time = false, amplitude = false;
  for (std::size_t j = 0; j < units.size(); ++j) {
    Use& u = use[j];
    const std::string& unit = units[j];
    if (factor_of(kLengthUnits, unit) && !setting) {
      u.kind = Kind::setting, setting = true, u.why = "the first column whose cells carry a length's unit";
    } else if (factor_of(kTimeUnits, unit) && !time) {
      u.kind = Kind::time, time = true, u.why = "the first column whose cells carry a time's unit";
    } else if (factor_of(kAngleUnits, unit) && !amplitude) {
      u.kind = Kind::amplitude, amplitude = true, u.why = "the first column whose cells carry an angle's unit";
    } else {
      u.why = unit.empty() ? "bare numbers beside cells with units (a per-row result?)"
                           : "cells in " + unit + " beside the setting and the periods already read";
    }
  }
  return use;
}

/// The roles of a headerless table's columns, from their numbers: the
/// setting first, each next column the uncertainty of the one before it
/// where its numbers read so, else the times, else the amplitude; but
/// the periods first where only that order makes a pendulum (a period's
/// 0.5-2 s beside lengths in cm), and x, y, sigma x, sigma y (every fitting
/// program's order) where the third and fourth read as the first two's
/// uncertainties and the second as none.
std::vector<Use> headerless_order(const std::vector<std::vector<double>>& c) {
  std::vector<Use> use(c.size());
  auto role = [&](std::size_t j, Kind kind, bool uncertainty, const char* why) {
    use[j].kind = kind, use[j].uncertainty = uncertainty, use[j].why = why;
  };
  if (c.size() == 4 && !reads_as_uncertainty(c[1], c[0]) && reads_as_uncertainty(c[2], c[0]) &&
      reads_as_uncertainty(c[3], c[1])) {
    role(0, Kind::setting, false, "the first of x, y, sigma x, sigma y (a fitting program's order)");
    role(1, Kind::time, false, "the second of x, y, sigma x, sigma y");
    role(2, Kind::setting, true, "the third of x, y, sigma x, sigma y: below a third of the first");
    role(3, Kind::time, true, "the fourth of x, y, sigma x, sigma y: below a third of the second");
    return use;
  }
  if (c.size() == 2 && !lengths_fit(c[0], "", c[1]) && swings_in(c[0], "", c[1]) == 0 && lengths_fit(c[1], "", c[0])) {
    role(0, Kind::time, false, "the periods: only they beside the second as lengths make a pendulum");
    role(1, Kind::setting, false, "the lengths: only they beside the first as periods make a pendulum");
    return use;
  }
  role(0, Kind::setting, false, "the first column");
  std::size_t last = 0;
  bool time = false, amplitude = false;
  for (std::size_t j = 1; j < c.size(); ++j) {
    // An uncertainty only where a column is left for the periods.
    if (!use[last].uncertainty && (time || j + 1 < c.size()) && reads_as_uncertainty(c[j], c[last])) {
      role(j, use[last].kind, true, "below a third of the column before it: its uncertainty");
    } else if (!time) {
      role(j, Kind::time, false, "the first column after the setting that is no uncertainty"), time = true;
    } else if (!amplitude) {
      role(j, Kind::amplitude, false, "after the periods"), amplitude = true;
    } else {
      use[j].why = "a column the reader has no role for";
      continue;
    }
    last = j;
  }
  return use;
}

/// The rows of `t` with each row's trials (the column `time` and those in
/// `trials`, an empty cell skipped) as rows of their own, the other cells
/// repeated; origin[i] is the row of `t` that row i comes from.
Table trial_rows(const Table& t, std::size_t time, const std::vector<std::size_t>& trials, std::vector<std::size_t>& origin) {
  Table out;
  out.columns.resize(t.columns.size());
  for (std::size_t i = 0; i < t.rows; ++i) {
    for (std::size_t k = 0; k <= trials.size(); ++k) {
      const double v = t.columns[k == 0 ? time : trials[k - 1]][i];
      if (std::isnan(v)) continue;
      for (std::size_t j = 0; j < t.columns.size(); ++j) out.columns[j].push_back(j == time ? v : t.columns[j][i]);
      origin.push_back(i);
      ++out.rows;
    }
  }
  return out;
}

/// The header's columns, a trailing delimiter's empty one dropped; under
/// a units row ("(m),,," below "Length,Time,..."), the names of the line
/// above with the units of that row.
std::vector<Column> header_columns(const HeaderLines& lines, const Dialect& dialect, const InputLimits& limits,
                                   const std::string& file) {
  auto columns_of = [&](std::string_view line) {
    std::vector<Column> cols;
    const std::size_t line_no = line.data() == lines.header->data() ? lines.header_line : lines.above_line;
    for (std::string_view cell : split_cells_within(line, dialect, limits, file, line_no)) cols.push_back(classify(cell));
    while (cols.size() > 1 && cols.back().name.empty()) cols.pop_back();
    return cols;
  };
  std::vector<Column> cols = columns_of(*lines.header);
  if (!lines.above || !units_row(cols)) return cols;
  std::vector<Column> named = columns_of(*lines.above);
  for (std::size_t j = 0; j < std::min(named.size(), cols.size()); ++j) {
    if (!cols[j].unit.empty()) named[j].unit = cols[j].unit;
  }
  return named;
}

/// N where a[i] = N b[i] at every row within 1 % (a whole N of 2 or
/// more: a time of N swings beside its period), else 0.
int whole_ratio(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.empty() || !(b[0] > 0.0)) return 0;
  const double n = std::round(a[0] / b[0]);
  if (n < 2.0) return 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!(std::fabs(a[i] / (n * b[i]) - 1.0) < 0.01)) return 0;
  }
  return static_cast<int>(n);
}

/// The setting a --columns word declares (its letter or its key), if any.
const SettingInfo* setting_declared(const std::string& word) {
  for (const SettingInfo& s : kSettingInfo) {
    if (word == s.letter || word == s.key) return &s;
  }
  return nullptr;
}

}  // namespace

std::string table_column_roles() {
  std::string out;
  for (const SettingInfo& s : kSettingInfo) out += std::string(out.empty() ? "" : ", ") + s.letter + " (" + s.words + ")";
  return out + ", T (period), tN (time of N oscillations: t10), theta (amplitude), u (the uncertainty of the column "
               "before)";
}

std::vector<TableColumnChoice> parse_table_column_spec(const std::string& spec, const std::string& where) {
  std::vector<TableColumnChoice> out;
  std::string previous;
  std::size_t start = 0, column = 0;
  for (;;) {
    ++column;
    const std::size_t comma = spec.find(',', start);
    std::string entry = spec.substr(start, comma == std::string::npos ? comma : comma - start);
    entry.erase(0, entry.find_first_not_of(' '));
    entry.erase(entry.find_last_not_of(' ') + 1);
    if (!entry.empty() && entry != "-") {
      const std::size_t colon = entry.find(':');
      const std::string word = lower_case(entry.substr(0, colon));
      TableColumnChoice c;
      c.column = column;
      c.unit = colon == std::string::npos ? std::string() : normal_unit(entry.substr(colon + 1));
      const SettingInfo* setting = setting_declared(word);
      if (setting) c.role = setting->key;
      else if (word == "t" || word == "period") c.role = "period";
      else if (word == "theta" || word == "amplitude") c.role = "amplitude";
      else if (const int n = oscillations_in(word); n > 0 && word[0] == 't') c.role = "time", c.oscillations = n;
      else if (word == "u" && !previous.empty()) c.role = previous + "_uncertainty";
      else {
        throw InputError(where, "got the column \"" + one_line(entry, 40) +
                                    "\"; expected " + table_column_roles() +
                                    ", or - for a column not used; each with :unit if wanted");
      }
      if (c.role.find("_uncertainty") == std::string::npos) previous = c.role;
      out.push_back(c);
    }
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

/// Whether the rows at each length are readings of their own, not repeats
/// of one: the rows (`period_s`, one oscillation's, s; its stated standard
/// uncertainty `sigma_s`, s; `length_m`, m; in the observations' order, `obs`
/// giving how many rows each holds; three lengths or more with repeats)
/// scattering about their length's mean beyond their stated uncertainty
/// (chi2, probability below 1 %), and as a length's error would, sigma^2 +
/// (T/2L)^2 tau^2, rather than as a stopwatch's, sigma^2 + s^2 with one s for
/// every length: the rows' spread about their means at least e times as
/// likely at the better tau as at the better s (one parameter each, so
/// neither model is favoured by its size). A class's pooled table, each
/// group's tape to its own point of the bob (issue 39's real table: rows at
/// 30 cm from 0.96 to 1.11 s, at 4 m within 0.05 s). Then `tau` is that
/// length's error (m).
bool readings_of_their_own(const std::vector<TableObservation>& obs, const std::vector<double>& period_s,
                           const std::vector<double>& sigma_s, const std::vector<double>& length_m, double& tau) {
  double chi2 = 0.0, nu = 0.0, largest = 0.0;
  std::vector<std::array<double, 4>> groups;  // n - 1, spread's sum of squares (s^2), stated variance (s^2), (T/2L)^2
  for (std::size_t k = 0, row = 0; k < obs.size(); row += obs[k].times.size(), ++k) {
    const std::size_t n = obs[k].times.size();
    if (n < 2) continue;
    double mean = 0.0, ss = 0.0, stated = 0.0;
    for (std::size_t i = row; i < row + n; ++i) mean += period_s[i] / static_cast<double>(n);
    for (std::size_t i = row; i < row + n; ++i) {
      ss += (period_s[i] - mean) * (period_s[i] - mean);
      chi2 += std::pow((period_s[i] - mean) / sigma_s[i], 2);
      stated += sigma_s[i] * sigma_s[i] / static_cast<double>(n);
    }
    const double f = std::pow(mean / (2.0 * length_m[row]), 2);
    groups.push_back({static_cast<double>(n - 1), ss, stated, f});
    nu += static_cast<double>(n - 1), largest = std::max(largest, ss / static_cast<double>(n - 1) / std::min(f, 1.0));
  }
  if (groups.size() < 3 || !(largest > 0.0)) return false;
  const auto probability = dispersion(chi2, static_cast<int>(nu)).probability;
  if (!probability || !(*probability < kOverDispersedProbability)) return false;
  // Each model's log-likelihood at its best excess variance x (golden
  // section over [0, the largest group's variance per unit of its factor]).
  auto best = [&](bool by_length) {
    auto log_likelihood = [&](double x) {
      double sum = 0.0;
      for (const auto& [v, ss, stated, f] : groups) {
        const double var = stated + x * (by_length ? f : 1.0);
        sum -= 0.5 * (v * std::log(var) + ss / var);
      }
      return sum;
    };
    const double golden = (std::sqrt(5.0) - 1.0) / 2.0;
    double a = 0.0, b = largest;
    for (int i = 0; i < 100; ++i) {
      const double c = b - golden * (b - a), d = a + golden * (b - a);
      const bool left = log_likelihood(c) > log_likelihood(d);
      (left ? b : a) = left ? d : c;
    }
    return std::pair{log_likelihood((a + b) / 2.0), (a + b) / 2.0};
  };
  const auto [length, tau2] = best(true);
  tau = std::sqrt(tau2);
  return length - best(false).first >= 1.0;
}

/// g from `theirs` over g from `periods` (s), each from the line T^2 against
/// the lengths (m) weighted as equal errors in T (sigma of T^2 = 2T sigma,
/// the least squares in T that reduce fits, to first order), with an
/// intercept where three or more lengths differ, as a length series fits
/// its offset; empty at fewer than two lengths.
std::optional<double> textbook_g_ratio(const std::vector<double>& lengths, const std::vector<double>& theirs,
                                       const std::vector<double>& periods) {
  std::vector<double> x, ours2, theirs2, ours_sigma, their_sigma;
  for (std::size_t i = 0; i < periods.size(); ++i) {
    if (!std::isfinite(theirs[i]) || !std::isfinite(periods[i])) continue;
    x.push_back(lengths[i]);
    ours2.push_back(periods[i] * periods[i]);
    theirs2.push_back(theirs[i] * theirs[i]);
    ours_sigma.push_back(2.0 * periods[i]);
    their_sigma.push_back(2.0 * theirs[i]);
  }
  std::vector<double> distinct(x);
  std::sort(distinct.begin(), distinct.end());
  const std::size_t n = std::unique(distinct.begin(), distinct.end()) - distinct.begin();
  if (n < 2) return std::nullopt;
  const std::vector<double> zero(x.size(), 0.0);
  const double ours_slope = fit_straight_line(x, ours2, zero, ours_sigma, n >= 3).slope,
               their_slope = fit_straight_line(x, theirs2, zero, their_sigma, n >= 3).slope;
  return std::isfinite(ours_slope / their_slope) ? std::optional<double>(ours_slope / their_slope) : std::nullopt;
}

/// Compares a second period column's periods (s) with the ones read, row
/// by row: their mean difference against its standard error (the
/// differences' scatter over sqrt n). Within 3 of them, or 10^-4 of the
/// period, `second`'s why says they agree; else a warning gives both and
/// the difference: two timings of the same swings that disagree, one of
/// which --columns picks. `lengths` (m), for a length series: the g each
/// column gives is compared too (textbook_g_ratio).
void compare_periods(Use& second, const std::string& name, const std::string& used_name,
                     const std::vector<double>& theirs, const std::vector<double>& periods,
                     const std::vector<double>* lengths, std::vector<RecordingNote>& warnings) {
  std::vector<double> d;
  for (std::size_t i = 0; i < periods.size(); ++i) {
    if (std::isfinite(theirs[i]) && std::isfinite(periods[i])) d.push_back(theirs[i] - periods[i]);
  }
  if (d.size() < 2) return;
  double mean = 0.0, var = 0.0;
  for (double x : d) mean += x / d.size();
  for (double x : d) var += (x - mean) * (x - mean) / (d.size() - 1.0);
  const double error = std::sqrt(var / d.size()), typical = median_of(periods);
  std::string by = format_number(mean, 3) + " s on average (" +
                   (error > 0.0 ? format_number(std::fabs(mean) / error, 3) + " standard errors" : "exactly");
  if (const auto ratio = lengths ? textbook_g_ratio(*lengths, theirs, periods) : std::nullopt) {
    by += "; read instead, g from the fit of T against L is " + format_number(std::fabs(*ratio - 1.0) * 100.0, 2) + " % " +
          (*ratio > 1.0 ? "higher" : "lower");
  }
  by += ")";
  if (std::fabs(mean) <= std::max(3.0 * error, 1e-4 * typical)) {
    second.why += "; its periods agree with it: they differ by " + by;
    return;
  }
  warnings.push_back({0, "\"" + name + "\" times the same rows " + format_number(mean / typical * 100.0, 3) +
                             " % " + (mean > 0.0 ? "longer" : "shorter") + " than \"" + used_name +
                             "\", which is read: they differ by " + by + "; two timings that disagree (--columns "
                             "reads the other)"});
  second.why += "; its periods differ from it by " + by;
}

/// Compares each derived column (Derived) with what its row's length and
/// period give, T^2 or 4 pi^2 L/T^2 (`g`, m/s^2; no amplitude taken off:
/// the textbook's), a row of several trials by their mean period, as its
/// working took them. Within 2 % at every row its why says so: a working
/// rounded to three figures is within 0.5 %, a slip in one (a digit, a
/// length in other units, another formula) is off by more. Beyond, a
/// warning names the line furthest off and both values. A unit other than
/// s^2 or m/s^2 (or none) is not compared, and the why says so.
template <class LineOf>
void compare_derived(std::vector<Use>& use, const std::vector<std::string>& names, const Table& table,
                     const std::vector<double>& meters, const std::vector<double>& periods, const LineOf& line_of,
                     std::vector<RecordingNote>& warnings) {
  // One entry per line of the file: its length, its trials' summed periods and count, its first row.
  struct Row {
    std::size_t line, first;
    double length, periods = 0.0;
    int trials = 0;
  };
  std::vector<Row> rows;
  for (std::size_t i = 0; i < periods.size(); ++i) {
    if (rows.empty() || rows.back().line != line_of(i)) rows.push_back({line_of(i), i, meters[i]});
    if (std::isfinite(periods[i])) rows.back().periods += periods[i], ++rows.back().trials;
  }
  for (std::size_t j = 0; j < use.size(); ++j) {
    Use& u = use[j];
    if (u.derived == Derived::none) continue;
    const bool squared = u.derived == Derived::period_squared;
    const std::string unit = squared ? "s^2" : "m/s^2";
    if (!u.unit.empty() && u.unit != unit && !(squared && u.unit == "s\xc2\xb2")) {
      u.why += "; not compared (its unit " + u.unit + ")";
      continue;
    }
    const Row* worst = nullptr;
    double off = 0.0, ours_at = 0.0;
    for (const Row& r : rows) {
      if (r.trials == 0) continue;
      const double t = r.periods / r.trials, theirs = table.columns[j][r.first];
      const double ours = squared ? t * t : gravity_for_period(r.length, t);
      if (!std::isfinite(theirs) || !(ours > 0.0)) continue;
      if (const double d = std::fabs(theirs / ours - 1.0); !worst || d > off) worst = &r, off = d, ours_at = ours;
    }
    if (!worst) continue;
    const std::string what = squared ? "T^2" : "4 pi^2 L/T^2";
    if (off <= 0.02) {
      u.why += "; compared with each row's " + what + ": within " + format_number(std::max(off * 100.0, 0.01), 2) +
               " % at every row";
      continue;
    }
    const std::string line = "line " + std::to_string(worst->line);
    warnings.push_back({worst->line, "\"" + names[j] + "\" at " + line + ": " +
                                         format_number(table.columns[j][worst->first], 6) + " " + unit +
                                         " where its row's " + what + " is " + format_number(ours_at, 6) + " " + unit +
                                         " (" + format_number(off * 100.0, 2) + " % off, the most of its rows): a slip "
                                         "in the working, or another formula? Not read"});
    u.why += "; compared with each row's " + what + ": " + format_number(off * 100.0, 2) + " % off at " + line;
  }
}

SettingsTable parse_settings_table(std::string_view text, const std::string& file, const TableOptions& options) {
  text = strip_bom(text);
  std::string spaced;  // a copy whose tabs are spaces, where both separate cells
  if (tabs_and_spaces(text)) {
    spaced.assign(text);
    std::replace(spaced.begin(), spaced.end(), '\t', ' ');
    text = spaced;
  }
  const HeaderLines lines = find_header(text, file);
  const DataRows data = data_rows(text, lines, file, "a table of settings and periods");
  const Dialect dialect = sniff(lines.header, data.first);

  std::vector<Column> cols;
  if (lines.header) {
    cols = header_columns(lines, dialect, options.limits, file);
  } else {
    cols.resize(split_cells_within(data.first, dialect, options.limits, file, lines.data_line).size());
  }
  std::vector<std::string> names(cols.size());  // as messages quote them
  for (std::size_t j = 0; j < cols.size(); ++j) names[j] = column_label(cols[j].name, j + 1);
  Table table = read_rows(data.begin, data.end, lines.data_line, dialect, names, file, options.limits);
  for (std::size_t j = 0; j < cols.size(); ++j) {
    if (cols[j].unit.empty()) cols[j].unit = table.cell_units[j];
  }
  while (cols.size() > 1 && std::none_of(table.columns.back().begin(), table.columns.back().end(),
                                         [](double v) { return std::isfinite(v); })) {
    cols.pop_back(), names.pop_back(), table.columns.pop_back();
  }
  const std::size_t header_line = lines.header ? lines.header_line : lines.data_line;
  auto refuse = [&](const std::string& message) { fail(file, header_line, 1, message); };
  if (table.rows < 2) {
    fail(file, lines.data_line, 1, "a table of " + std::to_string(table.rows) +
                                       " row; expected a row per timing, two or more (one timing is a scene's "
                                       "timing: pendulum-g template prints one)");
  }

  auto listed = [&] {
    std::string all;
    for (const auto& n : names) all += (all.empty() ? "\"" : ", \"") + n + "\"";
    return all;
  };
  // Roles: the option's, else the header's words, else the numbers'.
  std::vector<Use> use(cols.size());
  if (!options.columns.empty()) {
    for (Use& u : use) u.decided = "option", u.why = "not declared";
    for (const TableColumnChoice& c : options.columns) {
      std::size_t j = c.column;
      if (j == 0) {
        const auto named = std::find_if(cols.begin(), cols.end(), [&](const auto& col) { return col.name == c.name; });
        if (named == cols.end()) {
          refuse("the column \"" + one_line(c.name, 40, true) + "\" declared for " + c.role +
                 " is not in the header; expected one of " + listed());
        }
        j = static_cast<std::size_t>(named - cols.begin()) + 1;
      }
      if (j > cols.size()) {
        refuse("column " + std::to_string(j) + " declared for " + c.role + "; expected at most the table's " +
               std::to_string(cols.size()) + " columns");
      }
      Use& u = use[j - 1];
      u = Use{};
      u.decided = "option";
      const std::string base = c.role.substr(0, c.role.find("_uncertainty"));
      u.uncertainty = base.size() != c.role.size();
      if (const SettingInfo* setting = setting_declared(base)) {
        u.kind = Kind::setting;
        u.setting = setting->setting;
      } else if (base == "period" || base == "time") {
        u.kind = Kind::time;
        u.oscillations = base == "period" ? 1 : c.oscillations;
      } else if (base == "amplitude") {
        u.kind = Kind::amplitude;
      }
      u.unit = c.unit;
    }
  } else if (lines.header && !generic_names(cols)) {
    const Use* last = nullptr;
    for (std::size_t j = 0; j < cols.size(); ++j) {
      Use& u = use[j] = from_header(cols[j]);
      if (u.uncertainty && u.kind == Kind::unused) {
        // "σ" alone: the uncertainty of the column before it.
        if (last && last->derived != Derived::none) {
          u.uncertainty = false, u.why = "the uncertainty of a student's working before it: not read";
        } else if (last && !last->uncertainty) {
          u.kind = last->kind, u.setting = last->setting, u.oscillations = last->oscillations;
          u.why = "the uncertainty of the column before it";
        } else {
          u.uncertainty = false, u.why = "an uncertainty of no column before it";
        }
      }
      if (u.kind != Kind::unused || u.derived != Derived::none) last = &u;
    }
  } else {
    // Headerless: a setting first, then each column the uncertainty of the
    // one before it where its numbers read so, else the times, else the amplitude.
    for (Use& u : use) u.decided = "content";
    if (cols.size() < 2 || cols.size() > 5) {
      refuse("a headerless table of " + std::to_string(cols.size()) + " column" + (cols.size() == 1 ? "" : "s") +
             "; expected 2 to 5 (a setting, its uncertainty, the periods, theirs, the amplitude), or a header, or "
             "the columns named: --columns (a scene's \"columns\"), e.g. \"l:m,T:s\"");
    }
    const auto order = std::any_of(table.cell_units.begin(), table.cell_units.end(), [](const auto& u) { return !u.empty(); })
                           ? roles_by_cell_units(table.cell_units)
                           : headerless_order(table.columns);
    for (std::size_t j = 0; j < order.size(); ++j) {
      Use& u = use[j];
      u.kind = order[j].kind, u.uncertainty = order[j].uncertainty, u.why = order[j].why;
      u.unit = cols[j].unit;  // the cells' own, if any
    }
    const auto periods = std::find_if(use.begin(), use.end(), [](const Use& u) { return u.kind == Kind::time && !u.uncertainty; });
    if (use[0].kind == Kind::setting && periods != use.end() &&
        reads_as_amplitudes(table.columns[0], table.columns[static_cast<std::size_t>(periods - use.begin())])) {
      for (Use& u : use) {
        if (u.kind == Kind::setting) u.kind = Kind::amplitude;
      }
      use[0].why = "release angles (an amplitude sweep): no length in any unit, at most 90, beside periods within 25 % "
                   "of each other that do not fall as the angle grows";
    }
  }
  // Stamps read off a trace beside their difference ("time1, time2, time"):
  // the difference is the period, the stamps are not. Of the columns that
  // are such a difference, the period is one whose name has no number (the
  // stamps are numbered), then the least; among a few time columns only,
  // and never over columns the option declared.
  if (options.columns.empty()) {
    std::vector<std::size_t> times;
    for (std::size_t j = 0; j < use.size(); ++j) {
      if (use[j].kind == Kind::time && !use[j].uncertainty) times.push_back(j);
    }
    std::optional<std::array<std::size_t, 3>> best;  // k = j - i
    auto rank = [&](std::size_t k) { return std::pair{use[k].oscillations != 0 || use[k].trial, median_of(table.columns[k])}; };
    for (std::size_t k : times.size() >= 3 && times.size() <= 8 ? times : std::vector<std::size_t>{}) {
      for (std::size_t i : times) {
        for (std::size_t j : times) {
          if (i == j || i == k || j == k || !is_difference(table.columns[k], table.columns[j], table.columns[i])) continue;
          if (!best || rank(k) < rank((*best)[0])) best = std::array<std::size_t, 3>{k, i, j};
        }
      }
    }
    if (best) {
      const auto [k, i, j] = *best;
      for (const std::size_t stamp : {i, j}) {
        use[stamp].kind = Kind::unused, use[stamp].trial = false;
        use[stamp].why = "a time stamp: column " + std::to_string(k + 1) + " is column " + std::to_string(j + 1) +
                         " minus column " + std::to_string(i + 1) + " at every row, the period between them";
      }
      use[k].oscillations = 0;  // "time" of none: a period
    }
  }
  // One column of each role: the first, but of a time of N swings beside
  // its period ("L, t, T": t/N = T), the period. A second period column
  // (Tracker's beside phyphox's) is compared once the periods are read.
  std::vector<std::pair<std::size_t, Use>> second_times;
  for (std::size_t j = 0; j < use.size(); ++j) {
    for (std::size_t i = 0; i < j && use[j].kind != Kind::unused; ++i) {
      if (same(use[i], use[j]) && use[i].kind == Kind::time && !use[i].uncertainty && !use[i].trial) {
        const int n_i = whole_ratio(table.columns[i], table.columns[j]), n_j = whole_ratio(table.columns[j], table.columns[i]);
        if (n_i > 1 || n_j > 1) {
          const std::size_t times = n_i > 1 ? i : j, periods = n_i > 1 ? j : i;
          const int n = std::max(n_i, n_j);
          use[times].kind = Kind::unused;
          use[times].why = "the time of " + std::to_string(n) + " oscillations beside the periods of column " +
                           std::to_string(periods + 1) + " (t/" + std::to_string(n) + " = T at every row within 1 %)";
          continue;
        }
      }
      if (same(use[i], use[j])) {
        if (use[j].kind == Kind::time && !use[j].uncertainty && !use[j].trial) second_times.emplace_back(j, use[j]);
        use[j].why = "a second " + quantity_name(use[j]) + " column: column " + std::to_string(i + 1) + " is used";
        use[j].kind = Kind::unused, use[j].uncertainty = false;
      }
    }
  }
  auto find = [&](Kind kind, bool uncertainty) -> std::optional<std::size_t> {
    for (std::size_t j = 0; j < use.size(); ++j) {
      if (use[j].kind == kind && use[j].uncertainty == uncertainty) return j;
    }
    return std::nullopt;
  };
  const auto setting_col = find(Kind::setting, false);
  const auto time_col = find(Kind::time, false);
  const auto amplitude_col = find(Kind::amplitude, false), amplitude_u = find(Kind::amplitude, true);
  if (!setting_col && !amplitude_col) {
    refuse("no setting column (length, pivot distance or pivot position) among " + listed() +
           "; expected one, e.g. \"L (m)\", \"h (cm)\", \"pivot position (cm)\", or an amplitude for an "
           "amplitude sweep (\"theta (deg)\"), or the columns named: --columns (a scene's \"columns\"), e.g. \"l:cm,T:s\"");
  }
  if (!time_col) {
    refuse("no period column among " + listed() + "; expected the periods (\"T (s)\") or the times of N "
           "oscillations (\"t10 (s)\", or --oscillations N), or the columns named: --columns (a scene's "
           "\"columns\"), e.g. \"l:cm,t10:s\"");
  }
  const auto setting_u = find(Kind::setting, true);
  auto time_u = find(Kind::time, true);

  SettingsTable out;
  out.rows = table.rows;
  if (lines.header && options.columns.empty() && generic_names(cols)) {
    out.warnings.push_back({header_line, "the header's names (" + listed() + ") are a fitting program's generic ones: "
                                         "the columns are read by place and their numbers, as without a header"});
  }
  // No setting beside amplitudes: one pendulum at several amplitudes.
  out.sweep = !setting_col;
  Use no_setting;
  no_setting.unit = "m";  // no length: nothing is scaled by it
  Use& su = setting_col ? use[*setting_col] : no_setting;
  Use& tu = use[*time_col];
  out.setting = su.setting;
  if (options.oscillations > 0) {
    tu.oscillations = options.oscillations;
    tu.why = "the time of " + std::to_string(options.oscillations) + " oscillations by --oscillations";
  }
  out.oscillations = std::max(tu.oscillations, 1);
  double n_osc = out.oscillations;
  // The trials' columns after the first: each row's trials are its repeats.
  std::vector<std::size_t> trials;
  for (std::size_t j = *time_col + 1; j < use.size(); ++j) {
    if (tu.trial && use[j].trial && use[j].kind == Kind::time && !use[j].uncertainty) trials.push_back(j);
  }

  // A length written once, in the first row, beside amplitudes is every
  // row's (one length measured for a sweep; elsewhere an empty cell is a
  // cell left empty), its uncertainty likewise.
  const auto setting_u_col = find(Kind::setting, true);
  if (setting_col && amplitude_col && table.rows > 1) {
    for (const auto col : {setting_col, setting_u_col}) {
      if (!col) continue;
      auto& v = table.columns[*col];
      if (std::isfinite(v[0]) && std::all_of(v.begin() + 1, v.end(), [](double x) { return std::isnan(x); })) {
        std::fill(v.begin() + 1, v.end(), v[0]);
        out.notes.push_back({0, "\"" + names[*col] + "\": written once, in the first row (line " +
                                    std::to_string(table.line(0)) + "): every row's"});
      }
    }
  }
  // Every used cell holds a number.
  for (std::size_t j = 0; j < use.size(); ++j) {
    if (use[j].kind == Kind::unused) continue;
    const auto& v = table.columns[j];
    for (std::size_t i = 0; i < table.rows; ++i) {
      if (std::isnan(v[i]) && std::find(trials.begin(), trials.end(), j) != trials.end()) continue;  // fewer trials
      if (std::isnan(v[i])) {
        fail(file, table.line(i), 1,
             "an empty cell in column \"" + names[j] + "\" (" + quantity_name(use[j]) +
                 "); expected a number in every used cell: a row without its " + quantity_name(use[j]) +
                 " is no timing (delete the row)");
      }
      // A timing's stated uncertainty weighs it in the fit: 0 would make it infinitely precise.
      const bool positive = use[j].kind == Kind::time;
      // An amplitude may be signed in a sweep (no setting, or one: releases to either side): its
      // size is used; beside settings that change, a negative one is a slip.
      const bool signed_amplitudes =
          out.sweep || std::all_of(table.columns[*setting_col].begin(), table.columns[*setting_col].end(),
                                   [&](double x) { return x == table.columns[*setting_col].front(); });
      const bool a_length = use[j].setting == Setting::length || use[j].setting == Setting::rod_length;
      const bool non_negative = (use[j].uncertainty && !positive) || (use[j].kind == Kind::setting && a_length) ||
                                (use[j].kind == Kind::amplitude && !signed_amplitudes);
      if ((positive && !(v[i] > 0.0)) || (non_negative && !(v[i] >= 0.0)) || !std::isfinite(v[i])) {
        fail(file, table.line(i), 1,
             "got " + format_number(v[i]) + " in column \"" + names[j] + "\" (" + quantity_name(use[j]) +
                 "); expected a " + (positive ? "positive" : non_negative ? "non-negative" : "finite") + " number");
      }
    }
  }
  std::vector<std::size_t> origin;  // the row of `source` each row of `table` comes from
  std::optional<Table> source;
  if (!trials.empty()) {
    source = std::move(table);
    table = trial_rows(*source, *time_col, trials, origin);
  }
  auto line_of = [&](std::size_t row) { return source ? source->line(origin[row]) : table.line(row); };
  auto refuse_cell = [&](std::size_t row, std::size_t col, const std::string& why) {
    fail(file, line_of(row), cell_column(text, line_of(row), dialect, col), "\"" + names[col] + "\": " + why);
  };

  // The time unit: the header's, else the numbers' (periods of 0.1 to 30 s).
  if (tu.unit.empty()) {
    const auto [lo, hi] = std::minmax_element(table.columns[*time_col].begin(), table.columns[*time_col].end());
    std::string plausible;
    for (const Scale& s : kTimeUnits) {
      if (std::string(s.name) == "min") continue;  // its periods overlap the seconds' of a short pendulum
      if (*lo * s.factor / n_osc >= 0.1 && *hi * s.factor / n_osc <= 30.0) plausible += plausible.empty() ? s.name : "";
    }
    if (plausible.empty()) {
      refuse("the column \"" + names[*time_col] + "\" has no unit and its " + quantity_name(tu) + "s, " +
             format_number(*lo, 4) + " to " + format_number(*hi, 4) + ", are no pendulum's in s, ms or min; "
             "expected its unit in the header (\"T (s)\") or declared: --columns (a scene's \"columns\")");
    }
    tu.unit = plausible;
    tu.decided = "content";
    out.warnings.push_back({0, "\"" + names[*time_col] + "\": no unit; read as " + plausible + " (a period of " +
                                   format_number(*lo / n_osc, 4) + " to " + format_number(*hi / n_osc, 4) + " " +
                                   plausible + " is a pendulum's in that unit only)"});
  }
  const auto time_factor = factor_of(kTimeUnits, tu.unit);
  if (!time_factor) refuse("got the unit \"" + one_line(tu.unit, 20, true) + "\" for \"" + names[*time_col] + "\"; expected " + names_of(kTimeUnits));
  out.time_unit = tu.unit;
  if (!out.sweep && out.setting == Setting::length && tu.oscillations == 0 && options.oscillations == 0 &&
      tu.decided != "option") {
    // Times that make no pendulum's periods beside these lengths: the times of N swings?
    const std::vector<double> seconds = scaled(table.columns[*time_col], *time_factor);
    const std::vector<double>& l = table.columns[*setting_col];
    const int n = lengths_fit(l, su.unit, seconds) ? 0 : swings_in(l, su.unit, seconds);
    if (n > 0) {
      tu.oscillations = out.oscillations = n;
      n_osc = n;
      tu.decided = "content";
      tu.why = "the time of " + std::to_string(n) + " oscillations by the numbers";
      out.warnings.push_back({0, "\"" + names[*time_col] + "\": read as the time of " + std::to_string(n) +
                                     " oscillations: as periods beside these lengths they make no pendulum, divided "
                                     "by " + std::to_string(n) + " they give the g nearest the Earth's of any count; "
                                     "say so in the header (\"t" + std::to_string(n) + " (s)\") or with --oscillations"});
    }
  }
  const std::vector<double> periods = scaled(table.columns[*time_col], *time_factor / n_osc);

  // The setting's unit: the header's, else the one the periods agree with.
  // A sweep's rows are grouped by their amplitude instead.
  const std::vector<double>& settings = table.columns[out.sweep ? *amplitude_col : *setting_col];
  if (su.unit.empty()) {
    std::vector<std::string> plausible;
    for (const Scale& s : kLengthUnits) {
      if (!unit_allowed(s, "")) continue;
      if (unit_check(su.setting).fits(scaled(settings, s.factor), periods)) plausible.emplace_back(s.name);
    }
    const auto [lo, hi] = std::minmax_element(settings.begin(), settings.end());
    const std::string range = format_number(*lo, 4) + " to " + format_number(*hi, 4);
    const std::string what = std::string(setting_key(su.setting));
    if (plausible.size() != 1 && su.decided == "content" && su.setting == Setting::length) {
      // Headerless: not a length series in any unit; a pivot scan?
      for (const Scale& s : kLengthUnits) {
        if (!unit_allowed(s, "")) continue;
        if (fits_pivot_distance(scaled(settings, s.factor), periods)) plausible.assign(1, s.name);
      }
      if (plausible.size() == 1) {
        su.setting = out.setting = Setting::pivot_distance;
        for (Use& u : use) {
          if (u.kind == Kind::setting) u.setting = Setting::pivot_distance;
        }
        su.why = "the first column; not lengths (4 pi^2 L/T^2 is no one g in any unit), but pivot distances "
                 "(h(gT^2/4pi^2 - h), the radius of gyration squared, the same at every row)";
      } else {
        plausible.clear();
      }
    }
    if (plausible.size() != 1) {
      std::string choice;
      for (const auto& u : plausible) choice += (choice.empty() ? "" : " or ") + u;
      refuse("the column \"" + names[*setting_col] + "\" (" + setting_key(su.setting) + ") has no unit and its values, " +
             range + ", " + (plausible.empty() ? "fit the periods in no unit (m, cm, mm)" : "fit the periods in " + choice) +
             "; expected its unit in the header (\"" + setting_info(su.setting).symbol +
             " (cm)\") or declared: --columns \"" + setting_info(su.setting).letter +
             ":cm,...\" (a scene's \"columns\": {\"" + what + "\": {\"column\": " + std::to_string(*setting_col + 1) +
             ", \"unit\": \"cm\"}})");
    }
    su.unit = plausible.front();
    if (su.decided != "option") su.decided = "content";
    out.warnings.push_back({0, "\"" + names[*setting_col] + "\": no unit; read as " + su.unit + " (" + range + " " +
                                   su.unit + "; " + unit_check(su.setting).alone + ")"});
  }
  const auto setting_factor = factor_of(kLengthUnits, su.unit);
  if (!setting_factor) {
    refuse("got the unit \"" + one_line(su.unit, 20, true) + "\" for \"" + names[*setting_col] + "\"; expected " + names_of(kLengthUnits));
  }
  out.setting_unit = su.unit;
  const std::vector<double> meters = scaled(settings, *setting_factor);
  for (const auto& [j, second] : second_times) {
    const auto factor = factor_of(kTimeUnits, second.unit.empty() ? tu.unit : second.unit);
    if (!factor) continue;
    compare_periods(use[j], names[j], names[*time_col], scaled(table.columns[j], *factor / std::max(second.oscillations, 1)),
                    periods, out.setting == Setting::length && !out.sweep ? &meters : nullptr, out.warnings);
  }
  // The other columns' units.
  auto unit_of = [&](std::optional<std::size_t> col, const Use& of, auto& units) -> double {
    if (!col) return 1.0;
    Use& u = use[*col];
    if (u.unit.empty()) u.unit = of.unit;
    const auto f = factor_of(units, u.unit);
    if (!f) refuse("got the unit \"" + one_line(u.unit, 20, true) + "\" for \"" + names[*col] + "\"; expected " + names_of(units));
    return *f;
  };
  const double setting_u_factor = unit_of(setting_u, su, kLengthUnits) / *setting_factor;
  const double time_u_factor = unit_of(time_u, tu, kTimeUnits) / *time_factor;
  if (time_u) {
    // A timing's uncertainty is below a third of it (the scene's rule): a larger one is no timing's.
    const auto& sigma = table.columns[*time_u];
    const auto& times = table.columns[*time_col];
    for (std::size_t i = 0; i < table.rows; ++i) {
      if (sigma[i] * time_u_factor < times[i] / 3.0) continue;
      use[*time_u].kind = Kind::unused, use[*time_u].uncertainty = false;
      use[*time_u].why = "too large for the uncertainty of the " + quantity_name(tu) + ": " +
                         format_number(sigma[i], 3) + " beside " + format_number(times[i], 4) + " at line " +
                         std::to_string(line_of(i)) + ", a third or more of it";
      out.warnings.push_back({0, "\"" + names[*time_u] + "\" not used: " + use[*time_u].why});
      time_u.reset();
      break;
    }
  }
  double amplitude_factor = 1.0;
  if (amplitude_col) {
    Use& au = use[*amplitude_col];
    if (au.unit.empty()) {
      const std::vector<double> a = sizes(table.columns[*amplitude_col]);
      const double hi = *std::max_element(a.begin(), a.end());
      const double lo = *std::min_element(a.begin(), a.end());
      // Degrees past 1.6 (92 deg in radians: no timed swing), or where one is past pi (180 deg in
      // radians: over the top); radians up to 0.35 (below 0.35 deg: no hand release); between, a
      // sweep's periods may say.
      au.unit = lo > 1.6 || hi > kPi ? "deg" : hi <= 0.35 ? "rad" : out.sweep ? sweep_angle_unit(a, periods) : "";
      const bool by_rise = !(lo > 1.6 || hi > kPi || hi <= 0.35) && !au.unit.empty();
      if (au.unit.empty()) {
        refuse("the column \"" + names[*amplitude_col] + "\" (amplitude) has no unit and its values, " +
               format_number(lo, 3) + " to " + format_number(hi, 3) + ", may be degrees or radians; expected its "
               "unit in the header (\"theta (deg)\") or declared: --columns (a scene's \"columns\": {\"amplitude\": "
               "{\"column\": " + std::to_string(*amplitude_col + 1) + ", \"unit\": \"deg\"}})");
      }
      au.decided = au.decided == "option" ? "option" : "content";
      out.warnings.push_back({0, "\"" + names[*amplitude_col] + "\": no unit; read as " + au.unit +
                                     (by_rise ? " (the periods rise with them as the law does in radians; in degrees "
                                                "they would hardly rise at all)"
                                              : "")});
    }
    const auto f = factor_of(kAngleUnits, au.unit);
    if (!f) refuse("got the unit \"" + one_line(au.unit, 20, true) + "\" for \"" + names[*amplitude_col] + "\"; expected deg or rad");
    amplitude_factor = *f;
    const std::vector<double> a = sizes(table.columns[*amplitude_col]);
    const std::size_t top = static_cast<std::size_t>(std::max_element(a.begin(), a.end()) - a.begin());
    const double largest = a[top];
    if (!accepts(ranges::amplitude, largest * amplitude_factor)) {
      refuse_cell(top, *amplitude_col, "got " + format_number(largest, 4) + " " +
             au.unit + (au.unit == "deg" ? "" : ", 180 deg or more") + " (over the top)" +
             (au.unit == "rad" && largest < 180.0 ? ": it holds degrees? Say so in the header (\"theta (deg)\") or "
                                                   "declared: --columns (a scene's \"columns\")"
                                                 : "; expected a swing's amplitude, below 180 deg"));
    }
    out.amplitude_unit = au.unit;
    (void)unit_of(amplitude_u, au, kAngleUnits);
    const auto& written = table.columns[*amplitude_col];
    if (std::any_of(written.begin(), written.end(), [](double x) { return x < 0.0; })) {
      out.notes.push_back({0, "\"" + names[*amplitude_col] + "\": signed (a release to either side); each "
                              "amplitude is its size"});
    }
  }
  const double amplitude_u_factor =
      amplitude_u ? *factor_of(kAngleUnits, use[*amplitude_u].unit) / amplitude_factor : 1.0;

  // What the scene reader refuses in an observation (argument_ranges.hpp),
  // refused here at its cell: import's scene would fail at a path the user
  // never wrote.
  for (std::size_t i = 0; i < table.rows; ++i) {
    if (!out.sweep && (out.setting == Setting::length || out.setting == Setting::rod_length)) {
      const std::string why = out_of_range(ranges::length, meters[i]);
      if (!why.empty()) refuse_cell(i, *setting_col, why);
      // As uncertain as itself, a length might be 0.
      if (setting_u && table.columns[*setting_u][i] * setting_u_factor >= settings[i]) {
        refuse_cell(i, *setting_u,
                    uncertainty_not_below_value(format_number(table.columns[*setting_u][i]) + " " + use[*setting_u].unit,
                                                format_number(settings[i]) + " " + su.unit));
      }
    }
    if (time_u) {
      const std::string why = out_of_range(ranges::timing_uncertainty, table.columns[*time_u][i] * time_u_factor * *time_factor);
      if (!why.empty()) refuse_cell(i, *time_u, why);
    }
  }

  // The physics across the rows: a row in another unit stands out.
  if (!out.sweep && out.setting == Setting::length) {
    // Each row's small-amplitude period: a 170 deg swing's is 0.36 of its own.
    std::vector<double> small = periods;
    for (std::size_t i = 0; amplitude_col && i < small.size(); ++i) {
      small[i] /= 1.0 + finite_amplitude_agm(std::fabs(table.columns[*amplitude_col][i]) * amplitude_factor);
    }
    const std::vector<double> g = row_g(meters, small);
    const double m = median_of(g);
    for (std::size_t i = 0; i < g.size(); ++i) {
      if (g[i] > 3.0 * m || g[i] < m / 3.0) {
        fail(file, line_of(i), 1,
             "L = " + format_number(settings[i], 6) + " " + su.unit + " and T = " + format_number(periods[i], 6) + " s" +
                 (amplitude_col ? " (T0 = " + format_number(small[i], 6) + " s at its amplitude)" : "") +
                 " give 4 pi^2 L/T" + (amplitude_col ? "0" : "") + "^2 = " + format_number(g[i], 3) + " m/s^2, " + format_number(g[i] / m, 2) +
                 " times the other rows' " + format_number(m, 3) + ": expected one unit in each column (a length or a "
                 "time written in another unit, mixed units?)");
      }
    }
    if (m < 2.0 || m > 50.0) {
      refuse("the lengths in " + su.unit + " and the periods in " + tu.unit + " give 4 pi^2 L/T^2 = " +
             format_number(m, 3) + " m/s^2; expected about 9.8: a unit in the header wrong?");
    }
    compare_derived(use, names, table, meters, periods, line_of, out.warnings);
  } else if (out.setting == Setting::pivot_distance) {
    const std::vector<double> k2 = row_k2(meters, periods);
    for (std::size_t i = 0; i < k2.size(); ++i) {
      // At h = 0 the equivalent length k^2/h + h below would be 0/0.
      if (!(meters[i] > 0.0)) {
        fail(file, line_of(i), 1,
             "got a pivot h = " + format_number(settings[i], 6) + " " + su.unit + " from the centre of mass; expected "
             "a pivot away from it (at the centre the body has no restoring torque and its period is infinite)");
      }
      if (!(k2[i] > 0.0)) {
        fail(file, line_of(i), 1,
             "h = " + format_number(settings[i], 6) + " " + su.unit + " is beyond the equivalent length gT^2/4pi^2 = " +
                 format_number(k2[i] / meters[i] + meters[i], 4) + " m of its period " + format_number(periods[i], 6) +
                 " s, which no body has; expected one unit in each column (mixed units?)");
      }
    }
  }


  // One length at several amplitudes: a sweep whose length is known.
  if (!out.sweep && amplitude_col && out.setting == Setting::length &&
      std::all_of(settings.begin(), settings.end(), [&](double x) { return x == settings.front(); })) {
    std::vector<double> a = sizes(table.columns[*amplitude_col]);
    std::sort(a.begin(), a.end());
    if (std::unique(a.begin(), a.end()) - a.begin() >= 3) {
      out.sweep = true;
      out.sweep_length = settings.front();
      if (setting_u) out.sweep_length_sigma = table.columns[*setting_u].front() * setting_u_factor;
    }
  }
  const std::vector<double>& group_by = out.sweep ? table.columns[*amplitude_col] : settings;
  const std::string setting_word = out.sweep ? "amplitude" : setting_key(out.setting);
  // The rows at one setting, together: one observation.
  std::map<double, std::size_t> seen;  // setting -> its observation's first line
  for (std::size_t i = 0; i < table.rows; ++i) {
    const double s = group_by[i];
    if (out.observations.empty() || out.observations.back().setting != s) {
      if (const auto before = seen.find(s); before != seen.end() && !out.sweep) {
        fail(file, line_of(i), 1,
             std::string(setting_key(out.setting)) + " " + format_number(s, 6) + " " + su.unit + " again, after other settings (line " +
                 std::to_string(before->second) + " had it); expected the rows at one setting together: sort the "
                 "table by \"" + names[*setting_col] + "\" if it is one setting read once, or, set again and "
                 "measured again, it is a reading of its own");
      }
      seen.emplace(s, line_of(i));
      TableObservation o;
      o.setting = s;
      o.first_line = line_of(i);
      out.observations.push_back(o);
    }
    TableObservation& o = out.observations.back();
    o.last_line = line_of(i);
    o.times.push_back(table.columns[*time_col][i]);
    if (setting_u) {
      o.setting_sigma = std::max(o.setting_sigma.value_or(0.0), table.columns[*setting_u][i] * setting_u_factor);
    }
  }
  // Per observation: the stated uncertainties (rms over its rows) and the amplitude's mean.
  std::size_t row = 0;
  double ss = 0.0;
  for (TableObservation& o : out.observations) {
    const std::size_t n = o.times.size();
    double mean = 0.0;
    for (double t : o.times) mean += t / static_cast<double>(n);
    for (double t : o.times) ss += (t - mean) * (t - mean);
    out.pooled_dof += n - 1;
    double a = 0.0, au2 = 0.0;
    std::vector<double> amps, time_sigmas;
    for (std::size_t k = 0; k < n; ++k, ++row) {
      if (time_u) time_sigmas.push_back(table.columns[*time_u][row] * time_u_factor);
      if (amplitude_col) amps.push_back(std::fabs(table.columns[*amplitude_col][row])), a += amps.back() / static_cast<double>(n);
      if (amplitude_u) au2 += std::pow(table.columns[*amplitude_u][row] * amplitude_u_factor, 2) / static_cast<double>(n);
    }
    if (time_u) o.time_sigma = rms(time_sigmas);
    if (amplitude_col) {
      o.amplitude = a;
      // The mean of the releases: its standard error, or the stated ones' over sqrt(n).
      double spread = 0.0;
      for (double x : amps) spread += n > 1 ? (x - a) * (x - a) / static_cast<double>(n - 1) : 0.0;
      const double sigma = amplitude_u ? std::sqrt(au2 / static_cast<double>(n)) : std::sqrt(spread / static_cast<double>(n));
      if (sigma > 0.0) o.amplitude_sigma = sigma;
    }
  }
  if (out.pooled_dof > 0) out.pooled_sigma = std::sqrt(ss / static_cast<double>(out.pooled_dof));
  // Rows at one length that are readings of their own, each its own observation.
  if (time_u && !out.sweep && out.setting == Setting::length) {
    std::vector<double> sigma_s(table.rows);
    for (std::size_t i = 0; i < table.rows; ++i) sigma_s[i] = table.columns[*time_u][i] * time_u_factor * *time_factor / n_osc;
    double tau = 0.0;
    if (readings_of_their_own(out.observations, periods, sigma_s, meters, tau)) {
      std::vector<TableObservation> rows;
      for (std::size_t k = 0, i = 0; k < out.observations.size(); ++k) {
        for (std::size_t r = 0; r < out.observations[k].times.size(); ++r, ++i) {
          TableObservation o;
          o.setting = out.observations[k].setting;
          if (setting_u) o.setting_sigma = table.columns[*setting_u][i] * setting_u_factor;
          o.times = {table.columns[*time_col][i]};
          o.time_sigma = table.columns[*time_u][i] * time_u_factor;
          if (amplitude_col) o.amplitude = std::fabs(table.columns[*amplitude_col][i]);
          if (amplitude_u) o.amplitude_sigma = table.columns[*amplitude_u][i] * amplitude_u_factor;
          o.first_line = o.last_line = line_of(i);
          rows.push_back(o);
        }
      }
      out.notes.push_back({0, "the rows at one length scatter beyond their stated uncertainty and as a length's error "
                              "would, (T/2L) x " + format_number(1000.0 * tau, 3) + " mm, not as a stopwatch's: "
                              "each row is a reading of its own (its length set and measured again: a class's "
                              "groups?), its own observation (docs/series.md, Repeats)"});
      out.observations = std::move(rows);
      out.pooled_sigma.reset(), out.pooled_dof = 0;
    }
  }
  // A few repeats say little about their own scatter (it is uncertain by
  // 1/sqrt(2(n-1)) of itself: 71 % for 2, 50 % for 3, 41 % for 4): the pooled
  // scatter of every setting's repeats, one hand's, is the floor of each
  // (read_timing takes the larger), and a single row's uncertainty, when no
  // column states one.
  if (!time_u) {
    for (TableObservation& o : out.observations) {
      const std::size_t n = o.times.size();
      if (out.pooled_sigma && out.pooled_dof > n - 1) o.time_sigma = out.pooled_sigma;
    }
    out.sigma_from_scatter = std::all_of(out.observations.begin(), out.observations.end(),
                                         [](const TableObservation& o) { return o.times.size() == 1 && !o.time_sigma; });
  }
  out.resolution = printed_resolution(table.columns[*time_col]);
  if (out.sigma_from_scatter) {
    out.notes.push_back({0, "each " + setting_word + " timed once and no uncertainty column: "
                            "the periods' uncertainty is their scatter about the fit (n - p degrees of freedom), "
                            "at least the printed digits' " + format_number(out.resolution, 3) + " " + tu.unit +
                            "/sqrt(12); such a fit cannot test itself, and its chi2 gives no verdict"});
  }
  if (out.observations.size() < table.rows) {
    out.notes.push_back({0, std::to_string(table.rows) + " rows at " + std::to_string(out.observations.size()) +
                                " settings: the rows at one setting are one observation (their mean, its standard "
                                "error and their count), its " + setting_word +
                                " measured once (docs/series.md, Repeats)"});
  }
  if (!time_u && out.pooled_sigma && out.pooled_dof > 0) {
    out.notes.push_back({0, "the repeats scatter by " + format_number(*out.pooled_sigma, 3) + " " + tu.unit +
                                " (pooled standard deviation of one " + (out.oscillations > 1 ? "time" : "period") +
                                ", " + std::to_string(out.pooled_dof) +
                                " degrees of freedom): the floor of each setting's own scatter, the uncertainty "
                                "of one timed once"});
  }

  for (std::size_t j = 0; j < cols.size(); ++j) {
    RecordingColumn c;
    c.index = j + 1;
    c.name = cols[j].name;
    if (use[j].kind == Kind::time) use[j].oscillations = out.oscillations;  // the trials' and the uncertainty's too
    c.role = quantity_name(use[j]);
    c.unit = use[j].kind == Kind::unused ? std::string() : use[j].unit;
    c.decided_by = use[j].decided;
    c.why = use[j].why;
    out.columns.push_back(std::move(c));
  }
  return out;
}

bool looks_like_settings_table(std::string_view text) {
  text = strip_bom(text);
  if (text.substr(0, 4) == std::string_view("PK\x03\x04", 4)) return false;
  try {
    const HeaderLines lines = find_header(text, "");
    if (lines.header) {
      const DataRows data = data_rows(text, lines, "", "a table or a recording");
      const Dialect d = sniff(lines.header, data.first);
      const std::vector<Column> header = header_columns(lines, d, kTableInput, "");
      if (generic_names(header)) {
        // Read by place, as without a header: a table if it reads as one.
        (void)parse_settings_table(text, "");
        return true;
      }
      std::optional<std::size_t> time;
      bool x = false, y = false, angle = false;
      for (std::size_t i = 0; i < header.size(); ++i) {
        const Column& c = header[i];
        if ((table_only(c.role) && c.role != Role::amplitude) || oscillations_in(c.word) > 0) return true;
        x |= c.role == Role::x, y |= c.role == Role::y, angle |= c.role == Role::angle || c.role == Role::amplitude;
        if ((c.role == Role::time || c.role == Role::period) && !time) time = i;
      }
      // An x without a y beside a time is a track's one coordinate, or a table's pivot
      // positions ("x (cm)", "T (s)"): a table where the times do not increase, as no
      // recording's do (but for one whose clock restarts). An angle beside times that
      // stay within 25 % of each other, not at a clock's steady step, is an amplitude
      // sweep's ("theta (deg)", "T (s)"): a record of a few swings that starts late has
      // such times, at one step. The rows are read as the table would read them.
      const bool track = x && !y;
      if (!(track || angle) || !time) return false;
      const std::vector<std::string> names(header.size());  // no message quotes them here
      const Table rows = read_rows(data.begin, data.end, lines.data_line, d, names, "", kTableInput);
      double previous = -HUGE_VAL, lo = HUGE_VAL, hi = 0.0;
      bool increasing = true;
      std::vector<double> steps;
      for (const double t : rows.columns[*time]) {
        if (std::isnan(t)) continue;  // an empty cell
        if (previous > -HUGE_VAL) steps.push_back(t - previous);
        increasing = increasing && t > previous;
        previous = t, lo = std::min(lo, t), hi = std::max(hi, t);
      }
      const bool clock = increasing && steps.size() >= 3 && [&] {
        const auto [s_lo, s_hi] = std::minmax_element(steps.begin(), steps.end());
        return *s_hi <= 1.5 * *s_lo;  // a sampling clock's step, jitter and all
      }();
      return (track && !increasing) || (angle && lo > 0.0 && hi <= 1.25 * lo && !clock);
    }
    (void)parse_settings_table(text, "");
    return true;
  } catch (const InputError&) {
    return false;
  }
}

SettingsTable read_settings_table(const std::string& path, const TableOptions& options,
                                  const std::optional<std::string>& within) {
  const std::string text = read_text(path, options.limits, "a table of settings and periods", within);
  // A spreadsheet's sheet is read as the CSV it holds.
  if (looks_like_xlsx(text)) return parse_settings_table(xlsx_sheet_csv(text, path, options.sheet, options.limits.bytes), path, options);
  return parse_settings_table(text, path, options);
}

bool file_holds_settings_table(const std::string& path, const std::string& sheet) {
  try {
    const InputFile file(path, "a table or a recording");
    if (file.size() <= kMaxSpreadsheetPeek) {
      const std::string text = read_text(path, {kMaxSpreadsheetPeek, 0, 0, "a spreadsheet"}, "a table or a recording");
      if (looks_like_xlsx(text)) return looks_like_settings_table(xlsx_sheet_csv(text, path, sheet, kMaxSpreadsheetPeek));
    }
    std::string head(std::min<std::size_t>(file.size(), 1 << 16), '\0');
    const ssize_t got = ::pread(file.fd(), head.data(), head.size(), 0);
    if (got <= 0) return false;
    head.resize(static_cast<std::size_t>(got));
    // Whole lines only: a row cut by the peek is no truncated row.
    if (file.size() > head.size()) head.resize(head.rfind('\n') == std::string::npos ? 0 : head.rfind('\n') + 1);
    return looks_like_settings_table(head);
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace pendulum
