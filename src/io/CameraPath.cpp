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

#include "core/Error.hpp"
#include "io/SceneSchema.hpp"
#include "io/SceneTables.hpp"

namespace og::io {
namespace fs = std::filesystem;
namespace {

using detail::applyKeys;
using detail::at;
using detail::integer;
using detail::number;
using detail::Setter;
using detail::tableOf;
using detail::text;
using detail::where;

std::string decimal(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// [scene]: the scene file's tables one level down, or older paths' flat keys.
void readScene(const fs::path& file, const toml::table& t, SceneSettings& s) {
  detail::readSceneTables(file, t, s, detail::SceneForm::PathScene);
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
  return readPathTable(detail::parseTomlOrJson(file), file, needKeyframes);
}

CameraPath readCameraPathText(const std::string& text, const fs::path& file, int firstLine,
                              bool needKeyframes) {
  return readPathTable(detail::parseTomlText(text, file, firstLine), file, needKeyframes);
}

void writeCameraPathJson(const fs::path& file, const CameraPath& path) {
  nlohmann::json root = {{"scene", detail::sceneJson(path.scene, false)}};
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
  detail::writeTextFile(file, root.dump(2) + "\n");
}

using detail::tomlNumber;
using detail::tomlString;

std::string pathSettingsToml(const CameraPath& path) {
  std::ostringstream t;
  t << sceneToml(path.scene, "scene.", false);
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
  detail::writeTextFile(file, t.str());
}

}  // namespace og::io
