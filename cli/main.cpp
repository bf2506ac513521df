// pendulum-g: reduce a pendulum experiment to g. Parses arguments, runs one
// subcommand, reports errors. Exit status: 0 success, 1 bad input, 2 bad
// usage, 3 internal error, 4 a suspect result under reduce --strict, 5 an
// output that could not be written. Nothing reaches stdout unless a whole
// result does.

#include <cstring>
#include <iostream>
#include <vector>

#include <glog/logging.h>

#include "commands.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/files.hpp"
#include "pendulum/printable.hpp"
#include "pendulum/json/scene_json.hpp"

namespace pendulum::cli {

void print_warnings(const std::vector<std::string>& warnings) {
  for (const auto& w : warnings) std::cerr << "pendulum-g: warning: " << w << "\n";
}

std::map<std::string, AmplitudeMethod> amplitude_methods(bool with_auto) {
  std::map<std::string, AmplitudeMethod> names;
  for (auto m : {AmplitudeMethod::small_angle, AmplitudeMethod::series, AmplitudeMethod::agm,
                 AmplitudeMethod::automatic}) {
    if (with_auto || m != AmplitudeMethod::automatic) names[method_name(m)] = m;
  }
  return names;
}

namespace {

/// Empty when `text` is a decimal number, else what the option expects.
std::string not_decimal(const std::string& text, const ArgumentRange& range) {
  if (decimal_number(text)) return "";
  return "got \"" + one_line(text, kShownValueBytes, true) + "\"; expected a decimal number: " + range.expected;
}

}  // namespace

CLI::Validator decimal(const ArgumentRange& range) {
  return CLI::Validator([range](std::string& text) { return not_decimal(text, range); }, "");
}

CLI::Validator whole_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::optional<double> n = decimal_number(text);
        // Digits only: decimal_number also takes 1e3, 2.0 and inf.
        if (n && text.find_first_not_of("+0123456789") == std::string::npos) return "";
        return "got \"" + one_line(text, kShownValueBytes, true) + "\"; expected a whole number in decimal digits";
      },
      "");
}

CLI::Validator in_range(const ArgumentRange& range) {
  return CLI::Validator(
      [range](std::string& text) {
        const std::string why = not_decimal(text, range);
        return why.empty() ? out_of_range(range, *decimal_number(text)) : why;
      },
      "");
}

void add_analysis_options(CLI::App& cmd, AnalysisOptions& options) {
  cmd.add_option("--negligible-fraction", options.negligible_fraction,
                 "Flag a correction negligible below this fraction of the period's "
                 "uncertainty (default 0.1)")
      ->check(in_range(ranges::negligible_fraction));
  cmd.add_option("--amplitude-method", options.reduction.amplitude_method,
                 "Finite-amplitude method: auto (default: the cheapest whose error bound "
                 "is below 1% of the period's uncertainty), agm (exact), series, small_angle")
      ->transform(CLI::CheckedTransformer(amplitude_methods(true), CLI::ignore_case).description(""))
      ->type_name("auto|agm|series|small_angle");
  cmd.add_option("--series-terms", options.reduction.series_terms,
                 "Terms of the Eq. (8) series for --amplitude-method series (default 4)")
      ->check(in_range(ranges::series_terms));
  // GUM Supplement 1 beside the budget (docs/uncertainty.md); --draws and --seed imply it.
  const auto monte_carlo = [&options]() -> MonteCarloOptions& {
    if (!options.monte_carlo) options.monte_carlo.emplace();
    return *options.monte_carlo;
  };
  cmd.add_option_function<std::string>(
         "--uncertainty",
         [&options, monte_carlo](const std::string& method) {
           if (method == "gum") options.monte_carlo.reset();
           else monte_carlo();
         },
         "gum (default: the linear budget, its expanded uncertainty from Student's t) or monte-carlo (GUM "
         "Supplement 1 beside it: every input drawn from its distribution and a series refitted per draw, the "
         "shortest 95 % interval, and a warning where the two disagree): docs/uncertainty.md")
      ->check(CLI::IsMember({"gum", "monte-carlo"}))
      ->type_name("gum|monte-carlo");
  cmd.add_option_function<long>("--draws", [monte_carlo](long n) { monte_carlo().draws = n; },
                                "Monte Carlo draws (default: adaptive, GUM S1 7.9, at most 10^6)")
      ->check(whole_number())
      ->check(CLI::Range(100L, kMostDraws));
  cmd.add_option_function<std::uint64_t>("--seed", [monte_carlo](std::uint64_t s) { monte_carlo().seed = s; },
                                         "Monte Carlo seed (default 1): the same seed, the same draws")
      ->check(whole_number());
}

}  // namespace pendulum::cli

