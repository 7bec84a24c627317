#pragma once
// The precomputed atmosphere on the GPU (Bruneton & Neyret 2008): computes the transmittance,
// irradiance and 4D scattering tables on the current GL context at start-up (or loads them from
// the on-disk cache), then the sea-level sky maps for the ocean and the sea-level irradiance
// table. Rendering passes include shaders/atmosphere/model.glsl (tables) and
// shaders/atmosphere/skymap.glsl (sky maps) and call bind() / bindSkyMaps().
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "atmosphere/Parameters.hpp"
#include "atmosphere/Reference.hpp"
#include "gl/Objects.hpp"
#include "gl/Shader.hpp"
#include "render/SkyRadialSums.hpp"

namespace og::render {

struct AtmosphereOptions {
  bool useCache = true;
  /// Empty: Atmosphere::defaultCacheDirectory().
  std::filesystem::path cacheDirectory;
};

/// How the ocean's sky reflection is filtered over its footprint ellipse (Bruneton 2010 §5.2:
/// textureGrad with the axes 2 sigma dU/dzeta; §7.3: "an average of nine texture2D samples
/// inside the elliptical filter support"). Chosen in one place, Atmosphere::chooseSkyFilter.
struct SkyFilter {
  int probes = 1;             ///< most textureGrad lookups along the ellipse's major axis (1 or 4)
  /// The sky maps' radial sums (render/SkyRadialSums): two lookups a layer for the sea (the
  /// frame layer's where a view reads it, else two Sun layers'); the probes only for the globe's
  /// horizon pixels below 20 km. On CPU rasterisers.
  bool radialSums = false;
  float maxAnisotropy = 1.0f; ///< the sky maps' sampler anisotropy (hardware filtering)
  std::string reason;         ///< why, for logs and `info`
};

class Atmosphere {
 public:
  /// Sun zenith angle of the sky maps' last Sun layer, rad (105°): layer k of L holds the Sun
  /// at k / (L - 1) of it (SKYMAP_MAX_ZENITH in shaders/atmosphere/skymap_common.glsl).
  static constexpr double kSkyMapMaxZenithRad = 1.8325957;
  /// What start-up cost and where the tables came from.
  struct Timing {
    double tablesMs = 0.0;   ///< precomputation, or loading and uploading the cached tables
    double skyMapsMs = 0.0;  ///< sky maps and the sea-level irradiance table
    bool fromCache = false;
    std::filesystem::path cacheFile;  ///< empty when caching is off or failed
  };

  /// Needs a current GL 4.5 context. Throws og::InputError for invalid parameters.
  explicit Atmosphere(const atmosphere::Parameters& parameters, const AtmosphereOptions& options = {});

  /// $OCEANGLOBE_CACHE_DIR, else $XDG_CACHE_HOME/oceanglobe, else ~/.cache/oceanglobe.
  static std::filesystem::path defaultCacheDirectory();

  /// The sky filter for the current context: on a GPU the sampler's hardware anisotropy (up to
  /// 16x), which filters the ellipse in one lookup; on a CPU rasteriser (llvmpipe: anisotropic
  /// filtering there is ~20x slower and blurs wrongly, docs/atmosphere.md) the layers' radial
  /// sums (two lookups a layer, docs/ocean.md), and for the globe's horizon pixels below 20 km
  /// the paper's §7.3 average of isotropic lookups spread along the ellipse's major axis (as many
  /// as its elongation, at most 4: SkyFilter::probes). The environment variable
  /// OCEANGLOBE_SKY_FILTER = hardware | radial | probes | probes9 | single forces one (for
  /// measurements); any other value throws og::InputError.
  static SkyFilter chooseSkyFilter();
  [[nodiscard]] const SkyFilter& skyFilter() const { return skyFilter_; }
  /// The layers' radial sums as last prepared (prepareFrameSkyLayer, prepareSunLayerSums), for tests.
  [[nodiscard]] const SkyRadialSums& skyRadialSums() const { return radial_; }

  /// Sets `program`'s uAtmosphere uniforms and the sky filter's uSkyFilterProbes
  /// (skymap.glsl) and binds the tables to units 2-5 (model.glsl).
  void bind(const gl::Program& program) const;
  /// Binds the sky maps (gl::kUnitSkyMap) and the sea-level irradiance table (gl::kUnitSkyIrradiance) (skymap.glsl).
  void bindSkyMaps() const;
  /// Fills the sky maps' frame layer (the array's last) with the maps at Sun zenith angle
  /// `sunZenithRad` (the two layers around it blended, every mip level), for shaders built with
  /// SKY_FRAME_LAYER (skymap.glsl), which read it alone: views whose Sun zenith hardly varies.
  /// With SkyFilter::radialSums also its radial sums (render/SkyRadialSums), when the Sun moved.
  void prepareFrameSkyLayer(double sunZenithRad) const;
  /// With SkyFilter::radialSums, the Sun layers' radial sums, made once (render/SkyRadialSums):
  /// for the sea's views that blend two layers (skymap.glsl without SKY_FRAME_LAYER).
  void prepareSunLayerSums() const;

  [[nodiscard]] const atmosphere::Parameters& parameters() const { return parameters_; }
  [[nodiscard]] const Timing& timing() const { return timing_; }

  /// The tables read back from the GPU, as the CPU reference lays them out (for tests).
  [[nodiscard]] atmosphere::ReferenceTables readTables() const;
  /// Level-0 texels of sky map `layer` (rgba, rows from v = 0), for tests and pictures.
  [[nodiscard]] std::vector<float> readSkyMap(int layer) const;
  /// skymap.glsl's sunIrradiance (the Sun's irradiance at sea level, per point from the
  /// transmittance table) evaluated on the GPU at each Sun zenith angle (radians), for tests.
  [[nodiscard]] std::vector<glm::dvec3> probeSunIrradiance(const std::vector<double>& zenithRad) const;

  /// Sets uAtmosphere.* of `program` (also used by the precomputation passes).
  static void setParameters(const gl::Program& program, const atmosphere::Parameters& p);

 private:
  void allocate();
  void precompute();
  bool loadCache(const std::filesystem::path& file);
  void saveCache(const std::filesystem::path& file) const;
  /// The sky maps' and sea-level irradiance table's storage (mip levels: skyMapLevels()).
  void allocateSkyMaps();
  void computeSkyMaps();
  /// The sky-map cache, beside the tables' file: its key (tables, sky-map code, sizes), its
  /// size in halfs, and loading (false when missing, stale or corrupt: then recomputed) and
  /// saving (written to a temporary name, then renamed; a failure is a warning).
  [[nodiscard]] int skyMapLevels() const;
  [[nodiscard]] std::uint64_t skyMapKey() const;
  [[nodiscard]] std::size_t skyMapHalfs() const;
  bool loadSkyMaps(const std::filesystem::path& file);
  void saveSkyMaps(const std::filesystem::path& file) const;

  atmosphere::Parameters parameters_;
  Timing timing_;
  SkyFilter skyFilter_;
  gl::Texture transmittance_;
  gl::Texture irradiance_;
  gl::Texture scattering_;
  gl::Texture singleMie_;
  gl::Texture skyMaps_;
  mutable gl::Program frameLayer_;  ///< atmosphere/skymap_frame.comp, compiled on first use
  mutable SkyRadialSums radial_;    ///< the layers summed along their radii (SkyFilter::radialSums)
  /// Each Sun layer's radiance below the horizon (its corner texel), for the sums' lookups.
  std::vector<glm::vec3> skyBelowHorizon_;
  gl::Texture skyIrradiance_;
};

}  // namespace og::render
