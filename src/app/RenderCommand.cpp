// oceanglobe render: one still image, 8-bit sRGB PNG or linear HDR OpenEXR.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/Aovs.hpp"
#include "app/Commands.hpp"
#include "app/SceneOptions.hpp"
#include "app/Startup.hpp"
#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/StartupTrace.hpp"
#include "data/Elevation.hpp"
#include "data/WindLayers.hpp"
#include "gl/Context.hpp"
#include "io/Image.hpp"
#include "render/GlobeRenderer.hpp"

namespace og::app {
namespace {

enum class Format { Png, Exr };

Format formatOf(const std::filesystem::path& out) {
  std::string ext = out.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".png") return Format::Png;
  if (ext == ".exr") return Format::Exr;
  throw InputError(out.string() + ": unsupported output format '" + ext +
                   "' (use .png for 8-bit sRGB or .exr for linear HDR)");
}

struct RenderOptions {
  SceneOptions scene;
  std::string output;
  std::string exrType = "half";
  std::vector<std::string> aovs;
};

}  // namespace

Run addRenderCommand(CLI::App& parent) {
  auto opts = std::make_shared<RenderOptions>();
  CLI::App* cmd = parent.add_subcommand("render", "render one still image of the globe");
  opts->scene.add(*cmd);
  cmd->add_option("-o,--output", opts->output, "output file: .png (sRGB) or .exr (linear HDR)")
      ->required();
  cmd->add_option("--exr-type", opts->exrType, "EXR pixel type: half or float")
      ->check(CLI::IsMember({"half", "float"}));
  addAovOption(*cmd, opts->aovs);
  return [opts]() {
    const io::SceneSettings scene = opts->scene.resolve();
    const std::filesystem::path out = opts->output;
    const Format format = formatOf(out);
    if (!opts->aovs.empty() && format != Format::Exr)
      throw InputError(out.string() + ": --aov needs an OpenEXR output (.exr): PNG has no extra channels");
    checkOutputWritable(out);  // fail before the (long) render, not after
    const std::future<void> defaultImagery = prefetchDefaultImagery();
    // Data layers before the GL context: a bad file exits 2 without rendering anything.
    const std::shared_ptr<const data::LatLonGrid> elevation = loadElevation(scene);
    const std::shared_ptr<const data::WindLayers> wind = loadWindLayers(scene);
    const std::vector<data::GeoImage> imagery = loadImageryLayers(scene);

    const auto backend = gl::parseBackend(scene.glBackend);
    auto context = [&] {
      const core::startup::Scope timed("GL context");
      return gl::createHeadlessContext(*backend);
    }();
    log::info("rendering " + std::to_string(scene.width) + "x" + std::to_string(scene.height) +
              " with " + context->info().backend + " (" + context->info().renderer + ")");
    std::optional<core::startup::Scope> setup(std::in_place, "renderer set-up (all of it)");
    render::GlobeRenderer renderer(elevation, scene.atmosphere);
    renderer.setWindLayers(wind);
    setImageryLayers(renderer.imagery(), scene, imagery);
    setup.reset();
    render::FrameInput frame = frameInputOf(scene);
    frame.auxiliaryOutputs = needsAuxiliaryOutputs(opts->aovs);
    frame.displayOnly = format == Format::Png;
    {
      const core::startup::Scope timed("first frame (render + glFinish)");
      renderer.render(frame);
      render::GlobeRenderer::finish();
    }
    {
      const core::startup::Scope timed("read-back + write image");
      if (format == Format::Png)
        io::writePng(out, renderer.display());
      else
        io::writeExr(out, renderer.radiance(),
                     opts->exrType == "float" ? io::ExrPixelType::Float : io::ExrPixelType::Half,
                     aovChannels(renderer, opts->aovs));
    }
    log::info("wrote " + out.string());
    writeStartupTrace();
    return static_cast<int>(kExitOk);
  };
}

}  // namespace og::app
