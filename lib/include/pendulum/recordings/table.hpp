#pragma once
/// \file recordings/table.hpp
/// \brief Tables of settings and periods (docs/series.md, "Tables"): a
/// length series or a pivot scan typed into a spreadsheet, read by the
/// recording reader's stages (decode, lines, split, words, rows), its rows at
/// one setting grouped into one observation.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pendulum/observation.hpp"
#include "pendulum/recordings/read.hpp"

namespace pendulum {

/// A column declared by a scene's "columns" or import's --columns: what it
/// holds and in what unit, where the header cannot say.
struct TableColumnChoice {
  /// "length", "pivot_distance", "pivot_position", "period", "time" (of
  /// `oscillations` oscillations), "amplitude", or one of them followed by
  /// "_uncertainty".
  std::string role;
  std::size_t column = 0;  ///< from 1; 0: by `name`
  std::string name;        ///< the header's name of the column
  std::string unit;        ///< empty: from the header or the numbers
  int oscillations = 0;    ///< a time column's oscillations (0: from the header)
};

struct TableOptions {
  /// Replaces what the header and the numbers say: only these columns are read.
  std::vector<TableColumnChoice> columns;
  /// The time column is the time of this many oscillations (import
  /// --oscillations); 0: from the header ("t10", "10T"), else 1.
  int oscillations = 0;
  /// A spreadsheet's (.xlsx) sheet, by its name or number from 1; the first by default.
  std::string sheet;
  /// Bytes, rows and columns read (docs/robustness.md, "Limits").
  InputLimits limits = kTableInput;
};

/// The rows at one setting: one observation (docs/series.md, "Repeats").
struct TableObservation {
  double setting = 0.0;                 ///< in SettingsTable::setting_unit
  std::optional<double> setting_sigma;  ///< the largest of its rows' (one measurement)
  std::vector<double> times;            ///< one per row, in time_unit, each of `oscillations` oscillations
  /// The uncertainty of one of `times` (time_unit): the rows' stated ones
  /// (their rms), else the pooled scatter of the table's repeats (the floor
  /// of the rows' own scatter); empty when their own scatter is all there is.
  std::optional<double> time_sigma;
  std::optional<double> amplitude, amplitude_sigma;  ///< in amplitude_unit
  std::size_t first_line = 0, last_line = 0;         ///< lines of the file
};

struct SettingsTable {
  Setting setting = Setting::length;
  std::string setting_unit, time_unit, amplitude_unit;  ///< scene unit names ("cm", "s", "deg")
  int oscillations = 1;
  std::vector<TableObservation> observations;
  std::size_t rows = 0;
  /// The pooled standard deviation of one time over the settings timed more
  /// than once (time_unit), and its degrees of freedom (sum of n - 1).
  std::optional<double> pooled_sigma;
  std::size_t pooled_dof = 0;
  /// Every setting timed once and no uncertainty column: the periods'
  /// uncertainty is the scatter about the fit (docs/series.md, "Single
  /// timings"), floored by `resolution`.
  bool sigma_from_scatter = false;
  /// One pendulum at several amplitudes (docs/series.md, "Amplitude
  /// sweeps"): no setting column beside amplitudes, or one length at three
  /// amplitudes or more; each observation's `setting` is its amplitude as
  /// written.
  bool sweep = false;
  /// A sweep's one length where the table gives it (setting_unit), with
  /// its uncertainty where stated; empty where the table has no length.
  std::optional<double> sweep_length, sweep_length_sigma;
  /// The step of the time column's printed digits (time_unit): 0.01 for "12.74".
  double resolution = 0.0;
  std::vector<RecordingColumn> columns;  ///< every column, used or not, and why
  std::vector<RecordingNote> notes;      ///< what was decided (units from the numbers, grouping)
  std::vector<RecordingNote> warnings;   ///< a unit taken from the numbers alone
};

/// Whether the text reads as a table of settings and periods rather than a
/// recording: a header naming a setting (length, pivot) or a time of N
/// oscillations, or an x without a y whose time column does not increase (a
/// table's pivot positions; a track's x has increasing times), or,
/// headerless, 2 to 5 columns whose numbers read as one (a setting, its
/// uncertainty, periods in 0.1-30 s, theirs).
bool looks_like_settings_table(std::string_view text);

/// Reads the table. Errors are InputError at "file:line:column" (or "file"):
/// no setting or no period column, one row, a cell that is not a number, an
/// empty cell, a unit the numbers leave open between two, rows whose periods
/// and settings disagree by a factor (units mixed), a setting that comes back
/// after others (its rows must be together).
SettingsTable parse_settings_table(std::string_view text, const std::string& file, const TableOptions& options = {});

/// The file at `path` (at most options.limits.bytes, beneath the folder
/// `within` when given: InputFile), parsed.
SettingsTable read_settings_table(const std::string& path, const TableOptions& options = {},
                                  const std::optional<std::string>& within = {});

/// The largest spreadsheet (.xlsx) file_holds_settings_table unpacks to look at (16 MiB).
inline constexpr std::size_t kMaxSpreadsheetPeek = std::size_t{1} << 24;

/// Whether the file at `path` holds a table of settings (its first 64 KiB
/// read as looks_like_settings_table; a spreadsheet's `sheet`, the first by
/// default, as the CSV it holds); false when it cannot be read.
bool file_holds_settings_table(const std::string& path, const std::string& sheet = {});

/// `--columns "l:cm,u,t10:s,u"`: one entry per column in file order: l
/// (length), h (pivot distance), x (pivot position), r (rod length), T (period), tN (time of
/// N oscillations), theta (amplitude), u (the uncertainty of the entry before
/// it), - (not used); each with an optional ":unit". InputError at `where`.
std::vector<TableColumnChoice> parse_table_column_spec(const std::string& spec, const std::string& where);

/// The roles a table's --columns entry takes, in words, for help and messages:
/// "l (length), h (pivot distance), x (pivot position), T (period), ...".
std::string table_column_roles();

}  // namespace pendulum

namespace pendulum {

/// The scene `pendulum-g import TABLE` prints: the table's observations
/// (numbers, one per setting), "amplitude": "not recorded" when the table
/// has no amplitude column, the unknowns a pivot scan needs in "fit", and
/// under "import" the columns used and how each was decided. JSON text.
std::string table_scene(const SettingsTable& table, const std::string& table_name);

}  // namespace pendulum