int main(int argc, char** argv) {
  constexpr int kExitInput = 1, kExitUsage = 2, kExitInternal = 3;
  pendulum::cli::guard_standard_streams();
  // Ceres reports through glog; pendulum-g reports through its own messages.
  FLAGS_minloglevel = google::GLOG_FATAL;
  CLI::App app{
      "pendulum-g: reduce a pendulum experiment to g.\n"
      "Start with `pendulum-g template > my_pendulum.json`, put your numbers in, then run\n"
      "`pendulum-g reduce --format table my_pendulum.json`. The scene (JSON) holds timing\n"
      "(oscillations_per_trial, unit, resolution, trials), length (pivot to the bob's centre),\n"
      "amplitude, and optionally bob, air, site, ...: docs/scene.md. An oscillation is a full\n"
      "swing, there and back; count full oscillations, not half swings."};
  app.require_subcommand(1);
  // The user's text in an option error (its value) escaped and cut, so that
  // neither control bytes nor a 100 KB value reach the terminal whole.
  app.failure_message([](const CLI::App* a, const CLI::Error& e) {
    return pendulum::one_line(e.what(), pendulum::kShownOptionErrorBytes, true) +
           CLI::FailureMessage::simple(a, e).substr(std::strlen(e.what()));
  });
  app.set_version_flag("--version", std::string("pendulum-g ") + PENDULUM_G_VERSION);

  const std::vector<pendulum::cli::Command> commands{
      pendulum::cli::add_reduce_command(app),
      pendulum::cli::add_fit_decay_command(app),
      pendulum::cli::add_batch_command(app),
      pendulum::cli::add_amplitude_command(app),
      pendulum::cli::add_import_command(app),
      pendulum::cli::add_report_command(app),
      pendulum::cli::add_clock_command(app),
      pendulum::cli::add_template_command(app),
  };

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    // Several scenes given to a command that takes one: batch takes many.
    const std::string command = argc > 1 ? argv[1] : "";
    if (dynamic_cast<const CLI::ExtrasError*>(&e) && (command == "reduce" || command == "fit-decay")) {
      std::string scenes;
      for (int i = 2; i < argc; ++i) {
        if (argv[i][0] != '-') scenes += " " + pendulum::printable_name(argv[i]);
      }
      std::cerr << "pendulum-g: " << command << " takes one scene; for several, run: pendulum-g batch" << scenes
                << "\n";
    }
    return kExitUsage;
  }

  for (const auto& command : commands) {
    if (!command.app->parsed()) continue;
    // The subcommand's input file, named in error messages.
    const CLI::Option* scene = command.app->get_option_no_throw("scene");
    const std::string file = scene && scene->count() ? pendulum::printable_name(scene->as<std::string>()) : "";
    auto output_failed = [] {
      const std::string why = pendulum::cli::standard_output_error();
      if (!why.empty()) std::cerr << "pendulum-g: error: output: cannot write standard output: " << why << "\n";
      return !why.empty();
    };
    try {
      const int status = command.run();
      return output_failed() ? pendulum::cli::kExitOutput : status;
    } catch (const pendulum::cli::OutputError& e) {
      output_failed();
      std::cerr << "pendulum-g: error: output: " << e.what() << "\n";
      return pendulum::cli::kExitOutput;
    } catch (const pendulum::cli::UsageError& e) {
      std::cerr << "pendulum-g: error: " << e.what() << "\n";
      return kExitUsage;
    } catch (const pendulum::InputError& e) {
      // Not twice: a recording's errors name their file (and line) already.
      const bool named = !file.empty() && (e.path() == file || e.path().rfind(file + ":", 0) == 0 ||
                                           (file == "-" && e.path() == "stdin"));
      std::cerr << "pendulum-g: error: " << (file.empty() || named ? "" : file + ": ") << e.what() << "\n";
      return kExitInput;
    } catch (const std::exception& e) {
      std::cerr << "pendulum-g: internal error: " << e.what() << "\n";
      return kExitInternal;
    }
  }
  return kExitUsage;
}
