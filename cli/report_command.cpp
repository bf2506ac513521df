#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/report/html_report.hpp"
#include "pendulum/report/plots.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/scene_json.hpp"

namespace pendulum::cli {

void write_output(const std::string& path, const std::string& text) {
  if (path == "-") {
    std::cout << text;
    return;
  }
  // A temporary file beside the target, renamed over it once whole: a
  // failure leaves no partial file, and an old report stays as it was.
  std::string temporary = path + ".XXXXXX";
  const int fd = mkstemp(temporary.data());
  if (fd < 0) throw InputError("", "cannot write " + path + ": " + std::strerror(errno));
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    written += static_cast<std::size_t>(n);
  }
  const int error = errno;
  // mkstemp makes the file 0600; a report is for others to read.
  const mode_t mask = umask(0);
  umask(mask);
  const bool ok = written == text.size() && fchmod(fd, 0666 & ~mask) == 0 && fsync(fd) == 0;
  if (::close(fd) != 0 || !ok || std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int e = ok ? errno : error;
    std::remove(temporary.c_str());
    throw InputError("", "cannot write " + path + ": " + std::strerror(e));
  }
}

Command add_report_command(CLI::App& app) {
  struct Options {
    std::string file;
    std::string output = "-";
    std::string format = "html";
    std::string plot;
    AnalysisOptions analysis;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "report", "Write one self-contained HTML page (or one SVG plot) of the reduction, for people to read");
  cmd->add_option("scene", o->file, "Scene file (JSON), or - for standard input")->required();
  cmd->add_option("-o,--output", o->output, "Output file (default: standard output); written whole or not at all");
  cmd->add_option("--format", o->format, "html (default: the whole report) or svg (one plot, see --plot)")
      ->check(CLI::IsMember({"html", "svg"}));
  cmd->add_option("--plot", o->plot, "The plot for --format svg: corrections, budget, decay, series (implies svg)")
      ->check(CLI::IsMember({"corrections", "budget", "decay", "series"}));
  add_analysis_options(*cmd, o->analysis);

  return {cmd, [o, cmd] {
    const bool svg = !o->plot.empty() || o->format == "svg";
    if (svg && o->plot.empty()) {
      std::cerr << cmd->get_name() << ": --format svg needs --plot corrections, budget or decay\n";
      return 2;
    }
    if (!o->plot.empty() && cmd->count("--format") && o->format != "svg") {
      std::cerr << cmd->get_name() << ": --plot makes one SVG; it does not go with --format " << o->format << "\n";
      return 2;
    }
    const ParsedScene scene = parse_scene(read_input(o->file));
    const Analysis analysis = analyse(scene, o->analysis);
    const report::SceneReport r = report::make_scene_report(o->file, scene, analysis);
    const std::string text = svg ? report::plot_svg(r, o->plot) : report::scene_report_html(r);
    print_warnings(scene.warnings);
    print_warnings(analysis.warnings);
    write_output(o->output, text);
    return 0;
  }};
}

}  // namespace pendulum::cli
