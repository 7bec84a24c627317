// OSMesa: Mesa's off-screen rasteriser, a fallback where EGL is unavailable.
#include <GL/osmesa.h>

#include <vector>

#include "core/Error.hpp"
#include "gl/Context.hpp"

namespace og::gl {
namespace {

void* osmesaProc(const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }

class OsMesaContext final : public Context {
 public:
  OsMesaContext() {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                           OSMESA_STENCIL_BITS, 0, OSMESA_ACCUM_BITS, 0,
                           OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
    context_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (context_ == nullptr) throw InternalError("OSMesa could not create a 4.5 core context");
    bind();
    finishInit("osmesa", osmesaProc);
  }
  ~OsMesaContext() override { OSMesaDestroyContext(context_); }
  void bind() override {
    if (OSMesaGetCurrentContext() == context_) return;
    // The default framebuffer is a token 1x1 buffer: all rendering goes to FBOs.
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1))
      throw InternalError("OSMesaMakeCurrent failed");
  }

 private:
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_ = std::vector<unsigned char>(4);
};

}  // namespace

std::unique_ptr<Context> createOsMesaContext() { return std::make_unique<OsMesaContext>(); }

}  // namespace og::gl
