#include "io/KmlTour.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"

namespace og::io {
namespace fs = std::filesystem;
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

/// An element's name without its namespace prefix ("gx:FlyTo" -> "FlyTo"). Prefixes are not
/// resolved: KML and its gx: extension share no element name this reader uses differently.
std::string_view localName(const pugi::xml_node& n) {
  const std::string_view name = n.name();
  const std::size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

/// The file's text, for line numbers (pugixml reports byte offsets).
class Source {
 public:
  explicit Source(fs::path file) : file_(std::move(file)) {
    std::ifstream in(file_, std::ios::binary);
    if (!in) throw InputError(file_.string() + ": cannot open for reading");
    std::ostringstream s;
    s << in.rdbuf();
    text_ = s.str();
  }
  [[nodiscard]] const std::string& text() const { return text_; }
  [[nodiscard]] int lineAt(std::ptrdiff_t offset) const {
    const auto end = text_.begin() + std::clamp<std::ptrdiff_t>(offset, 0, static_cast<std::ptrdiff_t>(text_.size()));
    return 1 + static_cast<int>(std::count(text_.begin(), end, '\n'));
  }
  [[nodiscard]] int lineOf(const pugi::xml_node& n) const { return lineAt(n.offset_debug()); }
  [[nodiscard]] std::string at(int line) const { return file_.string() + ":" + std::to_string(line) + ": "; }
  [[nodiscard]] std::string at(const pugi::xml_node& n) const { return at(lineOf(n)); }
  [[nodiscard]] const fs::path& file() const { return file_; }

 private:
  fs::path file_;
  std::string text_;
};

/// Elements the reader does not use: one warning per kind, naming the first place.
class Skipped {
 public:
  void add(const pugi::xml_node& n, int line) {
    const auto [it, added] = seen_.try_emplace(n.name(), line, 0);
    ++it->second.second;
    if (added) order_.emplace_back(n.name());
  }
  void warn(const Source& src) const {
    for (const std::string& name : order_) {
      const auto& [line, count] = seen_.at(name);
      log::warn(src.at(line) + "skipped <" + name + "> (not part of a camera flight)" +
                (count > 1 ? "; " + std::to_string(count - 1) + " more like it" : std::string()));
    }
  }

 private:
  std::map<std::string, std::pair<int, int>> seen_;
  std::vector<std::string> order_;
};

std::string trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  return std::string(s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1));
}

