#include "app/window_pacing.hpp"

#include <cstdlib>

namespace nbscope {

bool have_display() {
  const char* x = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x != nullptr && *x != '\0') || (wayland != nullptr && *wayland != '\0');
}

std::string fallback_screenshot_path(const std::string& stem) {
  const char* tmp = std::getenv("TMPDIR");
  const std::string dir = tmp != nullptr && *tmp != '\0' ? tmp : "/tmp";
  return dir + "/nbscope-" + stem + ".png";
}

void IdlePacer::pace(render::GlfwWindow& window, bool moving) {
  if (moving) frames_before_sleep_ = kFramesBeforeSleep;
  if (frames_before_sleep_ > 0) {
    window.poll_events();
    --frames_before_sleep_;
  } else if (window.wait_events(kIdleWaitSeconds)) {
    frames_before_sleep_ = kFramesBeforeSleep;
  }
}

}  // namespace nbscope
