#pragma once
// The sky maps' radial sums: the frame layer of the sky maps (Atmosphere::prepareFrameSkyLayer)
// integrated along the map's radii, so that the sea's reflected sky is filtered over its
// footprint ellipse, stretched radially, in two lookups on a CPU rasteriser however long it is
// (shaders/atmosphere/skymap_radial.comp, skymap.glsl's SKY_RADIAL_SUMS; docs/ocean.md, "The sky
// filter").
#include <vector>

#include <glm/vec3.hpp>

#include "gl/Objects.hpp"
#include "gl/Shader.hpp"

namespace og::render {

class SkyRadialSums {
 public:
  /// Texels around a turn and along the radius (to SKY_RADIAL_MAX_RHO = 1.6 in |u|): 512 / 2 pi
  /// = 81 per unit of u around the horizon's circle, 128 / 1.6 = 80 along the radius, so texels
  /// are square there, and finer than the sky maps' 128 over 2.2.
  static constexpr int kAzimuths = 512;
  static constexpr int kRadii = 128;

  /// Refills the sums from the frame layer of the sky maps `skyMapsId` (its last layer, index
  /// `skyMapLayers`; bound to gl::kUnitSkyMap), every mip level. Skipped when `frameKey` (what the frame
  /// layer was made from: the Sun's zenith angle) did not change. Reads one texel of the frame
  /// layer back (its radiance below the horizon): on CPU rasterisers, where this is used, that
  /// waits only for work the frame needs anyway.
  void update(GLuint skyMapsId, int skyMapLayers, double frameKey);
  /// Binds the sums to gl::kUnitSkyRadialSums.
  void bind() const;
  /// Sets skymap.glsl's uniform of the sums on `program` (the radiance below the horizon).
  void setUniforms(const gl::Program& program) const;
  [[nodiscard]] bool ready() const { return texture_.id() != 0; }
  /// Level 0 (rgba per texel, rows of azimuths from the zenith outwards), for tests.
  [[nodiscard]] std::vector<float> read() const;
  /// The frame layer's radiance below the horizon that the sums leave out, as last read.
  [[nodiscard]] glm::vec3 belowHorizon() const { return belowHorizon_; }

 private:
  gl::Texture texture_;
  gl::Program fill_;  ///< atmosphere/skymap_radial.comp, compiled on first use
  glm::vec3 belowHorizon_{0.0f};
  double frameKey_ = 0.0;
};

}  // namespace og::render
