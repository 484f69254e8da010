// nbscope render: a GLFW window with a GL 3.3 core context. Only the windowed loop creates one;
// the headless path never touches GLFW (glfwInit fails without a display).
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "render/gl_context.hpp"

struct GLFWwindow;

namespace nbscope::render {

// One key or mouse-button event as GLFW reported it, in arrival order (ui::InputReplay applies them).
struct InputEvent {
  enum class Kind : std::uint8_t { Key, MouseButton };
  enum class Action : std::uint8_t { Press, Release, Repeat };
  Kind kind = Kind::Key;
  Action action = Action::Press;
  int code = 0;  // GLFW_KEY_* (ImGui's io.KeysDown index) or GLFW_MOUSE_BUTTON_* (io.MouseDown's)
  friend bool operator==(const InputEvent&, const InputEvent&) = default;
};

class GlfwWindow final : public GlContext {
 public:
  // Opens a window of width x height pixels (`maximized`: asks the window manager to maximise it,
  // which leaves room for its frame); Error("window: cannot open: <reason>") otherwise.
  GlfwWindow(int width, int height, const std::string& title, bool maximized = false);
  // The primary monitor's work area (its size less task bars and docks), or nullopt when GLFW
  // cannot start or knows no monitor. Starts GLFW if needed (the window's constructor starts it too).
  [[nodiscard]] static std::optional<std::array<int, 2>> primary_work_area();
  ~GlfwWindow() override;
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  [[nodiscard]] const char* kind() const override { return "window"; }
  [[nodiscard]] int width() const override;
  [[nodiscard]] int height() const override;
  // The window's size in screen coordinates (what a next start reopens at).
  [[nodiscard]] std::array<int, 2> window_size() const;
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
  // The key and mouse-button events since the last call, oldest first (then forgotten). The window
  // queues them from GLFW's callbacks, which ImGui's GLFW backend chains to its own, so a tap that
  // starts and ends between two frames is kept, not lost between two polls of the keys' state.
  [[nodiscard]] std::vector<InputEvent> take_input();
  // Queues one event, as GLFW's callbacks do (at most kMaxQueuedInput wait; the oldest go first).
  void queue_input(const InputEvent& event);
  static constexpr std::size_t kMaxQueuedInput = 1024;

 private:
  GLFWwindow* window_ = nullptr;
  std::vector<InputEvent> input_;
};

}  // namespace nbscope::render
