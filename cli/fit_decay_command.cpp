#include <iostream>
#include <map>
#include <memory>

#include "commands.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/result_json.hpp"
#include "pendulum/scene_json.hpp"

namespace pendulum::cli {

Command add_fit_decay_command(CLI::App& app) {
  struct Options {
    std::string file;
    std::optional<DecayModel> model;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "fit-decay", "Fit alpha and beta (Eq. 25) to the scene's decay record and print the fit as JSON");
  cmd->add_option("scene", o->file, "Scene file (JSON) with decay.data, or - for standard input")
      ->required();
  const std::map<std::string, DecayModel> models{{"both", DecayModel::both},
                                                 {"linear_only", DecayModel::linear_only},
                                                 {"quadratic_only", DecayModel::quadratic_only}};
  cmd->add_option("--model", o->model,
                  "Force a model: both, linear_only (beta = 0), quadratic_only (alpha = 0); "
                  "by default the data decide")
      ->transform(CLI::CheckedTransformer(models, CLI::ignore_case));

  return {cmd, [o] {
    const ParsedScene scene = parse_scene(read_input(o->file));
    if (!scene.decay_data) throw InputError("decay.data", "missing; fit-decay needs a decay record");
    DecayFitOptions fit_options;
    fit_options.model = o->model;
    const DecayFit fit = fit_decay(*scene.decay_data, fit_options);
    nlohmann::ordered_json out = {{"schema", "pendulum-g/decay-fit/1"}, {"input", o->file}};
    out.update(decay_fit_to_json(fit, scene.value.decay));
    const ParsedScene fitted = with_fitted_decay(scene, fit);
    if (const auto drag = predict_drag(fitted.value)) {
      out["drag_theory"] = drag_to_json(*drag, *fitted.value.decay);
    }
    std::vector<std::string> warnings = scene.warnings;
    for (auto& w : review_decay_fit(fit)) warnings.push_back(std::move(w));
    out["warnings"] = warnings;
    print_warnings(warnings);
    std::cout << json_text(out) << "\n";
    return 0;
  }};
}

}  // namespace pendulum::cli
