#include "gl/Loader.hpp"

#include <glad/gl.h>

#include "core/Error.hpp"

namespace og::gl {
namespace {
void* (*gGetProc)(const char*) = nullptr;
GLADapiproc trampoline(const char* name) {
  return reinterpret_cast<GLADapiproc>(gGetProc(name));
}
}  // namespace

void loadGlFunctions(void* (*getProcAddress)(const char*)) {
  gGetProc = getProcAddress;
  const int version = gladLoadGL(trampoline);
  if (version == 0) throw InternalError("could not load OpenGL functions");
  if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 45)
    throw InternalError("OpenGL 4.5 core is required, the context offers " +
                        std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                        std::to_string(GLAD_VERSION_MINOR(version)));
}

}  // namespace og::gl
