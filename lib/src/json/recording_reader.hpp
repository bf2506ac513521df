#pragma once
// A scene's `timing` or `decay.data` naming a recording in place of numbers
// (docs/recordings.md, "In a scene"): the file, resolved against the scene's
// directory, is read and analysed by analyse_recording(), each file once, and
// what it gives fills the same fields as hand-typed input.

#include <optional>
#include <string>
#include <vector>

#include "pendulum/parsed_scene.hpp"
#include "pendulum/json/scene_json.hpp"
#include "reader.hpp"

namespace pendulum::json_reader {

/// An object with the key "recording": a reference to a recording file.
inline bool names_recording(const json& j) { return j.is_object() && j.contains("recording"); }

/// The file a scene in `directory` names `name`: relative to the folder, an
/// absolute name as it is.
std::string scene_file(const std::string& directory, const std::string& name);

/// Reads the recordings a scene names, each file (with its options) once.
class RecordingReader {
 public:
  explicit RecordingReader(SceneFiles files) : files_(std::move(files)) {}

  /// The reference `o` (keys recording, format, set, bob_width, source): its file
  /// analysed and appended to out.recordings; returns its index there.
  /// InputError at `o.recording` naming the file opened (and its line and
  /// column for an error inside it).
  std::size_t read(Object& o, ParsedScene& out);

  /// The file a scene's `o.key` names, resolved against the scene's folder
  /// and confined to it unless --allow-outside (docs/robustness.md):
  /// InputError at `o.key` otherwise, or when the scene was read as text.
  std::string resolve(Object& o, const std::string& key, const char* what) const;

  /// The folder a resolved file is opened beneath (InputFile): the scene's,
  /// none with --allow-outside.
  std::optional<std::string> within() const {
    return files_.allow_outside ? std::nullopt : files_.directory;
  }

  /// The limits of a file of a kind whose defaults are `defaults`, as the command raised them.
  InputLimits limits(const InputLimits& defaults) const { return files_.limits.applied_to(defaults); }

 private:
  SceneFiles files_;
  struct Done {
    std::string file, format, set;
    std::optional<double> bob_width;
    std::optional<std::pair<double, double>> range;
    bool whole_record = false;
    RecordingSummary summary;
  };
  std::vector<Done> done_;
};

/// `timing` naming a recording: one trial of all its periods, with the
/// period's uncertainty from the crossing times.
void read_recorded_timing(Object& parent, const std::string& prefix, Observation<double>& value,
                          Observation<double>& sigma, ObservationSource& source, ParsedScene& out,
                          RecordingReader& recordings);

/// A scene whose one timing names a recording whose amplitude's change
/// matters against its period's uncertainty (amplitude_shift_sigmas() over
/// kSwingBySwingShift; or its timing's "reduce" asks): its observation becomes
/// the series of the recording's groups of swings (swing_groups()) at the
/// shared length. Called once the decay is read. Records the decision in the
/// timing's SceneRecording::reduction.
void reduce_swing_by_swing(ParsedScene& out);

/// `decay.data` naming a recording (under `decay`): one amplitude per swing.
DecayData read_recorded_decay(Object& decay, ParsedScene& out, RecordingReader& recordings);

}  // namespace pendulum::json_reader
