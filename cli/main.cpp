// pendulum-g: reduce a pendulum experiment to g. Parses arguments, calls the
// library, prints. Exit status: 0 success, 1 bad input, 2 bad usage,
// 3 internal error. Nothing reaches stdout unless the whole result does.

#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

#include "pendulum/analysis.hpp"
#include "pendulum/result_json.hpp"
#include "pendulum/scene_json.hpp"

namespace {

constexpr int kExitInput = 1;
constexpr int kExitUsage = 2;
constexpr int kExitInternal = 3;

std::string read_input(const std::string& file) {
  if (file == "-") {
    return std::string(std::istreambuf_iterator<char>(std::cin), {});
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw pendulum::InputError("", "cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw pendulum::InputError("", "cannot read the file");
  return text.str();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pendulum-g: reduce a pendulum experiment to g (docs/ for the scene schema)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("pendulum-g ") + PENDULUM_G_VERSION);

  auto* reduce = app.add_subcommand(
      "reduce", "Apply every period correction the scene needs and print g as JSON");
  std::string file;
  std::string format = "json";
  pendulum::AnalysisOptions options;
  reduce->add_option("scene", file, "Scene file (JSON), or - for standard input")->required();
  reduce->add_option("--format", format, "Output: json (default) or table")
      ->check(CLI::IsMember({"json", "table"}));
  reduce->add_option("--negligible-fraction", options.negligible_fraction,
                     "Flag a correction negligible below this fraction of the period's "
                     "uncertainty (default 0.1)")
      ->check(CLI::Range(0.0, 1e6));
  const std::map<std::string, pendulum::AmplitudeMethod> methods{
      {"agm", pendulum::AmplitudeMethod::agm},
      {"series", pendulum::AmplitudeMethod::series},
      {"small_angle", pendulum::AmplitudeMethod::small_angle}};
  reduce->add_option("--amplitude-method", options.reduction.amplitude_method,
                     "Finite-amplitude method: agm (exact, default), series, small_angle")
      ->transform(CLI::CheckedTransformer(methods, CLI::ignore_case));
  reduce->add_option("--series-terms", options.reduction.series_terms,
                     "Terms of the Eq. (8) series for --amplitude-method series (default 4)")
      ->check(CLI::Range(1, 1000));

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitUsage;
  }

  try {
    const pendulum::ParsedScene scene = pendulum::parse_scene(read_input(file));
    const pendulum::Analysis analysis = pendulum::analyse(scene, options);
    const std::string text =
        format == "table" ? pendulum::result_to_table(scene, analysis)
                          : pendulum::result_to_json(scene, analysis, options, file).dump(2) + "\n";
    for (const auto& w : scene.warnings) std::cerr << "pendulum-g: warning: " << w << "\n";
    std::cout << text;
    std::cout.flush();
    return std::cout ? 0 : kExitInternal;
  } catch (const pendulum::InputError& e) {
    std::cerr << "pendulum-g: error: " << file << ": " << e.what() << "\n";
    return kExitInput;
  } catch (const std::exception& e) {
    std::cerr << "pendulum-g: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
}
