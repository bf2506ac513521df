#pragma once
/// \file output_files.hpp
/// \brief Writing the files pendulum-g writes (docs/robustness.md, "Files"):
/// whole or not at all, never over one of its inputs.

#include <stdexcept>
#include <string>
#include <vector>

namespace pendulum {

/// An output that could not be written: what() is "cannot write NAME: reason"
/// (the CLI's exit status 5).
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Arguments that make no sense together (an output that is an input): the
/// CLI's exit status 2, as for its argument parser's errors.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Throws UsageError when `output` (not "-") is, by device and inode, one of
/// `inputs`: `report x.json -o x.json`, or through a link; "-" is standard
/// input's file (`report - -o x.json < x.json`).
void refuse_output_over_inputs(const std::string& output, const std::vector<std::string>& inputs);

/// Writes `text` to `path` ("-": standard output): a regular file through a
/// temporary file renamed over it, so that a failure leaves no partial file;
/// a device or pipe (/dev/stdout) in place. Throws OutputError.
void write_output(const std::string& path, const std::string& text);

}  // namespace pendulum
