#pragma once
// RAII owners for OpenGL objects (DSA, GL 4.5). Move-only; deleting 0 is a no-op.
#include <glad/gl.h>

#include <cstddef>
#include <utility>

namespace og::gl {

template <void (*Delete)(GLuint)>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint id) : id_(id) {}
  ~Handle() { reset(); }
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  [[nodiscard]] GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_ != 0) Delete(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

void deleteBuffer(GLuint id);
void deleteVertexArray(GLuint id);
void deleteTexture(GLuint id);
void deleteFramebuffer(GLuint id);
void deleteRenderbuffer(GLuint id);
void deleteShader(GLuint id);
void deleteProgram(GLuint id);
void deleteQuery(GLuint id);

using Buffer = Handle<deleteBuffer>;
using VertexArray = Handle<deleteVertexArray>;
using Texture = Handle<deleteTexture>;
using Framebuffer = Handle<deleteFramebuffer>;
using Renderbuffer = Handle<deleteRenderbuffer>;
using ShaderObject = Handle<deleteShader>;
using ProgramObject = Handle<deleteProgram>;
using Query = Handle<deleteQuery>;

Buffer createBuffer();
/// Makes `buffer` hold at least `bytes` (immutable storage with `flags`, contents undefined):
/// where `capacity` (its size so far, bytes; 0 before the first) is less, a new buffer of
/// exactly `bytes`, and `capacity` then `bytes`. For buffers that grow with the frame and are
/// never shrunk.
void ensureBufferCapacity(Buffer& buffer, std::size_t& capacity, std::size_t bytes, GLbitfield flags = 0);
VertexArray createVertexArray();
Texture createTexture(GLenum target);
Framebuffer createFramebuffer();
Renderbuffer createRenderbuffer();
Query createQuery(GLenum target);

/// Runs `draw` inside a query of `target` (GL_SAMPLES_PASSED, GL_ANY_SAMPLES_PASSED, ...) and
/// returns its result: waits for the GL work (for tests, measurements and decisions the next
/// draw needs, not for frames that must not wait).
template <class Draw>
GLuint64 queryResult(GLenum target, Draw&& draw) {
  const Query query = createQuery(target);
  glBeginQuery(target, query.id());
  draw();
  glEndQuery(target);
  GLuint64 result = 0;
  glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &result);
  return result;
}

/// A square 2D array texture of `size`² texels × `layers` in `format` with `levels` mip levels
/// (at most fullMipLevels(size)): trilinear filtering when it has more than one level, nearest
/// otherwise; `wrap` (e.g. GL_REPEAT, GL_CLAMP_TO_EDGE) on both axes.
Texture createSquareArray(GLenum format, int size, int layers, int levels, GLenum wrap);
/// Levels of a full mip chain for a `size`-texel square, down to 1 × 1 (floor(log2 size) + 1).
int fullMipLevels(int size);

/// An off-screen render target: one colour texture and a 32-bit float depth + 8-bit stencil
/// texture (reversed-Z: clear to 0, GL_GREATER). With samples > 1 both are multisample textures
/// (GL_TEXTURE_2D_MULTISAMPLE); `samples` is then the count the driver allocated, which may
/// exceed the one asked for.
struct RenderTarget {
  Framebuffer fbo;
  Texture color;
  Texture auxiliary;  ///< optional second colour attachment (COLOR_ATTACHMENT1): extra outputs
  Texture depth;
  int width = 0;
  int height = 0;
  int samples = 1;
};

/// A single-sample colour-only target whose colour is a view of `of`'s colour in `viewFormat`
/// (glTextureView: the same bytes, e.g. a GL_SRGB8_ALPHA8 target's as GL_RGBA8, which no driver
/// decodes when read back or blitted from). Throws og::InternalError if incomplete.
RenderTarget createViewTarget(const RenderTarget& of, GLenum viewFormat);

/// A framebuffer over `colour`'s texture (COLOR_ATTACHMENT0) and `depth`'s depth-stencil
/// texture, both single-sampled and of one size: e.g. the display target's colour over the HDR
/// target's depth, for a pass that writes the display itself. Throws og::InternalError if
/// incomplete.
Framebuffer createFramebufferOver(const RenderTarget& colour, const RenderTarget& depth);

/// colorFormat e.g. GL_RGBA32F (HDR radiance) or GL_RGBA8 (display). samples must not exceed
/// maxSamples(colorFormat). Throws og::InternalError if the framebuffer is incomplete.
/// auxiliaryFormat != 0 adds a second colour attachment of that format (same samples), and
/// both attachments are draw buffers (fragment outputs 0 and 1).
RenderTarget createRenderTarget(int width, int height, GLenum colorFormat, bool withDepth,
                                int samples = 1, GLenum auxiliaryFormat = 0);

/// The most samples a multisample render target of this colour format (with a 32-bit float
/// depth + 8-bit stencil texture) can have on the current context; 1 without multisampling.
int maxSamples(GLenum colorFormat);

/// Whether the current context renders on the CPU (Mesa's llvmpipe, softpipe, swrast, or
/// lavapipe underneath Zink), from GL_RENDERER.
bool isSoftwareRenderer();

/// Throws og::InternalError naming `where` if glGetError reports an error.
void checkErrors(const char* where);

}  // namespace og::gl
