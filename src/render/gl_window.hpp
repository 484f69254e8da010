// nbscope render: a GLFW window with a GL 3.3 core context. Only the windowed loop creates one;
// the headless path never touches GLFW (glfwInit fails without a display).
#pragma once
#include <string>

#include "render/gl_context.hpp"

struct GLFWwindow;

namespace nbscope::render {

class GlfwWindow final : public GlContext {
 public:
  // Opens a window of width x height pixels; Error("window: cannot open: <reason>") otherwise.
  GlfwWindow(int width, int height, const std::string& title);
  ~GlfwWindow() override;
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  [[nodiscard]] const char* kind() const override { return "window"; }
  [[nodiscard]] int width() const override;
  [[nodiscard]] int height() const override;
  void make_current() override;
  void present() override;

  // The GLFW handle (for ImGui's GLFW platform backend).
  [[nodiscard]] GLFWwindow* handle() const { return window_; }
  // True once the user asked to close the window.
  [[nodiscard]] bool should_close() const;
  // Processes pending window events (input reaches ImGui through its GLFW callbacks).
  void poll_events();
  // Sleeps until a window event arrives or `timeout_seconds` pass, then processes the events as
  // poll_events() does; true when it woke before the timeout (input, most likely).
  bool wait_events(double timeout_seconds);
  // Swap interval: 1 waits for vertical sync, 0 does not.
  void set_vsync(bool on);
  // Seconds since the window opened (GLFW's clock).
  [[nodiscard]] double time() const;

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace nbscope::render
