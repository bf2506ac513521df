#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/files.hpp"
#include "pendulum/report/html_report.hpp"
#include "pendulum/recordings/swings.hpp"
#include "pendulum/report/plots.hpp"
#include "pendulum/report/recording_report.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/scene_json.hpp"

namespace pendulum::cli {

namespace {

/// A recording, not a scene: a regular file (a pipe is not read ahead) whose
/// text does not open a JSON object or array and has three lines or more (no
/// recording has fewer; a short or empty file gets the scene reader's
/// message, as from reduce).
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
  return std::count(head.begin() + static_cast<std::ptrdiff_t>(at), head.end(), '\n') >= 2;
}

}  // namespace

Command add_report_command(CLI::App& app) {
  struct Options {
    std::string file;
    std::string output = "-";
    std::vector<std::string> formats;
    std::string plot;
    AnalysisOptions analysis;
    SwingOptions swing;
    std::string set;
    bool allow_outside = false;
    std::string columns;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "report", "Write one self-contained HTML page (or one SVG plot) of the reduction of a scene or a "
                "recording, for people to read");
  cmd->add_option("scene", o->file,
                  "Scene file (JSON), or - for standard input, or a recording (as for import, docs/recordings.md)")
      ->required();
  cmd->add_option("-o,--output", o->output, "Output file (default: standard output); written whole or not at all");
  std::vector<std::string> formats = {"html", "svg"};
  for (const auto& f : recording_family_names()) formats.push_back(f);
  cmd->add_option("--format", o->formats,
                  "html (default: the whole report) or svg (one plot, see --plot), and/or a recording's family "
                  "as for import (auto, phyphox, vernier, pasco, plain, tracker: the input is a recording); may "
                  "be given twice")
      ->check(CLI::IsMember(formats))
      ->allow_extra_args(false)  // one value each time: the file after it is not a format
      ->take_all();
  cmd->add_option("--plot", o->plot,
                  "The plot for --format svg (implies svg): corrections, budget, decay, series, pivot-scan for a "
                  "scene; signal, amplitude, period-amplitude for a recording")
      ->check(CLI::IsMember(
          {"corrections", "budget", "decay", "series", "pivot-scan", "signal", "amplitude", "period-amplitude"}));
  add_analysis_options(*cmd, o->analysis);
  add_recording_options(*cmd, o->swing, o->set, o->columns);
  add_allow_outside_option(*cmd, o->allow_outside);

  return {cmd, [o, cmd] {
    std::string format = "html";
    for (const auto& f : o->formats) {
      if (f == "html" || f == "svg") format = f;
    }
    const bool format_named = std::count(o->formats.begin(), o->formats.end(), format) > 0;
    const bool svg = !o->plot.empty() || format == "svg";
    if (svg && o->plot.empty()) {
      std::cerr << cmd->get_name()
                << ": --format svg needs --plot corrections, budget, decay, series or pivot-scan (a scene), or signal, "
                   "amplitude or period-amplitude (a recording)\n";
      return 2;
    }
    if (!o->plot.empty() && format_named && format != "svg") {
      std::cerr << cmd->get_name() << ": --plot makes one SVG; it does not go with --format " << format << "\n";
      return 2;
    }
    refuse_output_over_inputs(o->output, {o->file});
    const std::optional<RecordingFormat> family = recording_family(o->formats);
    if (family || looks_like_recording(o->file)) {
      const Recording samples = read_recording(o->file, family.value_or(RecordingFormat::automatic), {}, o->set, o->columns);
      const RecordingSummary summary{o->file,      samples.format,  samples.kind,
                                     samples.rows, samples.dropped, analyse_swings(samples, o->file, o->swing),
                                     samples.set,  samples.columns, samples.notes, o->columns};
      const report::RecordingRecord r = report::make_recording_record(summary, &samples);
      write_output(o->output, svg ? report::recording_plot_svg(r, o->plot) : report::recording_report_html(r));
      return 0;
    }
    const std::string text = read_input(o->file);
    const SceneFiles files = scene_files(o->file, o->allow_outside);
    refuse_output_over_inputs(o->output, scene_file_names(text, files));  // before any is read
    const ParsedScene scene = parse_scene(text, files);
    const Analysis analysis = analyse(scene, o->analysis);
    // The recordings the scene names, read again for their signal plots
    // (once each: the report draws a recording named twice once).
    RecordingLimits limits;
    limits.within = o->allow_outside ? std::nullopt : files.directory;
    std::vector<Recording> samples;
    for (std::size_t i = 0; i < scene.recordings.size(); ++i) {
      const RecordingSummary& s = scene.recordings[i].summary;
      const bool named_before = std::any_of(scene.recordings.begin(), scene.recordings.begin() + i, [&](const auto& o) {
        return o.summary.file == s.file && o.summary.set == s.set;
      });
      samples.push_back(named_before ? Recording{} : read_recording(s.file, s.format, limits, s.set, s.column_spec));
    }
    const report::SceneReport r = report::make_scene_report(o->file, scene, analysis, samples);
    const std::string page = svg ? report::plot_svg(r, o->plot) : report::scene_report_html(r);
    print_warnings(scene.warnings);
    print_warnings(analysis.warnings);
    write_output(o->output, page);
    return 0;
  }};
}

}  // namespace pendulum::cli
