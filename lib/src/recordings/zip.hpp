#pragma once
// phyphox's zip export: one CSV per sensor set (Gyroscope.csv,
// Accelerometer.csv, ...) and a meta/ folder (docs/recordings.md, "zip");
// a spreadsheet's sheet (.xlsx) as CSV text (docs/series.md, "Tables").

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
/// set that unpacks to more than limits.input.bytes in all (a zip bomb). A
/// set's own errors name "file/set:line:column".
Recording read_zip_recording(std::string_view bytes, const std::string& file, RecordingFormat format,
                             const std::string& set, const RecordingLimits& limits);

/// Whether `bytes` are a spreadsheet (.xlsx): a zip archive holding xl/workbook.xml.
bool looks_like_xlsx(std::string_view bytes);

/// A sheet of a spreadsheet (.xlsx, Office Open XML) as comma-separated
/// text, for the table and recording readers: `sheet` by its name (any case)
/// or number from 1, the first by default; each cell's value (a formula's
/// cached one, a shared or inline string, a number as stored), the empty
/// rows and the columns no row uses left out, a line's number the sheet's
/// row's up to the first row used (its empty rows above as empty lines;
/// after it an empty row is skipped). Refused (InputError naming
/// `file`): a damaged archive, a part missing, a sheet not there or empty,
/// a part that unpacks to over `max_bytes`.
std::string xlsx_sheet_csv(std::string_view bytes, const std::string& file, const std::string& sheet,
                           std::size_t max_bytes);

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
