#include <iostream>

#include "commands.hpp"

namespace pendulum::cli {

namespace {

/// A ball on a string timed with a phone: every key a first-year student
/// needs, and nothing else (docs/scene.md explains each). Its numbers are a
/// real pendulum's: it reduces to g = 9.808 +- 0.025 m/s^2, status ok.
constexpr const char* kBallOnAString = R"({
  "schema": "pendulum-g/scene/1",
  "title": "A steel ball on a string, timed with a phone",
  "notes": "Replace every number with yours. oscillations_per_trial: full oscillations timed in each trial (an oscillation is a full swing, there and back). trials: the times read off the stopwatch, one per trial. length: pivot to the ball's centre (or set measured_to to top_of_bob or bottom_of_bob). amplitude: how far the ball was pulled aside at the start, as an angle. Each uncertainty is your best guess of how far off the value may be.",
  "timing": {
    "oscillations_per_trial": 10,
    "unit": "s",
    "resolution": 0.01,
    "trials": [20.09, 20.03, 20.12, 20.06, 20.08]
  },
  "length": {"value": 100.0, "uncertainty": 0.2, "unit": "cm", "measured_to": "center"},
  "amplitude": {"value": 5, "uncertainty": 1, "unit": "deg"},
  "bob": {
    "diameter": {"value": 25.4, "uncertainty": 0.1, "unit": "mm"},
    "mass": {"value": 67.4, "uncertainty": 0.1, "unit": "g"}
  },
  "air": {
    "pressure": {"value": 1013, "unit": "hPa"},
    "temperature": {"value": 21, "unit": "degC"}
  }
}
)";

}  // namespace

Command add_template_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "template",
      "Print a starter scene: a ball on a string timed with a phone. Save it, put your numbers in, and "
      "run: pendulum-g reduce --format table my_pendulum.json");
  return {cmd, [] {
    std::cout << kBallOnAString;
    return 0;
  }};
}

}  // namespace pendulum::cli
