#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"

namespace pendulum::cli {

namespace {

/// The ball and the room's air, the same in every template.
constexpr const char* kBobAndAir = R"(  "bob": {
    "diameter": {"value": 25.4, "uncertainty": 0.1, "unit": "mm"},
    "mass": {"value": 67.4, "uncertainty": 0.1, "unit": "g"}
  },
  "air": {
    "pressure": {"value": 1013, "unit": "hPa"},
    "temperature": {"value": 21, "unit": "degC"}
  })";

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
)";

/// The same ball swung at five lengths, each taped to the top of the ball:
/// `"fit": ["length_offset"]` finds the distance from that mark to the
/// ball's centre (docs/series.md). Its trials are a real pendulum's at
/// standard gravity with the corrections (2 pi sqrt((L + 12.7 mm)/g)), timed
/// by hand: it reduces to g = 9.804 +- 0.037 m/s^2 and an offset of
/// 12.2 +- 3.2 mm (the radius is 12.7 mm), status ok.
constexpr const char* kSeries = R"({
  "schema": "pendulum-g/scene/1",
  "title": "A steel ball on a string at five lengths, taped to the top of the ball",
  "notes": "Replace every number with yours; add or remove observations (at least two lengths, the more spread the better). Each observation is one length with its own timing: oscillations_per_trial full oscillations (there and back) timed in each trial. The amplitude, the same release every time, is given once at the top; give each observation its own instead if they differ. Lengths are from the pivot to whatever mark you measured to, the same mark every time: fit length_offset finds the distance from that mark to the ball's centre, and g.",
  "fit": ["length_offset"],
)";
constexpr const char* kSeriesObservations = R"(,
  "amplitude": {"value": 5, "uncertainty": 1, "unit": "deg"},
  "observations": [
    {"length": {"value": 40.0, "uncertainty": 0.2, "unit": "cm"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.01, "trials": [12.91, 12.85, 12.94, 12.88, 12.90]}},
    {"length": {"value": 60.0, "uncertainty": 0.2, "unit": "cm"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.01, "trials": [15.68, 15.73, 15.76, 15.67, 15.71]}},
    {"length": {"value": 80.0, "uncertainty": 0.2, "unit": "cm"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.01, "trials": [18.14, 18.10, 18.05, 18.12, 18.09]}},
    {"length": {"value": 100.0, "uncertainty": 0.2, "unit": "cm"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.01, "trials": [20.18, 20.25, 20.20, 20.16, 20.21]}},
    {"length": {"value": 120.0, "uncertainty": 0.2, "unit": "cm"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.01, "trials": [22.11, 22.08, 22.13, 22.15, 22.08]}}
  ]
}
)";


/// A metre stick hung on a nail through holes at eight places, k and the
/// centre fitted (docs/physical.md). Its trials are a uniform 1 m stick's
/// (k = 1 m/sqrt(12), centre at 50 cm) at standard gravity, 2 pi
/// sqrt((k^2 + h^2)/(g h)) times the exact 5 deg factor, timed by hand
/// (N(0, 0.03 s), read to 0.01 s; Python's random, seed 3): it reduces to
/// g = 9.812 +- 0.025 m/s^2, status ok.
constexpr const char* kPivotScan = R"({
  "schema": "pendulum-g/scene/1",
  "title": "A metre stick hung on a nail through its holes",
  "notes": "Replace every number with yours. pivot_position: where the nail goes through the stick, measured from one end, the same end every time. Each observation is one hole with its own timing: oscillations_per_trial full oscillations (there and back) timed in each trial. fit finds g, the radius of gyration and the centre of mass's position; holes on both sides of the centre and near it pin them down best. The amplitude, the same release every time, is given once.",
  "fit": ["radius_of_gyration", "center_of_mass_position"],
  "amplitude": {"value": 5, "uncertainty": 1, "unit": "deg"},
  "observations": [
    {"pivot_position": {"value": 5.0, "uncertainty": 0.1, "unit": "cm"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.01, "trials": [16.0, 16.04, 15.97]}},
    {"pivot_position": {"value": 15.0, "uncertainty": 0.1, "unit": "cm"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.01, "trials": [15.42, 15.39, 15.39]}},
    {"pivot_position": {"value": 25.0, "uncertainty": 0.1, "unit": "cm"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.01, "trials": [15.39, 15.34, 15.33]}},
    {"pivot_position": {"value": 35.0, "uncertainty": 0.1, "unit": "cm"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.01, "trials": [16.88, 16.9, 16.86]}},
    {"pivot_position": {"value": 65.0, "uncertainty": 0.1, "unit": "cm"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.01, "trials": [16.88, 16.83, 16.85]}},
    {"pivot_position": {"value": 75.0, "uncertainty": 0.1, "unit": "cm"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.01, "trials": [15.32, 15.29, 15.29]}},
    {"pivot_position": {"value": 85.0, "uncertainty": 0.1, "unit": "cm"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.01, "trials": [15.35, 15.39, 15.39]}},
    {"pivot_position": {"value": 95.0, "uncertainty": 0.1, "unit": "cm"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.01, "trials": [15.99, 16.0, 15.96]}}
  ]
}
)";

