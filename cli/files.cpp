// The CLI's files and standard streams (docs/robustness.md, "Files"): the
// scene read within one limit and without waiting, standard streams guarded;
// outputs are written by lib/src/io/output_files.cpp.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>

#include "commands.hpp"
#include "pendulum/files.hpp"
#include "pendulum/json/scene_json.hpp"

namespace pendulum::cli {

std::string read_input(const std::string& file, const SceneFiles& given) {
  return read_text(file, given.limits.applied_to(kSceneInput), "a scene file");
}

SceneFiles scene_files(const std::string& file, const SceneFiles& given) {
  SceneFiles files = given;
  files.directory = scene_directory(file);
  return files;
}

void add_scene_file_options(CLI::App& cmd, SceneFiles& given) {
  cmd.add_flag("--allow-outside", given.allow_outside,
               "Read recordings the scene names outside its own folder (an absolute name, .., a link leading "
               "out); by default they are refused, so that a scene reads nothing else (docs/robustness.md)");
  add_limit_options(cmd, given.limits);
}

void add_limit_options(CLI::App& cmd, GivenLimits& given) {
  cmd.add_option("--max-bytes", given.bytes,
                 "Raise the most bytes read of every input to this (defaults: a scene, a list or standard input "
                 "1 MiB; a table 256 MiB; a recording 1 GiB; a lower value lowers none)")
      ->check(whole_number())
      ->check(CLI::PositiveNumber);
  cmd.add_option("--max-rows", given.rows,
                 "Raise the most rows read of every table and recording to this (defaults: a table 10000; a "
                 "recording 16777216)")
      ->check(whole_number())
      ->check(CLI::PositiveNumber);
  cmd.add_option("--max-columns", given.columns,
                 "Raise the most columns read of every table and recording to this (defaults: a table 256; a "
                 "recording 1024)")
      ->check(whole_number())
      ->check(CLI::PositiveNumber);
}

void guard_standard_streams() {
  // A closed descriptor 0, 1 or 2 would be the next file opened, and what
  // is printed would go into that file. /dev/null opened the other way
  // round takes its place, so that reading stdin or writing stdout fails
  // with EBADF, named as such; stderr's is written to (and lost).
  const int flags[] = {O_WRONLY, O_RDONLY, O_WRONLY};
  for (int fd = 0; fd < 3; ++fd) {
    if (::fcntl(fd, F_GETFD) == -1 && errno == EBADF && ::open("/dev/null", flags[fd]) != fd) std::_Exit(kExitOutput);
  }
}

std::string standard_output_error() {
  std::cout.flush();
  if (std::cout && !std::ferror(stdout) && std::fflush(stdout) == 0) return "";
  // The stream keeps no errno: writing what is left again says why.
  errno = 0;
  std::clearerr(stdout);
  const bool failed = std::fflush(stdout) != 0 || std::fputc('\n', stdout) == EOF || std::fflush(stdout) != 0;
  return failed && errno ? std::strerror(errno) : "the output stream failed";
}

}  // namespace pendulum::cli
