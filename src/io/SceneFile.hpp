#pragma once
// Scene settings shared by render, record, view and bench, and their file form (TOML, or JSON
// by extension; the keys, units and ranges are those of the scene schema, io/SceneSchema.hpp):
//
//   [camera]  latitude_deg, longitude_deg, height_m, heading_deg, pitch_deg, roll_deg, fov_deg
//   [sun]     time = "2024-06-20T12:00:00Z"  |  elevation_deg, azimuth_deg
//   [image]   width, height, exposure, samples (per pixel: "auto", 1, 2, 4 or 8)
//   [ocean]   model = "bruneton" | "classic", wind_speed_ms, wind_from_deg (where it comes from,
//             meteorological; older name wind_direction_deg), time_s (wave clock), seed
//   [layers]  wind = ["FILE[:U,V]", ...] (first is the bottom of the stack), elevation = "FILE[:VAR]"
//   [gl]      backend = "auto" | "egl" | "osmesa"
//   [atmosphere] solar_irradiance, rayleigh_scattering, mie_scattering, mie_extinction,
//             ozone_absorption, ground_albedo ([r, g, b]); rayleigh_scale_height_m,
//             mie_scale_height_m, mie_phase_g, ozone_center_altitude_m, ozone_half_width_m,
//             sun_angular_radius_deg, bottom_radius_m, thickness_m, mu_s_min,
//             scattering_orders (docs/atmosphere.md; Earth defaults)
#include <filesystem>
#include <optional>
#include <string>
#include <cstdint>
#include <vector>

#include "atmosphere/Parameters.hpp"
#include "core/Time.hpp"
#include "geo/Camera.hpp"
#include "geo/Wind.hpp"

namespace og::io {

struct SceneSettings {
  geo::CameraPose camera;
  std::optional<UtcTime> time;            ///< Sun from the almanac at this instant, or
  std::optional<double> sunElevationDeg;  ///< Sun elevation at the point under the camera
  std::optional<double> sunAzimuthDeg;    ///< clockwise from north at that point
  int width = 512;
  int height = 512;
  double exposure = 6.0;
  int samples = 0;  ///< multisampling per pixel: 1, 2, 4 or 8; 0 = auto (4 on a GPU, 1 on the CPU)
  std::string glBackend = "auto";
  std::string oceanModel = "bruneton";    ///< "bruneton" (filtered, default) or "classic"
  double windSpeedMs = 7.0;               ///< 10 m wind where no wind layer covers, [0, 50]
  /// Where the wind comes from, degrees clockwise from north (meteorological: 270 = a westerly,
  /// blowing towards the east).
  double windFromDeg = 270.0;
  /// The constant wind (speed, and the direction it blows towards) of windSpeedMs/windFromDeg.
  [[nodiscard]] geo::Wind wind() const { return geo::Wind::blowingFrom(windSpeedMs, windFromDeg); }
  std::vector<std::string> windLayers;    ///< "FILE[:U,V]" specs, bottom of the stack first
  std::string elevationLayer;             ///< "FILE[:VAR]", empty = embedded default
  /// "auto" (the default layer's shallow-bank placeholder corrected), "etopo5-banks" (any
  /// layer's) or "none" (data::ElevationCorrection).
  std::string elevationCorrection = "auto";
  /// Georeferenced imagery draped over the land (GDAL rasters), bottom first; the embedded
  /// Blue Marble is always underneath.
  std::vector<std::string> imageryLayers;
  double simulationTimeS = 0.0;           ///< wave clock at the image (record: at frame 0), s
  /// record/view: UTC seconds that pass per second of path (or of viewing), [0, 1e6]; the Sun
  /// and the wind layers follow this clock, the waves keep real time. 1 = real time.
  double timeLapse = 1.0;
  std::uint64_t waveSeed = 1;             ///< wave directions and phases are reproducible from it
  atmosphere::Parameters atmosphere;      ///< [atmosphere]: Earth defaults
};

/// Reads a scene file (TOML, or JSON by extension) over `base` (keys absent from the file keep
/// base's values). Throws og::InputError "FILE:LINE: problem" for unknown keys, wrong types,
/// bad values.
SceneSettings readSceneFile(const std::filesystem::path& file, SceneSettings base);

/// Writes every setting (optional ones when given; [atmosphere] where it differs from Earth's
/// defaults) as TOML, or JSON by extension, atomically: readSceneFile gives the same settings
/// back. Throws og::InputError when the file cannot be written.
void writeSceneFile(const std::filesystem::path& file, const SceneSettings& scene);

/// Throws og::InputError naming the first invalid setting (`origin` prefixes the message):
/// each setting against its range in the scene schema, the pose, the Sun given once, the
/// atmosphere as a whole.
void validateScene(const SceneSettings& scene, const std::string& origin);

}  // namespace og::io
