#include "io/CameraPath.hpp"

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"

namespace og::io {
namespace fs = std::filesystem;
namespace {

// "FILE:LINE: " for TOML; JSON-built nodes have no source position, so just "FILE: ".
std::string at(const fs::path& file, toml::source_index line) {
  std::string s = file.string();
  if (line > 0) s.append(":").append(std::to_string(line));  // (not ":" + ...: GCC 12 -Wrestrict)
  return s.append(": ");
}
std::string where(const fs::path& file, const toml::node& n) { return at(file, n.source().begin.line); }

std::string decimal(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

double number(const fs::path& file, const toml::node& n, const std::string& key) {
  if (auto v = n.value<double>(); v && n.is_number()) {
    if (!std::isfinite(*v)) throw InputError(where(file, n) + "'" + key + "' must be finite");
    return *v;
  }
  throw InputError(where(file, n) + "'" + key + "' must be a number");
}

std::int64_t integer(const fs::path& file, const toml::node& n, const std::string& key,
                     std::int64_t lo, std::int64_t hi) {
  if (auto v = n.value<std::int64_t>(); v && n.is_integer()) {
    if (*v < lo || *v > hi)
      throw InputError(where(file, n) + "'" + key + "' must be within [" + std::to_string(lo) +
                       ", " + std::to_string(hi) + "]");
    return *v;
  }
  throw InputError(where(file, n) + "'" + key + "' must be an integer");
}

std::string text(const fs::path& file, const toml::node& n, const std::string& key) {
  if (auto v = n.value<std::string>(); v && n.is_string()) return *v;
  throw InputError(where(file, n) + "'" + key + "' must be a string");
}

const toml::table& tableOf(const fs::path& file, const toml::node& n, const std::string& name) {
  const toml::table* t = n.as_table();
  if (t == nullptr) throw InputError(where(file, n) + "'" + name + "' must be a table");
  return *t;
}

using Setter = std::function<void(const toml::node&, const std::string&)>;

// Calls the setter of each key of `table`; unknown keys are errors.
void applyKeys(const fs::path& file, const toml::table& table, const std::string& section,
               const std::map<std::string, Setter>& schema) {
  for (const auto& [key, value] : table) {
    const std::string k(key.str());
    const auto it = schema.find(k);
    if (it == schema.end())
      throw InputError(at(file, key.source().begin.line) + "unknown key '" + k + "' in " + section);
    it->second(value, k);
  }
}

void readScene(const fs::path& file, const toml::table& t, SceneSettings& s) {
  auto num = [&](double& out) -> Setter {
    return [&](const toml::node& n, const std::string& k) { out = number(file, n, k); };
  };
  const std::map<std::string, Setter> schema = {
      {"time",
       [&](const toml::node& n, const std::string& k) {
         const std::string value = text(file, n, k);
         s.time = UtcTime::parseIso8601(value);
         if (!s.time)
           throw InputError(where(file, n) + "'time' is not an ISO-8601 UTC time: '" + value + "'");
       }},
      {"sun_elevation_deg",
       [&](const toml::node& n, const std::string& k) { s.sunElevationDeg = number(file, n, k); }},
      {"sun_azimuth_deg",
       [&](const toml::node& n, const std::string& k) { s.sunAzimuthDeg = number(file, n, k); }},
      {"width",
       [&](const toml::node& n, const std::string& k) {
         s.width = static_cast<int>(integer(file, n, k, 1, 16384));
       }},
      {"height",
       [&](const toml::node& n, const std::string& k) {
         s.height = static_cast<int>(integer(file, n, k, 1, 16384));
       }},
      {"exposure", num(s.exposure)},
      {"samples",  // "auto" or 1, 2, 4, 8 (validateScene refuses the others)
       [&](const toml::node& n, const std::string& k) {
         s.samples = n.is_string() && n.value<std::string>() == "auto"
                         ? 0
                         : static_cast<int>(integer(file, n, k, 1, 8));
       }},
      {"ocean_model", [&](const toml::node& n, const std::string& k) { s.oceanModel = text(file, n, k); }},
      {"wind_speed_ms", num(s.windSpeedMs)},
      {"wind_direction_deg", num(s.windFromDeg)},
      {"wind_layers",
       [&](const toml::node& n, const std::string& k) {
         const toml::array* list = n.as_array();
         if (list == nullptr) throw InputError(where(file, n) + "'" + k + "' must be an array of strings");
         s.windLayers.clear();
         for (const toml::node& item : *list) s.windLayers.push_back(text(file, item, k));
       }},
      {"elevation_layer",
       [&](const toml::node& n, const std::string& k) { s.elevationLayer = text(file, n, k); }},
      {"imagery_layers",
       [&](const toml::node& n, const std::string& k) {
         const toml::array* list = n.as_array();
         if (list == nullptr) throw InputError(where(file, n) + "'" + k + "' must be an array of strings");
         s.imageryLayers.clear();
         for (const toml::node& item : *list) s.imageryLayers.push_back(text(file, item, k));
       }},
  };
  applyKeys(file, t, "[scene]", schema);
  try {
    validateScene(s, "");
  } catch (const InputError& e) {
    throw InputError(where(file, t) + "[scene]: " + e.what());
  }
}

// --- keyframes ------------------------------------------------------------------------------
// A keyframe is a camera (latitude_deg, longitude_deg, height_m, pitch_deg) or a look-at view
// (look_at = {latitude_deg, longitude_deg, height_m}, range_m, tilt_deg); keys left out are kept
// from the keyframe before, and a keyframe with no position keys after a look-at keyframe
// looks at its target too.

/// The keys of one [[keyframe]] table as given (nullptr / false where absent).
struct KeyframeKeys {
  bool lat = false, lon = false, height = false, pitch = false, heading = false;
  const toml::node *time = nullptr, *duration = nullptr, *target = nullptr, *range = nullptr,
                   *tilt = nullptr;
  double timeS = 0, durationS = 0, rangeM = 0, tiltDeg = 0;
};

// The target of a look-at keyframe from its look_at table over the previous target.
void readTarget(const fs::path& file, const toml::node& node, const std::string& name,
                const std::optional<geo::LookAt>& previous, geo::Geodetic& target) {
  const toml::table& t = tableOf(file, node, "look_at");
  bool lat = false, lon = false;
  auto num = [&](double& out, bool* seen) -> Setter {
    return [&out, seen, &file](const toml::node& n, const std::string& k) {
      out = number(file, n, k);
      if (seen != nullptr) *seen = true;
    };
  };
  applyKeys(file, t, name + " look_at",
            {{"latitude_deg", num(target.latitudeDeg, &lat)},
             {"longitude_deg", num(target.longitudeDeg, &lon)},
             {"height_m", num(target.heightM, nullptr)}});
  if (!previous && !(lat && lon))
    throw InputError(where(file, node) + name + ": look_at needs latitude_deg and longitude_deg");
}

// The look-at view of a keyframe, or nullopt for a camera keyframe.
std::optional<geo::LookAt> lookAtOf(const fs::path& file, const toml::table& t, const std::string& name,
                                    const KeyframeKeys& keys, const geo::Keyframe* previous,
                                    double headingDeg) {
  const bool lookAtKeys = keys.target || keys.range || keys.tilt;
  const bool cameraKeys = keys.lat || keys.lon || keys.height || keys.pitch;
  if (lookAtKeys && cameraKeys)
    throw InputError(where(file, t) + name + ": give a camera (latitude_deg, longitude_deg, height_m, "
                     "pitch_deg) or a look-at view (look_at, range_m, tilt_deg), not both");
  const std::optional<geo::LookAt> before = previous ? previous->lookAt : std::nullopt;
  if (!lookAtKeys && !(before && !cameraKeys)) return std::nullopt;
  geo::LookAt v = before.value_or(geo::LookAt{});
  if (!before) v.target.heightM = 0.0;
  if (keys.target) readTarget(file, *keys.target, name, before, v.target);
  else if (!before) throw InputError(where(file, t) + name + ": a look-at keyframe needs look_at = {...}");
  if (keys.range) v.rangeM = keys.rangeM;
  else if (!before) throw InputError(where(file, t) + name + ": a look-at keyframe needs range_m");
  if (keys.tilt) v.tiltDeg = keys.tiltDeg;
  if (keys.heading || !before) v.headingDeg = headingDeg;
  if (auto problem = geo::validateLookAt(v)) throw InputError(where(file, t) + name + ": " + *problem);
  return v;
}

// The keyframe's time from time_s / duration_s after `previous` (nullptr for the first).
double keyframeTime(const fs::path& file, const toml::table& t, const std::string& name,
                    const KeyframeKeys& keys, const geo::Keyframe* previous) {
  if (keys.time != nullptr && keys.duration != nullptr)
    throw InputError(where(file, *keys.duration) + name + ": give time_s or duration_s, not both");
  if (previous == nullptr) {
    if (keys.duration != nullptr)
      throw InputError(where(file, *keys.duration) + name +
                       ": the first keyframe takes time_s (default 0), not duration_s");
    if (keys.timeS < 0.0) throw InputError(where(file, *keys.time) + name + ": time_s must be >= 0");
    return keys.timeS;
  }
  if (keys.time != nullptr) {
    if (!(keys.timeS > previous->timeS))
      throw InputError(where(file, *keys.time) + name + ": keyframes out of order: time_s " + decimal(keys.timeS) +
                       " is not after the previous keyframe's " + decimal(previous->timeS));
    return keys.timeS;
  }
  if (keys.duration != nullptr) {
    if (!(keys.durationS > 0.0))
      throw InputError(where(file, *keys.duration) + name + ": duration_s must be > 0");
    return previous->timeS + keys.durationS;
  }
  throw InputError(where(file, t) + name + ": needs time_s or duration_s");
}

geo::Keyframe readKeyframe(const fs::path& file, const toml::table& t, std::size_t index,
                           const geo::Keyframe* previous) {
  const std::string name = "keyframe " + std::to_string(index);
  geo::Keyframe key;
  if (previous != nullptr) key.pose = previous->pose;  // inherit omitted keys
  KeyframeKeys keys;
  auto num = [&](double& out, bool* seen = nullptr) -> Setter {
    return [&out, seen, &file](const toml::node& n, const std::string& k) {
      out = number(file, n, k);
      if (seen != nullptr) *seen = true;
    };
  };
  auto node = [&](const toml::node*& where, double* out = nullptr) -> Setter {
    return [&where, out, &file](const toml::node& n, const std::string& k) {
      if (out != nullptr) *out = number(file, n, k);
      where = &n;
    };
  };
  geo::CameraPose& p = key.pose;
  const std::map<std::string, Setter> schema = {
      {"latitude_deg", num(p.position.latitudeDeg, &keys.lat)},
      {"longitude_deg", num(p.position.longitudeDeg, &keys.lon)},
      {"height_m",
       [&](const toml::node& n, const std::string& k) {
         p.position.heightM = number(file, n, k);
         keys.height = true;
         if (p.position.heightM < kLowestPathHeightM)
           throw InputError(where(file, n) + name + ": height_m " + decimal(p.position.heightM) +
                            " is below the lowest allowed camera height (-500 m)");
       }},
      {"heading_deg", num(p.headingDeg, &keys.heading)},
      {"pitch_deg", num(p.pitchDeg, &keys.pitch)},
      {"roll_deg", num(p.rollDeg)},
      {"fov_deg", num(p.verticalFovDeg)},
      {"time_s", node(keys.time, &keys.timeS)},
      {"duration_s", node(keys.duration, &keys.durationS)},
      {"look_at", node(keys.target)},
      {"range_m", node(keys.range, &keys.rangeM)},
      {"tilt_deg", node(keys.tilt, &keys.tiltDeg)},
      {"easing",
       [&](const toml::node& n, const std::string& k) {
         const std::string e = text(file, n, k);
         const auto easing = geo::parseEasing(e);
         if (!easing)
           throw InputError(where(file, n) + name + ": unknown easing '" + e +
                            "' (use smooth, ease-in, ease-out or ease-in-out)");
         key.easing = *easing;
       }},
  };
  applyKeys(file, t, "[[keyframe]] " + std::to_string(index), schema);

  if (previous == nullptr && !(keys.lat && keys.lon && keys.height) && keys.target == nullptr)
    throw InputError(where(file, t) + name +
                     ": the first keyframe needs latitude_deg, longitude_deg and height_m (or look_at)");
  key.timeS = keyframeTime(file, t, name, keys, previous);
  if (const auto view = lookAtOf(file, t, name, keys, previous, p.headingDeg))
    key = geo::lookAtKeyframe(*view, p.rollDeg, p.verticalFovDeg, key.timeS, key.easing);
  if (auto problem = geo::validatePose(key.pose)) throw InputError(where(file, t) + name + ": " + *problem);
  return key;
}

void readKeyframes(const fs::path& file, const toml::node& node, CameraPath& path) {
  const toml::array* list = node.as_array();
  if (list == nullptr || list->empty())
    throw InputError(where(file, node) + "'keyframe' must be an array of tables ([[keyframe]])");
  std::size_t index = 0;
  for (const toml::node& item : *list) {
    ++index;
    const toml::table& t = tableOf(file, item, "keyframe " + std::to_string(index));
    path.keyframes.push_back(
        readKeyframe(file, t, index, path.keyframes.empty() ? nullptr : &path.keyframes.back()));
  }
}

// [path] interpolation = "geodesic" | "smooth".
void readPathSection(const fs::path& file, const toml::table& t, CameraPath& path) {
  applyKeys(file, t, "[path]",
            {{"interpolation", [&](const toml::node& n, const std::string& k) {
                const std::string name = text(file, n, k);
                const auto i = geo::parseInterpolation(name);
                if (!i)
                  throw InputError(where(file, n) + "unknown interpolation '" + name +
                                   "' (use geodesic or smooth)");
                path.interpolation = *i;
              }}});
}

// [orbit]: a circle around a point, as look-at keyframes.
void readOrbit(const fs::path& file, const toml::table& t, CameraPath& path) {
  geo::Orbit o;
  o.start.tiltDeg = 45.0;
  o.start.target.heightM = 0.0;
  bool lat = false, lon = false, range = false, duration = false;
  auto num = [&](double& out, bool* seen = nullptr) -> Setter {
    return [&out, seen, &file](const toml::node& n, const std::string& k) {
      out = number(file, n, k);
      if (seen != nullptr) *seen = true;
    };
  };
  applyKeys(file, t, "[orbit]",
            {{"latitude_deg", num(o.start.target.latitudeDeg, &lat)},
             {"longitude_deg", num(o.start.target.longitudeDeg, &lon)},
             {"height_m", num(o.start.target.heightM)},
             {"range_m", num(o.start.rangeM, &range)},
             {"tilt_deg", num(o.start.tiltDeg)},
             {"heading_deg", num(o.start.headingDeg)},
             {"degrees", num(o.degrees)},
             {"duration_s", num(o.durationS, &duration)},
             {"roll_deg", num(o.rollDeg)},
             {"fov_deg", num(o.verticalFovDeg)},
             {"easing", [&](const toml::node& n, const std::string& k) {
                const std::string e = text(file, n, k);
                const auto easing = geo::parseEasing(e);
                if (!easing) throw InputError(where(file, n) + "[orbit]: unknown easing '" + e + "'");
                o.easing = *easing;
              }}});
  if (!(lat && lon && range && duration))
    throw InputError(where(file, t) + "[orbit] needs latitude_deg, longitude_deg, range_m and duration_s");
  try {
    path.keyframes = geo::orbitKeyframes(o);
  } catch (const InputError& e) {
    throw InputError(where(file, t) + e.what());
  }
}

// JSON has the same structure as the TOML form; convert it so one reader checks both.
toml::table fromJson(const nlohmann::json& j, const fs::path& file);

void insertJson(toml::table& t, const std::string& key, const nlohmann::json& v, const fs::path& file);

toml::array arrayFromJson(const nlohmann::json& j, const fs::path& file) {
  toml::array a;
  for (const auto& v : j) {
    if (v.is_object()) a.push_back(fromJson(v, file));
    else if (v.is_string()) a.push_back(v.get<std::string>());
    else if (v.is_number_integer()) a.push_back(v.get<std::int64_t>());
    else if (v.is_number()) a.push_back(v.get<double>());
    else if (v.is_boolean()) a.push_back(v.get<bool>());
    else throw InputError(file.string() + ": unsupported JSON array element " + v.dump());
  }
  return a;
}

void insertJson(toml::table& t, const std::string& key, const nlohmann::json& v, const fs::path& file) {
  if (v.is_object()) t.insert(key, fromJson(v, file));
  else if (v.is_array()) t.insert(key, arrayFromJson(v, file));
  else if (v.is_string()) t.insert(key, v.get<std::string>());
  else if (v.is_number_integer()) t.insert(key, v.get<std::int64_t>());
  else if (v.is_number()) t.insert(key, v.get<double>());
  else if (v.is_boolean()) t.insert(key, v.get<bool>());
  else throw InputError(file.string() + ": '" + key + "' has an unsupported JSON value (null?)");
}

toml::table fromJson(const nlohmann::json& j, const fs::path& file) {
  if (!j.is_object()) throw InputError(file.string() + ": expected a JSON object");
  toml::table t;
  for (const auto& [key, value] : j.items()) insertJson(t, key, value, file);
  return t;
}

toml::table parseFile(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".json") {
    std::ifstream in(file);
    if (!in) throw InputError(file.string() + ": cannot open for reading");
    try {
      return fromJson(nlohmann::json::parse(in), file);
    } catch (const nlohmann::json::parse_error& e) {
      throw InputError(file.string() + ": JSON syntax error at byte " + std::to_string(e.byte));
    }
  }
  try {
    return toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    throw InputError(file.string() + ":" + std::to_string(e.source().begin.line) + ": " +
                     std::string(e.description()));
  }
}

}  // namespace

namespace {
CameraPath readPathTable(const toml::table& root, const fs::path& file, bool needKeyframes) {
  CameraPath path;
  const toml::node* keyframes = nullptr;
  const toml::table* orbit = nullptr;
  for (const auto& [sectionKey, node] : root) {
    const std::string section(sectionKey.str());
    if (section == "keyframe") {
      keyframes = &node;
    } else if (section == "path") {
      readPathSection(file, tableOf(file, node, section), path);
    } else if (section == "orbit") {
      orbit = &tableOf(file, node, section);
    } else if (section == "scene") {
      readScene(file, tableOf(file, node, section), path.scene);
    } else if (section == "video") {
      const std::map<std::string, Setter> schema = {
          {"fps",
           [&](const toml::node& n, const std::string& k) {
             const double fps = number(file, n, k);
             if (!(fps > 0.0 && fps <= 240.0))
               throw InputError(where(file, n) + "'fps' must be within (0, 240]");
             path.fps = fps;
           }},
          {"crf",
           [&](const toml::node& n, const std::string& k) {
             path.crf = static_cast<int>(integer(file, n, k, 0, 51));
           }},
      };
      applyKeys(file, tableOf(file, node, section), "[video]", schema);
    } else {
      throw InputError(at(file, sectionKey.source().begin.line) + "unknown section [" + section +
                       "] (expected [scene], [video], [path], [orbit], [[keyframe]])");
    }
  }
  if (orbit != nullptr && keyframes != nullptr)
    throw InputError(where(file, *orbit) + "give [orbit] or [[keyframe]] tables, not both");
  if (orbit != nullptr) readOrbit(file, *orbit, path);
  if (keyframes != nullptr) readKeyframes(file, *keyframes, path);
  if (path.keyframes.empty()) {
    if (!needKeyframes) return path;
    throw InputError(file.string() + ":1: no keyframes (add [[keyframe]] tables or an [orbit])");
  }
  path.scene.camera = path.keyframes.front().pose;
  return path;
}
}  // namespace

CameraPath readCameraPath(const fs::path& file, bool needKeyframes) {
  return readPathTable(parseFile(file), file, needKeyframes);
}

CameraPath readCameraPathText(const std::string& text, const fs::path& file, int firstLine,
                              bool needKeyframes) {
  // Blank lines in front make toml++'s line numbers those of the enclosing file.
  const std::string shifted = std::string(static_cast<std::size_t>(std::max(firstLine - 1, 0)), '\n') + text;
  try {
    return readPathTable(toml::parse(shifted, file.string()), file, needKeyframes);
  } catch (const toml::parse_error& e) {
    throw InputError(file.string() + ":" + std::to_string(e.source().begin.line) + ": " +
                     std::string(e.description()));
  }
}

void writeCameraPathJson(const fs::path& file, const CameraPath& path) {
  const SceneSettings& s = path.scene;
  nlohmann::json scene = {{"width", s.width},
                          {"height", s.height},
                          {"exposure", s.exposure},
                          {"ocean_model", s.oceanModel},
                          {"wind_speed_ms", s.windSpeedMs},
                          {"wind_direction_deg", s.windFromDeg},
                          {"wind_layers", s.windLayers}};
  if (s.time) scene["time"] = s.time->toIso8601();
  if (s.sunElevationDeg) scene["sun_elevation_deg"] = *s.sunElevationDeg;
  if (s.sunAzimuthDeg) scene["sun_azimuth_deg"] = *s.sunAzimuthDeg;
  if (!s.elevationLayer.empty()) scene["elevation_layer"] = s.elevationLayer;
  if (!s.imageryLayers.empty()) scene["imagery_layers"] = s.imageryLayers;
  nlohmann::json root = {{"scene", scene}};
  nlohmann::json video = nlohmann::json::object();
  if (path.fps) video["fps"] = *path.fps;
  if (path.crf) video["crf"] = *path.crf;
  if (!video.empty()) root["video"] = video;
  if (path.interpolation) root["path"] = {{"interpolation", geo::interpolationName(*path.interpolation)}};
  for (const auto& k : path.keyframes) {
    nlohmann::json key;
    if (k.lookAt) {
      const geo::LookAt& v = *k.lookAt;
      key = {{"look_at", {{"latitude_deg", v.target.latitudeDeg},
                          {"longitude_deg", v.target.longitudeDeg},
                          {"height_m", v.target.heightM}}},
             {"range_m", v.rangeM}, {"heading_deg", v.headingDeg}, {"tilt_deg", v.tiltDeg}};
    } else {
      key = {{"latitude_deg", k.pose.position.latitudeDeg}, {"longitude_deg", k.pose.position.longitudeDeg},
             {"height_m", k.pose.position.heightM}, {"heading_deg", k.pose.headingDeg},
             {"pitch_deg", k.pose.pitchDeg}};
    }
    key.update({{"roll_deg", k.pose.rollDeg}, {"fov_deg", k.pose.verticalFovDeg}, {"time_s", k.timeS},
                {"easing", geo::easingName(k.easing)}});
    root["keyframe"].push_back(key);
  }
  writeFileAtomically(file, [&](const fs::path& tmp) {
    std::ofstream out(tmp);
    out << root.dump(2) << "\n";
    if (!out.flush()) throw InputError(file.string() + ": cannot write");
  });
}

namespace {
// Shortest decimal that reads back to the same double; TOML takes "1e+07" as a float.
std::string tomlNumber(double v) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

std::string tomlString(const std::string& v) {
  std::string out = "\"";
  for (const char c : v) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || u == 0x7F) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04X", static_cast<unsigned>(u));
      out += esc;
    } else {
      out += c;
    }
  }
  return out + "\"";
}
}  // namespace

