#include "gl/Readback.hpp"

#include <algorithm>

namespace og::gl {
namespace {
template <class T>
std::vector<T> read(GLuint fbo, int width, int height, GLenum format, GLenum type,
                     int components) {
  const auto rowLen = static_cast<std::size_t>(width) * static_cast<std::size_t>(components);
  std::vector<T> pixels(rowLen * static_cast<std::size_t>(height));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadnPixels(0, 0, width, height, format, type, static_cast<GLsizei>(pixels.size() * sizeof(T)),
                pixels.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(pixels.begin() + static_cast<std::ptrdiff_t>(rowLen * static_cast<std::size_t>(y)),
                     pixels.begin() + static_cast<std::ptrdiff_t>(rowLen * static_cast<std::size_t>(y + 1)),
                     pixels.begin() + static_cast<std::ptrdiff_t>(rowLen * static_cast<std::size_t>(height - 1 - y)));
  return pixels;
}
}  // namespace

std::vector<float> readRgbaF(GLuint fbo, int width, int height) {
  return read<float>(fbo, width, height, GL_RGBA, GL_FLOAT, 4);
}
std::vector<std::uint8_t> readRgba8(GLuint fbo, int width, int height) {
  return read<std::uint8_t>(fbo, width, height, GL_RGBA, GL_UNSIGNED_BYTE, 4);
}
std::vector<float> readRedF(GLuint fbo, int width, int height, int attachment) {
  glNamedFramebufferReadBuffer(fbo, static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + attachment));
  std::vector<float> v = read<float>(fbo, width, height, GL_RED, GL_FLOAT, 1);
  glNamedFramebufferReadBuffer(fbo, GL_COLOR_ATTACHMENT0);
  return v;
}
std::vector<float> readDepth(GLuint fbo, int width, int height) {
  return read<float>(fbo, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, 1);
}

}  // namespace og::gl
