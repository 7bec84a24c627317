#pragma once
// The sky maps' radial rip-map: the frame layer of the sky maps (Atmosphere::prepareFrameSkyLayer)
// prefiltered along the map's radial direction, so that the sea's reflected sky is filtered over
// its footprint ellipse in one lookup on a CPU rasteriser (shaders/atmosphere/skymap_rip.comp,
// skymap.glsl's SKY_RIP_MAP; docs/ocean.md, "The sky filter").
#include <vector>

#include "gl/Objects.hpp"
#include "gl/Shader.hpp"

namespace og::render {

class SkyRipMap {
 public:
  /// Radial blurs of 1, 2, 4, 8 texels: footprints up to 8:1 in one lookup (longer ones are
  /// filtered isotropically over an eighth of their major axis).
  static constexpr int kLayers = 4;

  /// Refills the rip-map from the frame layer of the sky maps bound at gl::kUnitSkyMap
  /// (`skyMapSize` texels square, every mip level). Skipped when `frameKey` (what the frame layer
  /// was made from: the Sun's zenith angle) did not change.
  void update(int skyMapSize, double frameKey);
  /// Binds the rip-map to gl::kUnitSkyRipMap.
  void bind() const;
  [[nodiscard]] bool ready() const { return texture_.id() != 0; }
  /// Level 0 of the rip-map (rgba per texel, layer after layer, rows from v = 0), for tests.
  [[nodiscard]] std::vector<float> read() const;

 private:
  gl::Texture texture_;
  gl::Program fill_;  ///< atmosphere/skymap_rip.comp, compiled on first use
  int size_ = 0;
  double frameKey_ = 0.0;
};

}  // namespace og::render
