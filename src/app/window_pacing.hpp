// nbscope app: what every window loop shares — whether there is a display (and where its picture goes without one), Ctrl+C / SIGTERM closing
// the window like its close button, and sleeping while nothing moves instead of redrawing the same
// frame as fast as the GPU allows.
#pragma once
#include <string>

#include "io/signals.hpp"  // install_stop_handlers, stop_requested: Ctrl+C and SIGTERM close the window
#include "render/gl_window.hpp"

namespace nbscope {

// True when $DISPLAY or $WAYLAND_DISPLAY names a display to open a window on.
[[nodiscard]] bool have_display();

// Where a window run without a display puts its screenshot: $TMPDIR (else /tmp)/nbscope-STEM.png.
[[nodiscard]] std::string fallback_screenshot_path(const std::string& stem);

// Events at the top of each frame: polled while something moves and a few frames after (ImGui
// settles hover states, popups and auto-sized panels over them); else a wait for input of at most
// kIdleWaitSeconds, after which one frame is drawn anyway (a tooltip's delay, a text cursor).
class IdlePacer {
 public:
  static constexpr double kIdleWaitSeconds = 0.25;
  static constexpr int kFramesBeforeSleep = 3;
  // Polls or waits for `window`'s events; `moving`: this frame must not wait.
  void pace(render::GlfwWindow& window, bool moving);

 private:
  int frames_before_sleep_ = kFramesBeforeSleep;
};

}  // namespace nbscope
