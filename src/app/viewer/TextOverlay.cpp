#include "app/viewer/TextOverlay.hpp"

#include "app/viewer/BitmapFont.hpp"
#include "gl/ShaderContract.hpp"

namespace og::app::viewer {

TextOverlay::TextOverlay()
    : program_({{GL_VERTEX_SHADER, "viewer/text.vert"}, {GL_FRAGMENT_SHADER, "viewer/text.frag"}}),
      vao_(gl::createVertexArray()) {
  program_.requireUniforms({"uRect", "uText"});  // what draw() sets
}

void TextOverlay::draw(const std::vector<std::string>& lines, int fbWidth, int fbHeight, int scale,
                       int marginPx) {
  if (lines.empty() || fbWidth <= 0 || fbHeight <= 0) return;
  if (lines != uploaded_ || scale != uploadedScale_ || !texture_) {
    const io::ImageRgba8 image = rasterizeText(lines, scale);
    if (!texture_ || image.width != width_ || image.height != height_) {
      // Immutable storage cannot be resized: a new texture for a new size.
      texture_ = gl::createTexture(GL_TEXTURE_2D);
      glTextureStorage2D(texture_.id(), 1, GL_RGBA8, image.width, image.height);
      glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      width_ = image.width;
      height_ = image.height;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(texture_.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        image.pixels.data());
    uploaded_ = lines;
    uploadedScale_ = scale;
  }
  // Pixel rectangle from the top-left corner, to NDC (y up).
  const float x0 = -1.0f + 2.0f * static_cast<float>(marginPx) / static_cast<float>(fbWidth);
  const float x1 = x0 + 2.0f * static_cast<float>(width_) / static_cast<float>(fbWidth);
  const float y1 = 1.0f - 2.0f * static_cast<float>(marginPx) / static_cast<float>(fbHeight);
  const float y0 = y1 - 2.0f * static_cast<float>(height_) / static_cast<float>(fbHeight);

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fbWidth, fbHeight);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  program_.use();
  program_.set("uRect", glm::vec4(x0, y0, x1, y1));
  program_.set("uText", 0);
  glBindTextureUnit(gl::kUnitOverlayText, texture_.id());
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glBindVertexArray(0);
  glDisable(GL_BLEND);
}

}  // namespace og::app::viewer
