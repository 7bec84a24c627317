#pragma once
// Turning a flight by hand into a camera path file for `oceanglobe record`: each call appends
// the current view as the last keyframe of a TOML (.json, or .kml: a Google Earth tour) path
// file, creating it if needed.
#include <cstddef>
#include <filesystem>

#include <glm/glm.hpp>

#include "geo/Camera.hpp"
#include "io/KmlTour.hpp"
#include "io/SceneFile.hpp"

namespace og::app::viewer {

/// Seconds `record` takes between two keyframes: about 2.5 s per "unit of perceived motion"
/// (a factor e in height, or a ground move as long as the mean height), at least as long as
/// turning at 30°/s, and within [2, 60] s. Edit time_s in the file to retime.
double suggestedDurationS(const geo::CameraPose& from, const geo::CameraPose& to);

struct AppendedKeyframe {
  std::size_t count = 0;  ///< keyframes in the file now
  double timeS = 0.0;     ///< time_s of the new keyframe
};

/// Appends `pose` to the path file `file` (read with io::readCameraPath when it exists; its
/// [video] section and keyframes are kept). [scene] is rewritten from `scene` so the path
/// records what the viewer shows: the Sun is expressed for the new (last) keyframe, as a UTC
/// time `viewerTime - time_s` when `scene.time` is set (record advances the clock along the
/// path), or as angles at that keyframe's ground point from `sunDirectionEcef` otherwise (the
/// convention record uses for angles). The write is atomic. Throws og::InputError when the
/// existing file is not a valid path or cannot be written. A .kml tour keeps its views (its
/// altitudes over `terrain` where they are relative; sea level when none is given) and is
/// written back as a tour that Google Earth opens.
AppendedKeyframe appendKeyframe(const std::filesystem::path& file, const geo::CameraPose& pose,
                                const io::SceneSettings& scene, const glm::dvec3& sunDirectionEcef,
                                const io::TerrainHeight& terrain = {});

}  // namespace og::app::viewer
