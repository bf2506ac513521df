#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/files.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/json/output.hpp"
#include "pendulum/recordings/read.hpp"
#include "pendulum/recordings/table.hpp"
#include "pendulum/reduce_scene.hpp"
#include "pendulum/json/scene_json.hpp"

namespace pendulum::cli {

namespace {

/// True if the text, after a byte-order mark and white space, opens a JSON object.
bool is_scene_text(const std::string& text) {
  const std::size_t bom = text.compare(0, 3, "\xef\xbb\xbf") == 0 ? 3 : 0;
  const std::size_t first = text.find_first_not_of(" \t\r\n", bom);
  return first != std::string::npos && text[first] == '{';
}

/// True if the file at `path` reads as a recording (read_recording).
bool reads_as_recording(const std::string& path) {
  try {
    (void)read_recording(path);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

/// The scene that reduces the recording `file` at `length` (m): its timing,
/// and its amplitude, from the recording (docs/recordings.md, "In a scene").
std::string recording_scene(const std::string& file, double length, std::optional<double> uncertainty) {
  const std::string name = std::filesystem::path(file).filename().string();
  nlohmann::ordered_json scene = {{"title", "the recording " + name},
                                  {"timing", {{"recording", name}}},
                                  {"length", {{"value", length}, {"unit", "m"}}}};
  if (uncertainty) scene["length"]["uncertainty"] = *uncertainty;
  return scene.dump();
}

}  // namespace

Command add_reduce_command(CLI::App& app) {
  struct Options {
    std::string file;
    std::string format = "json";
    bool strict = false;
    SceneFiles given;  // --allow-outside, --max-bytes, ...
    std::optional<double> length;
    std::optional<double> length_uncertainty;
    AnalysisOptions analysis;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "reduce", "Apply every period correction the scene needs and print g as JSON");
  cmd->add_option("scene", o->file, "Scene file (JSON), or - for standard input")->required();
  cmd->add_option("--format", o->format, "Output: json (default) or table")
      ->check(CLI::IsMember({"json", "table"}));
  cmd->add_flag("--strict", o->strict,
               "Exit with status 4 when the result is suspect (g far from the expected value, or an input "
               "that looks like a slip); the result is printed all the same");
  cmd->add_option("--length", o->length,
                  "A recording instead of a scene: the pendulum's length, pivot to bob centre (m); the recording "
                  "gives the period and the amplitude")
      ->check(in_range(ranges::length));
  cmd->add_option("--length-uncertainty", o->length_uncertainty, "The length's standard uncertainty (m), with --length")
      ->check(in_range(ranges::length_uncertainty))
      ->needs("--length");
  add_analysis_options(*cmd, o->analysis);
  add_scene_file_options(*cmd, o->given);

  return {cmd, [o] {
    if (o->length && o->file == "-") {
      throw InputError("-", "standard input with --length; expected a recording file's name");
    }
    // A recording is read by its own reader, not as a scene's text.
    const std::string text = o->length ? recording_scene(o->file, *o->length, o->length_uncertainty) : read_input(o->file, o->given);
    const ParsedScene scene = [&] {
      try {
        return parse_scene(text, scene_files(o->file, o->given));
      } catch (const InputError&) {
        // A file that is no scene but reads as a recording: say how to reduce it.
        if (o->length || o->file == "-" || is_scene_text(text) || looks_like_settings_table(text) ||
            !reads_as_recording(o->file)) {
          throw;
        }
        throw InputError(o->file, "a recording, not a scene (JSON); expected a scene, or the recording with the "
                                  "pendulum's length: pendulum-g reduce " + printable_name(o->file) + " --length L (m, "
                                  "pivot to bob centre; --length-uncertainty U), or pendulum-g import " +
                                  printable_name(o->file) + " for its scene parts (docs/recordings.md)");
      }
    }();
    if (!scene.length_measured) {
      // An amplitude sweep without its length: T0 and the law, no g.
      const AmplitudeSweep sweep = *amplitude_sweep_of(scene);
      std::cout << (o->format == "table" ? sweep_result_table(scene, sweep)
                                         : sweep_result_json(scene, sweep, printable_name(o->file)));
      if (o->format != "table") print_warnings(scene.warnings);
      return o->strict && !sweep_reasons(scene, sweep).empty() ? kExitSuspect : 0;
    }
    const Analysis analysis = reduce_scene(scene, o->analysis);
    const std::string output =
        o->format == "table"
            ? result_table(scene, analysis)
            : result_json(scene, analysis, o->analysis, printable_name(o->file)) + "\n";
    // The table holds the warnings and the status: not twice on a terminal.
    if (o->format != "table") {
      print_warnings(scene.warnings);
      print_warnings(analysis.warnings);
      for (const auto& r : analysis.status_reasons) std::cerr << "pendulum-g: suspect: " << r << "\n";
    }
    std::cout << output;
    return o->strict && analysis.status == ResultStatus::suspect ? kExitSuspect : 0;
  }};
}

}  // namespace pendulum::cli
