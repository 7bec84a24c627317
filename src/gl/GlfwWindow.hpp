#pragma once
// A GLFW window with a 4.5 core context, for the interactive viewer.
#include <string>

#include "gl/Context.hpp"

struct GLFWwindow;

namespace og::gl {

class GlfwWindow final : public Context {
 public:
  /// Opens a window; throws og::InternalError when no display or no 4.5 context is available.
  GlfwWindow(int width, int height, const std::string& title);
  ~GlfwWindow() override;

  void swapBuffers();
  [[nodiscard]] bool shouldClose() const;
  void pollEvents();
  /// Framebuffer size in pixels (may differ from the window size on HiDPI screens).
  void framebufferSize(int& width, int& height) const;
  [[nodiscard]] GLFWwindow* handle() const { return window_; }

 protected:
  void bind() override;

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace og::gl
