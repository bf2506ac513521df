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
#include "pendulum/result_json.hpp"
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

/// The summary line of one scene; never throws.
nlohmann::ordered_json process(const Job& job, const AnalysisOptions& options) {
  try {
    const ParsedScene scene = parse_scene(job.text ? *job.text : read_input(job.name));
    return batch_summary(job.name, scene, analyse(scene, options));
  } catch (const InputError& e) {
    return batch_failure(job.name, e.what());
  } catch (const std::exception& e) {
    return batch_failure(job.name, std::string("internal error: ") + e.what());
  }
}

}  // namespace

Command add_batch_command(CLI::App& app) {
  struct Options {
    std::vector<std::string> paths;
    std::string list;
    std::string format = "jsonl";
    unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "batch", "Reduce many scenes (files, folders of *.json, a list, or JSON lines on stdin) to one summary");
  cmd->add_option("scenes", o->paths, "Scene files, folders, or - for one scene per line of standard input");
  cmd->add_option("--list", o->list, "A file naming one scene file per line (# starts a comment)");
  cmd->add_option("--format", o->format, "Summary: jsonl (default, one JSON object per scene) or csv")
      ->check(CLI::IsMember({"jsonl", "csv"}));
  cmd->add_option("--jobs", o->jobs, "Scenes reduced at once (default: the number of cores)")
      ->check(CLI::Range(1u, 256u));

  return {cmd, [o] {
    const std::vector<Job> jobs = gather(o->paths, o->list);
    if (jobs.empty()) throw InputError("", "no scenes: give files, folders, --list, or - for standard input");
    const AnalysisOptions options;
    std::vector<std::optional<nlohmann::ordered_json>> results(jobs.size());
    std::mutex mutex;
    std::condition_variable ready;
    std::atomic<std::size_t> next{0};
    auto work = [&] {
      for (std::size_t i = next++; i < jobs.size(); i = next++) {
        auto line = process(jobs[i], options);
        std::lock_guard<std::mutex> lock(mutex);
        results[i] = std::move(line);
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
      nlohmann::ordered_json line;
      {
        std::unique_lock<std::mutex> lock(mutex);
        ready.wait(lock, [&] { return results[i].has_value(); });
        line = std::move(*results[i]);
      }
      failed += !line.at("ok").get<bool>();
      std::cout << (o->format == "csv" ? batch_csv_row(line) : json_text(line, -1) + "\n");
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
    return failed ? 1 : 0;
  }};
}

}  // namespace pendulum::cli
