#pragma once
// The sky maps' radial sums: each layer of the sky maps (one per Sun zenith angle, and the frame
// layer, Atmosphere::prepareFrameSkyLayer) integrated along the map's radii, so that the sea's
// reflected sky is filtered over its footprint ellipse, stretched radially, in two lookups a
// layer on a CPU rasteriser however long it is (shaders/atmosphere/skymap_radial.comp,
// skymap.glsl's SKY_RADIAL_SUMS; docs/ocean.md, "The sky filter").
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

  /// Refills the frame layer's sums from the sky maps `skyMapsId` (its last layer, index
  /// `skyMapLayers`; bound to gl::kUnitSkyMap), every mip level. Skipped when `frameKey` (what
  /// the frame layer was made from: the Sun's zenith angle) did not change. `belowHorizon`: the
  /// frame layer's radiance below the horizon (the two Sun layers' blended as the layer is;
  /// the compute reads the texel itself: no read-back, which would wait for the queue).
  void updateFrameLayer(GLuint skyMapsId, int skyMapLayers, double frameKey, const glm::vec3& belowHorizon);
  /// Fills the Sun layers' sums (one per entry of `belowHorizon`, each layer's radiance below
  /// the horizon) once, for views whose sea spans several Sun zenith angles (llvmpipe, 32
  /// layers: ~20 ms, ~60-90 ms in a first frame with the two compute programs' compiles; the
  /// array holds 1.33 MiB a layer, 43 MiB at the default 32).
  void ensureSunLayers(GLuint skyMapsId, const std::vector<glm::vec3>& belowHorizon);
  /// Binds the sums made so far to gl::kUnitSkyRadialSums (the frame layer's, a 2D texture:
  /// llvmpipe makes a lone layer's mip levels ~30 times slower through a view of an array) and
  /// gl::kUnitSkyRadialSumsLayers (the Sun layers', an array).
  void bind() const;
  /// Sets skymap.glsl's uniforms of the sums on `program` (each layer's radiance below the
  /// horizon).
  void setUniforms(const gl::Program& program) const;
  [[nodiscard]] bool ready() const { return frame_.id() != 0 || layers_.id() != 0; }
  /// Mip level `level` of layer `layer` (0 ... skyMapLayers; skyMapLayers: the frame layer's),
  /// rgba per texel, rows of azimuths from the zenith outwards (kAzimuths >> level of them, at
  /// least 1, and kRadii >> level rows, at least 1), for tests.
  [[nodiscard]] std::vector<float> read(int layer, int level = 0) const;
  /// Layer `layer`'s radiance below the horizon that the sums leave out, as last given.
  [[nodiscard]] glm::vec3 belowHorizon(int layer) const;

 private:
  /// Sums layers first ... first + count - 1 of the maps into the frame's texture (`frame`) or
  /// the layers' array at the same indices, and makes their mip levels.
  void fill(GLuint skyMapsId, int first, int count, bool frame);

  gl::Texture frame_;      ///< GL_TEXTURE_2D: the frame layer's sums
  gl::Texture layers_;     ///< GL_TEXTURE_2D_ARRAY: the Sun layers'
  gl::Program fillFrame_;  ///< atmosphere/skymap_radial.comp (SKY_RADIAL_FRAME), on first use
  gl::Program fillLayers_; ///< atmosphere/skymap_radial.comp, on first use
  gl::Program mips_;       ///< atmosphere/skymap_radial_mip.comp, on first use
  gl::Program frameMips_;  ///< atmosphere/skymap_radial_mip.comp (SKY_RADIAL_FRAME), on first use
  int skyMapLayers_ = 0;
  std::vector<glm::vec3> belowHorizon_;  ///< the Sun layers', then the frame layer's
  double frameKey_ = 0.0;
};

}  // namespace og::render