/// Kater's reversible pendulum: two knife edges on opposite sides of the
/// centre of mass, each a pivot_position from the same end (a pivot_distance
/// is positive on both sides, so it cannot say "opposite"), the centre of
/// mass given so that Bessel's formula applies (docs/physical.md). Its
/// numbers are data/kater_reversible_pendulum.json's (make_physical_scenes
/// kater, seed 1011): it reduces to g = 9.81206 +- 0.00037 m/s^2, Bessel's
/// g beside it, status ok.
constexpr const char* kKater = R"({
  "schema": "pendulum-g/scene/1",
  "title": "Kater's reversible pendulum, knife edges 0.994 m apart",
  "notes": "Replace every number with yours. pivot_position: each knife edge measured from the same end of the bar, one on each side of the centre of mass (a pivot_distance is positive on both sides, so it cannot say which side). center_of_mass_position: where the bar balances, from the same end; with it the report adds Bessel's formula. Time each edge the same way: oscillations_per_trial full oscillations (there and back) in each trial. temperature, reference_temperature and material correct the bar's thermal expansion; leave all three out if you do not know them.",
  "fit": ["radius_of_gyration"],
  "center_of_mass_position": {"value": 0.8, "uncertainty": 0.001, "unit": "m"},
  "temperature": {"value": 23.0, "uncertainty": 0.5, "unit": "degC"},
  "reference_temperature": {"value": 20.0, "unit": "degC"},
  "material": "steel",
  "air": {
    "pressure": {"value": 99.5, "uncertainty": 0.3, "unit": "kPa"},
    "temperature": {"value": 23.0, "uncertainty": 0.5, "unit": "degC"}
  },
  "site": {
    "latitude": {"value": 52.0, "unit": "deg"},
    "height": {"value": 60.0, "unit": "m"},
    "height_reference": "sea_level"
  },
  "observations": [
    {"pivot_position": {"value": 0.02711, "uncertainty": 2.1e-05, "unit": "m"},
     "amplitude": {"value": 1.0, "uncertainty": 0.2, "unit": "deg"},
     "timing": {"oscillations_per_trial": 50, "unit": "s", "resolution": 0.0001, "trials": [99.9932, 99.9936, 99.9935]}},
    {"pivot_position": {"value": 1.02158, "uncertainty": 2.1e-05, "unit": "m"},
     "amplitude": {"value": 1.0, "uncertainty": 0.2, "unit": "deg"},
     "timing": {"oscillations_per_trial": 50, "unit": "s", "resolution": 0.0001, "trials": [99.9306, 99.9309, 99.9303]}}
  ]
}
)";

/// A ball timed by a phone's or a photogate's recording (docs/recordings.md):
/// timing and the decay record come from the file, named relative to this
/// scene's folder.
constexpr const char* kRecording = R"({
  "schema": "pendulum-g/scene/1",
  "title": "A ball on a string, timed by a phone's recording",
  "notes": "Put the file your phone or photogate wrote (phyphox CSV or zip, Vernier, PASCO, Tracker) beside this scene and write its name in timing.recording and decay.data.recording; pendulum-g import FILE shows what it finds in it. Replace the length and the ball with yours.",
  "timing": {"recording": "my_recording.csv", "format": "auto"},
  "decay": {"data": {"recording": "my_recording.csv"}},
  "length": {"value": 80.0, "uncertainty": 0.1, "unit": "cm", "measured_to": "center"},
)";