double numberIn(const Source& src, const pugi::xml_node& n, double lo, double hi) {
  const std::string text = trimmed(n.child_value());
  double v = 0.0;
  const char* begin = text.data() + (text.starts_with('+') ? 1 : 0);
  const auto [end, ec] = std::from_chars(begin, text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
    throw InputError(src.at(n) + "<" + n.name() + "> '" + text + "' is not a number");
  if (v < lo || v > hi) {
    std::ostringstream range;
    range << "<" << n.name() << "> " << text << " is outside [" << lo << ", " << hi << "]";
    throw InputError(src.at(n) + range.str());
  }
  return v;
}

AltitudeMode altitudeMode(const Source& src, const pugi::xml_node& n) {
  const std::string text = trimmed(n.child_value());
  static const std::map<std::string, AltitudeMode, std::less<>> modes = {
      {"absolute", AltitudeMode::Absolute},
      {"relativeToGround", AltitudeMode::RelativeToGround},
      {"clampToGround", AltitudeMode::ClampToGround},
      {"relativeToSeaFloor", AltitudeMode::RelativeToSeaFloor},
      {"clampToSeaFloor", AltitudeMode::ClampToSeaFloor}};
  const auto it = modes.find(text);
  if (it == modes.end())
    throw InputError(src.at(n) + "<" + n.name() + "> '" + text +
                     "' is not an altitude mode (absolute, relativeToGround, clampToGround, "
                     "relativeToSeaFloor, clampToSeaFloor)");
  return it->second;
}

KmlView readView(const Source& src, const pugi::xml_node& view, Skipped& skipped) {
  KmlView v;
  v.lookAt = localName(view) == "LookAt";
  v.line = src.lineOf(view);
  for (const pugi::xml_node& c : view.children()) {
    if (c.type() != pugi::node_element) continue;
    const std::string_view name = localName(c);
    if (name == "longitude") v.longitudeDeg = numberIn(src, c, -180.0, 180.0);
    else if (name == "latitude") v.latitudeDeg = numberIn(src, c, -90.0, 90.0);
    else if (name == "altitude") v.altitudeM = numberIn(src, c, -1e9, 1e9);
    else if (name == "heading") v.headingDeg = numberIn(src, c, -3600.0, 3600.0);
    else if (name == "tilt") v.tiltDeg = numberIn(src, c, 0.0, v.lookAt ? 90.0 : 180.0);
    else if (name == "roll" && !v.lookAt) v.rollDeg = numberIn(src, c, -180.0, 180.0);
    else if (name == "range" && v.lookAt) v.rangeM = numberIn(src, c, 0.0, 1e9);
    else if (name == "altitudeMode") v.altitudeMode = altitudeMode(src, c);
    else if (name == "horizFov") v.horizontalFovDeg = numberIn(src, c, 0.1, 179.0);
    else skipped.add(c, src.lineOf(c));
  }
  return v;
}

/// One entry of a playlist: a FlyTo (with its view) or a Wait.
struct Step {
  bool wait = false;
  bool bounce = true;  // gx:flyToMode's default
  double durationS = 0.0;
  KmlView view;
  int line = 0;
};

Step readFlyTo(const Source& src, const pugi::xml_node& flyTo, Skipped& skipped) {
  Step s;
  s.line = src.lineOf(flyTo);
  bool hasView = false;
  for (const pugi::xml_node& c : flyTo.children()) {
    if (c.type() != pugi::node_element) continue;
    const std::string_view name = localName(c);
    if (name == "duration") {
      s.durationS = numberIn(src, c, 0.0, 1e7);
    } else if (name == "flyToMode") {
      const std::string mode = trimmed(c.child_value());
      if (mode != "bounce" && mode != "smooth")
        throw InputError(src.at(c) + "<" + c.name() + "> '" + mode + "' is not bounce or smooth");
      s.bounce = mode == "bounce";
    } else if (name == "Camera" || name == "LookAt") {
      if (hasView) throw InputError(src.at(c) + "a <gx:FlyTo> takes one view (<Camera> or <LookAt>)");
      s.view = readView(src, c, skipped);
      hasView = true;
    } else {
      skipped.add(c, src.lineOf(c));
    }
  }
  if (!hasView) throw InputError(src.at(flyTo) + "<" + std::string(flyTo.name()) + "> has no view (<Camera> or <LookAt>)");
  return s;
}

Step readWait(const Source& src, const pugi::xml_node& wait, Skipped& skipped) {
  Step s;
  s.wait = true;
  s.line = src.lineOf(wait);
  for (const pugi::xml_node& c : wait.children()) {
    if (c.type() != pugi::node_element) continue;
    if (localName(c) == "duration") s.durationS = numberIn(src, c, 0.0, 1e7);
    else skipped.add(c, src.lineOf(c));
  }
  return s;
}

geo::Easing easingFor(bool restAtStart, bool restAtEnd) {
  if (restAtStart && restAtEnd) return geo::Easing::EaseInOut;
  if (restAtStart) return geo::Easing::EaseIn;
  return restAtEnd ? geo::Easing::EaseOut : geo::Easing::Smooth;
}

/// Google Earth's timing (see KmlTour.hpp): keyframes with times, and where the camera rests.
std::vector<KmlKey> timeline(const Source& src, const std::vector<Step>& steps, int playlistLine) {
  std::vector<KmlKey> keys;
  std::vector<bool> rest;
  double t = 0.0, hold = 0.0;
  for (const Step& s : steps) {
    if (s.wait) {
      if (keys.empty()) {
        hold += s.durationS;  // before the first view: frame 0 shows it for longer
        continue;
      }
      rest.back() = true;
      if (s.durationS > 0.0) {
        keys.push_back({keys.back().view, t += s.durationS});
        rest.push_back(true);
      }
    } else if (keys.empty()) {
      keys.push_back({s.view, 0.0});
      rest.push_back(true);
      hold += s.durationS;
      if (hold > 0.0) {
        keys.push_back({s.view, t = hold});
        rest.push_back(true);
      }
    } else {
      if (!(s.durationS > 0.0))
        throw InputError(src.at(s.line) + "a <gx:FlyTo> after the first needs a <gx:duration> > 0 "
                         "(a cut cannot be flown; start a new tour instead)");
      if (s.bounce) rest.back() = true;
      keys.push_back({s.view, t += s.durationS});
      rest.push_back(s.bounce);
    }
  }
  if (keys.empty()) throw InputError(src.at(playlistLine) + "the tour has no <gx:FlyTo> with a view");
  rest.back() = true;  // a tour ends at rest
  for (std::size_t k = 0; k < keys.size(); ++k)
    keys[k].easing = easingFor(rest[k], k + 1 < keys.size() && rest[k + 1]);
  return keys;
}

pugi::xml_node findElement(const pugi::xml_node& root, std::string_view name) {
  return root.find_node([&](const pugi::xml_node& n) {
    return n.type() == pugi::node_element && localName(n) == name;
  });
}

/// The settings oceanglobe wrote into <ExtendedData><Data name="oceanglobe"><value>.
std::optional<CameraPath> embeddedSettings(const Source& src, const pugi::xml_node& root) {
  const pugi::xml_node data = root.find_node([](const pugi::xml_node& n) {
    return n.type() == pugi::node_element && localName(n) == "Data" &&
           std::string_view(n.attribute("name").value()) == "oceanglobe";
  });
  if (!data) return std::nullopt;
  const pugi::xml_node value = data.child("value");
  const pugi::xml_node text = value.first_child();
  if (!text) return std::nullopt;
  return readCameraPathText(text.value(), src.file(), src.lineOf(text), false);
}

std::string number(double v) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

void addValue(pugi::xml_node parent, const char* name, double v) {
  parent.append_child(name).text().set(number(v).c_str());
}

void writeView(pugi::xml_node parent, const geo::Keyframe& k, double aspect) {
  const double halfV = 0.5 * k.pose.verticalFovDeg * kDeg;
  const bool lookAt = k.lookAt.has_value();
  const geo::Geodetic& at = lookAt ? k.lookAt->target : k.pose.position;
  pugi::xml_node view = parent.append_child(lookAt ? "LookAt" : "Camera");
  addValue(view, "gx:horizFov", 2.0 * std::atan(std::tan(halfV) * aspect) / kDeg);
  addValue(view, "longitude", std::remainder(at.longitudeDeg, 360.0));
  addValue(view, "latitude", at.latitudeDeg);
  addValue(view, "altitude", at.heightM);
  addValue(view, "heading", lookAt ? k.lookAt->headingDeg : k.pose.headingDeg);
  addValue(view, "tilt", lookAt ? k.lookAt->tiltDeg : k.pose.pitchDeg + 90.0);
  if (lookAt)
    addValue(view, "range", k.lookAt->rangeM);
  else
    addValue(view, "roll", k.pose.rollDeg);
  view.append_child("altitudeMode").text().set("absolute");
}

}  // namespace

