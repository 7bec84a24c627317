#include "gl/Context.hpp"

#include <glad/gl.h>

#include <cstdlib>
#include <string_view>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "gl/Loader.hpp"

namespace og::gl {

std::optional<Backend> parseBackend(std::string_view name) {
  if (name == "auto") return Backend::Auto;
  if (name == "egl") return Backend::Egl;
  if (name == "osmesa") return Backend::OsMesa;
  return std::nullopt;
}

const char* backendName(Backend b) {
  switch (b) {
    case Backend::Auto: return "auto";
    case Backend::Egl: return "egl";
    case Backend::OsMesa: return "osmesa";
  }
  return "?";
}

namespace {
const Context* gLoadedBy = nullptr;  // whose entry points glad currently holds

bool hasGlExtension(std::string_view name) {
  GLint n = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &n);
  for (GLint i = 0; i < n; ++i) {
    const auto* e = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
    if (e != nullptr && name == e) return true;
  }
  return false;
}

// An environment switch set to "0" (the paths it turns off are for comparing, not for users).
bool envSaysOff(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr && std::string_view(v) == "0";
}
}  // namespace

Context::~Context() {
  if (gLoadedBy == this) gLoadedBy = nullptr;
}

void Context::makeCurrent() {
  bind();
  if (gLoadedBy != this && getProcAddress_ != nullptr) {
    loadGlFunctions(getProcAddress_);
    gLoadedBy = this;
  }
}

void Context::finishInit(std::string backend, void* (*getProcAddress)(const char*)) {
  getProcAddress_ = getProcAddress;
  loadGlFunctions(getProcAddress);
  gLoadedBy = this;
  auto str = [](GLenum e) {
    const auto* s = reinterpret_cast<const char*>(glGetString(e));
    return std::string(s ? s : "");
  };
  info_.backend = std::move(backend);
  info_.vendor = str(GL_VENDOR);
  info_.renderer = str(GL_RENDERER);
  info_.version = str(GL_VERSION);
  GLfloat anisotropy = 1.0f;  // GL 4.6 or ARB/EXT_texture_filter_anisotropic; else an error
  glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &anisotropy);
  while (glGetError() != GL_NO_ERROR) {
  }
  info_.profile = makeDriverProfile(info_.renderer, anisotropy);
  info_.profile.stencilExport = hasGlExtension("GL_ARB_shader_stencil_export") &&
                                !envSaysOff("OCEANGLOBE_STENCIL_EXPORT");
  if (const char* fft = std::getenv("OCEANGLOBE_FFT"); fft != nullptr && *fft != '\0')
    info_.profile.cpuWaveFft = std::string_view(fft) == "cpu";
  if (const char* blocks = std::getenv("OCEANGLOBE_MSAA_PART_BLOCKS"); blocks != nullptr && *blocks != '\0')
    info_.profile.multisampleShadesEveryBlock = std::string_view(blocks) == "1";
  log::info("GL context: " + info_.backend + ", " + info_.renderer + ", " + info_.version);
}

const ContextInfo& currentContextInfo() {
  if (gLoadedBy == nullptr) throw InternalError("no GL context of ours is current");
  return gLoadedBy->info();
}

const DriverProfile& driverProfile() { return currentContextInfo().profile; }

std::unique_ptr<Context> createHeadlessContext(Backend backend) {
  switch (backend) {
    case Backend::Egl: return createEglContext();
    case Backend::OsMesa: return createOsMesaContext();
    case Backend::Auto: break;
  }
  std::string why;
  try {
    return createEglContext();
  } catch (const InternalError& e) {
    why = std::string("EGL: ") + e.what();
    log::info(why + "; trying OSMesa");
  }
  try {
    return createOsMesaContext();
  } catch (const InternalError& e) {
    throw InternalError("no OpenGL 4.5 context available (" + why + "; OSMesa: " + e.what() +
                        ")");
  }
}

}  // namespace og::gl
