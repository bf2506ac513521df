// libFuzzer target: any bytes through the scene parser and the whole
// reduction, with each amplitude method, as `pendulum-g reduce` runs them.
// Bad input must end in an InputError whose message is one printable line;
// a scene that passes must give finite numbers everywhere and a positive g.
// Anything else (another exception, a sanitizer report, a failed check
// below) is a finding.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "pendulum/analysis.hpp"
#include "pendulum/result_json.hpp"
#include "pendulum/scene_json.hpp"

namespace {

void require(bool ok, const char* what, const std::string& detail) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_scene: %s: %s\n", what, detail.c_str());
  std::abort();
}

void require_finite(const nlohmann::ordered_json& j, const std::string& path) {
  if (j.is_structured()) {
    for (const auto& item : j.items()) require_finite(item.value(), path + "/" + item.key());
  } else if (j.is_number_float()) {
    require(std::isfinite(j.get<double>()), "non-finite number in the result", path);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  pendulum::ParsedScene scene;
  try {
    scene = pendulum::parse_scene(text);
  } catch (const pendulum::InputError& e) {
    const std::string message = e.what();
    for (const char c : message) {
      require(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f,
              "control character in an error message", message);
    }
    require(message.size() <= 1000, "error message over 1000 characters", message.substr(0, 200));
    return 0;
  }
  using pendulum::AmplitudeMethod;
  for (const auto method : {AmplitudeMethod::agm, AmplitudeMethod::series, AmplitudeMethod::small_angle}) {
    pendulum::AnalysisOptions options;  // --amplitude-method
    options.reduction.amplitude_method = method;
    const pendulum::Analysis analysis = pendulum::analyse(scene, options);
    const auto result = pendulum::result_to_json(scene, analysis, options, "fuzz");
    require_finite(result, "");
    require(analysis.g.value > 0.0, "g not positive", result.dump());
    (void)pendulum::result_to_table(scene, analysis);
  }
  return 0;
}