bool isKmlFile(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".kml";
}

void writePathFile(const fs::path& file, const CameraPath& path) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".kml")
    writeKmlTour(file, path);
  else if (ext == ".json")
    writeCameraPathJson(file, path);
  else
    writeCameraPathToml(file, path);
}

KmlTour readKmlTour(const fs::path& file) {
  const Source src(file);
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(src.text().data(), src.text().size());
  if (parsed.status == pugi::status_no_document_element)
    throw InputError(src.at(1) + "not a KML file (no XML element in it)");
  if (!parsed)
    throw InputError(src.at(src.lineAt(parsed.offset)) + "not a KML file: " + parsed.description());
  const pugi::xml_node root = doc.document_element();
  if (localName(root) != "kml")
    throw InputError(src.at(root) + "not a KML file (the root element is <" + std::string(root.name()) +
                     ">, expected <kml>)");
  const pugi::xml_node tour = findElement(root, "Tour");
  if (!tour)
    throw InputError(src.at(root) + "no <gx:Tour> in this KML file (make one in Google Earth: "
                     "Add > Tour, then save the tour as .kml)");
  pugi::xml_node playlist;
  Skipped skipped;
  for (const pugi::xml_node& c : tour.children()) {
    if (c.type() != pugi::node_element) continue;
    const std::string_view name = localName(c);
    if (name == "Playlist" && !playlist) playlist = c;
    else if (name != "name" && name != "description" && name != "visibility" && name != "open")
      skipped.add(c, src.lineOf(c));
  }
  if (!playlist) throw InputError(src.at(tour) + "<" + std::string(tour.name()) + "> has no <gx:Playlist>");

  std::vector<Step> steps;
  for (const pugi::xml_node& c : playlist.children()) {
    if (c.type() != pugi::node_element) continue;
    const std::string_view name = localName(c);
    if (name == "FlyTo") steps.push_back(readFlyTo(src, c, skipped));
    else if (name == "Wait") steps.push_back(readWait(src, c, skipped));
    else skipped.add(c, src.lineOf(c));
  }
  KmlTour result;
  result.file = file;
  result.keys = timeline(src, steps, src.lineOf(playlist));
  result.settings = embeddedSettings(src, root);
  skipped.warn(src);
  return result;
}

