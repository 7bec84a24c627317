#pragma once
// OpenGL 4.5 core contexts behind one interface. Headless rendering uses EGL (a GPU through
// EGL_EXT_platform_device where present, else Mesa's surfaceless platform) or OSMesa; the
// interactive viewer uses a GLFW window (GlfwWindow.hpp). All draw into framebuffer objects.
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "gl/DriverProfile.hpp"

namespace og::gl {

enum class Backend { Auto, Egl, OsMesa };

/// Parses "auto" | "egl" | "osmesa".
std::optional<Backend> parseBackend(std::string_view name);
const char* backendName(Backend b);

struct ContextInfo {
  std::string backend;   ///< "egl-device", "egl-surfaceless", "osmesa", "glfw"
  std::string vendor;    ///< GL_VENDOR
  std::string renderer;  ///< GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string version;   ///< GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6"
  DriverProfile profile; ///< what this driver is good and bad at, decided once (DriverProfile.hpp)
};

class Context {
 public:
  virtual ~Context();
  Context() = default;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  /// Makes this context current on the calling thread; GL entry points are reloaded when a
  /// different context loaded them last (drivers may hand out different functions).
  void makeCurrent();
  [[nodiscard]] const ContextInfo& info() const { return info_; }

 protected:
  /// Loads GL functions through `getProcAddress` and fills info_. Call once current.
  void finishInit(std::string backend, void* (*getProcAddress)(const char*));
  /// Platform part of makeCurrent.
  virtual void bind() = 0;
  ContextInfo info_;

 private:
  void* (*getProcAddress_)(const char*) = nullptr;
};

/// The info of the current context (of ours). Throws og::InternalError when none is current.
[[nodiscard]] const ContextInfo& currentContextInfo();

/// Creates a headless 4.5 core context and makes it current. Auto tries EGL then OSMesa.
/// Throws og::InternalError listing what each backend said when none works.
std::unique_ptr<Context> createHeadlessContext(Backend backend = Backend::Auto);

std::unique_ptr<Context> createEglContext();     ///< throws og::InternalError
std::unique_ptr<Context> createOsMesaContext();  ///< throws og::InternalError

}  // namespace og::gl
