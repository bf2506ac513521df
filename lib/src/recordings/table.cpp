// Tables of settings and periods (table.hpp; docs/series.md, "Tables"): the
// recording reader's stages read the text (stages.hpp), then each column's
// role and unit is decided from the option, the header or the numbers, the
// units are checked against the physics (T^2 against L), and the rows at one
// setting become one observation.
#include "pendulum/recordings/table.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>

#include "pendulum/files.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/numeric.hpp"
#include "../text.hpp"
#include "stages.hpp"

namespace pendulum {

namespace {

using namespace recording_text;

constexpr double kStandardGravity = 9.80665;  // m/s^2, the scale of a T^2-against-L check only

enum class Kind { unused, setting, time, amplitude };

/// How one column is read.
struct Use {
  Kind kind = Kind::unused;
  bool uncertainty = false;
  Setting setting = Setting::length;
  std::string unit;  ///< normal form; empty until given or decided
  int oscillations = 0;
  std::string decided = "header";
  std::string why;
};

bool same(const Use& a, const Use& b) { return a.kind == b.kind && a.uncertainty == b.uncertainty; }

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
  const bool count_word = after == "oscillations" || after == "swings" || after == "periods" || after == "osc";
  const bool time_word = before == "t" || before == "time" || before == "timeof" || before == "timefor";
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

/// An uncertainty column's word ("σT", "dT", "u(T)", "sigma_l", "err h", or
/// "σ" alone): the quantity it is the uncertainty of; a Use of Kind::unused
/// for "the column before"; nullopt when the word is no uncertainty's.
std::optional<Use> uncertainty_of(const Column& c) {
  static const char* const kPrefixes[] = {"sigma_", "sigma ", "sigma", "\xcf\x83_", "\xcf\x83 ", "\xcf\x83",
                                          "\xce\xb4", "\xce\x94", "u_", "u(", "err_", "err ", "error_", "error ",
                                          "err", "uncertainty of ", "uncertainty_", "uncertainty ", "+-",
                                          "\xc2\xb1", "d"};
  const std::string& w = c.word;
  static const char* const kAlone[] = {"sigma", "\xcf\x83", "error", "err", "uncertainty", "u", "+-", "\xc2\xb1"};
  for (const char* alone : kAlone) {
    if (w == alone) {
      // "u(T)" without a unit: the header's "(t)" was taken for one.
      if (auto q = quantity_of(c.unit)) return q;
      return Use{};
    }
  }
  for (const char* prefix : kPrefixes) {
    if (!starts_with(w, prefix)) continue;
    std::string rest = w.substr(std::strlen(prefix));
    while (!rest.empty() && (rest.back() == ')' || rest.back() == ' ')) rest.pop_back();
    if (auto q = quantity_of(rest)) return q;
  }
  return std::nullopt;
}

/// A column's role from its header cell.
Use from_header(const Column& c) {
  Use u;
  if (const int n = oscillations_in(c.word)) {
    u.kind = Kind::time, u.oscillations = n, u.unit = c.unit;
    u.why = "the time of " + std::to_string(n) + " oscillations by the header";
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
  u.why = c.role == Role::counter ? "a counter or index" : c.name.empty() ? "not needed" : "a word the reader does not know";
  return u;
}

double median(std::vector<double> x) {
  const auto mid = x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2);
  std::nth_element(x.begin(), mid, x.end());
  return *mid;
}

/// True if `u` reads as the uncertainty of `v`: never negative, not all zero
/// and below a third of v's typical size.
bool reads_as_uncertainty(const std::vector<double>& u, const std::vector<double>& v) {
  std::vector<double> size;
  for (double x : v) size.push_back(std::fabs(x));
  const double typical = median(size);
  const double top = *std::max_element(u.begin(), u.end());
  return std::all_of(u.begin(), u.end(), [](double x) { return x >= 0.0; }) && top > 0.0 && top < typical / 3.0;
}

struct Scale {
  const char* name;
  double factor;
};
constexpr Scale kLengthUnits[] = {{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}, {"in", 0.0254}, {"ft", 0.3048}};
constexpr Scale kTimeUnits[] = {{"s", 1.0}, {"ms", 1e-3}, {"min", 60.0}};
constexpr Scale kAngleUnits[] = {{"deg", kPi / 180.0}, {"rad", 1.0}};

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
  for (std::size_t i = 0; i < l.size(); ++i) g[i] = 4.0 * kPi * kPi * l[i] / (t[i] * t[i]);
  return g;
}

/// k^2 = h (l - h) of each row (m^2), l = g0 T^2 / (4 pi^2) the equivalent
/// length: the body's radius of gyration squared, the same at every pivot.
std::vector<double> row_k2(const std::vector<double>& h, const std::vector<double>& t) {
  std::vector<double> k2(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double l = kStandardGravity * t[i] * t[i] / (4.0 * kPi * kPi);
    k2[i] = h[i] * (l - h[i]);
  }
  return k2;
}

/// Whether the settings (m) and periods (s) read as a length series: a g
/// from 4 to 25 m/s^2 at every row, within 25 % of their median.
bool fits_length(const std::vector<double>& l, const std::vector<double>& t) {
  const std::vector<double> g = row_g(l, t);
  const double m = median(g);
  return m >= 4.0 && m <= 25.0 && std::all_of(g.begin(), g.end(), [&](double x) { return x > 0.8 * m && x < 1.25 * m; });
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
  const double l = kStandardGravity * std::pow(*std::max_element(t.begin(), t.end()), 2) / (4.0 * kPi * kPi);
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

std::vector<double> scaled(const std::vector<double>& v, double f) {
  std::vector<double> out(v);
  for (double& x : out) x *= f;
  return out;
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

SettingsTable parse_settings_table(std::string_view text, const std::string& file, const TableOptions& options) {
  text = strip_bom(text);
  const HeaderLines lines = find_header(text, file);
  const DataRows data = data_rows(text, lines, file, "a table of settings and periods");
  const Dialect dialect = sniff(lines.header, data.first);

  std::vector<Column> cols;
  if (lines.header) {
    for (std::string_view cell : split_cells(*lines.header, dialect)) cols.push_back(classify(cell));
    while (cols.size() > 1 && cols.back().name.empty()) cols.pop_back();  // a trailing delimiter
  } else {
    cols.resize(split_cells(data.first, dialect).size());
  }
  std::vector<std::string> names(cols.size());  // as messages quote them
  for (std::size_t j = 0; j < cols.size(); ++j) names[j] = column_label(cols[j].name, j + 1);
  Table table = read_rows(data.begin, data.end, lines.data_line, dialect, names, file);
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
  } else if (lines.header) {
    const Use* last = nullptr;
    for (std::size_t j = 0; j < cols.size(); ++j) {
      Use& u = use[j] = from_header(cols[j]);
      if (u.uncertainty && u.kind == Kind::unused) {
        // "σ" alone: the uncertainty of the column before it.
        if (last && !last->uncertainty) {
          u.kind = last->kind, u.setting = last->setting, u.oscillations = last->oscillations;
          u.why = "the uncertainty of the column before it";
        } else {
          u.uncertainty = false, u.why = "an uncertainty of no column before it";
        }
      }
      if (u.kind != Kind::unused) last = &u;
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
    use[0].kind = Kind::setting;
    use[0].why = "the first column";
    std::size_t last = 0;
    bool time = false, amplitude = false;
    for (std::size_t j = 1; j < cols.size(); ++j) {
      Use& u = use[j];
      if (!use[last].uncertainty && reads_as_uncertainty(table.columns[j], table.columns[last])) {
        u.kind = use[last].kind, u.uncertainty = true;
        u.why = "below a third of the column before it: its uncertainty";
      } else if (!time) {
        u.kind = Kind::time, time = true, u.why = "the first column after the setting that is no uncertainty";
      } else if (!amplitude) {
        u.kind = Kind::amplitude, amplitude = true, u.why = "after the periods";
      } else {
        u.why = "a column the reader has no role for";
        continue;
      }
      last = j;
    }
  }
  // One column of each role: the first.
  for (std::size_t j = 0; j < use.size(); ++j) {
    for (std::size_t i = 0; i < j && use[j].kind != Kind::unused; ++i) {
      if (same(use[i], use[j])) {
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
  if (!setting_col) {
    refuse("no setting column (length, pivot distance or pivot position) among " + listed() +
           "; expected one, e.g. \"L (m)\", \"h (cm)\", \"pivot position (cm)\", or the columns named: "
           "--columns (a scene's \"columns\"), e.g. \"l:cm,T:s\"");
  }
  if (!time_col) {
    refuse("no period column among " + listed() + "; expected the periods (\"T (s)\") or the times of N "
           "oscillations (\"t10 (s)\", or --oscillations N), or the columns named: --columns (a scene's "
           "\"columns\"), e.g. \"l:cm,t10:s\"");
  }
  const auto setting_u = find(Kind::setting, true), time_u = find(Kind::time, true);
  const auto amplitude_col = find(Kind::amplitude, false), amplitude_u = find(Kind::amplitude, true);

  SettingsTable out;
  out.rows = table.rows;
  Use& su = use[*setting_col];
  Use& tu = use[*time_col];
  out.setting = su.setting;
  if (options.oscillations > 0) {
    tu.oscillations = options.oscillations;
    tu.why = "the time of " + std::to_string(options.oscillations) + " oscillations by --oscillations";
  }
  out.oscillations = std::max(tu.oscillations, 1);
  const double n_osc = out.oscillations;

  // Every used cell holds a number.
  for (std::size_t j = 0; j < use.size(); ++j) {
    if (use[j].kind == Kind::unused) continue;
    const auto& v = table.columns[j];
    for (std::size_t i = 0; i < table.rows; ++i) {
      if (std::isnan(v[i])) {
        fail(file, table.line(i), 1,
             "an empty cell in column \"" + names[j] + "\" (" + quantity_name(use[j]) +
                 "); expected a number in every used cell: a row without its " + quantity_name(use[j]) +
                 " is no timing (delete the row)");
      }
      // A timing's stated uncertainty weighs it in the fit: 0 would make it infinitely precise.
      const bool positive = use[j].kind == Kind::time;
      const bool non_negative = (use[j].uncertainty && !positive) || (use[j].kind == Kind::setting && use[j].setting == Setting::length) ||
                                use[j].kind == Kind::amplitude;
      if ((positive && !(v[i] > 0.0)) || (non_negative && !(v[i] >= 0.0)) || !std::isfinite(v[i])) {
        fail(file, table.line(i), 1,
             "got " + format_number(v[i]) + " in column \"" + names[j] + "\" (" + quantity_name(use[j]) +
                 "); expected a " + (positive ? "positive" : non_negative ? "non-negative" : "finite") + " number");
      }
    }
  }
  auto line_of = [&](std::size_t row) { return table.line(row); };

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
  const std::vector<double> periods = scaled(table.columns[*time_col], *time_factor / n_osc);

  // The setting's unit: the header's, else the one the periods agree with.
  const std::vector<double>& settings = table.columns[*setting_col];
  if (su.unit.empty()) {
    std::vector<std::string> plausible;
    for (const Scale& s : kLengthUnits) {
      if (std::string(s.name) == "in" || std::string(s.name) == "ft") continue;  // a metric lab's, unless said
      if (unit_check(su.setting).fits(scaled(settings, s.factor), periods)) plausible.emplace_back(s.name);
    }
    const auto [lo, hi] = std::minmax_element(settings.begin(), settings.end());
    const std::string range = format_number(*lo, 4) + " to " + format_number(*hi, 4);
    const std::string what = std::string(setting_key(su.setting));
    if (plausible.size() != 1 && su.decided == "content" && su.setting == Setting::length) {
      // Headerless: not a length series in any unit; a pivot scan?
      for (const Scale& s : kLengthUnits) {
        if (std::string(s.name) == "in" || std::string(s.name) == "ft") continue;
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
  // The physics across the rows: a row in another unit stands out.
  if (out.setting == Setting::length) {
    const std::vector<double> g = row_g(meters, periods);
    const double m = median(g);
    for (std::size_t i = 0; i < g.size(); ++i) {
      if (g[i] > 3.0 * m || g[i] < m / 3.0) {
        fail(file, line_of(i), 1,
             "L = " + format_number(settings[i], 6) + " " + su.unit + " and T = " + format_number(periods[i], 6) +
                 " s give 4 pi^2 L/T^2 = " + format_number(g[i], 3) + " m/s^2, " + format_number(g[i] / m, 2) +
                 " times the other rows' " + format_number(m, 3) + ": expected one unit in each column (a length or a "
                 "time written in another unit, mixed units?)");
      }
    }
    if (m < 2.0 || m > 50.0) {
      refuse("the lengths in " + su.unit + " and the periods in " + tu.unit + " give 4 pi^2 L/T^2 = " +
             format_number(m, 3) + " m/s^2; expected about 9.8: a unit in the header wrong?");
    }
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
  double amplitude_factor = 1.0;
  if (amplitude_col) {
    Use& au = use[*amplitude_col];
    if (au.unit.empty()) {
      const auto& a = table.columns[*amplitude_col];
      const double hi = *std::max_element(a.begin(), a.end());
      const double lo = *std::min_element(a.begin(), a.end());
      // Degrees past 1.6 (92 deg in radians: no timed swing); radians up to 0.35 (below 0.35 deg: no hand release).
      au.unit = lo > 1.6 ? "deg" : hi <= 0.35 ? "rad" : "";
      if (au.unit.empty()) {
        refuse("the column \"" + names[*amplitude_col] + "\" (amplitude) has no unit and its values, " +
               format_number(lo, 3) + " to " + format_number(hi, 3) + ", may be degrees or radians; expected its "
               "unit in the header (\"theta (deg)\") or declared: --columns (a scene's \"columns\": {\"amplitude\": "
               "{\"column\": " + std::to_string(*amplitude_col + 1) + ", \"unit\": \"deg\"}})");
      }
      au.decided = au.decided == "option" ? "option" : "content";
      out.warnings.push_back({0, "\"" + names[*amplitude_col] + "\": no unit; read as " + au.unit});
    }
    const auto f = factor_of(kAngleUnits, au.unit);
    if (!f) refuse("got the unit \"" + one_line(au.unit, 20, true) + "\" for \"" + names[*amplitude_col] + "\"; expected deg or rad");
    amplitude_factor = *f;
    out.amplitude_unit = au.unit;
    (void)unit_of(amplitude_u, au, kAngleUnits);
  }
  const double amplitude_u_factor =
      amplitude_u ? *factor_of(kAngleUnits, use[*amplitude_u].unit) / amplitude_factor : 1.0;

  // The rows at one setting, together: one observation.
  std::map<double, std::size_t> seen;  // setting -> its observation's first line
  for (std::size_t i = 0; i < table.rows; ++i) {
    const double s = settings[i];
    if (out.observations.empty() || out.observations.back().setting != s) {
      if (const auto before = seen.find(s); before != seen.end()) {
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
    double su2 = 0.0, a = 0.0, au2 = 0.0;
    std::vector<double> amps;
    for (std::size_t k = 0; k < n; ++k, ++row) {
      if (time_u) su2 += std::pow(table.columns[*time_u][row] * time_u_factor, 2) / static_cast<double>(n);
      if (amplitude_col) amps.push_back(table.columns[*amplitude_col][row]), a += amps.back() / static_cast<double>(n);
      if (amplitude_u) au2 += std::pow(table.columns[*amplitude_u][row] * amplitude_u_factor, 2) / static_cast<double>(n);
    }
    if (time_u) o.time_sigma = std::sqrt(su2);
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
  // A few repeats say little about their own scatter (it is uncertain by
  // 1/sqrt(2(n-1)) of itself: 71 % for 2, 50 % for 3, 41 % for 4): the pooled
  // scatter of every setting's repeats, one hand's, is the floor of each
  // (read_timing takes the larger), and a single row's uncertainty, when no
  // column states one.
  if (!time_u) {
    for (TableObservation& o : out.observations) {
      const std::size_t n = o.times.size();
      if (out.pooled_sigma && out.pooled_dof > n - 1) o.time_sigma = out.pooled_sigma;
      if (n == 1 && !o.time_sigma) {
        fail(file, o.first_line, 1,
             "one row at " + std::string(setting_key(out.setting)) + " " + format_number(o.setting, 6) + " " + su.unit +
                 ", no uncertainty column and no repeats elsewhere in the table to take a scatter from; expected an "
                 "uncertainty column (\"sigma_T (s)\", each timing's), or the setting timed more than once "
                 "(docs/series.md, Repeats); the scatter about the fit is not taken instead: it would make chi2/dof "
                 "1 by construction, and the fit could no longer say when the data disagree with their uncertainties");
      }
    }
  }
  if (out.observations.size() < table.rows) {
    out.notes.push_back({0, std::to_string(table.rows) + " rows at " + std::to_string(out.observations.size()) +
                                " settings: the rows at one setting are one observation (their mean, its standard "
                                "error and their count), its " + setting_key(out.setting) +
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
      const std::vector<std::string_view> header = split_cells(*lines.header, d);
      std::optional<std::size_t> time;
      bool x = false, y = false;
      for (std::size_t i = 0; i < header.size(); ++i) {
        const Column c = classify(header[i]);
        if (c.role == Role::length || c.role == Role::pivot_distance || c.role == Role::pivot_position ||
            oscillations_in(c.word) > 0) {
          return true;
        }
        x |= c.role == Role::x, y |= c.role == Role::y;
        if ((c.role == Role::time || c.role == Role::period) && !time) time = i;
      }
      // An x without a y beside a time is a track's one coordinate, or a table's pivot
      // positions ("x (cm)", "T (s)"): a table where the times do not increase, as no
      // recording's do. The rows are read as the table would read them.
      if (!x || y || !time) return false;
      const std::vector<std::string> names(header.size());  // no message quotes them here
      const Table rows = read_rows(data.begin, data.end, lines.data_line, d, names, "");
      double previous = -HUGE_VAL;
      for (const double t : rows.columns[*time]) {
        if (std::isnan(t)) continue;  // an empty cell
        if (!(t > previous)) return true;
        previous = t;
      }
      return false;
    }
    (void)parse_settings_table(text, "");
    return true;
  } catch (const InputError&) {
    return false;
  }
}

SettingsTable read_settings_table(const std::string& path, const TableOptions& options, std::size_t max_bytes,
                                  const std::optional<std::string>& within) {
  return parse_settings_table(read_text(path, max_bytes, "a table of settings and periods", within), path, options);
}

bool file_holds_settings_table(const std::string& path) {
  try {
    const InputFile file(path, "a table or a recording");
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