std::vector<geo::Keyframe> kmlKeyframes(const KmlTour& tour, double aspect, const TerrainHeight& terrain) {
  std::vector<geo::Keyframe> keys;
  for (const KmlKey& key : tour.keys) {
    const KmlView& v = key.view;
    const std::string at = tour.file.string() + ":" + std::to_string(v.line) + ": ";
    auto surface = [&](bool seaFloor) {
      const double h = terrain(v.latitudeDeg, v.longitudeDeg);
      return seaFloor ? h : std::max(h, 0.0);
    };
    double heightM = v.altitudeM;
    switch (v.altitudeMode) {
      case AltitudeMode::Absolute: break;
      case AltitudeMode::RelativeToGround: heightM += surface(false); break;
      case AltitudeMode::ClampToGround: heightM = surface(false); break;
      case AltitudeMode::RelativeToSeaFloor: heightM += surface(true); break;
      case AltitudeMode::ClampToSeaFloor: heightM = surface(true); break;
    }
    const double halfH = 0.5 * v.horizontalFovDeg * kDeg;
    const double verticalFovDeg = 2.0 * std::atan(std::tan(halfH) / aspect) / kDeg;
    geo::Keyframe k;
    if (v.lookAt) {
      const geo::LookAt view{{v.latitudeDeg, v.longitudeDeg, heightM}, v.rangeM, v.headingDeg, v.tiltDeg};
      if (auto problem = geo::validateLookAt(view)) throw InputError(at + *problem);
      k = geo::lookAtKeyframe(view, 0.0, verticalFovDeg, key.timeS, key.easing);
    } else {
      if (heightM < kLowestPathHeightM)
        throw InputError(at + "the camera is " + number(-heightM) + " m below sea level (lowest: 500 m)");
      k.pose = {{v.latitudeDeg, v.longitudeDeg, heightM}, v.headingDeg, v.tiltDeg - 90.0, v.rollDeg, verticalFovDeg};
      k.timeS = key.timeS;
      k.easing = key.easing;
    }
    if (auto problem = geo::validatePose(k.pose))
      throw InputError(at + *problem + " (gx:horizFov " + number(v.horizontalFovDeg) + " for a " +
                       number(aspect) + ":1 image)");
    keys.push_back(k);
  }
  return keys;
}

