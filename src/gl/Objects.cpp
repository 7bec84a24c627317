#include "gl/Objects.hpp"

#include "gl/DriverProfile.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/Error.hpp"

namespace og::gl {

void deleteBuffer(GLuint id) { glDeleteBuffers(1, &id); }
void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
void deleteTexture(GLuint id) { glDeleteTextures(1, &id); }
void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
void deleteRenderbuffer(GLuint id) { glDeleteRenderbuffers(1, &id); }
void deleteShader(GLuint id) { glDeleteShader(id); }
void deleteProgram(GLuint id) { glDeleteProgram(id); }
void deleteQuery(GLuint id) { glDeleteQueries(1, &id); }

Buffer createBuffer() {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  return Buffer(id);
}
void ensureBufferCapacity(Buffer& buffer, std::size_t& capacity, std::size_t bytes, GLbitfield flags) {
  if (bytes <= capacity) return;
  buffer = createBuffer();
  glNamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(bytes), nullptr, flags);
  capacity = bytes;
}
VertexArray createVertexArray() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return VertexArray(id);
}
Texture createTexture(GLenum target) {
  GLuint id = 0;
  glCreateTextures(target, 1, &id);
  return Texture(id);
}
Framebuffer createFramebuffer() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  return Framebuffer(id);
}
Renderbuffer createRenderbuffer() {
  GLuint id = 0;
  glCreateRenderbuffers(1, &id);
  return Renderbuffer(id);
}
Query createQuery(GLenum target) {
  GLuint id = 0;
  glCreateQueries(target, 1, &id);
  return Query(id);
}

Texture createSquareArray(GLenum format, int size, int layers, int levels, GLenum wrap) {
  Texture t = createTexture(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(t.id(), levels, format, size, size, layers);
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, levels > 1 ? GL_LINEAR : GL_NEAREST);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
  return t;
}

int fullMipLevels(int size) {
  int levels = 1;
  while ((size >> levels) > 0) ++levels;
  return levels;
}

namespace {
// Throws og::InternalError "<what> incomplete (0x....)" unless `fbo` is complete.
void requireComplete(const Framebuffer& fbo, const char* what) {
  const GLenum status = glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER);
  if (status == GL_FRAMEBUFFER_COMPLETE) return;
  char buf[64];
  std::snprintf(buf, sizeof buf, " incomplete (0x%04x)", status);
  throw InternalError(std::string(what) + buf);
}
}  // namespace

RenderTarget createViewTarget(const RenderTarget& of, GLenum viewFormat) {
  RenderTarget t;
  t.width = of.width;
  t.height = of.height;
  GLuint view = 0;
  glGenTextures(1, &view);  // (a view needs a name never bound: glCreateTextures' are)
  glTextureView(view, GL_TEXTURE_2D, of.color.id(), viewFormat, 0, 1, 0, 1);
  t.color = Texture(view);
  checkErrors("gl::createViewTarget (glTextureView)");
  t.fbo = createFramebuffer();
  glNamedFramebufferTexture(t.fbo.id(), GL_COLOR_ATTACHMENT0, t.color.id(), 0);
  requireComplete(t.fbo, "view framebuffer");
  return t;
}

Framebuffer createFramebufferOver(const RenderTarget& colour, const RenderTarget& depth) {
  if (colour.samples != 1 || depth.samples != 1 || colour.width != depth.width || colour.height != depth.height)
    throw InternalError("gl::createFramebufferOver needs single-sampled targets of one size");
  Framebuffer fbo = createFramebuffer();
  glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, colour.color.id(), 0);
  glNamedFramebufferTexture(fbo.id(), GL_DEPTH_STENCIL_ATTACHMENT, depth.depth.id(), 0);
  requireComplete(fbo, "framebuffer over two targets");
  return fbo;
}

RenderTarget createRenderTarget(int width, int height, GLenum colorFormat, bool withDepth,
                                int samples, GLenum auxiliaryFormat) {
  RenderTarget t;
  t.width = width;
  t.height = height;
  t.fbo = createFramebuffer();
  const bool multisample = samples > 1;
  // Fixed sample locations: colour and depth must agree for the framebuffer to be complete.
  auto storage = [&](const Texture& tex, GLenum format) {
    if (multisample)
      glTextureStorage2DMultisample(tex.id(), samples, format, width, height, GL_TRUE);
    else
      glTextureStorage2D(tex.id(), 1, format, width, height);
  };
  const GLenum target = multisample ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D;
  auto colour = [&](Texture& tex, GLenum format, GLenum attachment) {
    tex = createTexture(target);
    storage(tex, format);
    if (!multisample) {  // multisample textures have no sampler state
      glTextureParameteri(tex.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      glTextureParameteri(tex.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTextureParameteri(tex.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    glNamedFramebufferTexture(t.fbo.id(), attachment, tex.id(), 0);
  };
  colour(t.color, colorFormat, GL_COLOR_ATTACHMENT0);
  if (auxiliaryFormat != 0) {
    colour(t.auxiliary, auxiliaryFormat, GL_COLOR_ATTACHMENT1);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(t.fbo.id(), 2, buffers);
  }
  if (withDepth) {
    t.depth = createTexture(target);
    storage(t.depth, GL_DEPTH32F_STENCIL8);
    glNamedFramebufferTexture(t.fbo.id(), GL_DEPTH_STENCIL_ATTACHMENT, t.depth.id(), 0);
  }
  if (multisample) {
    GLint allocated = 0;
    glGetTextureLevelParameteriv(t.color.id(), 0, GL_TEXTURE_SAMPLES, &allocated);
    t.samples = static_cast<int>(allocated);
  }
  requireComplete(t.fbo, "framebuffer");
  return t;
}

int maxSamples(GLenum colorFormat) {
  GLint limit = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &limit);
  for (const GLenum pname : {GL_MAX_COLOR_TEXTURE_SAMPLES, GL_MAX_DEPTH_TEXTURE_SAMPLES}) {
    GLint v = 1;
    glGetIntegerv(pname, &v);
    limit = std::min(limit, v);
  }
  // Per format: float formats may allow fewer samples than the global limits.
  for (const GLenum format : {colorFormat, static_cast<GLenum>(GL_DEPTH32F_STENCIL8)}) {
    GLint counts = 0, highest = 1;
    glGetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, format, GL_NUM_SAMPLE_COUNTS, 1, &counts);
    if (counts > 0) glGetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, format, GL_SAMPLES, 1, &highest);
    limit = std::min(limit, highest);  // counts come highest first
  }
  return std::max(limit, 1);
}

bool isSoftwareRenderer() { return driverProfile().software; }

void checkErrors(const char* where) {
  const GLenum e = glGetError();
  if (e == GL_NO_ERROR) return;
  char buf[64];
  std::snprintf(buf, sizeof buf, "OpenGL error 0x%04x", e);
  throw InternalError(std::string(buf) + " in " + where);
}

}  // namespace og::gl
