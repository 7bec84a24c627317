// EGL headless contexts: first a device (EGL_EXT_platform_device; hardware before Mesa's
// software device), then Mesa's surfaceless platform. No window system, no surface: we render
// to framebuffer objects (EGL_KHR_surfaceless_context).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "gl/Context.hpp"

namespace og::gl {
namespace {

bool hasExtension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

template <class Fn>
Fn proc(const char* name) {
  return reinterpret_cast<Fn>(eglGetProcAddress(name));
}

void* eglProc(const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); }

std::string eglErrorString() {
  char buf[32];
  std::snprintf(buf, sizeof buf, "EGL error 0x%04x", static_cast<unsigned>(eglGetError()));
  return buf;
}

class EglContext final : public Context {
 public:
  EglContext(EGLDisplay display, EGLContext context, std::string kind)
      : display_(display), context_(context) {
    bind();
    finishInit(std::move(kind), eglProc);
  }
  ~EglContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
  void bind() override {
    if (eglGetCurrentContext() == context_) return;
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw InternalError("eglMakeCurrent failed: " + eglErrorString());
  }

 private:
  EGLDisplay display_;
  EGLContext context_;
};

/// Initialises `display` and creates a 4.5 core context on it, or says why not.
std::unique_ptr<Context> tryDisplay(EGLDisplay display, const std::string& kind,
                                    std::string& why) {
  if (display == EGL_NO_DISPLAY) {
    why += kind + ": no display; ";
    return nullptr;
  }
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) {
    why += kind + ": eglInitialize failed (" + eglErrorString() + "); ";
    return nullptr;
  }
  const char* exts = eglQueryString(display, EGL_EXTENSIONS);
  if (!hasExtension(exts, "EGL_KHR_surfaceless_context")) {
    why += kind + ": no EGL_KHR_surfaceless_context; ";
    eglTerminate(display);
    return nullptr;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    why += kind + ": desktop OpenGL not supported; ";
    eglTerminate(display);
    return nullptr;
  }
  EGLConfig config = nullptr;
  if (!hasExtension(exts, "EGL_KHR_no_config_context")) {
    const EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                              EGL_PBUFFER_BIT, EGL_NONE};
    EGLint count = 0;
    if (!eglChooseConfig(display, attribs, &config, 1, &count) || count < 1) {
      why += kind + ": no OpenGL config; ";
      eglTerminate(display);
      return nullptr;
    }
  }
  const EGLint ctxAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext ctx = eglCreateContext(display, config, EGL_NO_CONTEXT, ctxAttribs);
  if (ctx == EGL_NO_CONTEXT) {
    why += kind + ": no OpenGL 4.5 core context (" + eglErrorString() + "); ";
    eglTerminate(display);
    return nullptr;
  }
  try {
    return std::make_unique<EglContext>(display, ctx, kind);
  } catch (const InternalError& e) {
    why += kind + ": " + e.what() + "; ";
    return nullptr;
  }
}

}  // namespace

std::unique_ptr<Context> createEglContext() {
  const char* clientExts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (clientExts == nullptr) throw InternalError("EGL is not available (no client extensions)");
  auto getPlatformDisplay = proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  std::string why;

  if (hasExtension(clientExts, "EGL_EXT_platform_device") && getPlatformDisplay) {
    auto queryDevices = proc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    auto queryDeviceString = proc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
    EGLint count = 0;
    std::vector<EGLDeviceEXT> devices(16);
    if (queryDevices && queryDevices(static_cast<EGLint>(devices.size()), devices.data(), &count)) {
      devices.resize(static_cast<std::size_t>(count));
      // Real GPUs first: Mesa lists its software rasteriser as a device too.
      std::vector<EGLDeviceEXT> ordered;
      for (int pass = 0; pass < 2; ++pass)
        for (EGLDeviceEXT d : devices) {
          const char* dexts = queryDeviceString ? queryDeviceString(d, EGL_EXTENSIONS) : nullptr;
          const bool software = hasExtension(dexts, "EGL_MESA_device_software");
          if (software == (pass == 1)) ordered.push_back(d);
        }
      for (std::size_t i = 0; i < ordered.size(); ++i) {
        EGLDisplay dpy = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, ordered[i], nullptr);
        if (auto ctx = tryDisplay(dpy, "egl-device", why)) return ctx;
      }
    }
  }
  if (hasExtension(clientExts, "EGL_MESA_platform_surfaceless") && getPlatformDisplay) {
    EGLDisplay dpy = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (auto ctx = tryDisplay(dpy, "egl-surfaceless", why)) return ctx;
  }
  throw InternalError(why.empty() ? "no usable EGL platform" : why.substr(0, why.size() - 2));
}

}  // namespace og::gl
