#pragma once
// Running the pendulum-g binary from a CLI test (tests/test_cli*.cpp): its
// exit status, stdout and stderr, and what several of those tests read of
// its output.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "scene_files.hpp"

namespace {

struct Run {
  int status;
  std::string out;
  std::string err;
};

// A new empty file in the temporary directory.
std::string temporary_file() {
  char name[] = "/tmp/pendulum-g-test-XXXXXX";
  const int fd = mkstemp(name);
  REQUIRE(fd >= 0);
  close(fd);
  return name;
}

// Runs pendulum-g with `args` (shell words) and captures everything.
Run run(const std::string& args) {
  const std::string err_file = temporary_file();
  const std::string command = std::string(PENDULUM_G_EXE) + " " + args + " 2>" + err_file;
  FILE* pipe = popen(command.c_str(), "r");
  REQUIRE(pipe);
  std::string out;
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
  const int raw = pclose(pipe);
  Run r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out, pendulum::test::read_text(err_file)};
  std::remove(err_file.c_str());
  return r;
}

// The bundled scene of Nelson & Olsson (1986).
const std::string kNelsonOlsson = std::string(PENDULUM_DATA_DIR) + "/nelson_olsson_1986.json";

inline const nlohmann::json& correction(const nlohmann::json& result, const std::string& id) {
  for (const auto& c : result.at("corrections")) {
    if (c.at("id") == id) return c;
  }
  FAIL("no correction " << id);
  throw;
}

// What in a page would load something from elsewhere: a scheme, a
// protocol-relative "//", a src, a CSS url() or @import, an element that
// fetches, or a link that leaves the page. Returns the first found, or "".
inline std::string external_reference(const std::string& page) {
  for (const char* bad : {"http:", "https:", "ftp:", "file://", "//", "src=", "srcset", "url(", "@import", "<link",
                          "<script", "<iframe", "<object", "<embed", "<img", "<base"}) {
    if (page.find(bad) != std::string::npos) return bad;
  }
  for (std::size_t at = page.find("href="); at != std::string::npos; at = page.find("href=", at + 1)) {
    if (page.compare(at, 7, "href=\"#") != 0) return page.substr(at, 20);
  }
  return "";
}

inline std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A new empty directory for a test's output.
inline std::string temporary_directory() {
  char name[] = "/tmp/pendulum-g-report-XXXXXX";
  REQUIRE(mkdtemp(name));
  return name;
}

}  // namespace
