#include "app/SceneOptions.hpp"

#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

#include "core/Error.hpp"
#include "core/StartupTrace.hpp"
#include "geo/Sun.hpp"
#include "io/SceneSchema.hpp"
#include "render/GlobeRenderer.hpp"

namespace og::app {

void SceneOptions::add(CLI::App& cmd) {
  cmd_ = &cmd;
  auto& c = flags_.camera;
  cmd.add_option("--config", config_, "TOML scene file (flags given here override it)");
  cmd.add_option("--lat", c.position.latitudeDeg, "camera latitude, degrees north [-90, 90]");
  cmd.add_option("--lon", c.position.longitudeDeg, "camera longitude, degrees east");
  cmd.add_option("--alt", c.position.heightM, "camera height above the WGS84 ellipsoid, metres");
  cmd.add_option("--heading", c.headingDeg, "view heading, degrees clockwise from north");
  cmd.add_option("--pitch", c.pitchDeg, "view pitch, degrees (0 horizon, -90 straight down)");
  cmd.add_option("--roll", c.rollDeg, "roll, degrees clockwise [-180, 180]");
  cmd.add_option("--fov", c.verticalFovDeg, "vertical field of view, degrees");
  cmd.add_option("--width", flags_.width, "image width, pixels");
  cmd.add_option("--height", flags_.height, "image height, pixels");
  cmd.add_option("--samples", samples_,
                 "samples per pixel for anti-aliased edges: auto (default: 4 on a GPU, 1 on the "
                 "CPU's llvmpipe, where 4 cost 1.6-5x), 1, 2, 4 or 8");
  auto* time = cmd.add_option("--time", time_, "UTC time (ISO 8601) that places the Sun");
  auto* el = cmd.add_option("--sun-elevation", sunElevation_,
                            "Sun elevation at the point under the camera, degrees");
  auto* az = cmd.add_option("--sun-azimuth", sunAzimuth_,
                            "Sun azimuth there, degrees clockwise from north");
  time->excludes(el)->excludes(az);
  cmd.add_option("--exposure", flags_.exposure, "exposure multiplier before tone mapping");
  cmd.add_option("--gl", flags_.glBackend, "OpenGL backend: auto, egl or osmesa");
  cmd.add_option("--ocean", flags_.oceanModel, "ocean model: bruneton (filtered) or classic");
  cmd.add_option("--t", flags_.simulationTimeS, "simulation time of the waves, seconds");
  cmd.add_option("--seed", flags_.waveSeed, "seed of the wave directions and phases");
  cmd.add_option("--time-lapse", flags_.timeLapse,
                 "record/view: UTC seconds per second of path, [0, 1e6] (default 1): the Sun and "
                 "wind layers with a time axis follow this clock, the waves keep real time");
  cmd.add_option("--wind", wind_,
                 "wind where no layer covers: SPEED[,FROM] in m/s and the direction it comes from, "
                 "degrees clockwise from north (meteorological; default 7,270)");
  cmd.add_option("--wind-layer", flags_.windLayers,
                 "wind field FILE[:U,V] (NetCDF or GRIB2); repeat to stack a regional layer over "
                 "a global one");
  cmd.add_option("--elevation-layer", flags_.elevationLayer,
                 "relief/bathymetry FILE[:VAR] in metres: NetCDF, GRIB or GeoTIFF (default: "
                 "embedded ETOPO5, 5' cells)");
  cmd.add_option("--elevation-correction", flags_.elevationCorrection,
                 "auto (default: the embedded layer's ETOPO5 -10 m shallow-bank placeholder "
                 "replaced near land, docs/coast.md), etopo5-banks (the same on any layer, e.g. "
                 "etopo5.cdf) or none");
  cmd.add_option("--imagery-layer", flags_.imageryLayers,
                 "georeferenced imagery FILE draped over the land (GeoTIFF/COG, JPEG/PNG with a "
                 "world file, ... in EPSG:4326, 3857 or any CRS PROJ knows); repeat, later on top "
                 "(default: the embedded Blue Marble)");
  cmd.add_option("--imagery-cache-cpu-mib", flags_.imageryCacheCpuMib,
                 "CPU memory for the imagery layers' decoded tiles, MiB [1, 65536] (default 256)");
  cmd.add_option("--imagery-cache-gpu-mib", flags_.imageryCacheGpuMib,
                 "GPU memory for the imagery layers' tiles, MiB [1, 65536] (default 256)");
}

io::SceneSettings SceneOptions::resolve(io::SceneSettings s) const {
  if (!config_.empty()) s = io::readSceneFile(config_, s);
  auto given = [&](const char* flag) { return cmd_->count(flag) > 0; };
  auto& c = s.camera;
  const auto& f = flags_.camera;
  if (given("--lat")) c.position.latitudeDeg = f.position.latitudeDeg;
  if (given("--lon")) c.position.longitudeDeg = f.position.longitudeDeg;
  if (given("--alt")) c.position.heightM = f.position.heightM;
  if (given("--heading")) c.headingDeg = f.headingDeg;
  if (given("--pitch")) c.pitchDeg = f.pitchDeg;
  if (given("--roll")) c.rollDeg = f.rollDeg;
  if (given("--fov")) c.verticalFovDeg = f.verticalFovDeg;
  if (given("--width")) s.width = flags_.width;
  if (given("--height")) s.height = flags_.height;
  if (given("--samples")) s.samples = parseSampleCount(samples_);
  if (given("--exposure")) s.exposure = flags_.exposure;
  if (given("--gl")) s.glBackend = flags_.glBackend;
  if (given("--ocean")) s.oceanModel = flags_.oceanModel;
  if (given("--t")) s.simulationTimeS = flags_.simulationTimeS;
  if (given("--seed")) s.waveSeed = flags_.waveSeed;
  if (given("--time-lapse")) s.timeLapse = flags_.timeLapse;
  if (given("--wind-layer")) s.windLayers = flags_.windLayers;
  if (given("--elevation-layer")) s.elevationLayer = flags_.elevationLayer;
  if (given("--elevation-correction")) s.elevationCorrection = flags_.elevationCorrection;
  if (given("--imagery-layer")) s.imageryLayers = flags_.imageryLayers;
  if (given("--imagery-cache-cpu-mib")) s.imageryCacheCpuMib = flags_.imageryCacheCpuMib;
  if (given("--imagery-cache-gpu-mib")) s.imageryCacheGpuMib = flags_.imageryCacheGpuMib;
  if (given("--wind")) {
    const geo::Wind wind = geo::parseWindFlag(wind_, s.windFromDeg);
    s.windSpeedMs = wind.speedMs;
    s.windFromDeg = wind.fromDeg();
  }
  if (given("--time")) {
    s.time = UtcTime::parseIso8601(time_);
    if (!s.time) throw InputError("--time: not an ISO-8601 UTC time: '" + time_ + "'");
    s.sunElevationDeg.reset();
    s.sunAzimuthDeg.reset();
  }
  if (given("--sun-elevation") || given("--sun-azimuth")) {
    s.time.reset();
    if (given("--sun-elevation")) s.sunElevationDeg = sunElevation_;
    if (given("--sun-azimuth")) s.sunAzimuthDeg = sunAzimuth_;
  }
  validateScene(s, "");
  return s;
}

int parseSampleCount(const std::string& text) {
  if (const auto n = io::parseSampleCount(text)) return *n;
  throw InputError("--samples: expected auto, 1, 2, 4 or 8, got '" + text + "'");
}

render::FrameInput frameInputOf(const io::SceneSettings& s) {
  render::FrameInput frame;
  frame.camera = s.camera;
  frame.sunDirectionEcef = sunDirectionOf(s);
  frame.exposure = s.exposure;
  frame.width = s.width;
  frame.height = s.height;
  frame.samples = s.samples;
  frame.oceanModel = oceanModelOf(s);
  frame.wind = s.wind();
  frame.simulationTimeS = s.simulationTimeS;
  frame.waveSeed = s.waveSeed;
  frame.utcTime = s.time;  // layers with a time axis follow it
  return frame;
}

glm::dvec3 sunDirectionOf(const io::SceneSettings& s) {
  if (s.time) return geo::sunEphemeris(*s.time).directionEcef;
  return geo::sunDirectionFromHorizontal(s.camera.position, s.sunElevationDeg.value_or(50.0),
                                         s.sunAzimuthDeg.value_or(150.0));
}

std::vector<data::GeoImage> loadImageryLayers(const io::SceneSettings& s) {
  std::vector<std::filesystem::path> files(s.imageryLayers.begin(), s.imageryLayers.end());
  if (files.empty()) return {};
  const core::startup::Scope timed("data: imagery layers");
  return data::loadImageryLayers(files);
}

std::future<void> prefetchDefaultImagery() {
  return std::async(std::launch::async, [] {
    (void)data::defaultDayImagery();
    (void)data::defaultNightLights();
  });
}

std::shared_ptr<const data::LatLonGrid> loadElevation(const io::SceneSettings& scene) {
  const core::startup::Scope timed("data: elevation layer (all of it)");
  return data::loadSharedElevationLayer(scene.elevationLayer, data::parseElevationCorrection(scene.elevationCorrection));
}

void setImageryLayers(render::ImageryTextures& imagery, const io::SceneSettings& s,
                      const std::vector<data::GeoImage>& layers) {
  constexpr std::size_t kMib = std::size_t{1} << 20;
  imagery.setCacheBudgets(static_cast<std::size_t>(s.imageryCacheCpuMib) * kMib,
                          static_cast<std::size_t>(s.imageryCacheGpuMib) * kMib);
  imagery.setLayers(layers);
}

std::shared_ptr<const data::WindLayers> loadWindLayers(const io::SceneSettings& s) {
  if (s.windLayers.empty()) return nullptr;
  const core::startup::Scope timed("data: wind layers");
  return std::make_shared<const data::WindLayers>(data::WindLayers::load(
      s.windLayers, s.wind().vector(), s.time));
}

render::OceanModel oceanModelOf(const io::SceneSettings& s) {
  return s.oceanModel == "classic" ? render::OceanModel::Classic : render::OceanModel::Bruneton;
}

}  // namespace og::app
