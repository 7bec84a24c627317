// oceanglobe path convert IN OUT: camera path files between TOML, JSON and Google Earth KML.
#include <memory>
#include <string>

#include "app/Commands.hpp"
#include "app/PathFiles.hpp"
#include "app/SceneOptions.hpp"
#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"

namespace og::app {

namespace {
struct PathOptions {
  SceneOptions scene;
  std::string input, output;
};
}  // namespace

Run addPathCommand(CLI::App& parent) {
  auto o = std::make_shared<PathOptions>();
  CLI::App* path = parent.add_subcommand("path", "camera path files (docs/recording.md)");
  path->require_subcommand(1);
  CLI::App* convert = path->add_subcommand(
      "convert", "convert a camera path between TOML, JSON and a Google Earth KML tour (by extension)");
  convert->add_option("input", o->input, "path file to read (.toml, .json or .kml)")->required();
  convert->add_option("output", o->output, "path file to write (.kml, .json, otherwise TOML)")->required();
  o->scene.add(*convert);
  hideCameraFlags(*convert);
  return [o, convert]() {
    refuseCameraFlags(*convert, "path convert");
    checkOutputWritable(o->output);
    const io::CameraPath p =
        loadPathFile(o->input, [&](const io::SceneSettings& s) { return o->scene.resolve(s); });
    io::writePathFile(o->output, p);
    log::info("wrote " + std::to_string(p.keyframes.size()) + " keyframes to " + o->output);
    return static_cast<int>(kExitOk);
  };
}

}  // namespace og::app
