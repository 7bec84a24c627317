#pragma once
// The scene schema: every scene setting once, with where it lives in a scene file
// ([section] key), its unit and its valid range. It drives the reading, writing and validation
// of scene files (io/SceneFile.hpp) and of the [scene] table of camera paths
// (io/CameraPath.hpp): a path's [scene] holds the same tables as a scene file, one level down
// ([scene.image] width = ...), camera excepted (the keyframes give it).
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "io/SceneFile.hpp"

namespace og::io {

/// Samples per pixel: 0 = auto (4 on a GPU, 1 on a software renderer), else 1, 2, 4 or 8.
/// The one list of valid counts (flags, scene files, paths and the renderer check with it).
inline constexpr int kAutoSamples = 0;
[[nodiscard]] constexpr bool isValidSampleCount(int n) {
  return n == kAutoSamples || n == 1 || n == 2 || n == 4 || n == 8;
}
/// "auto", "1", "2", "4" or "8" as a sample count; nullopt for anything else.
std::optional<int> parseSampleCount(std::string_view text);
/// How the valid sample counts read in messages.
inline constexpr std::string_view kSampleCountChoices = "\"auto\", 1, 2, 4 or 8";

enum class FieldType {
  Number,    ///< a finite double
  Integer,   ///< a whole number
  Text,      ///< a string (from `choices` when given)
  TextList,  ///< an array of strings
  Triple,    ///< an array of 3 numbers (RGB)
  Time,      ///< an ISO-8601 UTC time string
  Samples,   ///< "auto" or 1, 2, 4, 8 (held as an integer, 0 = auto)
};

/// One value as read from or written to a file; monostate = an optional setting not given.
using FieldValue =
    std::variant<std::monostate, double, std::int64_t, std::string, std::vector<std::string>, glm::dvec3>;

struct SceneField {
  std::string_view section;  ///< scene-file table: camera sun image ocean layers gl atmosphere
  std::string_view key;      ///< key in that table (unit in the name)
  FieldType type = FieldType::Number;
  std::string_view unit;     ///< for messages and docs: "deg", "m", "m/s", "s", "px", "" ...
  std::string_view label;    ///< in messages about a flag or setting: "wind speed"
  double min = -std::numeric_limits<double>::infinity();  ///< valid range of numbers, integers
  double max = std::numeric_limits<double>::infinity();   ///< and each triple component
  bool minOpen = false;                 ///< min itself is not allowed
  std::vector<std::string_view> choices;  ///< Text: the values allowed (empty = any)
  std::vector<std::string_view> aliases;  ///< older keys in the same table, still read
  std::string_view legacyPathKey;  ///< the flat key older path files used in [scene], or ""
  std::function<FieldValue(const SceneSettings&)> get;
  std::function<void(SceneSettings&, const FieldValue&)> set;
};

/// Every scene setting, in the order files are written.
const std::vector<SceneField>& sceneSchema();

/// What is wrong with `value` for `field`, or nullopt. `value` has the field's C++ type
/// (double, int64, string, string list, dvec3). Messages start with "'key'" when `byKey`
/// (a file), else with the field's label (a flag or a setting).
std::optional<std::string> checkField(const SceneField& field, const FieldValue& value, bool byKey);

/// The scene as TOML tables ("[PREFIXsection]" then "key = value" lines, numbers in their
/// shortest exact decimal form): every setting, optional ones only when given, [camera] only
/// `withCamera`, [atmosphere] only where it differs from Earth's defaults.
std::string sceneToml(const SceneSettings& scene, std::string_view tablePrefix, bool withCamera);

}  // namespace og::io
