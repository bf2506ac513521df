#include <iostream>
#include <map>
#include <memory>

#include "commands.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/files.hpp"
#include "pendulum/json/output.hpp"
#include "pendulum/json/scene_json.hpp"

namespace pendulum::cli {

Command add_fit_decay_command(CLI::App& app) {
  struct Options {
    std::string file;
    std::optional<DecayModel> model;
    std::string format = "json";
    SceneFiles given;  // --allow-outside, --max-bytes, ...
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "fit-decay", "Fit alpha and beta (Eq. 25) to the scene's decay record and print the fit as JSON");
  cmd->add_option("scene", o->file,
                  "Scene file (JSON) with decay.data, or a file holding only decay (with data), or - for "
                  "standard input")
      ->required();
  cmd->add_option("--format", o->format, "Output: json (default) or table")->check(CLI::IsMember({"json", "table"}));
  const std::map<std::string, DecayModel> models{{"both", DecayModel::both},
                                                 {"linear_only", DecayModel::linear_only},
                                                 {"quadratic_only", DecayModel::quadratic_only}};
  cmd->add_option("--model", o->model,
                  "Force a model: both, linear_only (beta = 0), quadratic_only (alpha = 0); "
                  "by default the data decide")
      ->transform(CLI::CheckedTransformer(models, CLI::ignore_case).description(""))
      ->type_name("both|linear_only|quadratic_only");
  add_scene_file_options(*cmd, o->given);

  return {cmd, [o] {
    const ParsedScene scene = parse_decay_document(read_input(o->file, o->given), scene_files(o->file, o->given));
    if (!scene.decay_data) throw InputError("decay.data", "missing; fit-decay needs a decay record");
    DecayFitOptions fit_options;
    fit_options.model = o->model;
    const DecayFit fit = fit_decay(*scene.decay_data, fit_options);
    std::vector<std::string> warnings = scene.warnings;
    for (auto& w : review_decay_fit(fit)) warnings.push_back(std::move(w));
    if (o->format == "table") {
      std::cout << decay_fit_table(scene, fit, warnings);  // the warnings are in the table
      return 0;
    }
    const std::string text = decay_fit_json(printable_name(o->file), scene, fit, warnings);
    print_warnings(warnings);
    std::cout << text << "\n";
    return 0;
  }};
}

}  // namespace pendulum::cli
