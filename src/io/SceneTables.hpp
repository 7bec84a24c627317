#pragma once
// Inside og_io only: the TOML/JSON plumbing that scene files (io/SceneFile.hpp) and camera
// paths (io/CameraPath.hpp) share, driven by the scene schema (io/SceneSchema.hpp). JSON is
// read by converting it to a TOML table, so one reader checks both forms.
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include "io/SceneFile.hpp"

namespace og::io::detail {

/// "FILE:LINE: " for TOML; JSON-built nodes have no source position, so just "FILE: ".
std::string at(const std::filesystem::path& file, toml::source_index line);
std::string where(const std::filesystem::path& file, const toml::node& n);

/// The value of `n` (named `key` in messages); og::InputError "FILE:LINE: 'key' must be ...".
double number(const std::filesystem::path& file, const toml::node& n, const std::string& key);
std::int64_t integer(const std::filesystem::path& file, const toml::node& n, const std::string& key,
                     std::int64_t lo, std::int64_t hi);
std::string text(const std::filesystem::path& file, const toml::node& n, const std::string& key);
const toml::table& tableOf(const std::filesystem::path& file, const toml::node& n, const std::string& name);

using Setter = std::function<void(const toml::node&, const std::string&)>;
/// Calls the setter of each key of `table`; unknown keys are errors naming `section`.
void applyKeys(const std::filesystem::path& file, const toml::table& table, const std::string& section,
               const std::map<std::string, Setter>& keys);

/// A TOML file, or a JSON file (by its extension) as the same table. Throws og::InputError.
toml::table parseTomlOrJson(const std::filesystem::path& file);
/// TOML text from line `firstLine` of `file` on (e.g. embedded in a KML tour).
toml::table parseTomlText(const std::string& text, const std::filesystem::path& file, int firstLine);

enum class SceneForm {
  File,       ///< a scene file: [camera], [sun], [image], ... at the top
  PathScene,  ///< a path's [scene]: the same tables one level down (no camera), or the flat
              ///< keys older path files used (time, width, ocean_model, wind_layers, ...)
};
/// Reads the settings in `table` over `s` by the scene schema (types and ranges checked, the
/// scene as a whole not: see validateScene). Throws og::InputError "FILE:LINE: problem".
void readSceneTables(const std::filesystem::path& file, const toml::table& table, SceneSettings& s,
                     SceneForm form);

/// The scene as JSON objects by section (as sceneToml writes TOML).
nlohmann::json sceneJson(const SceneSettings& s, bool withCamera);

/// A double in its shortest exact decimal form (TOML reads "1e+07" as a float).
std::string tomlNumber(double v);
/// A TOML basic string, quoted and escaped.
std::string tomlString(const std::string& v);

/// Writes `text` to `file` through a temporary file. Throws og::InputError.
void writeTextFile(const std::filesystem::path& file, const std::string& text);

}  // namespace og::io::detail
