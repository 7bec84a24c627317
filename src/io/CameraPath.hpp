#pragma once
// Camera path files for `oceanglobe record`: keyframes plus the scene they fly through.
//
//   [scene.sun]        all optional: the tables of a scene file (io/SceneFile.hpp, the keys,
//   time = "2024-06-20T18:30:00Z"   units and ranges of io/SceneSchema.hpp) under [scene], all
//                                   but [camera] (the keyframes give it); flags override them.
//                                   time: UTC of the first frame (the Sun moves with the clock),
//                                   or elevation_deg / azimuth_deg: the Sun's angles at the LAST
//                                   keyframe's ground point; time_lapse = 1080: UTC seconds
//                                   per second of path (default 1): the Sun and timed wind
//                                   layers follow this clock, the waves keep real time
//   [scene.image]      width = 1280, height = 720, exposure = 6, samples = 4 ("auto", 1, 2, 4, 8)
//   [scene.ocean]      model = "bruneton", wind_speed_ms = 7, wind_from_deg = 270, time_s, seed
//   [scene.layers]     wind = ["winds.nc:UWND,VWND"], elevation = "relief.nc:ROSE"
//   [scene.gl]         backend = "auto"
//   [scene.atmosphere] as in a scene file
//   Older path files put flat keys in [scene]; they are still read: time, sun_elevation_deg,
//   sun_azimuth_deg, width, height, exposure, samples, ocean_model, wind_speed_ms,
//   wind_direction_deg (from), wind_layers, elevation_layer, time_lapse.
//
//   [video]
//   fps = 30                             # frames per second, (0, 240]
//   crf = 20                             # H.264 constant rate factor, [0, 51]
//
//   [[keyframe]]                         # one table per keyframe, in time order
//   latitude_deg = 36.0                  # required on the first keyframe; later ones inherit
//   longitude_deg = -9.0                 #   any pose key they omit from the keyframe before
//   height_m = 400000                    # above the WGS84 ellipsoid, >= -500
//   heading_deg = 90                     # clockwise from north
//   pitch_deg = -90                      # 0 horizon, -90 straight down
//   roll_deg = 0
//   fov_deg = 45                         # vertical
//   time_s = 0                           # seconds from the start, or
//   duration_s = 5                       #   seconds since the previous keyframe (not both)
//   easing = "smooth"                    # segment to the next keyframe: smooth | ease-in |
//                                        #   ease-out | ease-in-out (see geo/FlightPath.hpp)
//
//   [[keyframe]]                         # a look-at keyframe (KML's LookAt) instead of a camera:
//   look_at = { latitude_deg = 45.83, longitude_deg = 6.86, height_m = 4800 }   # the target
//   range_m = 12000                      # eye to target, [0, 1e9]
//   tilt_deg = 65                        # 0 looks straight down, 90 level
//   heading_deg = 200                    # the way the eye looks; roll_deg, fov_deg as above
//                                        # (a keyframe without position keys after a look-at
//                                        #  keyframe keeps its target, range and tilt)
//
//   [path]
//   interpolation = "geodesic"           # or "smooth" (continuous direction; geo/FlightPath.hpp)
//
//   [orbit]                              # instead of keyframes: circle a point
//   latitude_deg = 45.83                 # the target (height_m, default 0)
//   longitude_deg = 6.86
//   range_m = 12000                      # tilt_deg (default 45), heading_deg (start, default 0)
//   degrees = 360                        # how far round, negative = anticlockwise (default 360)
//   duration_s = 30                      # fov_deg, roll_deg, easing (of the start and end)
//
// The same structure in JSON (.json: {"scene": {"image": {...}, ...}, "video": {...},
// "keyframe": [{...}]})
// is read and written too. Heights are only checked against -500 m here: the check against
// the terrain under the path needs the elevation layer and is left to the renderer.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geo/FlightPath.hpp"
#include "io/SceneFile.hpp"

namespace og::io {

/// The lowest camera height a path file may ask for, metres above the ellipsoid.
inline constexpr double kLowestPathHeightM = -500.0;

struct CameraPath {
  std::vector<geo::Keyframe> keyframes;  ///< at least one, times strictly increasing
  SceneSettings scene;                   ///< camera = the first keyframe's pose
  std::optional<double> fps;             ///< [video] fps when given
  std::optional<int> crf;                ///< [video] crf when given
  std::optional<geo::Interpolation> interpolation;  ///< [path] interpolation when given

  /// The flight through the keyframes (geodesic unless the path says otherwise).
  [[nodiscard]] geo::FlightPath flight() const {
    return geo::FlightPath(keyframes, interpolation.value_or(geo::Interpolation::Geodesic));
  }
};

/// Reads a TOML (or, by extension, JSON) path file. Throws og::InputError "FILE:LINE: problem"
/// for syntax errors, unknown sections or keys, wrong types, non-finite numbers, keyframes out
/// of time order, heights below kLowestPathHeightM and invalid poses or scene settings.
/// JSON carries no line numbers; its messages name the keyframe and key instead.
/// With `needKeyframes` false a file of settings alone ([scene], [video], [path]) is read too
/// (its keyframes, if any, are read and checked as well).
CameraPath readCameraPath(const std::filesystem::path& file, bool needKeyframes = true);

/// Reads a path from TOML text found in `file` from line `firstLine` on (e.g. embedded in a KML
/// tour); messages name the file and its lines.
CameraPath readCameraPathText(const std::string& text, const std::filesystem::path& file,
                              int firstLine, bool needKeyframes = true);

/// The [scene], [video] and [path] sections of a path as TOML text (what writeCameraPathToml
/// writes before the keyframes).
std::string pathSettingsToml(const CameraPath& path);

/// Writes a path as JSON (all keys explicit, keyframe times as time_s; the scene by the scene
/// schema, nothing of it dropped), atomically.
void writeCameraPathJson(const std::filesystem::path& file, const CameraPath& path);

/// Writes a path as TOML in the form readCameraPath reads (all keys explicit, keyframe times
/// as time_s, numbers in their shortest exact decimal form), atomically.
void writeCameraPathToml(const std::filesystem::path& file, const CameraPath& path);

}  // namespace og::io
