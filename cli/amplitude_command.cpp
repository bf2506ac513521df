#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "pendulum/json/scene_json.hpp"

namespace pendulum::cli {

Command add_amplitude_command(CLI::App& app) {
  struct Options {
    double theta0_deg = 0.0;
    AmplitudeMethod method = AmplitudeMethod::agm;
    int terms = 4;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "amplitude", "Print T/T0 and the finite-amplitude correction at one amplitude as JSON");
  // Range checks happen in the run, so that a bad amplitude is bad input
  // (exit 1), not bad usage.
  cmd->add_option("--theta0-deg", o->theta0_deg, "Amplitude (deg), 0 <= X < 180")
      ->required()
      ->check(decimal(ranges::amplitude_deg));
  cmd->add_option("--method", o->method,
                  "agm (exact, default), series (Eq. 8, --terms terms), small_angle (theta0^2/16)")
      ->transform(CLI::CheckedTransformer(amplitude_methods(false), CLI::ignore_case).description(""))
      ->type_name("agm|series|small_angle");
  cmd->add_option("--terms", o->terms, "Terms of the Eq. (8) series (default 4)")
      ->check(in_range(ranges::amplitude_terms));

  return {cmd, [o] {
    const double deg = o->theta0_deg;
    const std::string why = out_of_range(ranges::amplitude_deg, deg);
    if (!why.empty()) throw InputError(ranges::amplitude_deg.option, why);
    const double theta0 = radians(deg);
    // The exact method takes degrees, so the deficit from 180 deg stays exact.
    const double ratio = o->method == AmplitudeMethod::agm
                             ? finite_amplitude_agm_deg(deg)
                             : finite_amplitude(o->method, theta0, o->terms);
    nlohmann::ordered_json out = {
        {"schema", "pendulum-g/amplitude/1"},
        {"theta0_deg", deg},
        {"method", method_name(o->method)},
        {"T_over_T0", 1.0 + ratio},
        {"delta_T_over_T0", ratio},
        {"error_bound_delta_T_over_T0",
         o->method == AmplitudeMethod::agm
             ? kExactRelativeErrorBound * ratio
             : amplitude_error_bound(o->method, theta0, o->terms)},
        {"equation", "Nelson & Olsson (1986) Eq. (8)"}};
    if (o->method == AmplitudeMethod::series) out["series_terms"] = o->terms;
    std::cout << out.dump(2) << "\n";
    return 0;
  }};
}

}  // namespace pendulum::cli
