#pragma once
// The subcommands of pendulum-g. Each registers its options on the app and
// returns the function that runs it once the arguments are parsed. A run
// throws pendulum::InputError for bad input; it prints nothing on stdout
// until its whole result is ready.

#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "pendulum/amplitude.hpp"
#include "pendulum/argument_ranges.hpp"
#include "pendulum/output_files.hpp"
#include "pendulum/json/scene_json.hpp"

namespace pendulum {
struct AnalysisOptions;
struct SwingOptions;
}

namespace pendulum::cli {

/// Exit status of `reduce --strict` on a suspect result (docs/output.md).
inline constexpr int kExitSuspect = 4;
/// Exit status when an output (standard output, a report) could not be
/// written whole (docs/output.md).
inline constexpr int kExitOutput = 5;

using pendulum::OutputError;
using pendulum::UsageError;
using pendulum::refuse_output_over_inputs;
using pendulum::write_output;

/// A registered subcommand and the function that runs it.
struct Command {
  CLI::App* app;
  std::function<int()> run;
};

/// The text of a scene file, or of standard input for "-", within
/// `given`'s limits (kSceneInput unless raised); a pipe or device named is
/// refused (cli/files.cpp).
std::string read_input(const std::string& file, const SceneFiles& given = {});

/// Where a scene file's recordings are looked for: its folder, and nowhere
/// else unless given.allow_outside (--allow-outside); `given`'s limits.
SceneFiles scene_files(const std::string& file, const SceneFiles& given);

/// The options of the commands that read a scene: --allow-outside and the
/// limits of what is read (--max-bytes, --max-rows, --max-columns).
void add_scene_file_options(CLI::App& cmd, SceneFiles& given);

/// --max-bytes, --max-rows, --max-columns: every input's limits (docs/robustness.md, "Limits").
void add_limit_options(CLI::App& cmd, GivenLimits& given);

/// Puts /dev/null in place of a closed standard input, output or error, the
/// wrong way round for the first two, so that using them fails by name
/// instead of reaching the next file opened.
void guard_standard_streams();

/// Empty when everything written to standard output got there; else why
/// not ("No space left on device").
std::string standard_output_error();

/// Each warning on stderr, prefixed "pendulum-g: warning: ".
void print_warnings(const std::vector<std::string>& warnings);

/// The finite-amplitude methods by their output names, `auto` included
/// when the command can choose.
std::map<std::string, AmplitudeMethod> amplitude_methods(bool with_auto);

/// A check of an option's number against its range in the table the Python
/// module checks too (pendulum/argument_ranges.hpp).
CLI::Validator in_range(const ArgumentRange& range);

/// A check that an option's number is decimal (0x10 is refused), its range
/// left to the command (where out of range is bad input, exit 1).
CLI::Validator decimal(const ArgumentRange& range);

/// A check that an option's count is written in decimal digits (0x10,
/// which CLI11 reads as 16, and 1e3 are refused).
CLI::Validator whole_number();

/// The options of an analysis (--negligible-fraction, --amplitude-method,
/// --series-terms), shared by the commands that reduce one scene.
void add_analysis_options(CLI::App& cmd, AnalysisOptions& options);

/// `pendulum-g reduce SCENE`: scene -> corrected g (cli/reduce_command.cpp).
Command add_reduce_command(CLI::App& app);

/// `pendulum-g amplitude --theta0-deg X`: T/T0 at one amplitude
/// (cli/amplitude_command.cpp).
Command add_amplitude_command(CLI::App& app);

/// `pendulum-g batch SCENES...`: many scenes -> one summary (cli/batch_command.cpp).
Command add_batch_command(CLI::App& app);

/// `pendulum-g template`: a starter scene on stdout (cli/template_command.cpp).
Command add_template_command(CLI::App& app);

/// `pendulum-g report SCENE -o report.html`: the reduction as one HTML page
/// or one SVG plot (cli/report_command.cpp).
Command add_report_command(CLI::App& app);

/// `pendulum-g fit-decay SCENE`: the decay record -> alpha, beta (cli/fit_decay_command.cpp).
Command add_fit_decay_command(CLI::App& app);

/// `pendulum-g import RECORDING`: a phone, photogate or video-tracker
/// recording -> period, amplitudes, timing and decay (cli/import_command.cpp).
Command add_import_command(CLI::App& app);

/// --bob-width-m and --length-m, a photogate's amplitudes (import and report).
void add_recording_options(CLI::App& cmd, SwingOptions& options, std::string& set, std::string& columns);

/// `pendulum-g clock SCENE`: circular and impulse error of a clock
/// pendulum (cli/clock_command.cpp).
Command add_clock_command(CLI::App& app);

}  // namespace pendulum::cli
