#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "commands.hpp"
#include "pendulum/analysis.hpp"
#include "pendulum/output.hpp"
#include "pendulum/report/html_report.hpp"
#include "pendulum/scene_json.hpp"

namespace pendulum::cli {
namespace {

/// One scene of the batch: a file to read, or a line of standard input.
struct Job {
  std::string name;
  std::optional<std::string> text;  ///< set for standard input
};

std::vector<Job> gather(const std::vector<std::string>& paths, const std::string& list) {
  std::vector<Job> jobs;
  auto add_path = [&](const std::string& p) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      std::vector<std::string> files;
      for (const auto& entry : fs::directory_iterator(p, ec)) {
        if (entry.path().extension() != ".json") continue;
        // A named pipe would block the reader forever, a device feed it junk.
        if (!entry.is_regular_file(ec)) {
          std::cerr << "pendulum-g: note: skipping " << entry.path().string()
                    << ": not a regular file (a named pipe, a device or a socket)\n";
          continue;
        }
        files.push_back(entry.path().string());
      }
      std::sort(files.begin(), files.end());
      for (auto& f : files) jobs.push_back({std::move(f), std::nullopt});
    } else {
      jobs.push_back({p, std::nullopt});
    }
  };
  for (const auto& p : paths) {
    if (p != "-") {
      add_path(p);
      continue;
    }
    std::string line;
    for (int n = 1; std::getline(std::cin, line); ++n) {
      if (line.find_first_not_of(" \t\r") != std::string::npos) jobs.push_back({"stdin:" + std::to_string(n), line});
    }
  }
  if (!list.empty()) {
    std::ifstream in(list);
    if (!in) throw InputError("", "cannot open the list " + list);
    std::string line;
    while (std::getline(in, line)) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (!line.empty() && line[0] != '#') add_path(line);
    }
  }
  return jobs;
}

/// The summary line of one scene and, for --report, its report; never throws.
struct Outcome {
  BatchLine line;
  report::ClassEntry entry;
};
Outcome process(const Job& job, const AnalysisOptions& options, bool with_report) {
  try {
    const ParsedScene scene = parse_scene(job.text ? *job.text : read_input(job.name));
    const Analysis analysis = analyse(scene, options);
    Outcome out{batch_line(job.name, scene, analysis), {job.name, std::nullopt, ""}};
    if (with_report) out.entry.report = report::make_scene_report(job.name, scene, analysis);
    return out;
  } catch (const InputError& e) {
    return {batch_failure(job.name, e.what()), {job.name, std::nullopt, e.what()}};
  } catch (const std::exception& e) {
    const std::string error = std::string("internal error: ") + e.what();
    return {batch_failure(job.name, error), {job.name, std::nullopt, error}};
  }
}

}  // namespace

Command add_batch_command(CLI::App& app) {
  struct Options {
    std::vector<std::string> paths;
    std::string list;
    std::string format = "jsonl";
    std::string report;
    unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "batch", "Reduce many scenes (files, folders of *.json, a list, or JSON lines on stdin) to one summary");
  cmd->add_option("scenes", o->paths, "Scene files, folders, or - for one scene per line of standard input");
  cmd->add_option("--list", o->list, "A file naming one scene file per line (# starts a comment)");
  cmd->add_option("--format", o->format, "Summary: jsonl (default, one JSON object per scene) or csv")
      ->check(CLI::IsMember({"jsonl", "csv"}));
  cmd->add_option("--report", o->report,
                  "Also write an HTML class report to this file: every g against the expected g, the failures, "
                  "each scene's section");
  cmd->add_option("--jobs", o->jobs, "Scenes reduced at once (default: the number of cores)")
      ->check(CLI::Range(1u, 256u));

  return {cmd, [o] {
    const std::vector<Job> jobs = gather(o->paths, o->list);
    if (jobs.empty()) throw InputError("", "no scenes: give files, folders, --list, or - for standard input");
    const AnalysisOptions options;
    std::vector<std::optional<Outcome>> results(jobs.size());
    std::vector<report::ClassEntry> entries;
    std::mutex mutex;
    std::condition_variable ready;
    std::atomic<std::size_t> next{0};
    auto work = [&] {
      for (std::size_t i = next++; i < jobs.size(); i = next++) {
        auto outcome = process(jobs[i], options, !o->report.empty());
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
    if (o->format == "csv") std::cout << batch_csv_header();
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      BatchLine line;
      {
        std::unique_lock<std::mutex> lock(mutex);
        ready.wait(lock, [&] { return results[i].has_value(); });
        line = std::move(results[i]->line);
        if (!o->report.empty()) entries.push_back(std::move(results[i]->entry));
      }
      failed += !line.ok;
      std::cout << (o->format == "csv" ? line.csv : line.json + "\n");
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
    if (!o->report.empty()) write_output(o->report, report::class_report_html(entries));
    return failed ? 1 : 0;
  }};
}

}  // namespace pendulum::cli
