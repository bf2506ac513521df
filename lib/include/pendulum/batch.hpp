#pragma once
/// \file batch.hpp
/// \brief The scenes of `pendulum-g batch` (docs/instructors.md): a folder's
/// scene files, and one scene reduced to its summary line without throwing.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pendulum/analysis.hpp"
#include "pendulum/json/output.hpp"
#include "pendulum/report/html_report.hpp"
#include "pendulum/site.hpp"
#include "pendulum/json/scene_json.hpp"

namespace pendulum {

/// One scene of a batch: a file to read, or a document of standard input.
struct BatchScene {
  std::string name;                 ///< as given: the file opened ("stdin:N" for standard input)
  std::optional<std::string> text;  ///< set for standard input
  /// `name` as printed (printable_name(): escaped, and distinct for
  /// distinct names).
  std::string shown() const;
  /// Where the files the scene names are looked for: the file's folder, the
  /// working folder for standard input; `given`'s allow_outside and limits.
  SceneFiles files(const SceneFiles& given) const;
};

/// An entry of a folder that is no scene, and why (a subfolder, a file not
/// named .json, a link to nothing, a named pipe).
struct SkippedEntry {
  std::string path;
  std::string why;
};

/// The scene files of `folder` (one level; *.json in any case), sorted by
/// name, each named folder/file; the other entries into `skipped`, sorted.
std::vector<std::string> folder_scenes(const std::string& folder, std::vector<SkippedEntry>& skipped);

/// One scene's summary line in `format` and, when `with_report`, its report;
/// an error (InputError, or any other as "internal error: ...") becomes the
/// failure's line. Never throws. A scene of standard input looks for its
/// recordings in the current folder. `given`: allow_outside and the limits
/// (its directory is each scene's own). `site`: where a scene that names
/// none was measured (batch --site, a class's lab); a scene's own wins.
struct BatchOutcome {
  BatchLine line;
  report::ClassEntry entry;
};
BatchOutcome reduce_batch_scene(const BatchScene& scene, const AnalysisOptions& options, BatchFormat format,
                                bool with_report, const SceneFiles& given, const std::optional<Site>& site = std::nullopt);

}  // namespace pendulum
