#pragma once
// Renders one frame of the globe into off-screen targets: an HDR radiance target (linear,
// float, alpha = coverage, reversed-Z depth) and a display target (tone-mapped sRGB, 8-bit).
#include <glm/glm.hpp>

#include <vector>

#include "data/LatLonGrid.hpp"
#include "geo/Camera.hpp"
#include "gl/Objects.hpp"
#include "gl/Shader.hpp"
#include "io/Image.hpp"

namespace og::render {

struct FrameInput {
  geo::CameraPose camera;
  glm::dvec3 sunDirectionEcef{1.0, 0.0, 0.0};  ///< unit, towards the Sun
  double exposure = 10.0;  ///< multiplies radiance (Sun-irradiance units) before tone mapping
  int width = 256;
  int height = 256;
  double simulationTimeS = 0.0;  ///< seconds since the start of the sequence (wave animation)
};

class GlobeRenderer {
 public:
  /// Needs a current GL 4.5 context. Uploads the elevation layer once.
  explicit GlobeRenderer(const data::LatLonGrid& elevation);

  /// Draws a frame into the internal targets (resized as needed).
  void render(const FrameInput& frame);

  /// Results of the last render().
  [[nodiscard]] io::ImageRgbaF radiance() const;
  [[nodiscard]] io::ImageRgba8 display() const;
  [[nodiscard]] std::vector<float> depth() const;

  /// The tone-mapped display target of the last render() (for blitting to a window).
  [[nodiscard]] GLuint displayFramebuffer() const { return ldr_.fbo.id(); }

  /// Blocks until the GPU has finished the last frame (for timing).
  static void finish();

 private:
  void ensureTargets(int width, int height);

  gl::Program globe_;
  gl::Program tonemap_;
  gl::VertexArray emptyVao_;
  gl::Texture elevation_;
  glm::vec4 elevationMap_{};
  glm::vec2 elevationSize_{};
  int elevationWraps_ = 0;
  gl::RenderTarget hdr_;
  gl::RenderTarget ldr_;
};

}  // namespace og::render
