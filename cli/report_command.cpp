#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/report/html_report.hpp"
#include "pendulum/recordings/swings.hpp"
#include "pendulum/report/plots.hpp"
#include "pendulum/report/recording_report.hpp"
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

namespace {

/// A recording, not a scene: a regular file (a pipe is not read ahead) whose
/// text does not open a JSON object or array and has three lines or more (no
/// recording has fewer; a short or empty file gets the scene reader's
/// message, as from reduce).
bool looks_like_recording(const std::string& file) {
  struct stat st;
  if (file == "-" || ::stat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return false;
  std::ifstream in(file, std::ios::binary);
  std::string head(65536, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
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
    const ParsedScene scene = parse_scene(read_input(o->file), {scene_directory(o->file)});
    const Analysis analysis = analyse(scene, o->analysis);
    // The recordings the scene names, read again for their signal plots
    // (once each: the report draws a recording named twice once).
    std::vector<Recording> samples;
    for (std::size_t i = 0; i < scene.recordings.size(); ++i) {
      const RecordingSummary& s = scene.recordings[i].summary;
      const bool named_before = std::any_of(scene.recordings.begin(), scene.recordings.begin() + i, [&](const auto& o) {
        return o.summary.file == s.file && o.summary.set == s.set;
      });
      samples.push_back(named_before ? Recording{} : read_recording(s.file, s.format, {}, s.set, s.column_spec));
    }
    const report::SceneReport r = report::make_scene_report(o->file, scene, analysis, samples);
    const std::string text = svg ? report::plot_svg(r, o->plot) : report::scene_report_html(r);
    print_warnings(scene.warnings);
    print_warnings(analysis.warnings);
    write_output(o->output, text);
    return 0;
  }};
}

}  // namespace pendulum::cli
