// Writes data/pendulum_lengths_series.json: a student's series of seven
// lengths of a steel ball on a thread, each length taped to the top of the
// ball (so the fitted length_offset should find the ball's radius), timed as
// five stopwatch trials of ten oscillations. Drawn from the simple
// pendulum's model (every correction, the exact amplitude factor) at the
// WGS84 normal gravity of the stated site, seeded:
//   true offset +12.7 mm (the radius), true amplitudes 5 deg + N(0, 0.5 deg),
//   trials 10 T + N(0, 0.06 s) rounded to 0.01 s (a hand on a stopwatch),
//   lengths read off a tape: true + N(0, 1 mm) rounded to 1 mm.
// Noise: Box-Muller on std::mt19937_64 (NormalDeviates), seed 2026, drawn
// per observation in the order amplitude, length, then the five trials.
//
// Usage: make_series_scene > data/pendulum_lengths_series.json
// The test "The bundled series is what its generator writes" checks it.
#include <cmath>
#include <iostream>

#include <nlohmann/json.hpp>

#include "pendulum/json/scene_json.hpp"
#include "simulations/series_simulation.hpp"
#include "pendulum/site.hpp"

int main() {
  using json = nlohmann::ordered_json;
  constexpr double kDeg = pendulum::kPi / 180.0;
  constexpr double kLatitude = 51.0, kHeight = 100.0;  // deg, m above sea level
  constexpr double kOffset = 0.0127;                   // m: the ball's radius
  constexpr int kOscillations = 10, kTrials = 5;
  const double g = pendulum::normal_gravity(kLatitude, kHeight);

  json scene = {
      {"schema", "pendulum-g/scene/1"},
      {"title", "A steel ball on a thread at seven lengths, taped to the top of the ball"},
      {"source", "synthetic student series: tests/tools/make_series_scene.cpp (seed 2026)"},
      {"notes", "Drawn from the simple pendulum's model at the site's WGS84 normal gravity, true length_offset "
                "+12.7 mm (the ball's radius), amplitudes 5 deg + N(0, 0.5 deg), trials 10 T + N(0, 0.06 s) "
                "rounded to 0.01 s, lengths true + N(0, 1 mm) rounded to 1 mm."},
      {"fit", {"length_offset"}},
      {"bob",
       {{"diameter", {{"value", 2.54}, {"uncertainty", 0.01}, {"unit", "cm"}, {"source", "calipers"}}},
        {"mass", {{"value", 66.9}, {"uncertainty", 0.1}, {"unit", "g"}, {"source", "kitchen scale"}}}}},
      {"wire", {{"mass", {{"value", 0.4}, {"uncertainty", 0.1}, {"unit", "g"}, {"source", "1.7 m of thread"}}}}},
      {"air",
       {{"pressure", {{"value", 100.8}, {"uncertainty", 0.3}, {"unit", "kPa"}}},
        {"temperature", {{"value", 21.0}, {"uncertainty", 1.0}, {"unit", "degC"}}}}},
      {"site",
       {{"latitude", {{"value", kLatitude}, {"unit", "deg"}}},
        {"height", {{"value", kHeight}, {"unit", "m"}}},
        {"height_reference", "sea_level"}}}};

  // The apparatus as the reader sees it, from the scene with one placeholder
  // observation (a 1 m pendulum's ten swings).
  json one = scene;
  one.erase("fit");
  one["length"] = {{"value", 1.0}, {"unit", "m"}};
  one["amplitude"] = {{"value", 5.0}, {"unit", "deg"}};
  one["timing"] = {{"oscillations_per_trial", 10}, {"unit", "s"}, {"resolution", 0.01}, {"trials", {20.07}}};
  const pendulum::Apparatus<double> apparatus = pendulum::parse_scene(one.dump()).apparatus;

  pendulum::NormalDeviates noise(2026);
  const double p[2] = {g, kOffset};
  json observations = json::array();
  for (const double length : {0.400, 0.600, 0.800, 1.000, 1.200, 1.400, 1.600}) {
    const double amplitude = (5.0 + 0.5 * noise.next()) * kDeg;
    const double taped = std::round((length + 0.001 * noise.next()) * 1000.0) / 1000.0;
    const pendulum::Observation<double> truth{0.0, length, amplitude, kOscillations};
    const double period =
        pendulum::model_period(p, truth, apparatus, pendulum::cheapest_amplitude_method(amplitude, 0.0));
    json trials = json::array();
    for (int i = 0; i < kTrials; ++i) {
      trials.push_back(std::round((kOscillations * period + 0.06 * noise.next()) * 100.0) / 100.0);
    }
    observations.push_back(
        {{"length", {{"value", taped}, {"uncertainty", 0.002}, {"unit", "m"}, {"source", "tape to the top of the ball"}}},
         {"amplitude", {{"value", 5}, {"uncertainty", 1}, {"unit", "deg"}}},
         {"timing", {{"oscillations_per_trial", kOscillations}, {"unit", "s"}, {"resolution", 0.01}, {"trials", trials}}}});
  }
  scene["observations"] = observations;
  std::cout << scene.dump(2) << "\n";
  return 0;
}
