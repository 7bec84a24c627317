// The deferred sea's surface buffer (render/SeaSurfaceBuffer): it holds only the compact
// layout's layers until a frame draws without it, then all of them from then on, and its
// framebuffer stays complete and writable through the change; clearClasses zeroes the classes.
#include <gtest/gtest.h>

#include <array>

#include "gl/Context.hpp"
#include "gl/Objects.hpp"
#include "gl/ShaderContract.hpp"
#include "render/SeaSurfaceBuffer.hpp"

using namespace og;

namespace {

/// The array texture the buffer binds for reading (to gl::kUnitSeaSurface).
GLuint boundTexture(const render::SeaSurfaceBuffer& b) {
  b.bindForReading();
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(gl::kUnitSeaSurface));
  GLint texture = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &texture);
  glActiveTexture(GL_TEXTURE0);
  return static_cast<GLuint>(texture);
}

/// Its layers.
int boundLayers(const render::SeaSurfaceBuffer& b) {
  const GLuint texture = boundTexture(b);
  GLint depth = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH, &depth);
  return depth;
}

/// Clears draw buffer `i` of the bound draw framebuffer to `v` and reads layer `i` back.
std::array<GLuint, 4> clearAndRead(const render::SeaSurfaceBuffer& b, int i, GLuint v) {
  const std::array<GLuint, 4> value{v, v + 1, v + 2, v + 3};
  glClearBufferuiv(GL_COLOR, i, value.data());
  std::array<GLuint, 4> back{};
  glGetTextureSubImage(boundTexture(b), 0, 3, 2, i, 1, 1, 1, GL_RGBA_INTEGER, GL_UNSIGNED_INT,
                       sizeof back, back.data());
  return back;
}

}  // namespace

TEST(SeaSurfaceBuffer, GrowsFromTheCompactLayersOnlyWhenAFrameNeedsThemAll) {
  const auto context = gl::createHeadlessContext();
  gl::Texture depth = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(depth.id(), 1, GL_DEPTH24_STENCIL8, 16, 8);
  render::SeaSurfaceBuffer b;
  b.bindForWriting(16, 8, depth.id(), /*compact=*/true);
  EXPECT_EQ(glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(boundLayers(b), render::SeaSurfaceBuffer::kCompactLayers);
  EXPECT_EQ(clearAndRead(b, 3, 40)[2], 42u);

  b.bindForWriting(16, 8, depth.id(), /*compact=*/false);
  EXPECT_EQ(glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(boundLayers(b), render::SeaSurfaceBuffer::kLayers);
  EXPECT_EQ(clearAndRead(b, 5, 70)[3], 73u);  // the last layer is attached and drawn to

  b.bindForWriting(16, 8, depth.id(), /*compact=*/true);  // compact again: kept whole
  EXPECT_EQ(boundLayers(b), render::SeaSurfaceBuffer::kLayers);
  b.bindForWriting(32, 8, depth.id(), /*compact=*/true);  // a new size: still all of them
  EXPECT_EQ(boundLayers(b), render::SeaSurfaceBuffer::kLayers);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// Without stencil export each pixel's class lies in layer 0 (the footprint's low bits, ocean/
// sea_surface.glsl), 0 where no sea is drawn: clearClasses zeroes that layer every frame, in
// the compact layout as in the full one (last frame's classes would otherwise stay where this
// frame draws no sea; a new texture's zeros do not show it).
TEST(SeaSurfaceBuffer, ClearClassesZeroesLayerZeroInBothLayouts) {
  const auto context = gl::createHeadlessContext();
  gl::Texture depth = gl::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(depth.id(), 1, GL_DEPTH24_STENCIL8, 16, 8);
  render::SeaSurfaceBuffer b;
  for (const bool compact : {true, false}) {
    SCOPED_TRACE(compact ? "compact" : "full");
    b.bindForWriting(16, 8, depth.id(), compact);
    EXPECT_EQ(clearAndRead(b, 0, 5)[1], 6u);  // a class left from an earlier frame
    b.clearClasses();
    std::array<GLuint, 4> back{1, 1, 1, 1};
    glGetTextureSubImage(boundTexture(b), 0, 3, 2, 0, 1, 1, 1, GL_RGBA_INTEGER, GL_UNSIGNED_INT, sizeof back,
                         back.data());
    EXPECT_EQ(back[1], 0u);
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}
