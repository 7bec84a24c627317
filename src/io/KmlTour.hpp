#pragma once
// Google Earth tours (KML 2.2 with the gx: extensions) <-> camera paths.
//
// Read: the first <gx:Tour> of a .kml file; its <gx:Playlist> of
//   <gx:FlyTo> <gx:duration>s</gx:duration> <gx:flyToMode>bounce|smooth</gx:flyToMode>
//              <Camera> or <LookAt> </gx:FlyTo>
//   <gx:Wait> <gx:duration>s</gx:duration> </gx:Wait>
// Camera: longitude, latitude, altitude, heading, tilt (0 straight down, 90 level, 180 straight
// up: pitch = tilt - 90), roll. LookAt: longitude, latitude, altitude of the target, heading,
// tilt (0-90), range. Both: altitudeMode / gx:altitudeMode (absolute, relativeToGround,
// clampToGround (the default), relativeToSeaFloor, clampToSeaFloor) and gx:horizFov (default:
// Google Earth's 60° horizontal field of view).
//
// Timing, as Google Earth plays a tour: frame 0 shows the first FlyTo's view, held for its
// duration (Google Earth would spend it flying there from wherever it was); every later FlyTo
// arrives at its view after its duration; a Wait holds the view. A run of smooth FlyTos is one
// unbroken flight that starts and ends at rest; a bounce FlyTo starts and ends at rest; a Wait
// (even of 0 s) breaks a run. So a tour of durations d1..dn lasts sum(d) seconds and has
// floor(sum(d) * fps) + 1 frames.
//
// Altitudes: oceanglobe's sea level is the WGS84 ellipsoid, so "absolute" altitudes are heights
// above it (the geoid's +-100 m is not modelled). The other modes measure from the terrain
// (the elevation layer with its detail): relativeToGround from the ground or the sea surface,
// relativeToSeaFloor from the sea floor; clampTo... put the point on that surface.
//
// Other elements in the tour (gx:AnimatedUpdate, gx:SoundCue, gx:TourControl, gx:TimeStamp,
// ...) are skipped with one warning per kind. Malformed XML or numbers, values out of range, a
// FlyTo without a view, a file that is not KML or holds no tour: og::InputError "FILE:LINE: ...".
//
// Written tours hold oceanglobe's settings ([scene], [video], [path] of a path file, as TOML)
// in the Document's <ExtendedData><Data name="oceanglobe">, which Google Earth keeps and ignores.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geo/FlightPath.hpp"
#include "io/CameraPath.hpp"

namespace og::io {

/// How a KML altitude is measured.
enum class AltitudeMode { Absolute, RelativeToGround, ClampToGround, RelativeToSeaFloor, ClampToSeaFloor };

/// Google Earth's default horizontal field of view, degrees.
inline constexpr double kKmlDefaultHorizontalFovDeg = 60.0;

/// A view of a tour as the KML states it (a Camera or a LookAt).
struct KmlView {
  bool lookAt = false;
  double longitudeDeg = 0, latitudeDeg = 0, altitudeM = 0;
  double headingDeg = 0, tiltDeg = 0, rollDeg = 0;  ///< roll: Camera only
  double rangeM = 0;                                ///< LookAt only
  AltitudeMode altitudeMode = AltitudeMode::ClampToGround;
  double horizontalFovDeg = kKmlDefaultHorizontalFovDeg;
  int line = 0;  ///< where the view starts in the file
};

/// A keyframe of the tour before it is placed on the terrain.
struct KmlKey {
  KmlView view;
  double timeS = 0.0;
  geo::Easing easing = geo::Easing::Smooth;
};

struct KmlTour {
  std::filesystem::path file;
  std::vector<KmlKey> keys;            ///< at least one, times strictly increasing
  std::optional<CameraPath> settings;  ///< the settings oceanglobe embedded, if any (no keyframes)
};

/// Parses the first gx:Tour of a KML file. Throws og::InputError "FILE:LINE: problem"; warns
/// (og::log) once per kind of element it skips.
KmlTour readKmlTour(const std::filesystem::path& file);

/// Terrain height in metres above sea level (negative: the sea floor) at a point.
using TerrainHeight = std::function<double(double latitudeDeg, double longitudeDeg)>;

/// The tour's keyframes for an image of `aspect` = width / height (Google Earth's fields of view
/// are horizontal, oceanglobe's vertical), with altitudes placed over `terrain` (called only
/// for views whose altitude mode needs it). Throws og::InputError "FILE:LINE: problem".
std::vector<geo::Keyframe> kmlKeyframes(const KmlTour& tour, double aspect, const TerrainHeight& terrain);

/// A scene's settings after the command line's flags (e.g. app::SceneOptions::resolve).
using SceneResolver = std::function<SceneSettings(const SceneSettings&)>;
/// The terrain heights for a scene (its elevation layer).
using TerrainFor = std::function<TerrainHeight(const SceneSettings&)>;

/// A KML tour as a camera path. Its settings ([scene], [video], [path]) are those embedded in the
/// file, else those of a path file of the same name beside it (tour.toml or tour.json; keyframes
/// there are not used), else the defaults; `resolve` then has the last word on the scene, and
/// path.scene is the result. The views become keyframes for that scene's image aspect over
/// `terrain(scene)`. The interpolation is smooth (Google Earth's spline through the views) unless
/// the settings name one. Throws og::InputError.
CameraPath readKmlPath(const std::filesystem::path& file, const SceneResolver& resolve,
                       const TerrainFor& terrain);

/// Writes `path` as a KML tour, atomically: one smooth gx:FlyTo per keyframe (Camera, or LookAt
/// for look-at keyframes, absolute altitudes, gx:horizFov for the scene's aspect), a 0 s gx:Wait
/// where the path comes to rest, and the settings in ExtendedData.
void writeKmlTour(const std::filesystem::path& file, const CameraPath& path);

/// True for a .kml file name (any case).
bool isKmlFile(const std::filesystem::path& file);

/// Writes a path by the file's extension, atomically: .kml a tour, .json JSON, else TOML (what
/// readCameraPath reads for any other name).
void writePathFile(const std::filesystem::path& file, const CameraPath& path);

}  // namespace og::io
