#pragma once
// Running the pendulum-g binary from a CLI test (tests/test_cli.cpp,
// tests/test_cli_swings.cpp): its exit status, stdout and stderr.
#include <catch2/catch.hpp>

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

}  // namespace
