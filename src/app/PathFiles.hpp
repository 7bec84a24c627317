#pragma once
// Camera path files of every kind for record, view, bench and `path convert`: TOML/JSON path
// files (io/CameraPath.hpp) and Google Earth KML tours (io/KmlTour.hpp).
#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>

#include "io/KmlTour.hpp"

namespace og::app {

/// Reads a path file (.toml, .json or .kml) and resolves its scene: path.scene is
/// `resolve(the file's scene)`. A KML tour's altitudes relative to the ground or the sea floor
/// are placed on the resolved scene's elevation layer (io::readKmlPath). Throws og::InputError.
io::CameraPath loadPathFile(const std::filesystem::path& file, const io::SceneResolver& resolve);

/// The terrain's height function (the elevation layer with its detail, as the renderer builds
/// its tiles from) for a scene's elevation layer.
io::TerrainHeight terrainHeights(const io::SceneSettings& scene);

/// The still-image camera flags (--lat --lon --alt --heading --pitch --roll --fov): hidden from
/// the help of commands that take the camera from a path, and refused when given.
void hideCameraFlags(CLI::App& cmd);
void refuseCameraFlags(const CLI::App& cmd, const std::string& command);

}  // namespace og::app
