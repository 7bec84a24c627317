#pragma once
// Draws text (rasterised with the built-in bitmap font) over the default framebuffer of the
// current GL context. GL lives here, not in the font or the controller.
#include <string>
#include <vector>

#include "gl/Objects.hpp"
#include "gl/Shader.hpp"

namespace og::app::viewer {

class TextOverlay {
 public:
  /// Needs a current GL 4.5 context.
  TextOverlay();
  /// Draws `lines` with their top-left corner `marginPx` from the framebuffer's top-left,
  /// glyphs magnified by `scale`. Re-uploads only when the text changed.
  void draw(const std::vector<std::string>& lines, int framebufferWidth, int framebufferHeight,
            int scale, int marginPx = 6);

 private:
  gl::Program program_;
  gl::VertexArray vao_;
  gl::Texture texture_;
  int width_ = 0, height_ = 0;
  std::vector<std::string> uploaded_;
  int uploadedScale_ = 0;
};

}  // namespace og::app::viewer
