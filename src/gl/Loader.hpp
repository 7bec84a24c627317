#pragma once
// Kept free of GL headers so platform code (which includes EGL/OSMesa's own gl.h) can call it.
namespace og::gl {
/// Loads the OpenGL 4.5 core entry points with glad. Throws og::InternalError on failure.
void loadGlFunctions(void* (*getProcAddress)(const char*));
}  // namespace og::gl