std::string pathSettingsToml(const CameraPath& path) {
  const SceneSettings& s = path.scene;
  std::ostringstream t;
  t << "[scene]\n";
  if (s.time) t << "time = " << tomlString(s.time->toIso8601()) << "\n";
  if (s.sunElevationDeg) t << "sun_elevation_deg = " << tomlNumber(*s.sunElevationDeg) << "\n";
  if (s.sunAzimuthDeg) t << "sun_azimuth_deg = " << tomlNumber(*s.sunAzimuthDeg) << "\n";
  t << "width = " << s.width << "\nheight = " << s.height << "\n";
  t << "exposure = " << tomlNumber(s.exposure) << "\n";
  t << "ocean_model = " << tomlString(s.oceanModel) << "\n";
  t << "wind_speed_ms = " << tomlNumber(s.windSpeedMs) << "\n";
  t << "wind_direction_deg = " << tomlNumber(s.windFromDeg) << "\n";
  t << "wind_layers = [";
  for (std::size_t i = 0; i < s.windLayers.size(); ++i)
    t << (i ? ", " : "") << tomlString(s.windLayers[i]);
  t << "]\n";
  if (!s.elevationLayer.empty()) t << "elevation_layer = " << tomlString(s.elevationLayer) << "\n";
  if (!s.imageryLayers.empty()) {
    t << "imagery_layers = [";
    for (std::size_t i = 0; i < s.imageryLayers.size(); ++i)
      t << (i ? ", " : "") << tomlString(s.imageryLayers[i]);
    t << "]\n";
  }
  if (path.fps || path.crf) {
    t << "\n[video]\n";
    if (path.fps) t << "fps = " << tomlNumber(*path.fps) << "\n";
    if (path.crf) t << "crf = " << *path.crf << "\n";
  }
  if (path.interpolation)
    t << "\n[path]\ninterpolation = " << tomlString(geo::interpolationName(*path.interpolation)) << "\n";
  return t.str();
}

