// A table of settings and periods as a scene's observations (table_reader.hpp),
// and the scene `pendulum-g import TABLE` prints (recordings/table.hpp).
#include <cmath>

#include "recording_reader.hpp"
#include "table_reader.hpp"
#include "pendulum/models/registry.hpp"

namespace pendulum {

namespace json_reader {

namespace {

template <class J>
J quantity_json(double value, const std::optional<double>& sigma, const std::string& unit) {
  J q = {{"value", value}};
  if (sigma && *sigma > 0.0) q["uncertainty"] = *sigma;
  q["unit"] = unit;
  return q;
}

/// `o.oscillations`: the whole number of oscillations each time in the table spans.
int oscillations_at(Object& o) {
  const json& n = o.at("oscillations");
  const double v = n.is_number() ? n.get<double>() : 0.0;
  PENDULUM_FAIL_IF(!(v >= 1.0 && v <= 1e6 && v == std::floor(v)), o.path("oscillations"),
                   "got " + shown(n) + "; expected the whole number of oscillations each time in the table spans");
  return static_cast<int>(v);
}

/// "columns": {"length": 1, "period": "T (s)", "time": {"column": 3, "oscillations": 10, "unit": "s"}, ...}.
TableOptions table_options(Object& t) {
  TableOptions options;
  if (t.has("oscillations")) options.oscillations = oscillations_at(t);
  if (!t.has("columns")) return options;
  const json& columns = t.at("columns");
  Object all(columns, t.path("columns"), "an object: each role's column, e.g. {\"length\": 1, \"period\": 2}");
  static const char* const kRoles[] = {"length", "pivot_distance", "pivot_position", "rod_length", "period", "time",
                                       "amplitude"};
  for (const char* role : kRoles) {
    for (const std::string& key : {std::string(role), std::string(role) + "_uncertainty"}) {
      if (!all.has(key)) continue;
      const json& j = all.at(key);
      const std::string at = all.path(key);
      TableColumnChoice c;
      c.role = key;
      auto column = [&](const json& v, const std::string& path) {
        if (v.is_string()) {
          c.name = v.get<std::string>();
          PENDULUM_FAIL_IF(c.name.empty(), path, "got \"\"; expected a column's name in the header, or its number (from 1)");
          return;
        }
        const double n = v.is_number() ? v.get<double>() : 0.0;
        PENDULUM_FAIL_IF(!(n >= 1.0 && n <= 1e4 && n == std::floor(n)), path,
                         "got " + shown(v) + "; expected a column's number (from 1) or its name in the header");
        c.column = static_cast<std::size_t>(n);
      };
      if (j.is_object()) {
        Object o(j, at);
        column(o.at("column"), o.path("column"));
        if (o.has("unit")) c.unit = o.text("unit");
        if (o.has("oscillations")) c.oscillations = oscillations_at(o);
        if (o.has("decided_by")) o.text("decided_by");  // import's report, echoed back
        if (o.has("why")) o.text("why");
        if (o.has("name")) o.text("name");
        o.finish();
      } else {
        column(j, at);
      }
      PENDULUM_FAIL_IF(std::string(role) == "time" && c.oscillations == 0 && options.oscillations == 0, at,
                       "a time column without its oscillations; expected {\"column\": ..., \"oscillations\": 10}, "
                       "or \"period\" for a column of single periods");
      options.columns.push_back(c);
    }
  }
  all.finish();
  return options;
}

/// The observations as `J` (json for the reader, ordered_json for import's
/// print); a sweep's length, where the table gives it, in each only where
/// `sweep_length_in_each` (a scene that names the table and gives none).
template <class J>
J observations_as(const SettingsTable& table, const std::string& name, bool sweep_length_in_each = false) {
  J list = J::array();
  for (const TableObservation& o : table.observations) {
    J item;
    if (!table.sweep) item[setting_key(table.setting)] = quantity_json<J>(o.setting, o.setting_sigma, table.setting_unit);
    if (table.sweep && table.sweep_length && sweep_length_in_each) {
      item["length"] = quantity_json<J>(*table.sweep_length, table.sweep_length_sigma, table.setting_unit);
    }
    if (o.amplitude) item["amplitude"] = quantity_json<J>(*o.amplitude, o.amplitude_sigma, table.amplitude_unit);
    J timing = {{"oscillations_per_trial", table.oscillations}, {"unit", table.time_unit}, {"trials", o.times}};
    if (o.time_sigma) timing["uncertainty"] = *o.time_sigma;
    if (table.sigma_from_scatter) timing["resolution"] = table.resolution;
    item["timing"] = timing;
    const std::size_t n = o.times.size();
    item["source"] = name + (n == 1 ? ", line " + std::to_string(o.first_line)
                                    : ", lines " + std::to_string(o.first_line) + "-" + std::to_string(o.last_line) +
                                          " (" + std::to_string(n) + " rows)");
    list.push_back(item);
  }
  return list;
}

}  // namespace

json table_observations(const SettingsTable& table, const std::string& name, bool sweep_length_in_each) {
  return observations_as<json>(table, name, sweep_length_in_each);
}

json read_table_reference(Object& top, ParsedScene& out, const RecordingReader& recordings) {
  Object t(top.at("observations"), "observations",
           "an array of observations, or an object naming a table: {\"table\": \"lengths.csv\"}");
  const std::string name = t.text("table");
  PENDULUM_FAIL_IF(name.empty() || name.find('\0') != std::string::npos, t.path("table"),
                   "got " + shown(t.at("table")) + "; expected the name of a table file (CSV or tab-separated)");
  TableOptions options = table_options(t);
  options.limits = recordings.limits(kTableInput);
  if (t.has("source")) t.text("source");
  t.finish();
  const std::string file = recordings.resolve(t, "table", "tables");
  SettingsTable table;
  try {
    table = read_settings_table(file, options, recordings.within());
  } catch (const InputError& e) {
    throw InputError(t.path("table"), e.what());  // "file: message" or "file:line:column: message"
  }
  PENDULUM_FAIL_IF(table.sweep && !table.sweep_length && !top.has("length"), "length",
                   "missing, and the table " + name + " is an amplitude sweep without its length; expected the "
                   "pendulum's length at the top level, or \"length\": \"" + std::string(kLengthNotMeasured) +
                   "\" for its small-amplitude period alone");
  out.period_uncertainty_from_scatter |= table.sigma_from_scatter;
  for (const RecordingNote& n : table.notes) out.assumptions.push_back("observations.table: " + name + ": " + n.text);
  for (const RecordingNote& n : table.warnings) out.warnings.push_back("observations.table: " + name + ": " + n.text);
  return table_observations(table, name, !top.has("length"));
}

}  // namespace json_reader

std::string table_scene(const SettingsTable& table, const std::string& table_name) {
  using json_reader::json;
  nlohmann::ordered_json scene;
  scene["schema"] = json_reader::kSceneSchema;
  scene["title"] = table_name + ": " + (table.sweep ? "an amplitude sweep" : setting_info(table.setting).series);
  scene["source"] = "pendulum-g import: table " + table_name;
  // What the table's kind cannot know without its parts (models/registry.hpp).
  visit_period_model(kind_of_setting(table.setting), [&](auto model) {
    using M = decltype(model);
    const auto unknowns = M::unknowns_of_observations_alone(table.setting);
    for (int p = 1; p < M::kParameters; ++p) {
      if (unknowns[p]) scene["fit"].push_back(M::kParameterInfo[p].name);
    }
  });
  // The textbook line's intercept: lengths taped to the top of the bob or a
  // knot run to another point than its centre, by the same distance at every
  // length; three lengths or more leave a degree of freedom beside it.
  if (table.setting == Setting::length && !table.sweep && table.observations.size() >= 3) {
    scene["fit"].push_back("length_offset");
  }
  // A sweep's length, once for all: T0 without it, g with it.
  if (table.sweep) {
    scene["length"] = table.sweep_length
                          ? json_reader::quantity_json<nlohmann::ordered_json>(*table.sweep_length, table.sweep_length_sigma, table.setting_unit)
                          : nlohmann::ordered_json(kLengthNotMeasured);
  }
  if (table.sigma_from_scatter) scene["period_uncertainty"] = "scatter_about_fit";
  const bool amplitudes = !table.observations.empty() && table.observations.front().amplitude;
  if (!amplitudes) scene["amplitude"] = "not recorded";
  scene["observations"] = json_reader::observations_as<nlohmann::ordered_json>(table, table_name);
  nlohmann::ordered_json report;
  report["table"] = table_name;
  report["rows"] = table.rows;
  report["observations"] = table.observations.size();
  report["columns"] = nlohmann::ordered_json::array();
  for (const RecordingColumn& c : table.columns) {
    report["columns"].push_back({{"column", c.index},
                                 {"name", c.name},
                                 {"role", c.role},
                                 {"unit", c.unit.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(c.unit)},
                                 {"decided_by", c.decided_by},
                                 {"why", c.why}});
  }
  report["notes"] = nlohmann::ordered_json::array();
  for (const RecordingNote& n : table.notes) report["notes"].push_back(n.text);
  report["warnings"] = nlohmann::ordered_json::array();
  for (const RecordingNote& n : table.warnings) report["warnings"].push_back(n.text);
  scene["import"] = report;
  return scene.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace pendulum
