// Writes the physical-pendulum scenes of data/ (docs/physical.md), drawn from
// the physical pendulum's model (exact amplitude factor, buoyancy of the body)
// at the WGS84 normal gravity of the stated site, seeded:
//
//   metre_stick  data/metre_stick_pivot_scan.json: a wooden metre stick
//     (700 kg/m^3, 1000 x 28 x 6 mm) with 3 mm holes every 5 cm, hung on a
//     nail at 18 of them; body given in parts, k and the centre fitted and
//     checked against the parts. Amplitudes 5 deg + N(0, 0.5 deg) (stated
//     +-1 deg); five
//     trials of 10 T + N(0, 0.03 s) rounded to 0.01 s; positions read off
//     the stick: true + N(0, 0.3 mm) rounded to 0.5 mm. Seed 1010.
//   kater        data/kater_reversible_pendulum.json: knife edges 0.994 m
//     apart about a centre found by balancing on an edge (true + N(0, 1 mm),
//     stated +-1 mm), the second 0.5 mm from the first one's conjugate (the
//     periods 1.3 ms apart); a photogate timing 50 oscillations, three
//     trials of 50 T + N(0, 0.3 ms) rounded to 0.1 ms; amplitudes 1 deg + N(0, 0.1 deg) read on a scale
//     (stated +-0.2 deg); steel at 23.0 degC, measured at 20 degC. Seed 1011.
//
// Noise: Box-Muller on std::mt19937_64 (NormalDeviates), drawn per
// observation in the order amplitude, position, then the trials.
//
// Usage: make_physical_scenes metre_stick|kater > data/...json
// The test "The bundled physical scenes are what their generator writes" checks them.
#include <cmath>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

#include "simulations/pivot_scan_simulation.hpp"
#include "pendulum/json/scene_json.hpp"
#include "pendulum/site.hpp"

