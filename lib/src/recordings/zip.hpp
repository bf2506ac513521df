#pragma once
// phyphox's zip export: one CSV per sensor set (Gyroscope.csv,
// Accelerometer.csv, ...) and a meta/ folder (docs/recordings.md, "zip").

#include <string>
#include <string_view>

#include "pendulum/recordings/read.hpp"

namespace pendulum {

/// Whether `bytes` start like a zip archive: a local file header, or the end
/// record of an empty archive.
bool looks_like_zip(std::string_view bytes);

/// Reads the recording in a zip archive. Each CSV outside meta/ is a
/// candidate set; `set` (its name inside, in any case, with or without
/// ".csv") picks one,
/// and otherwise the set with the best signal is read: an angular rate, then
/// a linear acceleration, then an acceleration with g, then any other that
/// reads. Without `set`, every set that reads is a candidate
/// (Recording::candidates, the one read first, each other one with its
/// parsed recording: no set is unpacked twice), whose periods
/// analyse_recording compares, and each set that does not read is a note.
/// Refused (InputError naming `file`): a damaged archive, no usable set, a
/// set that unpacks to more than limits.max_bytes in all (a zip bomb). A
/// set's own errors name "file/set:line:column".
Recording read_zip_recording(std::string_view bytes, const std::string& file, RecordingFormat format,
                             const std::string& set, const RecordingLimits& limits);

/// Whether `bytes` are a phyphox experiment file (".phyphox": XML whose
/// first kilobyte opens a <phyphox> element).
bool looks_like_phyphox_experiment(std::string_view bytes);

/// Reads the recording in a phyphox experiment file saved with its data:
/// each <set> of its <export> names its columns (<data name="Time (s)">
/// buffer</data>), whose numbers are the buffers' <container init="v1,v2,...">;
/// each set is then read as phyphox's CSV export of it, and the best chosen
/// as in a zip archive (read_zip_recording: `set` picks one by its name).
/// Refused (InputError naming `file`): no <export>, no set that reads.
Recording read_phyphox_experiment(std::string_view xml, const std::string& file, RecordingFormat format,
                                  const std::string& set);

}  // namespace pendulum
