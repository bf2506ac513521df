#include <iostream>
#include <map>
#include <memory>

#include "commands.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/files.hpp"
#include "pendulum/output.hpp"
#include "pendulum/scene_json.hpp"

namespace pendulum::cli {

Command add_reduce_command(CLI::App& app) {
  struct Options {
    std::string file;
    std::string format = "json";
    bool strict = false;
    bool allow_outside = false;
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
  add_analysis_options(*cmd, o->analysis);
  add_allow_outside_option(*cmd, o->allow_outside);

  return {cmd, [o] {
    const ParsedScene scene = parse_scene(read_input(o->file), scene_files(o->file, o->allow_outside));
    const Analysis analysis = analyse(scene, o->analysis);
    const std::string text =
        o->format == "table"
            ? result_table(scene, analysis)
            : result_json(scene, analysis, o->analysis, printable_name(o->file)) + "\n";
    // The table holds the warnings and the status: not twice on a terminal.
    if (o->format != "table") {
      print_warnings(scene.warnings);
      print_warnings(analysis.warnings);
      for (const auto& r : analysis.status_reasons) std::cerr << "pendulum-g: suspect: " << r << "\n";
    }
    std::cout << text;
    return o->strict && analysis.status == ResultStatus::suspect ? kExitSuspect : 0;
  }};
}

}  // namespace pendulum::cli
