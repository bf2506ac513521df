#pragma once
/// \file recordings/read.hpp
/// \brief Reading the files that phones, photogates and video trackers
/// export (docs/recordings.md): the family is recognised from the header,
/// the delimiter (comma, tab, semicolon) and the decimal mark (point or
/// comma) from the text. One pass over the text, numbers by std::from_chars,
/// no allocation per cell.
///
/// Header layouts (docs/recordings.md, "Formats", says where each came from):
///  - phyphox: "Time (s)","Gyroscope x (rad/s)",... (Gyroscope),
///    "Acceleration x (m/s^2)" (Acceleration with g), "Linear Acceleration x
///    (m/s^2)", "Rotation x (rad/s)" (the Pendulum experiment's raw data).
///  - Vernier (Graphical Analysis, Logger Pro): "Latest: Time (s)",
///    "Latest: GateState" (or "Run 1: ...", "Gate State"), one row per gate
///    change with the state, 0 or 1; "Period (s)" where present.
///  - PASCO Capstone: "Time (s) Run #n" and a measurement of that run (1 unless asked): "Angle
///    (rad) Run #1", "Angular Velocity (rad/s) Run #1", "State Run #1".
///  - plain: one column of blocking times, header optional ("t (ms)").
///  - Tracker: a line naming the track ("mass A"), then "t","x","y",...
///    or "t","θ"/"theta" or "ω"/"omega".

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pendulum/files.hpp"

