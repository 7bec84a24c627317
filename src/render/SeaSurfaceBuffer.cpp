#include "render/SeaSurfaceBuffer.hpp"

#include <array>
#include <cassert>

#include "gl/ShaderContract.hpp"
#include "core/Error.hpp"

namespace og::render {

GLuint SeaSurfaceBuffer::boundDepthStencilTexture() {
  GLint fbo = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
  if (fbo == 0) return 0;
  const auto name = static_cast<GLuint>(fbo);
  GLint type = GL_NONE, object = 0;
  glGetNamedFramebufferAttachmentParameteriv(name, GL_DEPTH_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  if (type != GL_TEXTURE) return 0;
  glGetNamedFramebufferAttachmentParameteriv(name, GL_DEPTH_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &object);
  GLint samples = 0;
  glGetTextureLevelParameteriv(static_cast<GLuint>(object), 0, GL_TEXTURE_SAMPLES, &samples);
  return samples <= 1 ? static_cast<GLuint>(object) : 0;
}

void SeaSurfaceBuffer::bindForWriting(int width, int height, GLuint depthStencil, bool compact) {
  // Only the compact layout's layers until a frame needs them all (then all, from then on):
  // llvmpipe zeroes a texture's storage when it makes it, and the two layers more are 29 MB at
  // 1280 x 720, ~15 ms of a first frame over the open sea.
  const int layers = compact && allocated_ < kLayers ? kCompactLayers : kLayers;
  if (width != width_ || height != height_ || layers_.id() == 0 || layers > allocated_) {
    layers_ = gl::createTexture(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(layers_.id(), 1, GL_RGBA32UI, width, height, layers);
    glTextureParameteri(layers_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(layers_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    fbo_ = gl::createFramebuffer();
    for (int i = 0; i < layers; ++i)
      glNamedFramebufferTextureLayer(fbo_.id(), GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i), layers_.id(), 0, i);
    width_ = width, height_ = height, depthStencil_ = 0, drawBuffers_ = 0, allocated_ = layers;
  }
  drawLayers(compact);
  if (depthStencil != depthStencil_) {
    glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_STENCIL_ATTACHMENT, depthStencil, 0);
    depthStencil_ = depthStencil;
    if (glCheckNamedFramebufferStatus(fbo_.id(), GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw InternalError("SeaSurfaceBuffer: the surface buffer's framebuffer is incomplete");
  }
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_.id());
}

void SeaSurfaceBuffer::drawLayers(bool compact) {
  assert(compact || allocated_ == kLayers);  // (the full layout's layers made by bindForWriting)
  // Each layer written costs llvmpipe ~0.9 ms a frame at 640x360 (one thread): the compact
  // layout leaves the water volume's two off.
  if (const int n = compact ? kCompactLayers : kLayers; n != drawBuffers_) {
    std::array<GLenum, kLayers> buffers{};
    for (int i = 0; i < kLayers; ++i)
      buffers.at(static_cast<std::size_t>(i)) = i < n ? GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i) : GL_NONE;
    glNamedFramebufferDrawBuffers(fbo_.id(), kLayers, buffers.data());
    drawBuffers_ = n;
  }
}

void SeaSurfaceBuffer::clearClasses() const {
  constexpr GLint kClassLayer = 0;  // its .y's low bits (ocean/sea_surface.glsl's SEA_CLASS_BITS)
  const std::array<GLuint, 4> none{};
  glClearNamedFramebufferuiv(fbo_.id(), GL_COLOR, kClassLayer, none.data());
}

void SeaSurfaceBuffer::bindForReading() const { glBindTextureUnit(gl::kUnitSeaSurface, layers_.id()); }

}  // namespace og::render