/// A phone hung by a string from its top, its face swinging in its plane,
/// at three string lengths (docs/phone.md). Its trials are such a phone's
/// (16 x 7.5 x 0.8 cm, 190 g) at standard gravity in this air: the exact
/// slow mode of the body on the string, the exact amplitude factor at the
/// pendulum's angle (0.93 to 0.97 of the phone's 10 deg), buoyancy; 10
/// oscillations per trial, N(0, 0.004 s) read to 0.001 s (Python's random,
/// seed 23; the generator is in docs/phone.md).
constexpr const char* kPhone = R"({
  "schema": "pendulum-g/scene/1",
  "title": "A phone on a string at three lengths",
  "notes": "Replace every number with yours. Tie the string to the top of the phone and measure each length from the pivot to the knot (measured_to top_of_bob adds half the phone's height); fit length_offset finds how far the knot's mark is from that. bob: width along the swing, height vertical, depth along the axis the phone turns about (its thickness when its face swings in its own plane). amplitude of body: the angle the phone's own sensor (phyphox's gyroscope) shows, which on a string is larger than the string's; the corrections take the pendulum's.",
  "fit": ["length_offset"],
  "amplitude": {"value": 10, "uncertainty": 1, "unit": "deg", "of": "body"},
  "bob": {
    "shape": "box",
    "width": {"value": 7.5, "uncertainty": 0.05, "unit": "cm"},
    "height": {"value": 16.0, "uncertainty": 0.05, "unit": "cm"},
    "depth": {"value": 0.8, "uncertainty": 0.05, "unit": "cm"},
    "mass": {"value": 190, "uncertainty": 1, "unit": "g"}
  },
  "air": {
    "pressure": {"value": 1013, "unit": "hPa"},
    "temperature": {"value": 21, "unit": "degC"}
  },
  "observations": [
    {"length": {"value": 30.0, "uncertainty": 0.2, "unit": "cm", "measured_to": "top_of_bob"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.001, "trials": [12.52, 12.507, 12.513]}},
    {"length": {"value": 50.0, "uncertainty": 0.2, "unit": "cm", "measured_to": "top_of_bob"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.001, "trials": [15.372, 15.37, 15.371]}},
    {"length": {"value": 80.0, "uncertainty": 0.2, "unit": "cm", "measured_to": "top_of_bob"},
     "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.001, "trials": [18.892, 18.893, 18.895]}}
  ]
}
)";

}  // namespace

Command add_template_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "template",
      "Print a starter scene. Save it, put your numbers in, and run: pendulum-g reduce --format table "
      "my_pendulum.json");
  auto kind = std::make_shared<std::string>("ball");
  cmd->add_option("kind", *kind,
                  "ball (default): a ball on a string timed with a phone; series: the same ball at several "
                  "lengths, with the offset from the measured mark to the ball's centre fitted; pivot-scan: a "
                  "metre stick hung at several holes (a physical pendulum); kater: Kater's reversible pendulum, "
                  "two knife edges, with Bessel's formula; recording: a ball timed by a phone's or a photogate's "
                  "file; phone: a phone on a string at several lengths (docs/phone.md)")
      ->check(CLI::IsMember({"ball", "series", "pivot-scan", "kater", "recording", "phone"}));
  cmd->footer("Kinds: ball, series, pivot-scan, kater, recording, phone. Example: pendulum-g template kater > kater.json\n");
  return {cmd, [kind] {
    if (*kind == "series") {
      std::cout << kSeries << kBobAndAir << kSeriesObservations;
    } else if (*kind == "pivot-scan") {
      std::cout << kPivotScan;
    } else if (*kind == "kater") {
      std::cout << kKater;
    } else if (*kind == "phone") {
      std::cout << kPhone;
    } else if (*kind == "recording") {
      std::cout << kRecording << kBobAndAir << "\n}\n";
    } else {
      std::cout << kBallOnAString << kBobAndAir << "\n}\n";
    }
    return 0;
  }};
}

}  // namespace pendulum::cli
