// `pendulum-g report`'s page (pendulum/report/report_page.hpp).
#include "pendulum/report/report_page.hpp"

#include <unistd.h>

#include <algorithm>

#include "pendulum/files.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/recordings/read.hpp"
#include "pendulum/recordings/table.hpp"
#include "pendulum/reduce_scene.hpp"
#include "pendulum/report/html_report.hpp"
#include "pendulum/report/plots.hpp"
#include "pendulum/report/recording_report.hpp"
#include "pendulum/json/scene_json.hpp"

namespace pendulum::report {

bool looks_like_recording(const std::string& file) {
  if (file == "-") return false;
  std::string head(65536, '\0');
  try {
    const InputFile in(file, "a scene or a recording");
    const ssize_t n = ::read(in.fd(), head.data(), head.size());
    head.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
  } catch (const InputError&) {
    return false;  // the scene reader says why
  }
  std::size_t at = head.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  at = head.find_first_not_of(" \t\r\n", at);
  if (at == std::string::npos || head[at] == '{' || head[at] == '[') return false;
  // A table of settings is no recording: the scene reader says to import it.
  return std::count(head.begin() + static_cast<std::ptrdiff_t>(at), head.end(), '\n') >= 2 &&
         !file_holds_settings_table(file);
}

ReportPage make_report_page(const ReportRequest& o,
                            const std::function<void(const std::vector<std::string>&)>& check_recordings) {
  const bool svg = !o.plot.empty();
  if (!o.text && (o.family || looks_like_recording(o.file))) {
    const Recording samples = read_recording(o.file, o.family.value_or(RecordingFormat::automatic), {o.limits.applied_to(kRecordingInput), std::nullopt}, o.set, o.columns);
    const RecordingSummary summary{o.file,      samples.format,  samples.kind,
                                   samples.rows, samples.dropped,
                                   analyse_candidates(samples, o.file, o.family.value_or(RecordingFormat::automatic),
                                                      o.swing, {}, o.set),
                                   samples.set,  samples.columns, samples.notes, o.columns};
    const RecordingRecord r = make_recording_record(summary, &samples);
    return {svg ? recording_plot_svg(r, o.plot) : recording_report_html(r), {}};
  }
  const std::string text = o.text ? *o.text : read_text(o.file, o.limits.applied_to(kSceneInput), "a scene file");
  const SceneFiles files{o.directory ? *o.directory : scene_directory(o.file), o.allow_outside, o.limits};
  if (check_recordings) check_recordings(scene_file_names(text, files));  // before any is read
  const ParsedScene scene = parse_scene(text, files);
  const Analysis analysis = reduce_scene(scene, o.analysis);
  // The recordings the scene names, read again for their signal plots
  // (once each: the report draws a recording named twice once).
  RecordingLimits limits{o.limits.applied_to(kRecordingInput), std::nullopt};
  limits.within = o.allow_outside ? std::nullopt : files.directory;
  std::vector<Recording> samples;
  for (std::size_t i = 0; i < scene.recordings.size(); ++i) {
    const RecordingSummary& s = scene.recordings[i].summary;
    const bool named_before = std::any_of(scene.recordings.begin(), scene.recordings.begin() + i, [&](const auto& r) {
      return r.summary.file == s.file && r.summary.set == s.set;
    });
    samples.push_back(named_before ? Recording{} : read_recording(s.file, s.format, limits, s.set, s.column_spec));
  }
  const SceneReport r = make_scene_report(o.file, scene, analysis, samples);
  ReportPage page{svg ? plot_svg(r, o.plot) : scene_report_html(r), scene.warnings};
  page.warnings.insert(page.warnings.end(), analysis.warnings.begin(), analysis.warnings.end());
  return page;
}

}  // namespace pendulum::report
