#pragma once
// What every libFuzzer target checks: a failed check aborts (a finding),
// and bad input ends in one printable line.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "pendulum/input_error.hpp"

namespace pendulum::fuzz {

inline void require(bool ok, const char* what, const std::string& detail) {
  if (ok) return;
  std::fprintf(stderr, "fuzz: %s: %s\n", what, detail.c_str());
  std::abort();
}

/// Bad input ends in one printable line of at most 1000 characters.
inline void require_clear_message(const InputError& e) {
  const std::string message = e.what();
  for (const char c : message) {
    require(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f, "control character in an error message", message);
  }
  require(message.size() <= 1000, "error message over 1000 characters", message.substr(0, 200));
}

}  // namespace pendulum::fuzz
