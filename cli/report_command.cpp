#include <algorithm>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/recordings/swings.hpp"
#include "pendulum/report/report_page.hpp"

namespace pendulum::cli {

Command add_report_command(CLI::App& app) {
  struct Options {
    report::ReportRequest request;
    std::string output = "-";
    std::vector<std::string> formats;
    SceneFiles given;  // --allow-outside, --max-bytes, ...
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "report", "Write one self-contained HTML page (or one SVG plot) of the reduction of a scene or a "
                "recording, for people to read");
  cmd->add_option("scene", o->request.file,
                  "Scene file (JSON), or - for standard input, or a recording (as for import, docs/recordings.md)")
      ->required();
  cmd->add_option("-o,--output", o->output, "Output file (default: standard output); written whole or not at all");
  std::vector<std::string> formats = {"html", "svg"};
  for (const auto& f : recording_family_names()) formats.push_back(f);
  cmd->add_option("--format", o->formats,
                  "html (default: the whole report) or svg (one plot, see --plot), and/or a recording's family "
                  "as for import (" + recording_family_words() + ": the input is a recording); may be given twice")
      ->check(CLI::IsMember(formats))
      ->allow_extra_args(false)  // one value each time: the file after it is not a format
      ->take_all();
  cmd->add_option("--plot", o->request.plot,
                  "The plot for --format svg (implies svg): corrections, budget, decay, series, pivot-scan for a "
                  "scene; signal, amplitude, period-amplitude for a recording")
      ->check(CLI::IsMember(
          {"corrections", "budget", "decay", "series", "pivot-scan", "signal", "amplitude", "period-amplitude"}));
  add_analysis_options(*cmd, o->request.analysis);
  add_recording_options(*cmd, o->request.swing, o->request.set, o->request.columns);
  add_scene_file_options(*cmd, o->given);

  return {cmd, [o, cmd] {
    std::string format = "html";
    for (const auto& f : o->formats) {
      if (f == "html" || f == "svg") format = f;
    }
    const bool format_named = std::count(o->formats.begin(), o->formats.end(), format) > 0;
    const bool svg = !o->request.plot.empty() || format == "svg";
    if (svg && o->request.plot.empty()) {
      std::cerr << cmd->get_name()
                << ": --format svg needs --plot corrections, budget, decay, series or pivot-scan (a scene), or signal, "
                   "amplitude or period-amplitude (a recording)\n";
      return 2;
    }
    if (!o->request.plot.empty() && format_named && format != "svg") {
      std::cerr << cmd->get_name() << ": --plot makes one SVG; it does not go with --format " << format << "\n";
      return 2;
    }
    o->request.allow_outside = o->given.allow_outside;
    o->request.limits = o->given.limits;
    refuse_output_over_inputs(o->output, {o->request.file});
    o->request.family = recording_family(o->formats);
    const report::ReportPage page = make_report_page(
        o->request, [&](const std::vector<std::string>& recordings) { refuse_output_over_inputs(o->output, recordings); });
    print_warnings(page.warnings);
    write_output(o->output, page.text);
    return 0;
  }};
}

}  // namespace pendulum::cli
