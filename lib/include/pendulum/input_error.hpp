#pragma once
/// \file input_error.hpp
/// \brief The error every reader and check throws for bad input.

#include <stdexcept>
#include <string>

namespace pendulum {

/// Bad input: `path` is the JSON path ("bob.diameter.unit", "timing.trials[3]",
/// or "" for the whole document); what() is "path: message".
class InputError : public std::runtime_error {
 public:
  InputError(std::string path, const std::string& message);
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace pendulum
