// The scenes of `pendulum-g batch` (pendulum/batch.hpp).
#include "pendulum/batch.hpp"

#include <algorithm>
#include <cctype>
#include <exception>
#include <filesystem>
#include <tuple>

#include "pendulum/files.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/reduce_scene.hpp"
#include "pendulum/json/scene_json.hpp"
#include "text.hpp"

namespace pendulum {
namespace {

/// ".json" in any case: CLARK.JSON is a scene too.
bool json_extension(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e == ".json";
}

}  // namespace

std::string BatchScene::shown() const { return printable_name(name); }

std::vector<std::string> folder_scenes(const std::string& folder, std::vector<SkippedEntry>& skipped) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<std::string> files;
  std::vector<SkippedEntry> found;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const fs::path& f = entry.path();
    if (entry.is_directory(ec)) {
      found.push_back({f.string(), "a folder (batch reads one level; name it to reduce its scenes)"});
    } else if (!json_extension(f)) {
      found.push_back({f.string(), json_extension(f.stem()) ? "not a .json file; rename it to " +
                                                                   f.stem().filename().string() + " to reduce it"
                                                             : std::string("not a .json file")});
    } else if (entry.is_symlink(ec) && !fs::exists(entry.status(ec))) {
      found.push_back({f.string(), "a symbolic link to nothing (" + printable_name(fs::read_symlink(f, ec).string()) + ")"});
    } else if (!entry.is_regular_file(ec)) {
      // A named pipe would block the reader forever, a device feed it junk.
      found.push_back({f.string(), "not a regular file (a named pipe, a device or a socket)"});
    } else {
      files.push_back(f.string());
    }
  }
  std::sort(files.begin(), files.end());
  std::sort(found.begin(), found.end(),
            [](const SkippedEntry& a, const SkippedEntry& b) { return std::tie(a.path, a.why) < std::tie(b.path, b.why); });
  for (auto& s : found) skipped.push_back(std::move(s));
  return files;
}

SceneFiles BatchScene::files(const SceneFiles& given) const {
  SceneFiles files = given;
  files.directory = text ? "." : scene_directory(name);
  return files;
}

BatchOutcome reduce_batch_scene(const BatchScene& job, const AnalysisOptions& options, BatchFormat format,
                                bool with_report, const SceneFiles& given, const std::optional<Site>& site) {
  const std::string name = job.shown();
  try {
    ParsedScene scene =
        parse_scene(job.text ? *job.text : read_text(job.name, given.limits.applied_to(kSceneInput), "a scene file"),
                    job.files(given));
    if (site && !scene.site) {
      scene.site = site;
      scene.assumptions.push_back("site: not given; the class's (batch --site): latitude " +
                                  format_number(*site->latitude_deg) + " deg, " + format_number(*site->height) +
                                  " m above sea level");
    }
    const Analysis analysis = reduce_scene(scene, options);
    BatchOutcome out{batch_line(name, scene, analysis, format), {name, std::nullopt, ""}};
    if (with_report) out.entry.report = report::make_scene_report(name, scene, analysis);
    return out;
  } catch (const InputError& e) {
    return {batch_failure(name, e.what(), format), {name, std::nullopt, e.what()}};
  } catch (const std::exception& e) {
    const std::string error = std::string("internal error: ") + e.what();
    return {batch_failure(name, error, format), {name, std::nullopt, error}};
  }
}

}  // namespace pendulum
