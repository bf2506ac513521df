#pragma once
/// \file scene_json.hpp
/// \brief Reading a scene file (docs/scene.md) into a Scene in SI units.
///
/// Validation happens here, once, at the edge: every error names the JSON
/// path, the value found and what was expected.

#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "pendulum/decay_fit.hpp"
#include "pendulum/scene.hpp"
#include "pendulum/site.hpp"

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

/// A scene as read from its file.
struct ParsedScene {
  Scene<double> value;        ///< SI values
  Scene<double> uncertainty;  ///< same shape; 0 where the file states none
  std::map<std::string, std::string> si_unit;  ///< JSON path -> SI unit
  std::string title;
  std::string source;
  int trial_count = 0;
  /// A decay record to fit alpha and beta from (decay.data); the fit
  /// replaces any alpha and beta given beside it.
  std::optional<DecayData> decay_data;
  /// Where the experiment was done, to compare g with.
  std::optional<Site> site;
  std::vector<std::string> assumptions;  ///< defaults the reduction used
  std::vector<std::string> warnings;     ///< legal but suspicious input
};

/// The largest scene text accepted (1 MiB): a scene is a few kB, and a
/// bound keeps a wrong file (a log, /dev/zero) from eating the memory.
inline constexpr std::size_t kMaxSceneBytes = std::size_t{1} << 20;

/// Parses and validates scene JSON text. Throws InputError.
ParsedScene parse_scene(const std::string& text);

}  // namespace pendulum
