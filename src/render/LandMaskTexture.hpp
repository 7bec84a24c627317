#pragma once
// The GSHHG land mask on the GPU (shaders/terrain/landmask.glsl): data::LandMask's packed bits
// as an R16UI texture on gl::kUnitLandMask, texel x of a row holding columns 8x − 4 … 8x + 11
// (1350 × 5400 texels, 14 MiB for the 2′ default), bound only
// where the mask decides the coast (a global elevation layer coarser than it); a 1×1 texture
// there otherwise, which landmask.glsl reads as "no mask".
#include <vector>

#include <glm/vec2.hpp>

#include "data/LandMask.hpp"
#include "gl/Objects.hpp"

namespace og::render {

class LandMaskTexture {
 public:
  /// Needs a current GL context. `mask` nullptr: no mask (the elevation layer's zero contour).
  explicit LandMaskTexture(const data::LandMask* mask);
  /// Binds the mask (or the 1×1 stand-in) to gl::kUnitLandMask.
  void bind() const;
  [[nodiscard]] bool active() const { return active_; }
  [[nodiscard]] std::size_t gpuBytes() const { return bytes_; }
  /// landmask.glsl's landFraction at (latitude, longitude) radians, evaluated on the GPU (for
  /// tests against data::LandMask::landFraction). Binds unit 18.
  [[nodiscard]] std::vector<float> probeLandFraction(const std::vector<glm::vec2>& latLonRad) const;

 private:
  gl::Texture texture_;
  bool active_ = false;
  std::size_t bytes_ = 0;
};

}  // namespace og::render