namespace pendulum {

/// The family of a recording; `automatic` recognises it from the header.
/// `columns`: no family's layout, read by its columns' roles (a header's
/// words and units, the numbers of a headerless file, or `--columns`).
enum class RecordingFormat { automatic, phyphox, vernier, pasco, plain, tracker, columns };

/// "auto", "phyphox", "vernier", "pasco", "plain", "tracker", "columns".
const char* recording_format_name(RecordingFormat format);

/// The families a user names (`import --format`, pendulum_g.read_recording):
/// auto, phyphox, vernier, pasco, plain, tracker.
std::vector<std::string> recording_family_names();

/// The same in words, for help and messages: "auto, phyphox, ... or tracker".
std::string recording_family_words();

/// The last family named among `formats`; empty when none is.
std::optional<RecordingFormat> recording_family(const std::vector<std::string>& formats);

/// What the channels of a recording measure.
enum class SignalKind {
  angular_rate,    ///< rad/s, one to three axes of a gyroscope
  acceleration,    ///< m/s^2, three axes including gravity (swings at 2f)
  linear_acceleration,  ///< m/s^2, gravity removed (swings at f)
  angle,           ///< rad, the pendulum's angle (tracked or a rotary sensor)
  position,        ///< x, y of the bob in any length unit (video track)
  gate_states,     ///< gate state (0 or 1) per event row; the state held for the shorter total time is "blocked"
  blocking_times,  ///< times at which the gate was blocked
  /// Event stamps: one time per period or per passage, as a hand-triggered
  /// timer or a photogate's pendulum mode logs them; `counts` holds the
  /// logger's own event numbers where the file has a counter column.
  event_stamps,
  /// One signal whose quantity the file does not say (a headerless column
  /// of a sensor's raw counts): it times the swing but does not measure it.
  unknown,
};

/// Whether the sensor turns with the bob it is in (a phone's gyroscope or
/// accelerometer): its amplitudes are then the bob's own angle, not the
/// line's (docs/phone.md).
constexpr bool sensor_in_bob(SignalKind kind) {
  return kind == SignalKind::angular_rate || kind == SignalKind::acceleration ||
         kind == SignalKind::linear_acceleration;
}

/// Something the reader decided or dropped, said where it happened.
struct RecordingNote {
  std::size_t line = 0;  ///< line of the file (from 1); 0 for the whole file
  std::string text;      ///< one sentence: what was done and why
};

/// How the reader used one column of the file (import's `columns`).
struct RecordingColumn {
  std::size_t index = 0;   ///< from 1, in file order
  std::string name;        ///< as in the header; empty in a headerless file
  std::string role;        ///< "time", "angle", "angular velocity", "x", "counter", ..., or "unused"
  std::string unit;        ///< the unit it was read in ("s", "deg", "rad/s", "px"); empty where none applies
  std::string decided_by;  ///< "header", "content" or "option" (--columns, a scene's "columns")
  std::string why;         ///< how the role or unit was decided, or why the column is unused
};

struct Recording;

/// A signal a file holds: what it is, and the `--columns` text (or, in a
/// zip archive, the `--set`) that reads the file with it alone.
struct SignalCandidate {
  std::string what;     ///< e.g. "the angle \"theta (deg)\"", "the x and y \"x (m)\", \"y (m)\"", "the set \"Gyroscope.csv\""
  std::string columns;  ///< e.g. "t:s,theta:deg", "t:s,-,x:m,y:m"; empty for a zip's set
  std::string set = {};  ///< a zip archive's set that holds it ("Accelerometer.csv"); empty: the file's columns
  /// A zip's set other than the one read, as the reader parsed it, so that no
  /// set is unpacked twice; null for the one read and for a file's columns.
  std::shared_ptr<const Recording> recording = {};
};

/// A recording in SI units, samples in time order.
struct Recording {
  RecordingFormat format = RecordingFormat::automatic;
  SignalKind kind = SignalKind::angular_rate;
  std::vector<std::string> channel_names;  ///< as in the header
  std::vector<double> time;                ///< (s), strictly increasing
  /// One vector per channel, as long as `time` (unit by `kind`).
  std::vector<std::vector<double>> channels;
  /// A period column of a photogate's pendulum timing (s), its non-empty
  /// cells in order; empty when the file has none.
  std::vector<double> periods;
  /// The clock's resolution (s): the smallest step between distinct time
  /// stamps when stamps repeat (a logger printing fewer decimals than its
  /// rate needs); 0 where every stamp is distinct.
  double time_quantum = 0.0;
  /// The event numbers of a counter column beside event stamps (as written,
  /// one per time); empty without one.
  std::vector<double> counts;
  /// What the reader decided (roles, units, ignored columns) and dropped
  /// (repeated or out-of-order samples, gaps), in file order.
  std::vector<RecordingNote> notes;
  /// Every column of the file, the ones used and the ones not (why).
  std::vector<RecordingColumn> columns;
  /// The file's signals where it holds more than one (an angle beside a
  /// track's x and y, an angle beside its angular velocity; a zip archive's
  /// sets that read), the one read first; empty otherwise, and when the
  /// columns or the set were given. analyse_recording compares their periods.
  std::vector<SignalCandidate> candidates;
  std::size_t rows = 0;     ///< data rows read
  std::size_t dropped = 0;  ///< rows skipped: an empty or NaN cell, a sample out of time order or repeated (noted)
  /// The CSV inside a zip archive it was read from ("Gyroscope.csv"), the
  /// PASCO run asked for ("Run #2"), or the Tracker track read, as Tracker
  /// names it ("mass B"); empty otherwise.
  std::string set;
};

/// Limits that keep a wrong file from eating the memory or the time.
struct RecordingLimits {
  /// Bytes, rows and columns (kRecordingInput unless raised). For a zip
  /// archive, its bytes are also the most its sets may unpack to, all together.
  InputLimits input = kRecordingInput;
  /// The folder the file must lie in, opened beneath it (InputFile): a
  /// scene's folder, unless --allow-outside.
  std::optional<std::string> within;
};

/// Reads a recording from its text. `file` names it in errors, which are
/// pendulum::InputError with path "file:line:column" (column in bytes, from
/// 1): an unrecognised header, mixed delimiters, a truncated or overlong
/// row, a cell that is not a number, time going backwards, a binary file.
/// `set` picks a PASCO run ("Run #2", "run 2" or "2"; by default run 1) or
/// the track of a Tracker export of several ("#multi:"; by its name in any
/// case, required there), and is refused for a family that has one set only.
/// `columns` ("t:s,theta:deg": a role and unit per column in file order,
/// "-" for one not used) declares what the file cannot say
/// (docs/recordings.md, "Columns"). More rows or columns than `limits`
/// allow are refused as they are reached.
Recording parse_recording(std::string_view text, const std::string& file,
                          RecordingFormat format = RecordingFormat::automatic, const std::string& set = {},
                          const std::string& columns = {}, const InputLimits& limits = kRecordingInput);

/// Reads the file at `path` (at most limits.input.bytes; a larger file, a
/// directory, a device or a pipe is refused) and parses it. A zip archive
/// (phyphox's zip export) is unpacked in memory: `set` names the CSV inside
/// to read, and by default the one with the best pendulum signal is read
/// (docs/recordings.md); in a text file `set` picks a PASCO run or a Tracker
/// track (parse_recording).
Recording read_recording(const std::string& path, RecordingFormat format = RecordingFormat::automatic,
                         const RecordingLimits& limits = {}, const std::string& set = {},
                         const std::string& columns = {});

}  // namespace pendulum
