#include "app/viewer/KeyframeLog.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.hpp"
#include "geo/Sun.hpp"
#include "io/CameraPath.hpp"

namespace og::app::viewer {
namespace fs = std::filesystem;

double suggestedDurationS(const geo::CameraPose& a, const geo::CameraPose& b) {
  const double ha = std::max(a.position.heightM, 1.0), hb = std::max(b.position.heightM, 1.0);
  const double vertical = std::abs(std::log(hb / ha));
  // Chord length between the ground points, in units of the geometric mean height.
  geo::Geodetic ga = a.position, gb = b.position;
  ga.heightM = gb.heightM = 0.0;
  const double ground = glm::length(geo::geodeticToEcef(gb) - geo::geodeticToEcef(ga)) / std::sqrt(ha * hb);
  double turn = std::abs(std::remainder(b.headingDeg - a.headingDeg, 360.0));
  turn = std::max({turn, std::abs(b.pitchDeg - a.pitchDeg), std::abs(b.rollDeg - a.rollDeg)});
  const double seconds = std::max(2.5 * std::hypot(vertical, ground), turn / 30.0);
  return std::clamp(seconds, 2.0, 60.0);
}

namespace {
// The existing keyframes of a path file (throws on a bad file: it is kept as it is).
io::CameraPath existingPath(const fs::path& file, const io::SceneSettings& scene,
                            const io::TerrainHeight& terrain) {
  std::error_code ec;
  if (!fs::exists(file, ec)) return {};
  if (!io::isKmlFile(file)) return io::readCameraPath(file);
  const io::TerrainHeight ground = terrain ? terrain : [](double, double) { return 0.0; };
  io::CameraPath path = io::readKmlPath(
      file, [&](const io::SceneSettings&) { return scene; }, [&](const io::SceneSettings&) { return ground; });
  // A tour ends at rest; the view appended now continues the flight from there.
  auto& keys = path.keyframes;
  if (keys.size() > 1) {
    keys.back().easing = geo::Easing::Smooth;
    geo::Easing& arriving = keys[keys.size() - 2].easing;
    if (arriving == geo::Easing::EaseInOut) arriving = geo::Easing::EaseIn;
    else if (arriving == geo::Easing::EaseOut) arriving = geo::Easing::Smooth;
  }
  return path;
}
}  // namespace

AppendedKeyframe appendKeyframe(const fs::path& file, const geo::CameraPose& pose,
                                const io::SceneSettings& scene, const glm::dvec3& sunDirectionEcef,
                                const io::TerrainHeight& terrain) {
  io::CameraPath path = existingPath(file, scene, terrain);

  geo::Keyframe key;
  key.pose = pose;
  if (!path.keyframes.empty()) {
    const geo::Keyframe& last = path.keyframes.back();
    key.timeS = last.timeS + suggestedDurationS(last.pose, pose);
  }
  if (auto problem = geo::validatePose(pose)) throw InputError(file.string() + ": " + *problem);
  path.keyframes.push_back(key);

  io::SceneSettings s = scene;
  s.camera = path.keyframes.front().pose;
  if (s.time) {
    s.time = UtcTime{s.time->unixSeconds - key.timeS};
    s.sunElevationDeg.reset();
    s.sunAzimuthDeg.reset();
  } else {
    const geo::HorizontalAngles sun = geo::horizontalAngles(pose.position, sunDirectionEcef);
    s.sunElevationDeg = sun.elevationDeg;
    s.sunAzimuthDeg = sun.azimuthDeg;
  }
  path.scene = s;

  io::writePathFile(file, path);
  return {path.keyframes.size(), key.timeS};
}

}  // namespace og::app::viewer
