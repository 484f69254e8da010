#include "render/gl_window.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/error.hpp"
#include "render/gl.hpp"

namespace nbscope::render {

namespace {
std::string g_last_glfw_error;

void remember_error(int code, const char* description) {
  g_last_glfw_error = std::string(description != nullptr ? description : "unknown") + " (GLFW error " +
                      std::to_string(code) + ")";
}

void* glfw_proc(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

InputEvent::Action action_of(int glfw_action) {
  if (glfw_action == GLFW_PRESS) return InputEvent::Action::Press;
  return glfw_action == GLFW_RELEASE ? InputEvent::Action::Release : InputEvent::Action::Repeat;
}

// GLFW's callbacks: queue the event on the window that owns the handle (its user pointer).
void on_key(GLFWwindow* handle, int key, int /*scancode*/, int action, int /*mods*/) {
  if (auto* w = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(handle)))
    w->queue_input(InputEvent{InputEvent::Kind::Key, action_of(action), key});
}
void on_mouse_button(GLFWwindow* handle, int button, int action, int /*mods*/) {
  if (auto* w = static_cast<GlfwWindow*>(glfwGetWindowUserPointer(handle)))
    w->queue_input(InputEvent{InputEvent::Kind::MouseButton, action_of(action), button});
}
}  // namespace

std::optional<std::array<int, 2>> GlfwWindow::primary_work_area() {
  glfwSetErrorCallback(&remember_error);
  if (glfwInit() != GLFW_TRUE) return std::nullopt;
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  if (monitor == nullptr) return std::nullopt;
  int x = 0, y = 0, w = 0, h = 0;
  glfwGetMonitorWorkarea(monitor, &x, &y, &w, &h);
  if (w <= 0 || h <= 0) return std::nullopt;
  return std::array<int, 2>{w, h};
}

GlfwWindow::GlfwWindow(int width, int height, const std::string& title, bool maximized) {
  glfwSetErrorCallback(&remember_error);
  g_last_glfw_error.clear();
  if (glfwInit() != GLFW_TRUE) throw Error("window: cannot open: " + g_last_glfw_error);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  glfwWindowHint(GLFW_MAXIMIZED, maximized ? GLFW_TRUE : GLFW_FALSE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    const std::string why = g_last_glfw_error;
    glfwTerminate();
    throw Error("window: cannot open: " + why);
  }
  glfwMakeContextCurrent(window_);
  // Installed before ImGui's GLFW backend, which chains to these from its own callbacks.
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, &on_key);
  glfwSetMouseButtonCallback(window_, &on_mouse_button);
  try {
    load_gl(&glfw_proc, "window");
  } catch (...) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw;
  }
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

int GlfwWindow::width() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return w;
}

int GlfwWindow::height() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return h;
}

std::array<int, 2> GlfwWindow::window_size() const {
  std::array<int, 2> size{};
  glfwGetWindowSize(window_, &size[0], &size[1]);
  return size;
}

void GlfwWindow::make_current() { glfwMakeContextCurrent(window_); }
void GlfwWindow::present() { glfwSwapBuffers(window_); }
bool GlfwWindow::should_close() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void GlfwWindow::poll_events() { glfwPollEvents(); }
bool GlfwWindow::wait_events(double timeout_seconds) {
  // GLFW does not say why it returned: an early return is taken for an event.
  const double start = glfwGetTime();
  glfwWaitEventsTimeout(timeout_seconds);
  return glfwGetTime() - start < timeout_seconds;
}
void GlfwWindow::set_vsync(bool on) { glfwSwapInterval(on ? 1 : 0); }
double GlfwWindow::time() const { return glfwGetTime(); }

std::vector<InputEvent> GlfwWindow::take_input() {
  std::vector<InputEvent> events;
  events.swap(input_);
  return events;
}

void GlfwWindow::queue_input(const InputEvent& event) {
  // A loop that never takes them (the verify window) keeps only the newest.
  if (input_.size() >= kMaxQueuedInput) input_.erase(input_.begin());
  input_.push_back(event);
}

}  // namespace nbscope::render
