#pragma once
// Reading the bundled scene files in tests.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace pendulum::test {

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A new empty directory in the temporary directory, named `stem` and six
/// random characters: two test runs at once (two clones on one machine) do
/// not share it.
inline std::string new_temporary_directory(const std::string& stem) {
  std::string name = (std::filesystem::temp_directory_path() / (stem + "-XXXXXX")).string();
  if (!mkdtemp(name.data())) throw std::runtime_error("cannot make a directory " + name);
  return name;
}

/// What a command prints on stdout; `status` gets its exit status.
inline std::string command_output(const std::string& command, int& status) {
  std::string text;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) {
    status = -1;
    return text;
  }
  char buffer[4096];
  while (const std::size_t k = std::fread(buffer, 1, sizeof buffer, pipe)) text.append(buffer, k);
  status = pclose(pipe);
  return text;
}

inline std::string nelson_olsson_text() {
  return read_text(std::string(PENDULUM_DATA_DIR) + "/nelson_olsson_1986.json");
}

}  // namespace pendulum::test
