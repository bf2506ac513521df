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
  auto fail = [&](int error) { return InputError("output", "cannot write " + path + ": " + std::strerror(error)); };
  struct stat existing;
  const bool exists = ::stat(path.c_str(), &existing) == 0;
  if (exists && S_ISDIR(existing.st_mode)) throw fail(EISDIR);
  if (exists && !S_ISREG(existing.st_mode)) {
    // A device or a pipe (/dev/stdout): written in place, never replaced.
    std::FILE* out = std::fopen(path.c_str(), "wb");
    if (!out) throw fail(errno);
    const bool ok = std::fwrite(text.data(), 1, text.size(), out) == text.size();
    const int error = errno;
    if (std::fclose(out) != 0 || !ok) throw fail(ok ? errno : error);
    return;
  }
  // A regular file: a temporary file beside it (beside the link's target for
  // a symbolic link), renamed over it once whole, so that a failure leaves no
  // partial file and an old report stays as it was.
  std::string target = path;
  if (exists) {
    if (char* resolved = ::realpath(path.c_str(), nullptr)) {
      target = resolved;
      std::free(resolved);
    }
  }
  std::string temporary = target + ".XXXXXX";
  const int fd = mkstemp(temporary.data());
  if (fd < 0) throw fail(errno);
  int error = 0;  // the first failure's errno
  for (std::size_t written = 0; written < text.size();) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error = n < 0 ? errno : EIO;
      break;
    }
    written += static_cast<std::size_t>(n);
  }
  // mkstemp makes the file 0600; a report is for others to read. umask is
  // read by setting it, and no other thread runs here.
  const mode_t mask = umask(0);
  umask(mask);
  if (!error && fchmod(fd, 0666 & ~mask) != 0) error = errno;
  if (!error && fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && !error) error = errno;
  if (!error && std::rename(temporary.c_str(), target.c_str()) != 0) error = errno;
  if (error) {
    std::remove(temporary.c_str());
    throw fail(error);
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
  cmd->add_option("--plot", o->plot, "The plot for --format svg: corrections, budget, decay, series, pivot-scan (implies svg)")
      ->check(CLI::IsMember({"corrections", "budget", "decay", "series", "pivot-scan"}));
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
