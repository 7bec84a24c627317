#include "app/PathFiles.hpp"

#include <memory>

#include "app/SceneOptions.hpp"
#include "core/Error.hpp"
#include "data/Elevation.hpp"
#include "terrain/Heightfield.hpp"

namespace og::app {
namespace fs = std::filesystem;
namespace {
constexpr const char* kCameraFlags[] = {"--lat", "--lon", "--alt", "--heading", "--pitch", "--roll", "--fov"};
}  // namespace

io::CameraPath loadPathFile(const fs::path& file, const io::SceneResolver& resolve) {
  if (io::isKmlFile(file)) return io::readKmlPath(file, resolve, terrainHeights);
  io::CameraPath path = io::readCameraPath(file);
  path.scene = resolve(path.scene);
  return path;
}

io::TerrainHeight terrainHeights(const io::SceneSettings& scene) {
  const auto ground = std::make_shared<const terrain::Heightfield>(loadElevation(scene));
  return [ground](double lat, double lon) { return ground->heightM(lat, lon); };
}

void hideCameraFlags(CLI::App& cmd) {
  for (const char* flag : kCameraFlags) cmd.get_option(flag)->group("");
}

void refuseCameraFlags(const CLI::App& cmd, const std::string& command) {
  for (const char* flag : kCameraFlags)
    if (cmd.count(flag) > 0)
      throw InputError(std::string(flag) + ": " + command + " takes the camera from the path file");
}

}  // namespace og::app
