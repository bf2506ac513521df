// libFuzzer target: any bytes through the scene parser and the whole
// reduction, with each amplitude method, as `pendulum-g reduce` runs them,
// and through the clock scene's parser and model, as `pendulum-g clock`.
// A scene may name the recordings of tests/fuzz/recording_seeds/ (its seeds
// there name the θ columns without unit, in degrees and in radians, so the
// reduction meets the unit decision), and nothing else.
// Bad input must end in an InputError whose message is one printable line;
// a scene that passes must give finite numbers everywhere and a positive g.
// Anything else (another exception, a sanitizer report, a failed check
// below) is a finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pendulum/reduce_scene.hpp"
#include "pendulum/json/output.hpp"
#include "pendulum/clock_scene.hpp"
#include "pendulum/json/scene_json.hpp"
#include "fuzz_checks.hpp"

namespace {

using pendulum::fuzz::require;
using pendulum::fuzz::require_clear_message;

/// The folder a scene's recordings are read from, confined to it as the CLI
/// confines a scene's, so that no mutated name opens a FIFO, /dev/zero or a
/// 1 GiB log.
pendulum::SceneFiles recording_seeds() {
  pendulum::SceneFiles files;
  files.directory = PENDULUM_FUZZ_RECORDINGS;
  return files;
}

void require_finite(const nlohmann::ordered_json& j, const std::string& path) {
  if (j.is_structured()) {
    for (const auto& item : j.items()) require_finite(item.value(), path + "/" + item.key());
  } else if (j.is_number_float()) {
    require(std::isfinite(j.get<double>()), "non-finite number in the result", path);
  }
}

void collect_numbers(nlohmann::json& j, std::vector<nlohmann::json*>& out) {
  if (j.is_number()) out.push_back(&j);
  if (j.is_structured()) {
    for (auto& item : j) collect_numbers(item, out);
  }
}

}  // namespace

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

// Byte mutations of a scene nearly always break its JSON or its physics, so
// the reduction would rarely see a scene (11 of the 1739 inputs a 30-minute
// campaign kept were scenes). Half the time, a valid scene has one number
// changed instead: a unit slip, a small step, a sign, or an edge value (for a
// clock scene too).
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t max_size, unsigned int seed) {
  std::minstd_rand random(seed);
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (random() % 2 == 0) return LLVMFuzzerMutate(data, size, max_size);
  // A valid scene or clock scene: the parsers also bound the nesting for
  // the recursion below.
  const auto valid = [&](auto parse) {
    try {
      parse(text);
      return true;
    } catch (const pendulum::InputError&) {
      return false;
    }
  };
  const auto scene_parser = [](const std::string& t) { return pendulum::parse_scene(t, recording_seeds()); };
  if (!valid(scene_parser) && !valid(pendulum::parse_clock_scene)) {
    return LLVMFuzzerMutate(data, size, max_size);
  }
  nlohmann::json scene = nlohmann::json::parse(text);
  std::vector<nlohmann::json*> numbers;
  collect_numbers(scene, numbers);
  nlohmann::json& x = *numbers[random() % numbers.size()];  // a scene has numbers
  const double v = x.get<double>();
  constexpr double edges[] = {0.0, 1e-300, 1e300, 5e-324, 1.7976931348623157e308, 1.0};
  switch (random() % 4) {
    case 0: x = v * std::pow(10.0, static_cast<int>(random() % 13) - 6); break;
    case 1: x = v * (1.0 + (static_cast<double>(random() % 2001) - 1000.0) * 1e-4); break;
    case 2: x = -v; break;
    default: x = edges[random() % std::size(edges)]; break;
  }
  const std::string mutated = scene.dump();
  if (mutated.size() > max_size) return LLVMFuzzerMutate(data, size, max_size);
  std::memcpy(data, mutated.data(), mutated.size());
  return mutated.size();
}

/// The same bytes as a clock scene, through `pendulum-g clock` with every
/// route (a route that cannot model the scene is bad input, as in the CLI).
void run_clock(const std::string& text) {
  pendulum::ClockScene scene;
  try {
    scene = pendulum::parse_clock_scene(text);
  } catch (const pendulum::InputError& e) {
    return require_clear_message(e);
  }
  using pendulum::ClockRoute;
  for (const auto route : {std::optional<ClockRoute>{}, std::optional{ClockRoute::cycloid},
                           std::optional{ClockRoute::circular_elliptic}, std::optional{ClockRoute::cycloid_damped},
                           std::optional{ClockRoute::circular_rk4}}) {
    try {
      const pendulum::ClockAnalysis analysis = pendulum::analyse_clock(scene, route);
      require_finite(nlohmann::ordered_json::parse(pendulum::clock_json(scene, analysis, "fuzz")), "");
      (void)pendulum::clock_table(scene, analysis);
    } catch (const pendulum::InputError& e) {
      require_clear_message(e);
    }
  }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  run_clock(text);
  // Bad input may be found while reading or, for inputs whose uncertainties
  // overflow g's, while propagating them: both as the CLI reports them.
  try {
    const pendulum::ParsedScene scene = pendulum::parse_scene(text, recording_seeds());
    using pendulum::AmplitudeMethod;
    for (const auto method : {AmplitudeMethod::agm, AmplitudeMethod::series, AmplitudeMethod::small_angle}) {
      pendulum::AnalysisOptions options;  // --amplitude-method
      options.reduction.amplitude_method = method;
      const pendulum::Analysis analysis = pendulum::reduce_scene(scene, options);
      const auto result = nlohmann::json::parse(pendulum::result_json(scene, analysis, options, "fuzz"));
      require_finite(result, "");
      // The detail only on failure: a scene of many observations dumps 200 kB.
      if (!(analysis.g.value > 0.0)) require(false, "g not positive", result.dump());
      (void)pendulum::result_table(scene, analysis);
    }
  } catch (const pendulum::InputError& e) {
    require_clear_message(e);
  }
  return 0;
}
