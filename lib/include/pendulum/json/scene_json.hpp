#pragma once
/// \file json/scene_json.hpp
/// \brief Reading a scene file (docs/scene.md) into a ParsedScene in SI units.
///
/// Validation happens here, once, at the edge: every error names the JSON
/// path, the value found and what was expected (InputError).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pendulum/files.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/parsed_scene.hpp"

namespace pendulum {

/// Where the files a scene names (a recording in `timing` or `decay.data`,
/// docs/recordings.md) are looked for.
struct SceneFiles {
  /// The directory a relative name is resolved against: the scene file's
  /// (scene_directory()). Without it, a scene that names a file is refused:
  /// parsing text opens no file unless the caller says where from (the
  /// fuzzer parses arbitrary text and passes none).
  std::optional<std::string> directory;
  /// Whether a name may lead out of `directory` (absolute, "..", a symbolic
  /// link pointing out): refused by default, so that a scene reads no file
  /// but its own recordings (docs/robustness.md, "Recordings a scene names").
  bool allow_outside = false;
  /// --max-bytes, --max-rows, --max-columns: the limits of the scene's text
  /// and of every file it names (docs/robustness.md, "Limits").
  GivenLimits limits{};
};

/// The directory of the scene file at `path`: "." for "-" (standard input)
/// and for a bare file name.
std::string scene_directory(const std::string& path);

/// The files the scene text names (its recordings and its table of
/// settings), as parse_scene() would open them, without opening any: so that
/// an output over one of them is refused before anything is read. None when
/// the text is no JSON or `files` has no directory (parse_scene says why).
std::vector<std::string> scene_file_names(const std::string& text, const SceneFiles& files);

/// Parses and validates scene JSON text. Throws InputError.
ParsedScene parse_scene(const std::string& text, const SceneFiles& files = {});

/// A whole scene, or a document holding only a decay record: `decay` (with
/// `data`) and the free-text keys (schema, title, source, notes), what
/// `fit-decay` reads. The latter has no observations. Throws InputError.
ParsedScene parse_decay_document(const std::string& text, const SceneFiles& files = {});

}  // namespace pendulum
