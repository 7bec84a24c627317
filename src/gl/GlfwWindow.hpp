#pragma once
// A GLFW window with a 4.5 core context for the interactive viewer, and its input: keys, mouse
// buttons, cursor and scroll in the window system's terms translated to ours, so nothing
// outside src/gl includes GLFW.
#include <functional>
#include <string>

#include "gl/Context.hpp"

struct GLFWwindow;

namespace og::gl {

/// The keys the viewer uses (docs/controls.md); every other key is Other.
enum class Key {
  Other, Escape, Q, P, F12, K, H, F1, O, L, Equal, KeypadAdd, Minus, KeypadSubtract,
  LeftBracket, RightBracket, N, Backspace, Home, Space, R,
  W, A, S, D, E, C, X, Z, Up, Down, Left, Right, PageUp, PageDown,
  LeftShift, RightShift, LeftControl, RightControl,
};
enum class KeyAction { Press, Repeat, Release };
enum class MouseButton { Left, Right, Middle, Other };
struct Modifiers {
  bool shift = false;
  bool control = false;
};

/// What the window reports, called from pollEvents() on the calling thread. Positions are in
/// window coordinates (pixels from the top left; see windowSize), scrolls in notches.
struct WindowInput {
  std::function<void(Key, KeyAction, Modifiers)> key;
  std::function<void(MouseButton, bool pressed, Modifiers)> button;
  std::function<void(double x, double y)> cursor;
  std::function<void(double notches)> scroll;
};

class GlfwWindow final : public Context {
 public:
  /// Opens a window; throws og::InternalError when no display or no 4.5 context is available.
  GlfwWindow(int width, int height, const std::string& title);
  ~GlfwWindow() override;

  void swapBuffers();
  /// Waits for `interval` screen refreshes per swap (1: in step with the display).
  void setSwapInterval(int interval);
  [[nodiscard]] bool shouldClose() const;
  /// Asks the loop to end (shouldClose() turns true).
  void close();
  /// Calls the input handlers for what happened since the last call.
  void pollEvents();
  void setInput(WindowInput input);
  /// Whether `key` is held down now.
  [[nodiscard]] bool isDown(Key key) const;
  /// Framebuffer size in pixels (may differ from the window size on HiDPI screens).
  void framebufferSize(int& width, int& height) const;
  /// Window size in the cursor's coordinates.
  void windowSize(int& width, int& height) const;

 protected:
  void bind() override;

 private:
  GLFWwindow* window_ = nullptr;
  WindowInput input_;
};

}  // namespace og::gl
