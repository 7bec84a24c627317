#include "render/SeaSurfaceBuffer.hpp"

#include <algorithm>
#include <array>
#include <cassert>

#include "gl/ShaderContract.hpp"
#include "core/Error.hpp"

namespace og::render {

SeaSurfaceBuffer::DepthStencil SeaSurfaceBuffer::boundDepthStencil() {
  GLint fbo = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
  if (fbo == 0) return {};
  const auto name = static_cast<GLuint>(fbo);
  GLint type = GL_NONE, object = 0;
  glGetNamedFramebufferAttachmentParameteriv(name, GL_DEPTH_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  if (type != GL_TEXTURE) return {};
  glGetNamedFramebufferAttachmentParameteriv(name, GL_DEPTH_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &object);
  GLint samples = 0;
  glGetTextureLevelParameteriv(static_cast<GLuint>(object), 0, GL_TEXTURE_SAMPLES, &samples);
  return {static_cast<GLuint>(object), std::max(samples, 1)};
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
    width_ = width, height_ = height, depthStencil_ = 0, drawBuffers_ = 0, allocated_ = layers, visibilityInSurface_ = 0;
  }
  drawLayers(compact);
  attachDepthStencil(fbo_, depthStencil, &depthStencil_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_.id());
}

void SeaSurfaceBuffer::attachDepthStencil(const gl::Framebuffer& fbo, GLuint depthStencil, GLuint* attached) {
  if (depthStencil == *attached) return;
  glNamedFramebufferTexture(fbo.id(), GL_DEPTH_STENCIL_ATTACHMENT, depthStencil, 0);
  *attached = depthStencil;
  if (glCheckNamedFramebufferStatus(fbo.id(), GL_DRAW_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw InternalError("SeaSurfaceBuffer: the surface buffer's framebuffer is incomplete");
}

void SeaSurfaceBuffer::ensureVisibility(int width, int height, int samples) {
  if (width == visibilityWidth_ && height == visibilityHeight_ && samples == visibilitySamples_ && visibility_.id() != 0)
    return;
  if (samples > 1) {  // (fixed sample locations, as gl::createRenderTarget's depth)
    visibility_ = gl::createTexture(GL_TEXTURE_2D_MULTISAMPLE);
    glTextureStorage2DMultisample(visibility_.id(), samples, GL_R32UI, width, height, GL_TRUE);
  } else {
    visibility_ = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(visibility_.id(), 1, GL_R32UI, width, height);
    glTextureParameteri(visibility_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(visibility_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  visibilityFbo_ = gl::createFramebuffer();
  glNamedFramebufferTexture(visibilityFbo_.id(), GL_COLOR_ATTACHMENT0, visibility_.id(), 0);
  visibilityWidth_ = width, visibilityHeight_ = height, visibilitySamples_ = samples, visibilityDepthStencil_ = 0;
  visibilityInSurface_ = 0;  // (a driver may give the new texture the old one's name)
}

void SeaSurfaceBuffer::bindVisibilityForWriting(int width, int height, GLuint depthStencil, int samples) {
  ensureVisibility(width, height, samples);
  attachDepthStencil(visibilityFbo_, depthStencil, &visibilityDepthStencil_);
  const std::array<GLuint, 4> none{};
  glClearNamedFramebufferuiv(visibilityFbo_.id(), GL_COLOR, 0, none.data());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, visibilityFbo_.id());
}

void SeaSurfaceBuffer::drawVisibility() {
  ensureVisibility(width_, height_, 1);
  constexpr GLenum kAttachment = GL_COLOR_ATTACHMENT0 + kLayers;
  if (visibilityInSurface_ != visibility_.id()) {
    glNamedFramebufferTexture(fbo_.id(), kAttachment, visibility_.id(), 0);
    visibilityInSurface_ = visibility_.id();
  }
  glNamedFramebufferDrawBuffers(fbo_.id(), 1, &kAttachment);
  drawBuffers_ = 0;  // (drawLayers sets the layers' again)
}

void SeaSurfaceBuffer::bindVisibilityForReading() const { glBindTextureUnit(gl::kUnitSeaSurface, visibility_.id()); }

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
