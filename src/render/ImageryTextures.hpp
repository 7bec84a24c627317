#pragma once
// Imagery on the GPU (shaders/terrain/imagery.glsl): the day colour that the globe's land and
// the terrain use as albedo, and the night lights. Three textures, all sRGB-encoded (the
// sampler returns linear colour) and mip-mapped:
//  * gl::kUnitImageryDay: the base day image, global (the embedded Blue Marble, 2048 × 1024);
//  * gl::kUnitImageryNight: the night lights, global (the embedded Earth at night, 2048 × 1024);
//  * gl::kUnitImageryLayers: the `--imagery-layer`s, a 2D array of kImageryLayerSizePx² layers
//    each over its own latitude/longitude extent, alpha = coverage, later layers on top.
// Each user layer is one whole mip-mapped texture (not streamed tiles): ~21 MiB of GPU memory
// per 2048² layer, at most data::kMaxImageryLayers (8) layers, so ≤ 170 MiB.
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "data/GeoRaster.hpp"
#include "gl/Objects.hpp"
#include "gl/Shader.hpp"

namespace og::render {

class ImageryTextures {
 public:
  /// Needs a current GL context. Uploads the embedded day and night images.
  ImageryTextures();

  /// Replaces the user's imagery layers (later ones on top); empty: only the base image.
  /// All layers must be square and of one size (data::loadImageryLayers makes them so).
  void setLayers(const std::vector<data::GeoImage>& layers);

  /// Scales the night lights' radiance (1 = the default; 0 = none). See imagery.glsl.
  void setNightLights(float scale) { nightScale_ = scale; }
  [[nodiscard]] float nightLights() const { return nightScale_; }

  /// Draws land with the stand-in material ramps instead of the imagery (comparisons, tests).
  void setEnabled(bool enabled) { enabled_ = enabled; }
  [[nodiscard]] bool enabled() const { return enabled_; }

  /// Bytes of GPU memory the imagery textures hold (with mip-maps).
  [[nodiscard]] std::size_t gpuBytes() const { return bytes_; }

  /// Binds the textures (gl::kUnitImagery*) and sets imagery.glsl's uniforms on `program`.
  void bind(const gl::Program& program) const;

 private:
  gl::Texture day_;
  gl::Texture night_;
  gl::Texture layers_;
  int layerCount_ = 0;
  std::vector<glm::vec4> layerBounds_;  ///< west, south, east, north, radians
  float layerTexelRad_ = 1.0f;          ///< angular size of a layer texel (the finest layer's)
  float dayTexelRad_ = 1.0f;
  float nightScale_ = 1.0f;
  bool enabled_ = true;
  std::size_t bytes_ = 0;
};

}  // namespace og::render
