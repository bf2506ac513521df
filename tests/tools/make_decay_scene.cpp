// Writes data/nelson_olsson_1986_decay.json: the Nelson-Olsson scene whose
// decay part is a synthetic record in the spirit of their Fig. 2, drawn from
// Eq. (25) with the paper's alpha, beta (Eqs. 28-29), theta0m = 17.5 deg and
// single-reading sigma = 0.3 deg (Sec. III.C.2), seeded. The paper prints only
// the fitted curve, not its data.
//
// Usage: make_decay_scene data/nelson_olsson_1986.json > data/nelson_olsson_1986_decay.json
// The test "The bundled decay record is what its generator writes" checks it.
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "simulations/decay_simulation.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: make_decay_scene BASE_SCENE.json\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  std::ostringstream text;
  text << in.rdbuf();
  auto scene = nlohmann::ordered_json::parse(text.str());

  constexpr double kDeg = pendulum::kPi / 180.0;
  const pendulum::DecaySimulation sim{2.49e-4, 3.17e-3, 17.5 * kDeg, 0.3 * kDeg, 3600.0, 361, 1986};
  const pendulum::DecayData data = pendulum::simulate_decay(sim);
  nlohmann::ordered_json times = nlohmann::ordered_json::array(), amplitudes = times;
  for (std::size_t i = 0; i < data.times.size(); ++i) {
    times.push_back(data.times[i]);
    // Readings to 1e-6 deg, far below sigma.
    amplitudes.push_back(std::round(data.amplitudes[i] / kDeg * 1e6) / 1e6);
  }
  scene["title"] = "Nelson & Olsson (1986) with a synthetic decay record (Fig. 2 parameters)";
  scene["decay"] = {
      {"data",
       {{"time_unit", "s"},
        {"amplitude_unit", "deg"},
        {"sigma", 0.3},
        {"source", "synthetic: Eq. (25) plus Gaussian noise, tests/tools/make_decay_scene.cpp"},
        {"generator",
         {{"model", "Nelson & Olsson (1986) Eq. (25)"},
          {"alpha_1_s", sim.alpha},
          {"beta_1_s_rad", sim.beta},
          {"initial_amplitude_deg", 17.5},
          {"sigma_deg", 0.3},
          {"duration_s", sim.duration},
          {"points", sim.points},
          {"seed", sim.seed},
          {"noise", "Box-Muller on std::mt19937_64"},
          {"rounding_deg", 1e-6}}},
        {"times", times},
        {"amplitudes", amplitudes}}}};
  std::cout << scene.dump(2) << "\n";
  return 0;
}
