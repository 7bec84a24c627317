#include "gl/Objects.hpp"

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

RenderTarget createRenderTarget(int width, int height, GLenum colorFormat, bool withDepth) {
  RenderTarget t;
  t.width = width;
  t.height = height;
  t.fbo = createFramebuffer();
  t.color = createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(t.color.id(), 1, colorFormat, width, height);
  glTextureParameteri(t.color.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t.color.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.color.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.color.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glNamedFramebufferTexture(t.fbo.id(), GL_COLOR_ATTACHMENT0, t.color.id(), 0);
  if (withDepth) {
    t.depth = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t.depth.id(), 1, GL_DEPTH_COMPONENT32F, width, height);
    glNamedFramebufferTexture(t.fbo.id(), GL_DEPTH_ATTACHMENT, t.depth.id(), 0);
  }
  const GLenum status = glCheckNamedFramebufferStatus(t.fbo.id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "framebuffer incomplete (0x%04x)", status);
    throw InternalError(buf);
  }
  return t;
}

void checkErrors(const char* where) {
  const GLenum e = glGetError();
  if (e == GL_NO_ERROR) return;
  char buf[64];
  std::snprintf(buf, sizeof buf, "OpenGL error 0x%04x", e);
  throw InternalError(std::string(buf) + " in " + where);
}

}  // namespace og::gl
