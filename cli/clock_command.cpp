#include <iostream>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "pendulum/clock_scene.hpp"
#include "pendulum/files.hpp"
#include "pendulum/json/output.hpp"
#include "pendulum/json/scene_json.hpp"

namespace pendulum::cli {

Command add_clock_command(CLI::App& app) {
  struct Options {
    std::string file;
    std::string format = "json";
    std::string route = "auto";
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "clock", "Circular and impulse (escapement) error of a clock pendulum (Feinstein 2005) as JSON");
  cmd->add_option("scene", o->file, "Clock scene file (JSON), or - for standard input")->required();
  cmd->add_option("--format", o->format, "Output: json (default) or table")
      ->check(CLI::IsMember({"json", "table"}));
  cmd->add_option("--route", o->route,
                  "Impulse-error route: auto (default: the cheapest within the scene's accuracy), "
                  "cycloid, circular_elliptic, cycloid_damped, circular_rk4")
      ->check(CLI::IsMember({"auto", "cycloid", "circular_elliptic", "cycloid_damped", "circular_rk4"}));

  return {cmd, [o] {
    const ClockScene scene = parse_clock_scene(read_input(o->file));
    std::optional<ClockRoute> route;
    for (ClockRoute r : {ClockRoute::cycloid, ClockRoute::circular_elliptic, ClockRoute::cycloid_damped,
                         ClockRoute::circular_rk4}) {
      if (o->route == route_name(r)) route = r;
    }
    const ClockAnalysis analysis = analyse_clock(scene, route);
    const std::string text =
        o->format == "table" ? clock_table(scene, analysis) : clock_json(scene, analysis, printable_name(o->file)) + "\n";
    print_warnings(analysis.warnings);
    std::cout << text;
    return 0;
  }};
}

}  // namespace pendulum::cli