CameraPath readKmlPath(const fs::path& file, const SceneResolver& resolve, const TerrainFor& terrain) {
  const KmlTour tour = readKmlTour(file);
  CameraPath path;
  if (tour.settings) {
    path = *tour.settings;
  } else {
    for (const char* ext : {".toml", ".json"}) {
      fs::path beside = file;
      beside.replace_extension(ext);
      std::error_code ec;
      if (!fs::is_regular_file(beside, ec)) continue;
      log::info("settings for " + file.string() + " from " + beside.string());
      path = readCameraPath(beside, false);
      path.keyframes.clear();
      break;
    }
  }
  if (!path.interpolation) path.interpolation = geo::Interpolation::Smooth;
  path.scene = resolve(path.scene);
  const double aspect = static_cast<double>(path.scene.width) / path.scene.height;
  // The terrain only for views that need it (loading an elevation layer takes a while).
  TerrainHeight heights;
  const TerrainHeight lazy = [&](double lat, double lon) {
    if (!heights) heights = terrain(path.scene);
    return heights(lat, lon);
  };
  path.keyframes = kmlKeyframes(tour, aspect, lazy);
  path.scene.camera = path.keyframes.front().pose;
  return path;
}

void writeKmlTour(const fs::path& file, const CameraPath& path) {
  const double aspect = static_cast<double>(path.scene.width) / path.scene.height;
  pugi::xml_document doc;
  pugi::xml_node decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  pugi::xml_node kml = doc.append_child("kml");
  kml.append_attribute("xmlns") = "http://www.opengis.net/kml/2.2";
  kml.append_attribute("xmlns:gx") = "http://www.google.com/kml/ext/2.2";
  pugi::xml_node document = kml.append_child("Document");
  const std::string name = file.stem().string();
  document.append_child("name").text().set(name.c_str());
  pugi::xml_node data = document.append_child("ExtendedData").append_child("Data");
  data.append_attribute("name") = "oceanglobe";
  const std::string settings = std::string(1, '\n').append(pathSettingsToml(path));
  data.append_child("value").append_child(pugi::node_cdata).set_value(settings.c_str());
  pugi::xml_node tour = document.append_child("gx:Tour");
  tour.append_child("name").text().set(name.c_str());
  pugi::xml_node playlist = tour.append_child("gx:Playlist");

  const auto& keys = path.keyframes;
  auto restsAt = [&](std::size_t k) {
    const bool in = k + 1 < keys.size() && (keys[k].easing == geo::Easing::EaseIn || keys[k].easing == geo::Easing::EaseInOut);
    const bool out = k > 0 && (keys[k - 1].easing == geo::Easing::EaseOut || keys[k - 1].easing == geo::Easing::EaseInOut);
    return in || out;
  };
  for (std::size_t k = 0; k < keys.size(); ++k) {
    pugi::xml_node flyTo = playlist.append_child("gx:FlyTo");
    addValue(flyTo, "gx:duration", k == 0 ? 0.0 : keys[k].timeS - keys[k - 1].timeS);
    flyTo.append_child("gx:flyToMode").text().set("smooth");
    writeView(flyTo, keys[k], aspect);
    // A 0 s wait breaks the smooth run: the camera comes to rest here.
    if (k > 0 && k + 1 < keys.size() && restsAt(k))
      addValue(playlist.append_child("gx:Wait"), "gx:duration", 0.0);
  }
  std::ostringstream text;
  doc.save(text, "  ", pugi::format_default, pugi::encoding_utf8);
  writeFileAtomically(file, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text.str();
    if (!out.flush()) throw InputError(file.string() + ": cannot write");
  });
}

}  // namespace og::io
