// libFuzzer target: any bytes through the recording readers and the swing
// analysis, as `pendulum-g import` runs them on a text export, with no set,
// a PASCO run and a Tracker track named. Bad input must end in an InputError
// whose message is one printable line; a recording that passes must give a
// finite period, uncertainty and amplitudes, and no swing a negative
// amplitude. A zip archive is refused here (parse_recording reads text;
// libzip unpacks a file's bytes), so the zip reader is left to its
// catalogue cases (tests/bad_recordings/); a spreadsheet (.xlsx) is unpacked
// here, its first sheet read as a table. A phyphox experiment file (XML)
// is read here as `import` reads it (read_phyphox_experiment). The same
// bytes as a table of settings and periods (docs/series.md, "Tables"): a
// table that reads must make a scene that reads, or refuses clearly, and
// reduces to a finite g.
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_checks.hpp"
#include "pendulum/recordings/read.hpp"
#include "pendulum/recordings/swings.hpp"
#include "pendulum/recordings/table.hpp"
#include "pendulum/reduce_scene.hpp"
#include "pendulum/json/scene_json.hpp"
#include "../../lib/src/recordings/zip.hpp"

using pendulum::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (const char* set : {"", "Run #2", "mass B"}) {
    try {
      const pendulum::Recording r = pendulum::parse_recording(text, "fuzz", pendulum::RecordingFormat::automatic, set);
      for (const auto& column : r.channels) require(column.size() == r.time.size(), "ragged columns", set);
      const pendulum::SwingAnalysis a = pendulum::analyse_swings(r, "fuzz");
      require(std::isfinite(a.period.value) && a.period.value > 0.0, "period not finite and positive", set);
      require(std::isfinite(a.period.uncertainty), "period uncertainty not finite", set);
      for (double x : a.decay.amplitudes) require(std::isfinite(x), "non-finite amplitude", set);
      for (const auto& w : a.swings) require(!(w.amplitude < 0.0), "negative amplitude", set);  // NaN: none
    } catch (const pendulum::InputError& e) {
      pendulum::fuzz::require_clear_message(e);
    }
  }
  // The same times as event stamps (a timer's log), without and with the
  // first channel as their counter, one stamp a period or a passage.
  try {
    pendulum::Recording r = pendulum::parse_recording(text, "fuzz");
    r.kind = pendulum::SignalKind::event_stamps;
    for (const bool numbered : {false, true}) {
      pendulum::Recording s = r;
      s.counts = numbered && !r.channels.empty() ? r.channels[0] : std::vector<double>{};
      s.channels.clear();
      for (const int per_period : {0, 2}) {
        pendulum::SwingOptions o;
        if (per_period) o.stamps_per_period = per_period;
        try {
          const pendulum::SwingAnalysis a = pendulum::analyse_swings(s, "fuzz", o);
          require(std::isfinite(a.period.value) && a.period.value > 0.0, "stamp period not finite and positive", "");
          require(std::isfinite(a.period.uncertainty), "stamp period uncertainty not finite", "");
        } catch (const pendulum::InputError& e) {
          pendulum::fuzz::require_clear_message(e);
        }
      }
    }
  } catch (const pendulum::InputError& e) {
    pendulum::fuzz::require_clear_message(e);
  }
  if (pendulum::looks_like_phyphox_experiment(text)) {
    try {
      const pendulum::Recording r = pendulum::read_phyphox_experiment(text, "fuzz", pendulum::RecordingFormat::automatic, "");
      const pendulum::SwingAnalysis a = pendulum::analyse_swings(r, "fuzz");
      require(std::isfinite(a.period.value) && a.period.value > 0.0, "experiment period not finite and positive", "");
    } catch (const pendulum::InputError& e) {
      pendulum::fuzz::require_clear_message(e);
    }
  }
  // A spreadsheet: its first sheet as CSV, then read as a table or a recording (tests/tables/lab_sheet.xlsx seeds it).
  if (pendulum::looks_like_xlsx(text)) {
    try {
      const std::string csv = pendulum::xlsx_sheet_csv(text, "fuzz", "", std::size_t{1} << 24);
      try {
        (void)pendulum::parse_settings_table(csv, "fuzz");
      } catch (const pendulum::InputError& e) {
        pendulum::fuzz::require_clear_message(e);
      }
    } catch (const pendulum::InputError& e) {
      pendulum::fuzz::require_clear_message(e);
    }
  }
  (void)pendulum::looks_like_settings_table(text);
  try {
    const pendulum::SettingsTable t = pendulum::parse_settings_table(text, "fuzz");
    require(!t.observations.empty(), "a table without observations", "");
    const pendulum::Analysis a = pendulum::reduce_scene(pendulum::parse_scene(pendulum::table_scene(t, "fuzz")));
    require(std::isfinite(a.g.value), "table g not finite", "");
  } catch (const pendulum::InputError& e) {
    pendulum::fuzz::require_clear_message(e);
  }
  return 0;
}