namespace {

using json = nlohmann::ordered_json;
constexpr double kDeg = pendulum::kPi / 180.0;

json q(double value, const char* unit) { return {{"value", value}, {"unit", unit}}; }
json q(double value, double uncertainty, const char* unit) {
  return {{"value", value}, {"uncertainty", uncertainty}, {"unit", unit}};
}

/// The scene as the reader sees it, with placeholder observations at the
/// first three positions (as many as the unknowns).
pendulum::ParsedScene parsed(json scene, const std::vector<double>& positions) {
  json observations = json::array();
  for (std::size_t i = 0; i < positions.size() && i < 3; ++i) {
    observations.push_back({{"pivot_position", q(positions[i], "m")},
                            {"amplitude", q(5.0, "deg")},
                            {"timing", {{"oscillations_per_trial", 1}, {"unit", "s"}, {"resolution", 0.01}, {"trials", {1.6}}}}});
  }
  scene["observations"] = observations;
  return pendulum::parse_scene(scene.dump());
}

/// Adds the observations at `positions` (m) to `scene`, drawn from the
/// model at p with the scene's apparatus.
void observe(json& scene, const double* p, const std::vector<double>& positions, double amplitude_deg,
             int oscillations, int trials, double trial_sigma, double resolution, double position_sigma,
             double position_step, std::uint64_t seed) {
  pendulum::Apparatus<double> app = parsed(scene, positions).apparatus;
  app.body->center_of_mass_position.reset();  // the truth's is p's
  app.body->radius_of_gyration.reset();
  pendulum::NormalDeviates noise(seed);
  json observations = json::array();
  for (const double x : positions) {
    const double amplitude = amplitude_deg * (1.0 + 0.1 * noise.next()) * kDeg;
    // Rounded by dividing by the integer 1/step, so that the file prints the decimal.
    const double read = std::round((x + position_sigma * noise.next()) / position_step) / std::round(1.0 / position_step);
    pendulum::Observation<double> truth{0.0, x, amplitude, oscillations, pendulum::Setting::pivot_position};
    const double period =
        pendulum::model_period<pendulum::PhysicalPendulum>(p, truth, app, pendulum::cheapest_amplitude_method(amplitude, 0.0));
    json times = json::array();
    for (int i = 0; i < trials; ++i) {
      times.push_back(std::round((oscillations * period + trial_sigma * noise.next()) / resolution) /
                      std::round(1.0 / resolution));
    }
    // The stated uncertainty holds the reading's noise and its rounding (to 1 um, up).
    const double stated =
        std::ceil(std::sqrt(position_sigma * position_sigma + position_step * position_step / 12.0) * 1e6) / 1e6;
    observations.push_back({{"pivot_position", q(read, stated, "m")},
                            {"amplitude", q(amplitude_deg, 0.2 * amplitude_deg, "deg")},
                            {"timing",
                             {{"oscillations_per_trial", oscillations},
                              {"unit", "s"},
                              {"resolution", resolution},
                              {"trials", times}}}});
  }
  scene["observations"] = observations;
}

json site(double latitude, double height) {
  return {{"latitude", q(latitude, "deg")}, {"height", q(height, "m")}, {"height_reference", "sea_level"}};
}

json metre_stick() {
  json parts = json::array();
  parts.push_back({{"shape", "box"},
                   {"length", q(1000, "mm")},
                   {"width", q(28, "mm")},
                   {"thickness", q(6, "mm")},
                   {"density", q(700, "kg/m^3")},
                   {"position", q(0.5, "m")},
                   {"source", "beech, 1 m long"}});
  std::vector<double> holes;
  for (int i = 1; i <= 19; ++i) {
    holes.push_back(0.05 * i);
    parts.push_back({{"shape", "cylinder"},
                     {"radius", q(1.5, "mm")},
                     {"length", q(6, "mm")},
                     {"axis", "swing"},
                     {"density", q(700, "kg/m^3")},
                     {"hole", true},
                     {"position", q(0.05 * i, "m")}});
  }
  json scene = {
      {"schema", "pendulum-g/scene/1"},
      {"title", "A metre stick hung on a nail at 18 of its holes"},
      {"source", "synthetic student pivot scan: tests/tools/make_physical_scenes.cpp metre_stick (seed 1010)"},
      {"notes", "Drawn from the physical pendulum's model at the site's WGS84 normal gravity and the k and centre "
                "of the parts below; amplitudes 5 deg + N(0, 0.5 deg), five trials 10 T + N(0, 0.03 s) rounded to "
                "0.01 s, pivot positions (from the 0 mark) true + N(0, 0.3 mm) rounded to 0.5 mm."},
      {"fit", {"radius_of_gyration", "center_of_mass_position"}},
      {"body", {{"parts", parts}}},
      {"air", {{"pressure", q(101.0, 0.3, "kPa")}, {"temperature", q(21.0, 1.0, "degC")}}},
      {"site", site(48.0, 250.0)}};
  std::vector<double> positions;
  for (const double x : holes) {
    if (std::abs(x - 0.5) > 0.01) positions.push_back(x);
  }
  // The truth: the parts' k and centre (the reader's), at the site's g.
  const auto body = *parsed(scene, positions).body_from_parts;
  const double p[3] = {pendulum::normal_gravity(48.0, 250.0), *body.radius_of_gyration, *body.center_of_mass_position};
  observe(scene, p, positions, 5.0, 10, 5, 0.03, 0.01, 0.0003, 0.0005, 1010);
  return scene;
}

json kater() {
  // k^2 = h1 h2 with h1 = 0.220 m, h2 = 0.774 m: the knife edges 0.994 m
  // apart, the seconds pendulum's equivalent length.
  constexpr double kCenter = 0.800, kH1 = 0.774, kH2 = 0.2205;
  json scene = {
      {"schema", "pendulum-g/scene/1"},
      {"title", "Kater's reversible pendulum, knife edges 0.994 m apart"},
      {"source", "synthetic teaching-lab Kater pendulum: tests/tools/make_physical_scenes.cpp kater (seed 1011)"},
      {"notes", "Drawn from the physical pendulum's model at the site's WGS84 normal gravity, k = sqrt(0.220 m x "
                "0.774 m), the second knife edge 0.5 mm from the conjugate of the first; steel at 23 degC, "
                "lengths measured at 20 degC; amplitudes 1 deg + N(0, 0.1 deg); photogate trials 50 T + N(0, 0.3 ms) "
                "rounded to 0.1 ms."},
      {"fit", {"radius_of_gyration"}},
      {"center_of_mass_position", {{"value", 0.800}, {"uncertainty", 0.001}, {"unit", "m"},
                                   {"source", "balanced on a knife edge, 0 mark at the top end"}}},
      {"temperature", q(23.0, 0.5, "degC")},
      {"reference_temperature", q(20.0, "degC")},
      {"material", "steel"},
      {"air", {{"pressure", q(99.5, 0.3, "kPa")}, {"temperature", q(23.0, 0.5, "degC")}}},
      {"site", site(52.0, 60.0)}};
  pendulum::NormalDeviates centre(1011);
  const double true_center = kCenter + 0.001 * centre.next();
  const double p[3] = {pendulum::normal_gravity(52.0, 60.0), std::sqrt(kH1 * 0.220), true_center};
  observe(scene, p, {true_center - kH1, true_center + kH2}, 1.0, 50, 3, 3e-4, 1e-4, 2e-5, 1e-5, 1012);
  return scene;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string which = argc > 1 ? argv[1] : "";
  if (which == "metre_stick") {
    std::cout << metre_stick().dump(2) << "\n";
  } else if (which == "kater") {
    std::cout << kater().dump(2) << "\n";
  } else {
    std::cerr << "usage: make_physical_scenes metre_stick|kater\n";
    return 1;
  }
  return 0;
}
