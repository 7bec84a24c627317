#define GLFW_INCLUDE_NONE
#include "gl/GlfwWindow.hpp"

#include <GLFW/glfw3.h>

#include "core/Error.hpp"

namespace og::gl {
namespace {
void* glfwProc(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

std::string lastGlfwError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}
}  // namespace

GlfwWindow::GlfwWindow(int width, int height, const std::string& title) {
  if (!glfwInit()) throw InternalError("cannot initialise GLFW: " + lastGlfwError());
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    const std::string why = lastGlfwError();
    glfwTerminate();
    throw InternalError("cannot open a window with OpenGL 4.5 core: " + why);
  }
  glfwMakeContextCurrent(window_);
  finishInit("glfw", glfwProc);
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void GlfwWindow::bind() { glfwMakeContextCurrent(window_); }
void GlfwWindow::swapBuffers() { glfwSwapBuffers(window_); }
bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(window_) != 0; }
void GlfwWindow::pollEvents() { glfwPollEvents(); }
void GlfwWindow::framebufferSize(int& width, int& height) const {
  glfwGetFramebufferSize(window_, &width, &height);
}

}  // namespace og::gl
