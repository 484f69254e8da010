#include "app/window_pacing.hpp"

#include <csignal>
#include <cstdlib>

namespace nbscope {

namespace {
volatile std::sig_atomic_t g_stop_requested = 0;
void request_stop(int) { g_stop_requested = 1; }
}  // namespace

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

void install_stop_handlers() {
  std::signal(SIGINT, &request_stop);
  std::signal(SIGTERM, &request_stop);
}

bool stop_requested() { return g_stop_requested != 0; }

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
