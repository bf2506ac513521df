// Reading a recording's text: the stages of stages.hpp put together, the
// roles of its columns decided (a family's layout, else the header's words,
// else the numbers), and the Recording assembled; and the file's opening.
#include "pendulum/recordings/read.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>

#include "pendulum/input_error.hpp"
#include "pendulum/numeric.hpp"
#include "../text.hpp"
#include "../io/mapped_file.hpp"
#include "stages.hpp"
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
    case RecordingFormat::columns: return "columns";
  }
  return "";
}

namespace {
constexpr RecordingFormat kFamilies[] = {RecordingFormat::automatic, RecordingFormat::phyphox,
                                         RecordingFormat::vernier,   RecordingFormat::pasco,
                                         RecordingFormat::plain,     RecordingFormat::tracker};
}  // namespace

std::vector<std::string> recording_family_names() {
  std::vector<std::string> names;
  for (auto f : kFamilies) names.push_back(recording_format_name(f));
  return names;
}

std::string recording_family_words() {
  const std::vector<std::string> names = recording_family_names();
  std::string words;
  for (std::size_t k = 0; k < names.size(); ++k) words += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + names[k];
  return words;
}

std::optional<RecordingFormat> recording_family(const std::vector<std::string>& formats) {
  std::optional<RecordingFormat> family;
  for (const auto& f : formats) {
    for (auto candidate : kFamilies) {
      if (f == recording_format_name(candidate)) family = candidate;
    }
  }
  return family;
}

