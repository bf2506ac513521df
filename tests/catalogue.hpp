#pragma once
// The scene catalogues (tests/bad_scenes.json, tests/valid_scenes.json): each
// case is a raw `text`, or a whole `scene`, or the Nelson-Olsson scene (or the
// file of data/ named by `base`) with an RFC 7386 merge `patch`, then optionally
// - `fill`: the array at the JSON pointer `fill.pointer` made of `fill.count`
//   copies of `fill.value` (a file too large to write out);
// - `splice`: {"PLACEHOLDER": "raw text"}: the string "PLACEHOLDER" in the
//   scene replaced by raw text that a JSON value cannot hold (1e400, -0, a
//   key given twice).
// Then "${PENDULUM_DATA_DIR}" and "${PENDULUM_TESTS_DIR}" become those
// directories: a recording a case names (docs/recordings.md) by absolute path,
// since the scene is written to a temporary file.
// Read by the CLI tests and by the fuzzer's seed writer.
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene_files.hpp"

namespace pendulum::test {

/// The scene text of one catalogue case; `base` is the scene patches apply to.
inline std::string catalogue_text(const nlohmann::json& entry, const nlohmann::json& base) {
  if (entry.contains("text")) return entry.at("text").get<std::string>();
  nlohmann::json scene = entry.contains("base")
                             ? nlohmann::json::parse(read_text(std::string(PENDULUM_DATA_DIR) + "/" +
                                                               entry.at("base").get<std::string>()))
                             : entry.value("scene", base);
  if (entry.contains("patch")) scene.merge_patch(entry.at("patch"));
  if (entry.contains("fill")) {
    const nlohmann::json& fill = entry.at("fill");
    scene[nlohmann::json::json_pointer(fill.at("pointer").get<std::string>())] =
        nlohmann::json(fill.at("count").get<std::size_t>(), fill.at("value"));
  }
  std::string text = scene.dump();
  const nlohmann::json splice = entry.value("splice", nlohmann::json::object());
  for (const auto& [placeholder, raw] : splice.items()) {
    const std::string quoted = nlohmann::json(placeholder).dump();
    text.replace(text.find(quoted), quoted.size(), raw.get<std::string>());
  }
  const std::pair<std::string, std::string> directories[] = {
    {"${PENDULUM_DATA_DIR}", PENDULUM_DATA_DIR},
#ifdef PENDULUM_TESTS_DIR
    {"${PENDULUM_TESTS_DIR}", PENDULUM_TESTS_DIR},
#endif
  };
  for (const auto& [name, directory] : directories) {
    for (auto at = text.find(name); at != std::string::npos; at = text.find(name, at)) text.replace(at, name.size(), directory);
  }
  return text;
}

#ifdef PENDULUM_TESTS_DIR
/// Nelson & Olsson's scene and every case of tests/valid_scenes.json, as
/// text: scenes of every kind, with every part and correction between them.
/// Their recordings are named by absolute path (parse with allow_outside).
inline std::vector<std::string> valid_scene_texts() {
  const nlohmann::json base = nlohmann::json::parse(nelson_olsson_text());
  const nlohmann::json catalogue =
      nlohmann::json::parse(read_text(std::string(PENDULUM_TESTS_DIR) + "/valid_scenes.json"));
  std::vector<std::string> out{nelson_olsson_text()};
  for (const nlohmann::json& entry : catalogue.at("cases")) out.push_back(catalogue_text(entry, base));
  return out;
}
#endif

/// Whether a message prints a NaN ("nan", "-nan", as printf writes one): a
/// number computed from nothing, which no message may show (issue 42). The
/// word "NaN" (a cell that marks a missing sample) is no number printed.
inline bool says_nan(const std::string& message) {
  static const std::regex nan("(^|[^A-Za-z])nan([^A-Za-z]|$)");
  return std::regex_search(message, nan);
}

}  // namespace pendulum::test
