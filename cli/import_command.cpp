// `pendulum-g import FILE`: a phone, photogate or video-tracker recording ->
// the period with its uncertainty, the amplitudes, and the `timing` and
// `decay` parts of a scene (docs/recordings.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

#include "commands.hpp"
#include "pendulum/numeric.hpp"
#include "pendulum/json/output.hpp"
#include "pendulum/recordings/swings.hpp"
#include "pendulum/recordings/table.hpp"
#include "pendulum/files.hpp"
#include "pendulum/printable.hpp"
#include "pendulum/input_error.hpp"

namespace pendulum::cli {
namespace {

/// One line per column of a recording or a table: its role, unit, header
/// name and how that was decided.
void put_columns(std::ostream& o, const std::vector<RecordingColumn>& columns) {
  for (const RecordingColumn& c : columns) {
    // The file's own header cells, as its messages quote them (column_label).
    const std::string name = c.name.empty() ? "" : " \"" + one_line(c.name, 40, true) + "\"";
    const std::string unit = c.unit.empty() ? "" : " (" + one_line(c.unit, 20, true) + ")";
    const std::string label = "column " + std::to_string(c.index);
    o << label << std::string(23 - std::min<std::size_t>(22, label.size()), ' ') << c.role << unit << name
      << ", by the " << c.decided_by << (c.why.empty() ? "" : ": " + c.why) << "\n";
  }
}

/// `import --format table` of a table of settings: its columns, what was
/// decided, and each observation the scene gets (its rows' mean).
std::string settings_table_text(const SettingsTable& t, const std::string& name) {
  std::ostringstream o;
  char line[200];
  auto put = [&](const char* fmt, auto... args) {
    std::snprintf(line, sizeof line, fmt, args...);
    o << line;
  };
  put("%-22s %s (%zu rows, %zu observations)\n", "table", name.c_str(), t.rows, t.observations.size());
  put_columns(o, t.columns);
  for (const auto* list : {&t.notes, &t.warnings}) {
    for (const RecordingNote& n : *list) {
      put("%-22s ", list == &t.warnings ? "warning" : n.line ? ("line " + std::to_string(n.line)).c_str() : "note");
      o << n.text << "\n";
    }
  }
  if (t.pooled_sigma) {
    put("%-22s %.3g %s for one time of %d oscillations (%zu degrees of freedom)\n", "repeats' scatter",
        *t.pooled_sigma, t.time_unit.c_str(), t.oscillations, t.pooled_dof);
  }
  // A sweep's rows are grouped by their amplitude, as written.
  const std::string setting = t.sweep ? "amplitude (" + t.amplitude_unit + ")"
                                      : std::string(setting_key(t.setting)) + " (" + t.setting_unit + ")";
  const std::string time = "mean of " + std::to_string(t.oscillations) + " T (" + t.time_unit + ")";
  put("\n%-22s %5s %-18s %-18s %s\n", setting.c_str(), "rows", time.c_str(), ("sigma of one (" + t.time_unit + ")").c_str(),
      "lines");
  for (const TableObservation& b : t.observations) {
    double mean = 0.0;
    for (double x : b.times) mean += x / static_cast<double>(b.times.size());
    char sigma[32] = "its scatter";
    if (b.time_sigma) std::snprintf(sigma, sizeof sigma, "%.3g", *b.time_sigma);
    put("%-22.6g %5zu %-18.7g %-18s %zu-%zu\n", b.setting + 0.0 /* no "-0" */, b.times.size(), mean, sigma, b.first_line, b.last_line);
  }
  return o.str();
}

std::string summary_table(const RecordingSummary& r) {
  const SwingAnalysis& a = r.swings;
  std::ostringstream o;
  char line[200];
  auto put = [&](const char* fmt, auto... args) {
    std::snprintf(line, sizeof line, fmt, args...);
    o << line;
  };
  put("%-22s %s (%zu rows, %zu skipped)\n", "recording", r.file.c_str(), r.rows, r.dropped);
  put("%-22s %s\n", "format", recording_format_name(r.format));
  if (!r.set.empty()) put("%-22s %s\n", "set", one_line(r.set, 40, true).c_str());
  put_columns(o, r.columns);
  for (const RecordingNote& n : r.notes) {
    put("%-22s ", n.line ? ("line " + std::to_string(n.line)).c_str() : "note");
    o << n.text << "\n";
  }
  put("%-22s %d (%zu crossings)\n", "full periods", a.period.periods, a.crossings.size());
  put("%-22s %.7f s +- %.2g s\n", "period", a.period.value, a.period.uncertainty);
  put("%-22s %.3g s rms, lag-1 correlation %.2f\n", "crossing residuals", a.period.residual_rms,
      a.period.lag1_correlation);
  if (std::isfinite(a.small_amplitude_period)) {
    put("%-22s %.7f s\n", "small-amplitude T0", a.small_amplitude_period);
  }
  if (std::isfinite(a.start_amplitude)) {
    put("%-22s %.3f deg at the first crossing (amplitude_range.start) -> %.3f deg at the last\n", "amplitude",
        degrees(a.start_amplitude), degrees(a.end_amplitude));
  } else if (!a.decay.amplitudes.empty()) {
    // Fewer than 8 swings, or half of them, have an amplitude: no smooth curve to take its ends from.
    const auto [lo, hi] = std::minmax_element(a.decay.amplitudes.begin(), a.decay.amplitudes.end());
    put("%-22s none at the first crossing (too few swings have one); the swings' from %.3f to %.3f deg\n",
        "amplitude", degrees(*lo), degrees(*hi));
  }
  for (const RecordingNote& note : a.notes) o << "note                   " << note.text << "\n";
  // The period against amplitude in ten slices of the record.
  const auto& c = a.period_curve;
  const std::size_t slices = std::min<std::size_t>(10, c.size());
  put("\n%10s %14s %14s\n", "time (s)", "amplitude (deg)", "period (s)");
  for (std::size_t k = 0; k < slices; ++k) {
    const std::size_t i = k * c.size() / slices, j = (k + 1) * c.size() / slices;
    double t = 0.0, amp = 0.0, per = 0.0;
    for (std::size_t m = i; m < j; ++m) t += c[m].time, amp += c[m].amplitude, per += c[m].period;
    const double count = static_cast<double>(j - i);
    if (std::isfinite(amp)) {
      put("%10.1f %14.3f %14.6f\n", t / count, degrees(amp / count), per / count);
    } else {
      put("%10.1f %14s %14.6f\n", t / count, "-", per / count);
    }
  }
  return o.str();
}

}  // namespace

void add_recording_options(CLI::App& cmd, SwingOptions& options, std::string& set, std::string& columns) {
  cmd.add_option("--bob-width-m", options.bob_width,
                 "Photogates: the bob's width across the beam (m), for the amplitudes")
      ->check(in_range(ranges::bob_width));
  cmd.add_option("--length-m", options.length,
                 "Pivot to bob centre (m). Photogates: without it the amplitudes take g as standard gravity; "
                 "a video track: its circle gives the angles only within 3 sigma of it (else of the period's length)")
      ->check(in_range(ranges::length));
  cmd.add_option_function<std::string>(
         "--range",
         [&options](const std::string& text) {
           // A:B in seconds of the file's own clock, or all: the whole record.
           if (text == "all") {
             options.whole_record = true;
             return;
           }
           const auto colon = text.find(':');
           const std::optional<double> a = decimal_number(std::string_view(text).substr(0, colon));
           const std::optional<double> b =
               colon == std::string::npos ? std::nullopt : decimal_number(std::string_view(text).substr(colon + 1));
           if (!a || !b || !std::isfinite(*a) || !std::isfinite(*b) || !(*a < *b)) {
             throw CLI::ValidationError("--range", "got \"" + one_line(text, kShownValueBytes, true) +
                                                       "\"; expected START:END in seconds of the recording's clock, "
                                                       "START before END (10:200), or all");
           }
           options.range = std::make_pair(*a, *b);
         },
         "Analyse only the samples or events from START to END (s, the file's own clock): START:END; or all, the "
         "whole record (default: the clean stretch, the release, the catch and the shorter side of a glitch cut)")
      ->type_name("START:END|all");
  cmd.add_option("--stamps-per-period", options.stamps_per_period,
                 "Event stamps: 1 (a timer, a photogate's pendulum mode) or 2 (one a passage); default: 2 where "
                 "consecutive intervals alternate, else 1")
      ->check(in_range(ranges::stamps_per_period));
  cmd.add_option("--set", set,
                 "Zip exports: the CSV inside to read (Gyroscope.csv, in any case; default: the one with the best "
                 "pendulum signal, a rate, then linear acceleration, then acceleration, the others' periods "
                 "compared with it). PASCO: the run (\"Run #2\"; "
                 "default run 1). Tracker's export of several tracks: the pendulum's track by its name "
                 "(\"mass B\"). A spreadsheet (.xlsx): the sheet, by its name or number from 1 (default the first; "
                 "also --sheet)");
  cmd.add_option("--sheet", set, "A spreadsheet (.xlsx): the sheet to read, as --set");
  cmd.add_option("--columns", columns,
                 "Each column's role and unit in file order, where the file cannot tell (a headerless file, an "
                 "angle without its unit): \"t:s,theta:deg\"; roles t, theta, omega, x, y, n (counter), state, "
                 "period, gyro, a, linear_a; - for a column not used (docs/recordings.md, Columns). A table's "
                 "(docs/series.md, Tables): " + table_column_roles() + ", e.g. \"x:cm,T:s,u\"");
}

/// Whether --columns names a table's columns (a length, a pivot, a time of
/// N oscillations, an uncertainty; an x without a y) rather than a recording's.
bool names_table_columns(const std::string& spec) {
  if (spec.empty()) return false;
  try {
    const auto columns = parse_table_column_spec(spec, "--columns");
    bool x = false, other_setting = false;
    for (const auto& c : columns) {
      x |= c.role == "pivot_position";
      other_setting |= c.role == "length" || c.role == "pivot_distance" || c.role == "rod_length" || c.role == "time" ||
                       c.role.find("_uncertainty") != std::string::npos;
    }
    return other_setting || (x && spec.find('y') == std::string::npos);
  } catch (const InputError&) {
    return false;
  }
}

Command add_import_command(CLI::App& app) {
  struct Options {
    std::string file;
    std::vector<std::string> formats;
    SwingOptions swing;
    std::string set;
    std::string columns;
    bool table = false;
    int oscillations = 0;
    GivenLimits limits;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "import", "Reduce a phone, photogate or video-tracker recording to a period, amplitudes and the "
                "timing and decay parts of a scene (docs/recordings.md), or read a table of settings and periods "
                "into a scene (docs/series.md, Tables)");
  cmd->add_option("recording", o->file, "Recording file (CSV or tab-separated text, or phyphox's zip export)")
      ->required();
  std::vector<std::string> formats = recording_family_names();
  formats.insert(formats.end(), {"json", "table", "scene"});
  cmd->add_option("--format", o->formats,
                  "The recording's family (" + recording_family_words() + "; default: from the header) and/or the "
                  "output (json, the default; table; or scene: a whole scene timed by the recording, the length "
                  "and the bob left for you to fill in, which reduce then reads; a table's JSON is a scene "
                  "already); may be given twice")
      ->check(CLI::IsMember(formats))
      ->allow_extra_args(false)  // one value each time: the file after it is not a format
      ->take_all();
  add_recording_options(*cmd, o->swing, o->set, o->columns);
  cmd->add_flag("--table", o->table,
                "Read the file as a table of settings and periods (lengths or pivots, periods or times of N "
                "oscillations; docs/series.md, Tables), which a header naming a length or a pivot says by itself");
  cmd->add_option("--oscillations", o->oscillations,
                  "Tables: the time column is the time of this many oscillations (a header's \"t10\" says so)")
      ->check(in_range(ranges::oscillations));
  add_limit_options(*cmd, o->limits);

  return {cmd, [o] {
    bool table = false, scene = false;
    for (const auto& f : o->formats) {
      if (f == "table" || f == "json" || f == "scene") table = f == "table", scene = f == "scene";
    }
    if (o->table || names_table_columns(o->columns) || file_holds_settings_table(o->file, o->set)) {
      TableOptions options;
      options.oscillations = o->oscillations;
      options.sheet = o->set;
      options.limits = o->limits.applied_to(kTableInput);
      if (!o->columns.empty()) options.columns = parse_table_column_spec(o->columns, "--columns");
      const SettingsTable t = read_settings_table(o->file, options);
      const std::string name = printable_name(o->file);
      std::vector<std::string> warnings;
      for (const RecordingNote& w : t.warnings) warnings.push_back(name + ": " + w.text);
      print_warnings(warnings);
      std::cout << (table ? settings_table_text(t, name) : table_scene(t, name));
      return 0;
    }
    const RecordingSummary summary = analyse_recording(
        o->file, recording_family(o->formats).value_or(RecordingFormat::automatic), o->swing,
        {o->limits.applied_to(kRecordingInput), std::nullopt}, o->set, o->columns);
    if (scene && o->swing.stamps_per_period) {
      // A scene's reference has no key for it: reduce would read the stamps its own way.
      throw UsageError("--stamps-per-period with --format scene: a scene cannot say it, and reduce would count "
                       "the stamps by their intervals; give the scene's timing as import's JSON pastes it instead");
    }
    if (scene) {
      const std::optional<RecordingFormat> family = recording_family(o->formats);
      RecordingReference ref;
      ref.recording = std::filesystem::path(o->file).filename().string();
      ref.format = family ? recording_format_name(*family) : "";
      ref.set = o->set, ref.columns = o->columns;
      ref.range = o->swing.range, ref.whole_record = o->swing.whole_record;
      ref.bob_width = o->swing.bob_width, ref.length = o->swing.length;
      std::cout << recording_scene(summary, ref) << "\n";
      return 0;
    }
    std::cout << (table ? summary_table(summary) : recording_json(summary) + "\n");
    return 0;
  }};
}

}  // namespace pendulum::cli
