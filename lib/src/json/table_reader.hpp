#pragma once
// A table of settings and periods in a scene (docs/series.md, "Tables"):
// "observations": {"table": "lengths.csv", "columns": {...}}, read by the
// table reader (recordings/table.hpp) into the observations a scene lists.

#include <string>

#include "pendulum/parsed_scene.hpp"
#include "pendulum/recordings/table.hpp"
#include "reader.hpp"

namespace pendulum::json_reader {

class RecordingReader;

/// The observations of a table, as a scene lists them: one per setting,
/// each with its setting, its amplitude where the table has one, its timing
/// (the rows' times as trials) and its lines as `source`.
/// A sweep's length, where the table gives one, goes in each observation
/// where `sweep_length_in_each` (the scene gives none at its top level).
json table_observations(const SettingsTable& table, const std::string& name, bool sweep_length_in_each);

/// `observations` naming a table: the file, confined like a recording, read
/// with its "columns"; its notes become assumptions and its warnings warnings.
json read_table_reference(Object& top, ParsedScene& out, const RecordingReader& recordings);

}  // namespace pendulum::json_reader
