#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

#include "commands.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/batch.hpp"
#include "pendulum/files.hpp"
#include "pendulum/json/output.hpp"
#include "pendulum/report/html_report.hpp"
#include "pendulum/json/scene_json.hpp"
#include "pendulum/printable.hpp"

namespace pendulum::cli {
namespace {

using Job = BatchScene;

/// The scenes on standard input, named "stdin:N" by the line each starts
/// on: one a line (JSON lines), or pretty-printed over many (cat *.json).
/// A scene ends where its outermost braces close, outside strings; text
/// outside braces is a scene to the end of its line (and fails as such).
std::vector<Job> split_documents(const std::string& input) {
  std::istringstream in(input);
  std::vector<Job> documents;
  std::string line, text;
  int depth = 0, start = 0;
  bool in_string = false, escaped = false;
  for (int n = 1; std::getline(in, line); ++n) {
    for (const char c : line) {
      if (depth == 0 && text.empty()) {
        if (c == ' ' || c == '\t' || c == '\r') continue;
        start = n;
      }
      text += c;
      if (in_string) {
        if (escaped) {
          escaped = false;
        } else if (c == '\\') {
          escaped = true;
        } else if (c == '"') {
          in_string = false;
        }
        continue;
      }
      if (c == '"') in_string = true;
      if (c == '{' || c == '[') ++depth;
      if ((c == '}' || c == ']') && depth > 0 && --depth == 0) {
        documents.push_back({"stdin:" + std::to_string(start), text});
        text.clear();
      }
    }
    if (depth == 0 && !text.empty()) {  // not a JSON object: the line is one (bad) scene
      documents.push_back({"stdin:" + std::to_string(start), text});
      text.clear();
    }
    if (!text.empty()) text += '\n';
  }
  if (!text.empty()) documents.push_back({"stdin:" + std::to_string(start), text});
  return documents;
}

/// The scenes to reduce, and a note on stderr for each entry of a folder
/// that is not one (a subfolder, davis.json.txt), so that none is skipped
/// without a word.
std::vector<Job> gather(const std::vector<std::string>& paths, const std::string& list, const InputLimits& limits) {
  std::vector<Job> jobs;
  auto add_path = [&](const std::string& p) {
    std::error_code ec;
    if (!std::filesystem::is_directory(p, ec)) {
      jobs.push_back({p, std::nullopt});
      return;
    }
    std::vector<SkippedEntry> skipped;
    for (auto& f : folder_scenes(p, skipped)) jobs.push_back({std::move(f), std::nullopt});
    for (const auto& [f, why] : skipped) {
      std::cerr << "pendulum-g: note: skipped " << printable_name(f) << ": " << why << "\n";
    }
  };
  for (const auto& p : paths) {
    if (p != "-") {
      add_path(p);
      continue;
    }
    for (auto& document : split_documents(read_text("-", limits, "scenes"))) {
      jobs.push_back(std::move(document));
    }
  }
  if (!list.empty()) {
    std::istringstream in(read_text(list, limits, "a list of scene files"));
    std::string line;
    while (std::getline(in, line)) {
      // Surrounding spaces (and a CR) are no part of a file name.
      const auto first = line.find_first_not_of(" \t\r");
      if (first == std::string::npos || line[first] == '#') continue;
      add_path(line.substr(first, line.find_last_not_of(" \t\r") - first + 1));
    }
  }
  return jobs;
}

/// --site "52.37,5": the class's lab, its latitude (deg, north positive) and
/// height above sea level (m), each checked as a scene's site.latitude and
/// site.height are (argument_ranges.hpp); why not, or empty.
std::string site_problem(const std::string& text, std::optional<Site>* site = nullptr) {
  const auto comma = text.find(',');
  const std::string expected = "; expected LATITUDE_DEG,HEIGHT_M (the lab's latitude, north positive, and height "
                               "above sea level), e.g. 52.37,5";
  const bool one_comma = comma != std::string::npos && text.find(',', comma + 1) == std::string::npos;
  auto number = [](std::string part) {  // "52.37, 5" as typed after a comma
    part.erase(0, part.find_first_not_of(' '));
    part.erase(part.find_last_not_of(' ') + 1);
    return decimal_number(part);
  };
  const std::optional<double> latitude = one_comma ? number(text.substr(0, comma)) : std::nullopt,
                              height = one_comma ? number(text.substr(comma + 1)) : std::nullopt;
  if (!latitude || !height) return "got \"" + one_line(text, kShownValueBytes, true) + "\"" + expected;
  for (const auto& [range, value] : {std::pair{ranges::latitude, *latitude}, std::pair{ranges::height, *height}}) {
    const std::string why = out_of_range(range, value);
    if (!why.empty()) return why;
  }
  if (site) {
    *site = Site{};
    (*site)->latitude_deg = *latitude + 0.0;  // -0 is 0
    (*site)->height = *height + 0.0;
    (*site)->height_above_ellipsoid = false;
  }
  return "";
}

}  // namespace

Command add_batch_command(CLI::App& app) {
  struct Options {
    std::vector<std::string> paths;
    std::string list;
    std::string format = "jsonl";
    std::string report;
    unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
    std::string site;
    SceneFiles given;  // --allow-outside, --max-bytes, ...
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "batch", "Reduce many scenes (files, folders of *.json, a list, or JSON lines on stdin) to one summary");
  cmd->add_option("scenes", o->paths,
                  "Scene files, folders (their *.json, any case; other entries are skipped with a note), or - "
                  "for scenes on standard input (one a line, or pretty-printed one after another)");
  cmd->footer(
      "Output: one line per scene, in the order given (folders: by file name), then a class line.\n"
      "Columns (CSV; JSON lines have the same keys): input, ok (a result exists), g_m_s2,\n"
      "g_uncertainty_m_s2, largest_budget_input and largest_budget_m_s2 (the input that dominates\n"
      "g's uncertainty), expected_g_m_s2 and z (with a site), warnings (JSON: their texts; CSV: the\n"
      "first), error, status (ok, suspect or failed), status_reasons (the likely slip and the input\n"
      "to fix), title; CSV only: warning_count.\n"
      "Table: file, status, g rounded to its uncertainty, z, the first reason (or the error) in brief.\n"
      "Class line: JSON {\"class\": true, \"counts\": ...}; CSV \"# class: ...\"; table \"class: ...\".\n"
      "Exit status 1 when any scene failed. docs/instructors.md has an example.");
  cmd->add_option("--list", o->list, "A file naming one scene file per line (# starts a comment)");
  cmd->add_option("--format", o->format,
                  "Summary: jsonl (default, one JSON object per scene), csv (the warnings counted, the first given), "
                  "or table (for people: file, status, g, z, the reason in brief)")
      ->check(CLI::IsMember({"jsonl", "csv", "table"}));
  cmd->add_option("--report", o->report,
                  "Also write an HTML class report to this file: every g against the expected g, the failures, "
                  "each scene's section");
  cmd->add_option("--site", o->site,
                  "The class's lab as LATITUDE_DEG,HEIGHT_M (north positive; height above sea level), e.g. 52.37,5: "
                  "each scene that names no site is compared with WGS84 normal gravity there")
      ->check(CLI::Validator([](std::string& text) { return site_problem(text); }, "LATITUDE_DEG,HEIGHT_M"));
  cmd->add_option("--jobs", o->jobs, "Scenes reduced at once (default: the number of cores)")
      ->check(whole_number())
      ->check(CLI::Range(1u, 256u));
  add_scene_file_options(*cmd, o->given);

  return {cmd, [o] {
    std::vector<std::string> inputs{o->list};
    for (const auto& p : o->paths) inputs.push_back(p);
    refuse_output_over_inputs(o->report, inputs);  // a folder is no file, but --list is
    const std::vector<Job> jobs = gather(o->paths, o->list, o->given.limits.applied_to(kSceneInput));
    if (jobs.empty()) throw InputError("", "no scenes: give files, folders, --list, or - for standard input");
    inputs.clear();
    for (const auto& job : jobs) {
      if (!job.text) inputs.push_back(job.name);
      // The recordings and tables it names too, before any is read.
      if (o->report.empty()) continue;
      try {
        const std::vector<std::string> named =
            scene_file_names(job.text ? *job.text : read_input(job.name, o->given), job.files(o->given));
        inputs.insert(inputs.end(), named.begin(), named.end());
      } catch (const InputError&) {
        // The scene's own line says why it cannot be read.
      }
    }
    refuse_output_over_inputs(o->report, inputs);
    const AnalysisOptions options;
    std::optional<Site> site;
    if (!o->site.empty()) site_problem(o->site, &site);
    const BatchFormat format = o->format == "csv"     ? BatchFormat::csv
                               : o->format == "table" ? BatchFormat::table
                                                      : BatchFormat::jsonl;
    std::vector<std::optional<BatchOutcome>> results(jobs.size());
    std::vector<report::ClassEntry> entries;
    std::mutex mutex;
    std::condition_variable ready;
    std::atomic<std::size_t> next{0};
    auto work = [&] {
      for (std::size_t i = next++; i < jobs.size(); i = next++) {
        auto outcome = reduce_batch_scene(jobs[i], options, format, !o->report.empty(), o->given, site);
        std::lock_guard<std::mutex> lock(mutex);
        results[i] = std::move(outcome);
        ready.notify_one();
      }
    };
    std::vector<std::thread> workers;
    for (unsigned k = 0; k < std::min<std::size_t>(o->jobs, jobs.size()); ++k) workers.emplace_back(work);

    // Print in input order as results arrive; a progress line on a terminal.
    const bool progress = isatty(STDERR_FILENO) && jobs.size() > 1;
    auto last_progress = std::chrono::steady_clock::now();
    std::size_t failed = 0;
    std::vector<BatchLine> printed;
    printed.reserve(jobs.size());
    std::size_t file_width = 4;
    for (const Job& j : jobs) file_width = std::max(file_width, j.shown().size());
    if (o->format == "csv") std::cout << batch_csv_header();
    if (o->format == "table") std::cout << batch_table_header(file_width);
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      BatchLine line;
      {
        std::unique_lock<std::mutex> lock(mutex);
        ready.wait(lock, [&] { return results[i].has_value(); });
        line = std::move(results[i]->line);
        if (!o->report.empty()) entries.push_back(std::move(results[i]->entry));
      }
      failed += !line.ok;
      if (format == BatchFormat::table) {
        const std::string name = jobs[i].shown();
        std::cout << name << std::string(file_width + 2 - name.size(), ' ') << line.text << "\n";
      } else {
        std::cout << line.text << (format == BatchFormat::jsonl ? "\n" : "");
      }
      printed.push_back(std::move(line));
      const auto now = std::chrono::steady_clock::now();
      if (progress && (now - last_progress > std::chrono::milliseconds(100) || i + 1 == jobs.size())) {
        last_progress = now;
        const std::size_t done = i + 1, width = 30, filled = width * done / jobs.size();
        std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << done << "/"
                  << jobs.size() << " scenes, " << failed << " failed" << std::flush;
      }
    }
    for (auto& w : workers) w.join();
    if (progress) std::cerr << "\n";
    const ClassSummary summary = summarise_class(printed);
    std::cout << (o->format == "csv"     ? batch_class_csv(summary)
                  : o->format == "table" ? batch_class_table(summary)
                                         : batch_class_json(summary) + "\n");
    if (!o->report.empty()) write_output(o->report, report::class_report_html(entries));
    return failed ? 1 : 0;
  }};
}

}  // namespace pendulum::cli
