#pragma once
// The scene flags shared by render/record/view: camera, Sun, image, GL backend, --config.
#include <CLI/CLI.hpp>

#include <glm/glm.hpp>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "data/Elevation.hpp"
#include "data/Imagery.hpp"
#include "data/WindLayers.hpp"
#include "io/SceneFile.hpp"
#include "render/GlobeRenderer.hpp"
#include "render/OceanRenderer.hpp"

namespace og::app {

class SceneOptions {
 public:
  /// Registers --lat --lon --alt --heading --pitch --roll --fov --width --height --samples
  /// --time --sun-elevation --sun-azimuth --exposure --gl --ocean --wind --wind-layer
  /// --elevation-layer --config on `cmd`.
  void add(CLI::App& cmd);
  /// `base` (defaults, or e.g. a camera path's scene), then --config FILE, then the flags
  /// given. Throws og::InputError.
  [[nodiscard]] io::SceneSettings resolve(io::SceneSettings base = {}) const;

 private:
  CLI::App* cmd_ = nullptr;
  io::SceneSettings flags_;
  std::string time_;
  double sunElevation_ = 0, sunAzimuth_ = 0;
  std::string config_;
  std::string wind_;
  std::string samples_;
};

/// A --samples value: "auto" (render::kAutoSamples), 1, 2, 4 or 8 (io::parseSampleCount).
/// Throws og::InputError.
int parseSampleCount(const std::string& text);

/// The frame a scene asks for: its camera, Sun (sunDirectionOf), exposure, image size, samples,
/// ocean model, constant wind, wave clock and seed. The one conversion from settings to a
/// frame (render, record, view, bench); a moving camera (record, view) then sets its pose, Sun
/// and clock per frame.
render::FrameInput frameInputOf(const io::SceneSettings& scene);

/// Direction to the Sun (ECEF, unit) for a scene: from the almanac at the scene's time, from
/// the given elevation/azimuth at the point under the camera, or a default afternoon Sun
/// (elevation 50°, azimuth 150° there) when neither is given.
glm::dvec3 sunDirectionOf(const io::SceneSettings& scene);

/// The scene's elevation layer (the embedded default when it names none), corrected as its
/// elevationCorrection says (data::ElevationCorrection), shared (the default is not copied).
/// Throws og::InputError.
std::shared_ptr<const data::LatLonGrid> loadElevation(const io::SceneSettings& scene);
/// Decodes the embedded default imagery (day and night, data::defaultDayImagery and
/// defaultNightLights, which keep it) on another thread, so that it overlaps reading the data
/// layers, making the GL context and loading the atmosphere: ~0.3 s of CPU off the start-up's
/// critical path. The renderer then finds it decoded (or waits for it). The future waits for
/// the thread when destroyed.
[[nodiscard]] std::future<void> prefetchDefaultImagery();

/// The scene's wind layers, loaded and validated (og::InputError for a bad file), or nullptr
/// when it names none: then the constant wind holds everywhere.
std::shared_ptr<const data::WindLayers> loadWindLayers(const io::SceneSettings& scene);
/// The scene's imagery layers (data::loadImageryLayers), read before any GL context so a bad
/// file exits 2 at once.
std::vector<data::GeoImage> loadImageryLayers(const io::SceneSettings& scene);
/// Hands `layers` (loadImageryLayers) to the renderer's imagery with the scene's tile cache
/// budgets (--imagery-cache-cpu-mib / --imagery-cache-gpu-mib).
void setImageryLayers(render::ImageryTextures& imagery, const io::SceneSettings& scene,
                      const std::vector<data::GeoImage>& layers);

/// The scene's ocean model ("bruneton" or "classic", validated by io::validateScene).
render::OceanModel oceanModelOf(const io::SceneSettings& scene);

}  // namespace og::app
