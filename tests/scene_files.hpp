#pragma once
// Reading the bundled scene files in tests.
#include <fstream>
#include <sstream>
#include <string>

namespace pendulum::test {

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::string nelson_olsson_text() {
  return read_text(std::string(PENDULUM_DATA_DIR) + "/nelson_olsson_1986.json");
}

}  // namespace pendulum::test