namespace {

using namespace recording_text;

/// Which columns hold what, and their scale to SI.
struct Layout {
  RecordingFormat format = RecordingFormat::automatic;
  SignalKind kind = SignalKind::angular_rate;
  std::size_t time = 0;
  std::vector<std::size_t> channels;
  std::optional<std::size_t> period;
  std::optional<std::size_t> counter;  ///< event numbers beside event stamps
  double time_scale = 1.0;
  double channel_scale = 1.0;
  std::string channel_unit;  ///< as read ("deg", "rad/s", "px"); empty where the kind has one unit
  std::string unit_why;      ///< how an angle's unit was decided, when not from the header
  std::string time_why;      ///< how a time's unit was decided where the file gives none
};

/// True if the column holds one number throughout, or none (stops at the first other).
bool is_constant(const std::vector<double>& column) {
  const auto first = std::find_if(column.begin(), column.end(), [](double v) { return std::isfinite(v); });
  return first == column.end() ||
         std::all_of(first, column.end(), [&](double v) { return !std::isfinite(v) || v == *first; });
}

/// The columns' numbers, and what each says, for the decisions a header
/// leaves open; a column's facts are found when first asked for (a named
/// family's file needs none, and its reading costs no more).
struct Content {
  const Table& table;
  bool skip_constant = true;  ///< pass over constant columns (a second try takes them)
  mutable std::vector<std::optional<ColumnFacts>> cache = std::vector<std::optional<ColumnFacts>>(table.columns.size());
  /// With `range`, the percentiles too (an angle's unit needs them).
  const ColumnFacts& facts(std::size_t j, bool range = true) const {
    if (!cache[j] || (range && !cache[j]->ranged)) cache[j] = examine(table.columns[j], range);
    return *cache[j];
  }
  bool constant(std::size_t j) const { return skip_constant && is_constant(table.columns[j]); }
};

/// The first column of `role`, of PASCO run `run` and Tracker track `track`
/// (-1: any), skipping columns that the content shows constant.
std::optional<std::size_t> find(const std::vector<Column>& cols, Role role, int run = -1, int track = -1,
                                const Content* content = nullptr) {
  for (std::size_t j = 0; j < cols.size(); ++j) {
    if (cols[j].role == role && (run < 0 || cols[j].run == run) && (track < 0 || cols[j].track == track) &&
        !(content && content->constant(j))) {
      return j;
    }
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

/// An angle column's scale to radians: by its unit, or, without one, by its
/// numbers once they are read.
double angle_scale(const Column& c, Layout& l, const Content* content, std::size_t j) {
  l.channel_unit = c.unit;
  if (c.unit == "deg") return kRadiansPerDegree;
  if (c.unit == "rad") return 1.0;
  if (!content) return 1.0;
  const ColumnFacts& f = content->facts(j);
  auto [unit, why] = unitless_angle(f);
  // A value beyond a turn is no tracked angle in radians either.
  if (unit == "rad" && std::max(std::fabs(f.lo), std::fabs(f.hi)) > 2.0 * kPi) {
    unit = "deg", why = "holds values beyond a turn in radians: read as degrees";
  }
  l.channel_unit = unit;
  l.unit_why = "no unit in the header; " + why;
  return unit == "deg" ? kRadiansPerDegree : 1.0;
}

double rate_scale(const Column& c, Layout& l) {
  l.channel_unit = c.unit.empty() ? "rad/s" : c.unit;
  return c.unit == "deg/s" ? kRadiansPerDegree : 1.0;
}

/// The layout of `format` for these columns, or nullopt if they do not fit
/// it. With `content`, a constant column is passed over (an all-zero angle
/// beside a track's x and y) and a unitless angle's unit decided.
std::optional<Layout> layout_for(RecordingFormat format, const std::vector<Column>& cols, bool preamble, int run,
                                 int track, const Content* content) {
  Layout l;
  l.format = format;
  switch (format) {
    case RecordingFormat::phyphox: {
      if (cols.empty() || cols[0].role != Role::time || cols[0].unit != "s") return std::nullopt;
      for (auto [role, kind] : {std::pair{Role::rate, SignalKind::angular_rate},
                                {Role::linear_acceleration, SignalKind::linear_acceleration},
                                {Role::acceleration, SignalKind::acceleration}}) {
        l.channels = find_all(cols, role);
        l.kind = kind;
        l.channel_unit = kind == SignalKind::angular_rate ? "rad/s" : "m/s^2";
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
      const auto scale = time_scale(cols[*t]);
      if (!scale) return std::nullopt;
      l.time_scale = *scale;
      return l;
    }
    case RecordingFormat::pasco: {
      const auto t = find(cols, Role::time, run);
      if (!t) return std::nullopt;
      l.time = *t;
      l.time_scale = time_scale(cols[*t]).value_or(1.0);
      if (const auto a = find(cols, Role::angle, run)) {
        l.kind = SignalKind::angle;
        l.channels = {*a};
        l.channel_scale = angle_scale(cols[*a], l, content, *a);
      } else if (const auto w = find(cols, Role::omega, run)) {
        l.kind = SignalKind::angular_rate;
        l.channels = {*w};
        l.channel_scale = rate_scale(cols[*w], l);
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
      l.time_scale = time_scale(cols[*t]).value_or(1.0);
      if (const auto a = find(cols, Role::angle, -1, track, content)) {
        l.kind = SignalKind::angle;
        l.channels = {*a};
        l.channel_scale = angle_scale(cols[*a], l, content, *a);
      } else if (const auto w = find(cols, Role::omega, -1, track, content)) {
        l.kind = SignalKind::angular_rate;
        l.channels = {*w};
        l.channel_scale = rate_scale(cols[*w], l);
      } else if (const auto x = find(cols, Role::x, -1, track), y = find(cols, Role::y, -1, track); x && y) {
        l.kind = SignalKind::position;
        l.channels = {*x, *y};
        l.channel_unit = cols[*x].unit;
      } else {
        return std::nullopt;
      }
      return l;
    }
    case RecordingFormat::plain: {
      // One column of blocking times; of several, the one named time.
      const auto t = cols.size() == 1 ? std::optional<std::size_t>(0) : find(cols, Role::time);
      if (!t) return std::nullopt;
      const auto scale = time_scale(cols[*t]);
      if (!scale) return std::nullopt;
      l.time = *t;
      l.kind = SignalKind::blocking_times;
      l.time_scale = *scale;
      return l;
    }
    case RecordingFormat::columns: {
      // By roles alone: a time, then the first signal that varies.
      const auto t = find(cols, Role::time);
      if (!t || !time_scale(cols[*t])) return std::nullopt;
      l.time = *t;
      l.time_scale = *time_scale(cols[*t]);
      if (const auto a = find(cols, Role::angle, -1, -1, content);
          a && cols[*a].decided == "content" && content && !angle_by_numbers(content->facts(*a))) {
        // The numbers alone called it a signal, and they are no angle's.
        l.kind = SignalKind::unknown;
        l.channels = {*a};
        l.unit_why = "no header; " + not_an_angle_why(content->facts(*a));
      } else if (a) {
        l.kind = SignalKind::angle;
        l.channels = {*a};
        l.channel_scale = angle_scale(cols[*a], l, content, *a);
      } else if (const auto w = find(cols, Role::omega, -1, -1, content)) {
        l.kind = SignalKind::angular_rate;
        l.channels = {*w};
        l.channel_scale = rate_scale(cols[*w], l);
      } else if (auto rates = find_all(cols, Role::rate); !rates.empty()) {
        l.kind = SignalKind::angular_rate;
        l.channels = rates;
        l.channel_scale = rate_scale(cols[rates[0]], l);
      } else if (auto lin = find_all(cols, Role::linear_acceleration); !lin.empty()) {
        l.kind = SignalKind::linear_acceleration;
        l.channels = lin;
      } else if (auto acc = find_all(cols, Role::acceleration); !acc.empty()) {
        l.kind = SignalKind::acceleration;
        l.channels = acc;
      } else if (const auto x = find(cols, Role::x), y = find(cols, Role::y);
                 x && y && !(content && content->constant(*x) && content->constant(*y))) {
        l.kind = SignalKind::position;
        l.channels = {*x, *y};
        l.channel_unit = cols[*x].unit;
      } else if (const auto s = find(cols, Role::state)) {
        l.kind = SignalKind::gate_states;
        l.channels = {*s};
        l.period = find(cols, Role::period);
      } else if (find(cols, Role::counter) ||
                 std::none_of(cols.begin(), cols.end(), [](const Column& c) { return c.role == Role::other && !c.known; })) {
        // Stamps, with the logger's event numbers beside them or alone.
        l.kind = SignalKind::event_stamps;
        l.counter = find(cols, Role::counter);
      } else {
        return std::nullopt;
      }
      return l;
    }
    case RecordingFormat::automatic: break;
  }
  return std::nullopt;
}

std::string signal_role(SignalKind kind, Role role) {
  switch (kind) {
    case SignalKind::angle: return "angle";
    case SignalKind::angular_rate: return role == Role::omega ? "angular velocity" : "angular rate";
    case SignalKind::position: return role == Role::x ? "x" : "y";
    case SignalKind::gate_states: return "gate state";
    case SignalKind::acceleration: return "acceleration";
    case SignalKind::linear_acceleration: return "linear acceleration";
    case SignalKind::unknown: return "signal";
    case SignalKind::blocking_times:
    case SignalKind::event_stamps: break;
  }
  return role_name(role);
}

/// The `--columns` text that reads the file with `l` alone: its time (or
/// `time_entry` in its place), signal, counter and period, "-" for the rest.
std::string columns_spec(const Layout& l, const std::vector<Column>& cols, const std::string& time_entry = {}) {
  std::vector<std::string> entries(cols.size(), "-");
  const Column& t = cols[l.time];
  entries[l.time] = !time_entry.empty() ? time_entry
                    : t.frame_rate > 0.0 ? "frame:" + format_number(t.frame_rate, 6) + "fps"
                                         : "t:" + (t.unit.empty() ? std::string("s") : t.unit);
  for (std::size_t j : l.channels) {
    const std::string& unit = cols[j].unit;
    const bool length = unit == "m" || unit == "cm" || unit == "mm" || unit == "px";
    switch (l.kind) {
      case SignalKind::angle: entries[j] = "theta:" + l.channel_unit; break;
      case SignalKind::angular_rate: entries[j] = (cols[j].role == Role::omega ? "omega:" : "gyro:") + l.channel_unit; break;
      case SignalKind::linear_acceleration: entries[j] = "linear_a"; break;
      case SignalKind::acceleration: entries[j] = "a"; break;
      case SignalKind::position: entries[j] = (cols[j].role == Role::x ? "x" : "y") + (length ? ":" + unit : ""); break;
      case SignalKind::gate_states: entries[j] = "state"; break;
      case SignalKind::unknown: entries[j] = "theta"; break;
      case SignalKind::blocking_times:
      case SignalKind::event_stamps: break;
    }
  }
  if (l.counter) entries[*l.counter] = "n";
  if (l.period) entries[*l.period] = "period";
  while (entries.size() > 1 && entries.back() == "-") entries.pop_back();
  std::string out;
  for (const auto& e : entries) out += (out.empty() ? "" : ",") + e;
  return out;
}

/// A layout's signal in words, with its columns' names.
std::string signal_words(const Layout& l, const std::vector<Column>& cols, const std::vector<std::string>& names) {
  std::string what = l.kind == SignalKind::position ? "the x and y" : "the " + signal_role(l.kind, cols[l.channels[0]].role);
  for (std::size_t k = 0; k < l.channels.size(); ++k) {
    what += (k ? ", \"" : " \"") + one_line(names[l.channels[k]], 40) + "\"";
  }
  return what;
}

/// The other signals a sampled recording holds beside `chosen` (an angle
/// beside a track's x and y, a rate beside an angle), of its run and track,
/// each as the layout that reads it: the roles layout of the columns with
/// the signals found so far taken out, until none is left.
std::vector<Layout> other_signals(const Layout& chosen, std::vector<Column> cols, const Content& content) {
  std::vector<Layout> out;
  const int run = cols[chosen.time].run, track = chosen.channels.empty() ? 0 : cols[chosen.channels[0]].track;
  for (Column& c : cols) {
    if ((run > 0 && c.run != run) || (track > 0 && c.track != track) || c.role == Role::counter) {
      c.role = Role::other, c.known = true;
    }
  }
  cols[chosen.time].role = Role::time;
  auto take_out = [&](const Layout& l) {
    for (std::size_t j : l.channels) cols[j].role = Role::other, cols[j].known = true;
  };
  take_out(chosen);
  for (;;) {
    const auto l = layout_for(RecordingFormat::columns, cols, false, -1, -1, &content);
    const bool sampled = l && l->kind != SignalKind::gate_states && l->kind != SignalKind::event_stamps &&
                         l->kind != SignalKind::blocking_times;
    if (!sampled) return out;
    if (std::any_of(l->channels.begin(), l->channels.end(), [&](std::size_t j) { return content.constant(j); })) {
      take_out(*l);
      continue;
    }
    Layout alternative = *l;
    alternative.time = chosen.time;
    alternative.time_scale = chosen.time_scale;
    alternative.format = chosen.format;
    out.push_back(alternative);
    take_out(alternative);
  }
}

/// The quoted names of `cols` (at most 300 bytes).
std::string quoted_names(const std::vector<Column>& cols) {
  std::string names;
  for (std::size_t j = 0; j < cols.size(); ++j) {
    if (names.size() < 300) names += (names.empty() ? "\"" : ", \"") + column_label(cols[j].name, j + 1) + "\"";
  }
  return names;
}

/// The family whose layout the columns fit: the forced one, else the first
/// of the named families (the most specific first: a PASCO gate file also
/// has what a Vernier one needs), else by roles.
Layout detect(RecordingFormat forced, const std::vector<Column>& cols, bool preamble, bool headerless,
              const std::string& file, std::size_t header_line, int run, int track, const Content* content) {
  // With the numbers read: constant columns passed over, then, if nothing
  // else fits, taken (the swing analysis then says there is no oscillation).
  auto fit = [&](RecordingFormat family) {
    auto l = layout_for(family, cols, preamble, run, track, content);
    if (!l && content) {
      Content all = *content;
      all.skip_constant = false;
      l = layout_for(family, cols, preamble, run, track, &all);
    }
    return l;
  };
  if (forced != RecordingFormat::automatic) {
    if (auto l = fit(forced)) return *l;
    if (forced == RecordingFormat::plain) {
      fail(file, header_line, 1,
           std::to_string(cols.size()) + " numeric columns (" + quoted_names(cols) +
               "); --format plain reads one column of blocking times: name it with --columns (\"-,t:s\" takes the "
               "second) or leave the format to the header");
    }
    fail(file, header_line, 1,
         std::string("the header does not fit a ") + recording_format_name(forced) + " export: " +
             (forced == RecordingFormat::phyphox   ? "expected \"Time (s)\" first and gyroscope, linear acceleration or acceleration axes"
              : forced == RecordingFormat::vernier ? "expected a time and a gate state column"
              : forced == RecordingFormat::pasco   ? "expected \"Time (s) Run #n\" and that run's angle, angular velocity or state"
              : forced == RecordingFormat::tracker ? "expected \"t\" and an angle (θ), angular velocity (ω) or x and y"
                                                   : "expected a time and a signal column") +
             "; got " + quoted_names(cols) + " (docs/recordings.md lists the columns each format needs)");
  }
  if (cols.size() == 1) {
    if (auto l = fit(RecordingFormat::plain)) return *l;
  } else {
    for (auto family : {RecordingFormat::pasco, RecordingFormat::vernier, RecordingFormat::tracker,
                        RecordingFormat::phyphox, RecordingFormat::columns}) {
      if (auto l = fit(family)) return *l;
    }
  }
  if (const auto counter = find(cols, Role::counter); counter && !find(cols, Role::time)) {
    // Frame numbers without a time: the frame rate makes them one.
    std::vector<Column> framed = cols;
    framed[*counter].role = Role::time, framed[*counter].frame_rate = 30.0;
    if (const auto l = layout_for(RecordingFormat::columns, framed, preamble, run, track, nullptr)) {
      fail(file, header_line, 1,
           "a counter \"" + one_line(cols[*counter].name, 40) +
               "\" and no time column: frame numbers? expected times: give the frame rate with --columns (a scene's "
               "\"columns\"), e.g. \"" + columns_spec(*l, framed) + "\" for 30 frames a second");
    }
  }
  if (headerless) {
    // Reached with content only: the numbers did not say enough. Named
    // columns here are a header of generic names (generic_names).
    const bool named = std::any_of(cols.begin(), cols.end(), [](const Column& c) { return !c.name.empty(); });
    fail(file, header_line, 1,
         (named ? "a file of " + std::to_string(cols.size()) + " columns under a fitting program's generic names, "
                  "read by its numbers, whose roles they do not tell ("
                : "a headerless file of " + std::to_string(cols.size()) + " columns whose roles its numbers do not tell (") +
             quoted_names(cols) + "); name them with --columns (a scene's \"columns\"), e.g. \"t:s,theta:deg\"");
  }
  fail(file, header_line, 1,
       "unrecognised header " + quoted_names(cols) +
           "; expected a phyphox, Vernier, PASCO or Tracker export, a time with an angle, angular velocity, "
           "x and y or gate state, or one column of blocking times (docs/recordings.md), or name the format "
           "with --format or the columns with --columns");
}

/// Roles of a headerless file's columns from their numbers: a counter steps
/// by one, or by one whole stride beside an increasing column of other
/// numbers (the time: "1;3.05", "3;9.202", a count of periods against the
/// time they took), the first other increasing column is the time, a
/// constant is unused; of two that remain, one the rate of the other is an angle and its
/// angular velocity; the first swinging at twice the second's frequency is
/// no track's x (a bob's y swings at twice x's): the second is then the one
/// signal; a second that follows the first's rate (could_be_track_y: no
/// bob's height on its arc does) is set aside beside that first, an angle;
/// else they are a track's x and y. Returns a note on a column set aside.
std::optional<std::string> roles_from_content(std::vector<Column>& cols, const Content& content) {
  std::optional<std::size_t> time;
  std::vector<std::size_t> signals;
  bool other_increasing = false;  // an increasing column not of whole numbers: a time beside a strided count
  for (std::size_t j = 0; j < cols.size(); ++j) {
    const ColumnFacts& f = content.facts(j, false);
    other_increasing |= f.increasing && !f.integers;
  }
  for (std::size_t j = 0; j < cols.size(); ++j) {
    const ColumnFacts& f = content.facts(j, false);
    Column& c = cols[j];
    c.decided = "content";
    c.known = true;
    if (c.role == Role::uncertainty) continue;
    if (f.counter || (f.stride > 0.0 && other_increasing)) c.role = Role::counter;
    else if (f.constant) c.role = Role::other;
    else if (f.increasing && !time) c.role = Role::time, time = j;
    else signals.push_back(j);
  }
  for (std::size_t j : signals) cols[j].known = false;
  if (!time || signals.size() > 2) return std::nullopt;  // detect() refuses, naming them
  std::optional<std::string> note;
  if (signals.size() == 1) {
    // One signal beside a time: an angle if its numbers can be one (layout_for).
    cols[signals[0]].role = Role::angle;
  } else if (signals.size() == 2) {
    const auto& t = content.table.columns[*time];
    const auto& a = content.table.columns[signals[0]];
    const auto& b = content.table.columns[signals[1]];
    if (is_rate_of(t, a, b)) {
      cols[signals[0]].role = Role::angle, cols[signals[1]].role = Role::omega;
    } else if (is_rate_of(t, b, a)) {
      cols[signals[1]].role = Role::angle, cols[signals[0]].role = Role::omega;
    } else if (const double pa = rough_period(t, a), pb = rough_period(t, b); pa < 0.7 * pb) {
      // An accelerometer's axis along the string beside the one across it, say.
      cols[signals[1]].role = Role::angle;
      note = "\"" + column_label(cols[signals[0]].name, signals[0] + 1) + "\" swings at " + format_number(pb / pa, 2) +
             " times the frequency of \"" + column_label(cols[signals[1]].name, signals[1] + 1) +
             "\": not a track's x beside its y (y swings at twice x's frequency), so set aside";
    } else if (pb < 0.7 * pa || t.back() - t.front() < 3.0 * pa || could_be_track_y(t, a, b)) {
      // Under three periods a drift follows the rate as well as a lag does.
      cols[signals[0]].role = Role::x, cols[signals[1]].role = Role::y;
    } else {
      // "t theta extra": a bob's height is a function of its x, in step with it.
      cols[signals[0]].role = Role::angle;
      note = "\"" + column_label(cols[signals[1]].name, signals[1] + 1) + "\" follows the rate of \"" +
             column_label(cols[signals[0]].name, signals[0] + 1) +
             "\" (a part a quarter period out of step), as no bob's height on its arc does: not a track's x and "
             "y, so set aside";
    }
  }
  for (std::size_t j : signals) cols[j].known = true;
  return note;
}

/// Why a column the layout does not use is left out.
std::string unused_why(const Column& c, const std::vector<double>& numbers, const Layout& l,
                       const std::vector<Column>& cols) {
  const auto first = std::find_if(numbers.begin(), numbers.end(), [](double v) { return std::isfinite(v); });
  if (first == numbers.end()) return "no numbers";
  if (is_constant(numbers)) return "constant (" + format_number(*first, 6) + "): no signal";
  switch (c.role) {
    case Role::uncertainty: return "an uncertainty of another column";
    case Role::derivative: return "a derivative of the track (velocity, acceleration): the positions or the angle are used";
    case Role::counter: return "a counter or index";
    case Role::other: return c.name.empty() || c.decided != "header" ? "not needed" : "a word the reader does not know";
    case Role::time: return "a second time column";
    default: break;
  }
  if (c.track > 0 && !l.channels.empty() && cols[l.channels[0]].track != c.track) return "another track's";
  if (c.run > 0 && cols[l.time].run != c.run) return "another run's";
  const std::string role = role_name(c.role);
  return std::string(role.find_first_of("aeiux") == 0 ? "an " : "a ") + role + " signal: the " + role_name(cols[l.channels.empty() ? l.time : l.channels[0]].role) +
         " is used";
}

/// A role each track of a Tracker export has once: its signals.
bool tracked(Role role) {
  return role != Role::time && role != Role::other && role != Role::derivative && role != Role::uncertainty &&
         role != Role::counter;
}

Recording parse_text(std::string_view text, const std::string& file, RecordingFormat format, const std::string& set,
                     const std::string& column_spec, const InputLimits& limits);

/// Throws, naming its line and column, if [text, text + size) holds a NUL byte.
void refuse_binary(std::string_view text, std::size_t size, const std::string& file) {
  if (size == 0) return;  // an empty file's data() may be null, which memchr may not take even for 0 bytes
  if (const void* nul = std::memchr(text.data(), '\0', size)) {
    const std::size_t at = static_cast<std::size_t>(static_cast<const char*>(nul) - text.data());
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.data(), text.data() + at, '\n'));
    const std::size_t bol = text.substr(0, at).rfind('\n');
    fail(file, line, at - (bol == std::string_view::npos ? 0 : bol + 1) + 1,
         "a NUL byte: this is a binary file, not a text export");
  }
}

}  // namespace

Recording parse_recording(std::string_view text, const std::string& file, RecordingFormat format,
                          const std::string& set, const std::string& columns, const InputLimits& limits) {
  if (looks_like_zip(text)) {
    fail(file, 1, 1, "a zip archive; expected a text export here (a zip is unpacked when read from its file: read_recording)");
  }
  // A binary file is named as such wherever its NUL byte is. parse_text
  // checks the lines before the data; in the data a NUL fits no cell, so the
  // rows refuse it, and the text is searched for it only then (a search of
  // the whole text up front took 3 % of reading a large file).
  try {
    return parse_text(text, file, format, set, columns, limits);
  } catch (const InputError&) {
    refuse_binary(text, text.size(), file);
    throw;
  }
}

namespace {

/// Tracker's export of several tracks ("#multi:"): each track's name stands
/// above its first column; numbers each column's track and returns the names.
std::vector<std::string> name_tracks(std::vector<Column>& cols, const HeaderLines& lines, const Dialect& dialect,
                                     const std::string& file) {
  std::vector<std::string> tracks;
  const std::size_t header_line = lines.header_line;
  const std::optional<std::string_view>& above_header = lines.above;
  if (!above_header || starts_with(*above_header, "#multi")) {
    fail(file, header_line, 1, "a Tracker export of several tracks (#multi:) without their names; expected "
                               "each track's name on the line above the header, over its first column");
  }
  const std::vector<std::string_view> names = split_cells(*above_header, dialect);
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
    const bool unnamed = c.track == 0 && tracked(c.role);
    if (unnamed || (tracked(c.role) && c.track > 0 && twice != cols.begin() + j)) {
      fail(file, lines.above_line, 1,
           "the track names are out of line with the columns: column " + std::to_string(j + 1) + " (\"" +
               column_label(c.name, j + 1) + "\") " +
               (unnamed ? std::string("comes before the first name")
                        : "is track \"" + column_label(tracks[c.track - 1], c.track) + "\"'s second \"" +
                              column_label(c.name, j + 1) + "\"") +
               "; expected each track's name above its first column (Tracker's #multi: export)");
    }
  }
  return tracks;
}

/// The option's declared columns (--columns, a scene's "columns") in place
/// of the header's, column by column; a column it leaves out is unused.
void declare_columns(std::vector<Column>& cols, const std::string& column_spec, const std::string& file) {
  const auto spec = parse_column_spec(column_spec, file);
  if (spec.size() > cols.size()) {
    throw InputError(file, "got " + std::to_string(spec.size()) + " columns in \"" + one_line(column_spec, 80) +
                               "\"; expected at most the file's " + std::to_string(cols.size()));
  }
  for (std::size_t j = 0; j < cols.size(); ++j) {
    const std::string name = cols[j].name;
    const int track = cols[j].track, run = cols[j].run;
    if (j < spec.size() && spec[j]) {
      cols[j] = *spec[j];
    } else {
      cols[j] = Column{};
      cols[j].decided = "option";
    }
    cols[j].name = name, cols[j].track = track, cols[j].run = run;
  }
}

/// Which of several Tracker tracks is the pendulum's (1 on), by its name
/// (`set`); refuses a choice that names none, or several, or a track with no
/// swing's columns.
int chosen_track(const std::vector<std::string>& tracks, const std::vector<Column>& cols, const std::string& set,
                 const std::string& file, std::size_t header_line) {
  std::string listed;
  for (const auto& t : tracks) listed += (listed.empty() ? "\"" : ", \"") + one_line(t, 40, true) + "\"";
  if (set.empty() && tracks.size() > 1) {
    fail(file, header_line, 1, "a Tracker export of " + std::to_string(tracks.size()) + " tracks (" + listed +
                                   "); expected the pendulum's chosen by its name (import --set, a scene's set)");
  }
  const auto is_set = [&](const std::string& t) { return lower_case(t) == lower_case(set); };
  const auto named = std::find_if(tracks.begin(), tracks.end(), is_set);
  if (!set.empty() && named == tracks.end()) {
    fail(file, header_line, 1, "got the set \"" + one_line(set, 40, true) + "\"; expected one of this Tracker export's tracks: " + listed);
  }
  if (!set.empty() && std::count_if(tracks.begin(), tracks.end(), is_set) > 1) {
    fail(file, header_line, 1, "got the set \"" + one_line(set, 40, true) + "\", the name of more than one track (" + listed +
                                   "); expected a name of one track (rename the others in Tracker)");
  }
  const int track = set.empty() ? 1 : static_cast<int>(named - tracks.begin()) + 1;
  const bool positions = find(cols, Role::x, -1, track) && find(cols, Role::y, -1, track);
  if (!find(cols, Role::angle, -1, track) && !find(cols, Role::omega, -1, track) && !positions) {
    std::string own;
    for (std::size_t j = 0; j < cols.size(); ++j) {
      if (cols[j].track == track) own += (own.empty() ? "\"" : ", \"") + column_label(cols[j].name, j + 1) + "\"";
    }
    fail(file, header_line, 1, "the track \"" + one_line(tracks[track - 1], 40, true) + "\" has the columns " + own +
                                   "; expected its angle (θ), angular velocity (ω) or x and y");
  }
  return track;
}

/// A PASCO run other than the first, by its number in `set` ("Run #2",
/// "run 2" or "2"). Refuses a set that names no run here.
int chosen_run(const std::vector<Column>& cols, const std::string& set, const std::string& file,
               std::size_t header_line) {
  const std::string name = lower_case(set);
  const std::size_t digits = name.find_first_of("0123456789");
  const bool number = digits != std::string::npos && name.find_first_not_of("0123456789", digits) == std::string::npos &&
                      digits < 8 && name.size() - digits < 6;
  const std::string prefix = number ? std::string(trim_cell(name.substr(0, digits))) : std::string();
  if (!number || !(prefix.empty() || prefix == "run #" || prefix == "run")) {
    fail(file, header_line, 1, "got the set \"" + one_line(set, 40, true) + "\"; expected a PASCO run (\"Run #2\") or the name of a track in a Tracker "
                                   "export of several (\"#multi:\")");
  }
  const int run = std::atoi(name.c_str() + digits);
  std::string runs;
  for (const auto& c : cols) {
    if (c.run > 0 && c.role == Role::time) runs += (runs.empty() ? "" : ", ") + std::to_string(c.run);
  }
  if (std::none_of(cols.begin(), cols.end(), [&](const Column& c) { return c.run == run; })) {
    fail(file, header_line, 1, "no column of run " + std::to_string(run) + " in the header; expected a PASCO " +
                                   "export with \"Run #" + std::to_string(run) + "\"" +
                                   (runs.empty() ? std::string() : " (its runs: " + runs + ")"));
  }
  return run;
}

/// The columns' report (role, unit and why, in words the file's reader can
/// check), before the numbers move into the recording.
std::vector<RecordingColumn> column_report(const std::vector<Column>& cols, const Layout& layout, const Table& table) {
  std::vector<RecordingColumn> out;
  for (std::size_t j = 0; j < cols.size(); ++j) {
    RecordingColumn c;
    c.index = j + 1;
    c.name = cols[j].name;
    c.decided_by = cols[j].decided;
    const auto used = std::find(layout.channels.begin(), layout.channels.end(), j);
    // Why, in words the file's reader can check; "by the header" needs none.
    std::vector<std::string> why;
    if (j == layout.time) {
      c.role = layout.kind == SignalKind::blocking_times ? "blocking time"
               : layout.kind == SignalKind::event_stamps ? "event stamp"
                                                         : "time";
      c.unit = cols[j].unit.empty() ? "s" : cols[j].unit;
      if (c.decided_by == "content") why.emplace_back("increasing, not a counter");
      if (!layout.time_why.empty()) why.push_back(layout.time_why);
    } else if (used != layout.channels.end()) {
      c.role = signal_role(layout.kind, cols[j].role);
      c.unit = layout.kind == SignalKind::gate_states ? "" : layout.channel_unit;
      if (!layout.unit_why.empty() && layout.kind == SignalKind::angle) {
        c.decided_by = "content";
        why.push_back("the role by the " + cols[j].decided + "; " + layout.unit_why);
      }
      if (layout.kind == SignalKind::unknown) why.push_back(layout.unit_why);
      if (layout.kind == SignalKind::position && cols[j].decided == "content") {
        why.emplace_back("two varying columns beside the time, neither the rate of the other");
      }
      if (layout.kind == SignalKind::angle && cols[j].decided == "content") {
        const bool rate = std::any_of(cols.begin(), cols.end(), [](const Column& o) { return o.role == Role::omega; });
        why.emplace_back(rate ? "the other varying column is its rate of change" : "the one varying column beside the time");
      }
    } else if (layout.counter && j == *layout.counter) {
      c.role = "counter";
      if (c.decided_by == "content") {
        const double stride = examine(table.columns[j], false).stride;
        why.emplace_back(stride > 1.0 ? "whole numbers stepping by " + format_number(stride) +
                                            " beside an increasing time: a count (of periods, say) at each time"
                                      : "whole numbers stepping by one");
      }
    } else if (layout.period && j == *layout.period) {
      c.role = "period";
      c.unit = "s";
    } else {
      c.role = "unused";
      why.push_back(unused_why(cols[j], table.columns[j], layout, cols));
    }
    if (cols[j].frame_rate > 0.0) why.push_back("frame numbers at " + format_number(cols[j].frame_rate, 6) + " frames/s");
    for (const auto& w : why) c.why += (c.why.empty() ? "" : "; ") + w;
    out.push_back(std::move(c));
  }
  return out;
}

/// The samples a swing needs into `rec` (scaled; a row without its time, a
/// channel or its count dropped), cleaned of repeated and out-of-order times
/// and, for a sampled signal, of held frames, each in a note.
void take_samples(Recording& rec, Table& table, const Layout& layout, bool sampled, const std::string& file) {
  // The columns a row needs: without its time, a channel or its count it is dropped.
  std::vector<std::size_t> needed{layout.time};
  needed.insert(needed.end(), layout.channels.begin(), layout.channels.end());
  if (layout.counter) needed.push_back(*layout.counter);
  std::vector<std::size_t> rows;  // the rows kept when some are dropped; empty: all
  const bool complete = !table.any_nan || std::all_of(needed.begin(), needed.end(), [&](std::size_t j) {
    return std::none_of(table.columns[j].begin(), table.columns[j].end(), [](double v) { return std::isnan(v); });
  });
  auto take = [&](std::size_t j, double scale) {
    std::vector<double> out;
    if (complete) {
      out = std::move(table.columns[j]);
    } else {
      out.reserve(rows.size());
      for (std::size_t i : rows) out.push_back(table.columns[j][i]);
    }
    if (scale != 1.0) {
      for (double& v : out) v *= scale;
    }
    return out;
  };
  if (!complete) {
    for (std::size_t i = 0; i < table.rows; ++i) {
      if (std::none_of(needed.begin(), needed.end(), [&](std::size_t j) { return std::isnan(table.columns[j][i]); })) {
        rows.push_back(i);
      }
    }
    rec.dropped = table.rows - rows.size();
  }
  rec.time = take(layout.time, layout.time_scale);
  for (std::size_t j : layout.channels) rec.channels.push_back(take(j, layout.channel_scale));
  if (layout.counter) rec.counts = take(*layout.counter, 1.0);

  // Time order: repeated and out-of-order samples, gaps.
  Cleaned cleaned = clean_times(rec.time, rows, table, sampled, file);
  rec.time_quantum = cleaned.quantum;
  rec.notes.insert(rec.notes.end(), cleaned.notes.begin(), cleaned.notes.end());
  if (!cleaned.all) {
    rec.dropped += rec.time.size() - cleaned.keep.size();  // out of time order or repeated, each in a note
    auto keep = [&](std::vector<double>& v) {
      for (std::size_t k = 0; k < cleaned.keep.size(); ++k) v[k] = v[cleaned.keep[k]];
      v.resize(cleaned.keep.size());
    };
    keep(rec.time);
    for (auto& c : rec.channels) keep(c);
    if (!rec.counts.empty()) keep(rec.counts);
  }
  if (sampled) {
    const Cleaned frames = held_frames(rec.time, rec.channels);
    rec.notes.insert(rec.notes.end(), frames.notes.begin(), frames.notes.end());
    rec.time_quantum = std::max(rec.time_quantum, frames.quantum);
  }
}

Recording parse_text(std::string_view text, const std::string& file, RecordingFormat format, const std::string& set,
                     const std::string& column_spec, const InputLimits& limits) {
  const std::string_view original = text;
  text = strip_bom(text);
  const HeaderLines lines = find_header(text, file);
  std::optional<std::string_view> header = lines.header;
  const std::size_t header_line = lines.header_line;
  const bool preamble = lines.preamble;
  refuse_binary(original, static_cast<std::size_t>(text.data() - original.data()) + lines.data_offset, file);
  const DataRows data = data_rows(text, lines, file, "a recording");
  std::vector<RecordingNote> header_notes;
  Dialect dialect = sniff(header, data.first);
  if (header) {
    // A header naming other columns than the rows hold is no guide to them.
    const std::size_t named = filled_cells(split_cells_within(*header, dialect, limits, file, header_line));
    const std::vector<std::string_view> first = split_cells_within(data.first, dialect, limits, file, lines.data_line);
    if (named != first.size() && named != filled_cells(first)) {
      header_notes.push_back({header_line, "the header names " + std::to_string(named) + " column" + (named == 1 ? "" : "s") +
                                               " over rows of " + std::to_string(first.size()) +
                                               ": it is set aside and the columns read by their numbers"});
      header.reset();
      dialect = sniff(header, data.first);
    }
  }

  std::vector<Column> cols;
  // Tracker's export of several tracks: "#multi:", then each track's name
  // above its first column, then the header (one time column for all).
  std::vector<std::string> tracks;
  if (header) {
    for (std::string_view cell : split_cells(*header, dialect)) {
      cols.push_back(classify(cell));
      if (table_only(cols.back().role)) cols.back().role = Role::other, cols.back().known = false;
    }
    while (cols.size() > 1 && cols.back().name.empty()) cols.pop_back();  // a trailing delimiter
    if (lines.several_tracks) tracks = name_tracks(cols, lines, dialect, file);
  } else {
    cols.resize(split_cells_within(data.first, dialect, limits, file, lines.data_line).size());
    for (std::size_t j = 0; j < cols.size(); ++j) cols[j].decided = "content";
  }
  std::vector<std::string> names(cols.size());  // as messages quote them
  for (std::size_t j = 0; j < cols.size(); ++j) names[j] = column_label(cols[j].name, j + 1);
  // What the option declares replaces what the header says, column by column.
  const bool declared = !column_spec.empty();
  if (declared) declare_columns(cols, column_spec, file);
  // Which of several Tracker tracks, or a PASCO run other than the first.
  const int track = tracks.empty() ? -1 : chosen_track(tracks, cols, set, file, header_line);
  const int run = !set.empty() && tracks.empty() ? chosen_run(cols, set, file, header_line) : 1;
  const bool generic = header && !declared && generic_names(cols);
  const bool headerless = (!header && !declared) || generic;
  // A header no layout fits is refused before its rows are read.
  if (!headerless) (void)detect(format, cols, preamble, false, file, header_line, run, track, nullptr);

  Table table = read_rows(data.begin, data.end, lines.data_line, dialect, names, file, limits);
  if (headerless) {
    // A trailing delimiter on every row is no column.
    while (cols.size() > 1 && is_constant(table.columns.back()) &&
           std::none_of(table.columns.back().begin(), table.columns.back().end(), [](double v) { return std::isfinite(v); })) {
      cols.pop_back(), names.pop_back(), table.columns.pop_back();
    }
  }
  const Content content{table};
  if (generic) {
    // A primed or d column never negative is an uncertainty: a swing's
    // derivative changes sign. The rest are read as a headerless file's.
    std::string set_aside;
    for (std::size_t j = 0; j < cols.size(); ++j) {
      const auto& v = table.columns[j];
      const bool sigma = cols[j].role != Role::x && cols[j].role != Role::y &&
                         std::none_of(v.begin(), v.end(), [](double x) { return x < 0.0; });
      cols[j].role = sigma ? Role::uncertainty : Role::other;
      if (sigma) set_aside += (set_aside.empty() ? "\"" : ", \"") + names[j] + "\"";
    }
    header_notes.push_back({header_line, "the header's names (" + quoted_names(cols) +
                                             ") are a fitting program's generic ones, not a time and a track: the "
                                             "columns are read by their numbers" +
                                             (set_aside.empty() ? std::string()
                                                                : ", " + set_aside + " (never negative) as uncertainties"
                                                                  " of the others")});
  }
  if (headerless && cols.size() > 1 && format != RecordingFormat::plain) {
    if (auto note = roles_from_content(cols, content)) header_notes.push_back({0, std::move(*note)});
  }
  Layout layout = detect(format, cols, preamble, headerless, file, header_line, run, track, &content);
  const bool holds_sets = layout.format == RecordingFormat::pasco || (layout.format == RecordingFormat::tracker && !tracks.empty());
  if (!set.empty() && !holds_sets) {
    fail(file, header_line, 1, "got the set \"" + one_line(set, 40, true) + "\", but this " + recording_format_name(layout.format) +
                                   " export holds a single set; expected a set in a zip archive, a PASCO file or a Tracker export of "
                                   "several tracks");
  }
  // An angle labelled radians that swings beyond 180 deg is degrees mislabelled.
  if (layout.kind == SignalKind::angle && layout.unit_why.empty() && layout.channel_unit == "rad" &&
      content.facts(layout.channels[0]).half_range() > kPi) {
    fail(file, header_line, 1,
         "the column \"" + names[layout.channels[0]] + "\" is in radians by its " +
             (cols[layout.channels[0]].decided == "option" ? "declared unit" : "header") + " but swings by +-" +
             format_number(content.facts(layout.channels[0]).half_range(), 3) +
             ", over 180 deg: it holds degrees? Declare them with --columns (a scene's \"columns\"), e.g. "
             "\"t:s,theta:deg\"");
  }

  // A time column without a unit whose numbers are whole and step by one
  // counts frames or events: read as seconds it would give a period in
  // frames (108 s for a 1.8 s swing at 60 frames/s). A unit written ("Time
  // (s)", "t:s") is taken at its word: ms and us step so at 1 kHz and 1 MHz.
  const Column& time_column = cols[layout.time];
  const std::vector<double>& times = table.columns[layout.time];
  const bool stepping_by_one = times.size() > 2 && times[0] == std::floor(times[0]) && times[1] - times[0] == 1.0 &&
                               times[2] - times[1] == 1.0;
  if (time_column.frame_rate == 0.0 && time_column.unit.empty() && stepping_by_one &&
      content.facts(layout.time, false).counter) {
    fail(file, header_line, 1,
         "the time column \"" + names[layout.time] + "\" holds whole numbers stepping by one (" +
             format_number(times.front(), 9) + " to " + format_number(times.back(), 9) +
             ") and no unit: frame numbers or a count, not seconds? expected times: give the frame rate with "
             "--columns (a scene's \"columns\"), e.g. \"" + columns_spec(layout, cols, "frame:30fps") +
             "\" for 30 frames a second, or \"" + columns_spec(layout, cols, "t:s") + "\" if they are seconds");
  }

  const bool sampled = layout.kind != SignalKind::gate_states && layout.kind != SignalKind::blocking_times &&
                       layout.kind != SignalKind::event_stamps;
  if (time_column.frame_rate == 0.0 && time_column.unit.empty()) {
    // A microcontroller's clock counts milliseconds: the swing's period says which.
    const double period = sampled ? rough_period(times, table.columns[layout.channels[0]]) : median_step(times);
    const auto [unit, why] = unitless_time(period);
    cols[layout.time].unit = unit;
    layout.time_scale = *time_scale(unit);
    layout.time_why = why;
  }

  // The columns' report, before the numbers move into the recording.
  Recording rec;
  rec.set = track > 0 ? tracks[static_cast<std::size_t>(track - 1)] : set;  // a track as Tracker names it
  rec.format = layout.format;
  rec.kind = layout.kind;
  rec.rows = table.rows;
  rec.columns = column_report(cols, layout, table);
  rec.notes = std::move(header_notes);
  if (!layout.unit_why.empty()) rec.notes.push_back({0, "\"" + names[layout.channels[0]] + "\": " + layout.unit_why});
  if (layout.time_scale != 1.0 && !layout.time_why.empty()) rec.notes.push_back({0, "\"" + names[layout.time] + "\": " + layout.time_why});
  if (!declared) {
    const std::vector<Layout> others = other_signals(layout, cols, content);
    if (!others.empty()) rec.candidates.push_back({signal_words(layout, cols, names), columns_spec(layout, cols)});
    for (const Layout& o : others) rec.candidates.push_back({signal_words(o, cols, names), columns_spec(o, cols)});
  }

  for (std::size_t j : layout.channels) rec.channel_names.push_back(cols[j].name);
  if (layout.period) {
    for (double v : table.columns[*layout.period]) {
      if (!std::isnan(v)) rec.periods.push_back(v * layout.time_scale);
    }
  }
  take_samples(rec, table, layout, sampled, file);
  return rec;
}

}  // namespace

Recording read_recording(const std::string& path, RecordingFormat format, const RecordingLimits& limits,
                         const std::string& set, const std::string& columns) {
  const InputFile file(path, "a recording file", limits.within);
  if (file.size() > limits.input.bytes) throw InputError(file.path(), over_limit(limits.input, Limit::bytes));
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
    const bool sheet = looks_like_xlsx(map.text());
    if (((looks_like_zip(map.text()) && !sheet) || looks_like_phyphox_experiment(map.text())) && !columns.empty()) {
      throw InputError(path, "a zip archive with columns declared; expected them for a text export only (a zip's "
                             "sets are phyphox's, whose headers say)");
    }
    // A spreadsheet's sheet is read as the CSV it holds, `set` naming the sheet.
    Recording r = sheet ? parse_recording(xlsx_sheet_csv(map.text(), path, set, limits.input.bytes), path, format, "", columns, limits.input)
                  : looks_like_zip(map.text())                 ? read_zip_recording(map.text(), path, format, set, limits)
                  : looks_like_phyphox_experiment(map.text()) ? read_phyphox_experiment(map.text(), path, format, set)
                                                              : parse_recording(map.text(), path, format, set, columns, limits.input);
    check_unchanged();
    return r;
  } catch (const InputError&) {
    check_unchanged();
    throw;
  }
}

}  // namespace pendulum
