#define GLFW_INCLUDE_NONE
#include "gl/GlfwWindow.hpp"

#include <GLFW/glfw3.h>

#include <array>
#include <utility>

#include "core/Error.hpp"

namespace og::gl {
namespace {
void* glfwProc(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

std::string lastGlfwError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}

// Our keys and GLFW's (Other has none).
constexpr std::array<std::pair<Key, int>, 38> kKeys = {{
    {Key::Escape, GLFW_KEY_ESCAPE}, {Key::Q, GLFW_KEY_Q}, {Key::P, GLFW_KEY_P},
    {Key::F12, GLFW_KEY_F12}, {Key::K, GLFW_KEY_K}, {Key::H, GLFW_KEY_H}, {Key::F1, GLFW_KEY_F1},
    {Key::O, GLFW_KEY_O}, {Key::L, GLFW_KEY_L}, {Key::Equal, GLFW_KEY_EQUAL},
    {Key::KeypadAdd, GLFW_KEY_KP_ADD}, {Key::Minus, GLFW_KEY_MINUS},
    {Key::KeypadSubtract, GLFW_KEY_KP_SUBTRACT}, {Key::LeftBracket, GLFW_KEY_LEFT_BRACKET},
    {Key::RightBracket, GLFW_KEY_RIGHT_BRACKET}, {Key::N, GLFW_KEY_N},
    {Key::Backspace, GLFW_KEY_BACKSPACE}, {Key::Home, GLFW_KEY_HOME}, {Key::Space, GLFW_KEY_SPACE},
    {Key::R, GLFW_KEY_R}, {Key::W, GLFW_KEY_W}, {Key::A, GLFW_KEY_A}, {Key::S, GLFW_KEY_S},
    {Key::D, GLFW_KEY_D}, {Key::E, GLFW_KEY_E}, {Key::C, GLFW_KEY_C}, {Key::X, GLFW_KEY_X},
    {Key::Z, GLFW_KEY_Z}, {Key::Up, GLFW_KEY_UP}, {Key::Down, GLFW_KEY_DOWN},
    {Key::Left, GLFW_KEY_LEFT}, {Key::Right, GLFW_KEY_RIGHT}, {Key::PageUp, GLFW_KEY_PAGE_UP},
    {Key::PageDown, GLFW_KEY_PAGE_DOWN}, {Key::LeftShift, GLFW_KEY_LEFT_SHIFT},
    {Key::RightShift, GLFW_KEY_RIGHT_SHIFT}, {Key::LeftControl, GLFW_KEY_LEFT_CONTROL},
    {Key::RightControl, GLFW_KEY_RIGHT_CONTROL},
}};

Key keyOf(int glfwKey) {
  for (const auto& [key, code] : kKeys)
    if (code == glfwKey) return key;
  return Key::Other;
}

int glfwKeyOf(Key key) {
  for (const auto& [k, code] : kKeys)
    if (k == key) return code;
  return GLFW_KEY_UNKNOWN;
}

Modifiers modifiersOf(int mods) {
  return {(mods & GLFW_MOD_SHIFT) != 0, (mods & GLFW_MOD_CONTROL) != 0};
}

GlfwWindow& self(GLFWwindow* w) { return *static_cast<GlfwWindow*>(glfwGetWindowUserPointer(w)); }
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
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int mods) {
    const WindowInput& in = self(w).input_;
    const KeyAction a = action == GLFW_RELEASE ? KeyAction::Release
                        : action == GLFW_REPEAT ? KeyAction::Repeat
                                                : KeyAction::Press;
    if (in.key) in.key(keyOf(key), a, modifiersOf(mods));
  });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int mods) {
    const WindowInput& in = self(w).input_;
    const MouseButton b = button == GLFW_MOUSE_BUTTON_LEFT     ? MouseButton::Left
                          : button == GLFW_MOUSE_BUTTON_RIGHT  ? MouseButton::Right
                          : button == GLFW_MOUSE_BUTTON_MIDDLE ? MouseButton::Middle
                                                               : MouseButton::Other;
    if (in.button) in.button(b, action != GLFW_RELEASE, modifiersOf(mods));
  });
  glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
    if (const WindowInput& in = self(w).input_; in.cursor) in.cursor(x, y);
  });
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double y) {
    if (const WindowInput& in = self(w).input_; in.scroll) in.scroll(y);
  });
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void GlfwWindow::bind() { glfwMakeContextCurrent(window_); }
void GlfwWindow::swapBuffers() { glfwSwapBuffers(window_); }
void GlfwWindow::setSwapInterval(int interval) { glfwSwapInterval(interval); }
bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(window_) != 0; }
void GlfwWindow::close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void GlfwWindow::pollEvents() { glfwPollEvents(); }
void GlfwWindow::setInput(WindowInput input) { input_ = std::move(input); }
bool GlfwWindow::isDown(Key key) const {
  const int code = glfwKeyOf(key);
  return code != GLFW_KEY_UNKNOWN && glfwGetKey(window_, code) == GLFW_PRESS;
}
void GlfwWindow::framebufferSize(int& width, int& height) const {
  glfwGetFramebufferSize(window_, &width, &height);
}
void GlfwWindow::windowSize(int& width, int& height) const { glfwGetWindowSize(window_, &width, &height); }

}  // namespace og::gl
