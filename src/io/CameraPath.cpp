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
  return file.string() + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": ";
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
  };
  applyKeys(file, t, "[scene]", schema);
  try {
    validateScene(s, "");
  } catch (const InputError& e) {
    throw InputError(where(file, t) + "[scene]: " + e.what());
  }
}

void readKeyframes(const fs::path& file, const toml::node& node, CameraPath& path) {
  const toml::array* list = node.as_array();
  if (list == nullptr || list->empty())
    throw InputError(where(file, node) + "'keyframe' must be an array of tables ([[keyframe]])");
  std::size_t index = 0;
  for (const toml::node& item : *list) {
    ++index;
    const std::string name = "keyframe " + std::to_string(index);
    const toml::table& t = tableOf(file, item, name);
    geo::Keyframe key;
    if (!path.keyframes.empty()) key.pose = path.keyframes.back().pose;  // inherit omitted keys
    bool hasLat = false, hasLon = false, hasHeight = false;
    const toml::node* timeNode = nullptr;
    const toml::node* durationNode = nullptr;
    double time = 0.0, duration = 0.0;
    auto num = [&](double& out, bool* seen = nullptr) -> Setter {
      return [&out, seen, &file](const toml::node& n, const std::string& k) {
        out = number(file, n, k);
        if (seen != nullptr) *seen = true;
      };
    };
    geo::CameraPose& p = key.pose;
    const std::map<std::string, Setter> schema = {
        {"latitude_deg", num(p.position.latitudeDeg, &hasLat)},
        {"longitude_deg", num(p.position.longitudeDeg, &hasLon)},
        {"height_m",
         [&](const toml::node& n, const std::string& k) {
           p.position.heightM = number(file, n, k);
           hasHeight = true;
           if (p.position.heightM < kLowestPathHeightM)
             throw InputError(where(file, n) + name + ": height_m " + decimal(p.position.heightM) +
                              " is below the lowest allowed camera height (-500 m)");
         }},
        {"heading_deg", num(p.headingDeg)},
        {"pitch_deg", num(p.pitchDeg)},
        {"roll_deg", num(p.rollDeg)},
        {"fov_deg", num(p.verticalFovDeg)},
        {"time_s",
         [&](const toml::node& n, const std::string& k) {
           time = number(file, n, k);
           timeNode = &n;
         }},
        {"duration_s",
         [&](const toml::node& n, const std::string& k) {
           duration = number(file, n, k);
           durationNode = &n;
         }},
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

    if (path.keyframes.empty() && !(hasLat && hasLon && hasHeight))
      throw InputError(where(file, t) + name +
                       ": the first keyframe needs latitude_deg, longitude_deg and height_m");
    if (timeNode != nullptr && durationNode != nullptr)
      throw InputError(where(file, *durationNode) + name + ": give time_s or duration_s, not both");
    if (path.keyframes.empty()) {
      if (durationNode != nullptr)
        throw InputError(where(file, *durationNode) + name +
                         ": the first keyframe takes time_s (default 0), not duration_s");
      if (time < 0.0) throw InputError(where(file, *timeNode) + name + ": time_s must be >= 0");
      key.timeS = time;
    } else {
      const double previous = path.keyframes.back().timeS;
      if (timeNode != nullptr) {
        if (!(time > previous))
          throw InputError(where(file, *timeNode) + name + ": keyframes out of order: time_s " + decimal(time) +
                           " is not after the previous keyframe's " + decimal(previous));
        key.timeS = time;
      } else if (durationNode != nullptr) {
        if (!(duration > 0.0))
          throw InputError(where(file, *durationNode) + name + ": duration_s must be > 0");
        key.timeS = previous + duration;
      } else {
        throw InputError(where(file, t) + name + ": needs time_s or duration_s");
      }
    }
    if (auto problem = geo::validatePose(key.pose)) throw InputError(where(file, t) + name + ": " + *problem);
    path.keyframes.push_back(key);
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

CameraPath readCameraPath(const fs::path& file) {
  const toml::table root = parseFile(file);
  CameraPath path;
  const toml::node* keyframes = nullptr;
  for (const auto& [sectionKey, node] : root) {
    const std::string section(sectionKey.str());
    if (section == "keyframe") {
      keyframes = &node;
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
      throw InputError(at(file, sectionKey.source().begin.line) + "unknown section [" + section + "] (expected [scene], [video], [[keyframe]])");
    }
  }
  if (keyframes == nullptr)
    throw InputError(file.string() + ":1: no keyframes (add [[keyframe]] tables)");
  readKeyframes(file, *keyframes, path);
  path.scene.camera = path.keyframes.front().pose;
  return path;
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
  nlohmann::json root = {{"scene", scene}};
  nlohmann::json video = nlohmann::json::object();
  if (path.fps) video["fps"] = *path.fps;
  if (path.crf) video["crf"] = *path.crf;
  if (!video.empty()) root["video"] = video;
  for (const auto& k : path.keyframes)
    root["keyframe"].push_back({{"latitude_deg", k.pose.position.latitudeDeg},
                                {"longitude_deg", k.pose.position.longitudeDeg},
                                {"height_m", k.pose.position.heightM},
                                {"heading_deg", k.pose.headingDeg},
                                {"pitch_deg", k.pose.pitchDeg},
                                {"roll_deg", k.pose.rollDeg},
                                {"fov_deg", k.pose.verticalFovDeg},
                                {"time_s", k.timeS},
                                {"easing", geo::easingName(k.easing)}});
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

void writeCameraPathToml(const fs::path& file, const CameraPath& path) {
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
  if (path.fps || path.crf) {
    t << "\n[video]\n";
    if (path.fps) t << "fps = " << tomlNumber(*path.fps) << "\n";
    if (path.crf) t << "crf = " << *path.crf << "\n";
  }
  for (const auto& k : path.keyframes) {
    const geo::CameraPose& p = k.pose;
    t << "\n[[keyframe]]\n"
      << "latitude_deg = " << tomlNumber(p.position.latitudeDeg) << "\n"
      << "longitude_deg = " << tomlNumber(p.position.longitudeDeg) << "\n"
      << "height_m = " << tomlNumber(p.position.heightM) << "\n"
      << "heading_deg = " << tomlNumber(p.headingDeg) << "\n"
      << "pitch_deg = " << tomlNumber(p.pitchDeg) << "\n"
      << "roll_deg = " << tomlNumber(p.rollDeg) << "\n"
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