void writeCameraPathToml(const fs::path& file, const CameraPath& path) {
  std::ostringstream t;
  t << pathSettingsToml(path);
  for (const auto& k : path.keyframes) {
    const geo::CameraPose& p = k.pose;
    t << "\n[[keyframe]]\n";
    if (k.lookAt) {
      const geo::LookAt& v = *k.lookAt;
      t << "look_at = { latitude_deg = " << tomlNumber(v.target.latitudeDeg)
        << ", longitude_deg = " << tomlNumber(v.target.longitudeDeg)
        << ", height_m = " << tomlNumber(v.target.heightM) << " }\n"
        << "range_m = " << tomlNumber(v.rangeM) << "\n"
        << "heading_deg = " << tomlNumber(v.headingDeg) << "\n"
        << "tilt_deg = " << tomlNumber(v.tiltDeg) << "\n";
    } else {
      t << "latitude_deg = " << tomlNumber(p.position.latitudeDeg) << "\n"
        << "longitude_deg = " << tomlNumber(p.position.longitudeDeg) << "\n"
        << "height_m = " << tomlNumber(p.position.heightM) << "\n"
        << "heading_deg = " << tomlNumber(p.headingDeg) << "\n"
        << "pitch_deg = " << tomlNumber(p.pitchDeg) << "\n";
    }
    t << "roll_deg = " << tomlNumber(p.rollDeg) << "\n"
      << "fov_deg = " << tomlNumber(p.verticalFovDeg) << "\n"
      << "time_s = " << tomlNumber(k.timeS) << "\n"
      << "easing = " << tomlString(geo::easingName(k.easing)) << "\n";
  }
  writeFileAtomically(file, [&](const fs::path& tmp) {
    std::ofstream out(tmp);
    out << t.str();
    if (!out.flush()) throw InputError(file.string() + ": cannot write");
  });
}

}  // namespace og::io
