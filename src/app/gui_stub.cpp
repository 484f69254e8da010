// Built instead of the window and the off-screen renderer when NBSCOPE_GUI=OFF (the sanitizer
// build): every request to render is refused with one error line (exit 2).
#include "app/commands.hpp"
#include "app/headless_view.hpp"
#include "app/replay.hpp"
#include "app/verify_view.hpp"
#include "core/error.hpp"

namespace nbscope {

std::unique_ptr<HeadlessView> make_headless_view(const ViewOptions&, const FrameLoop&) {
  throw Error("--screenshot: this nbscope was built without rendering (NBSCOPE_GUI=OFF)");
}

bool replay_window_available() { return false; }

int run_replay_window(const HeadlessOptions&) { throw Error("replay: this nbscope was built without the window (NBSCOPE_GUI=OFF)"); }

std::string write_verify_screenshot(const VerifyArraysRun&, const ViewOptions&) {
  throw Error("--screenshot: this nbscope was built without rendering (NBSCOPE_GUI=OFF)");
}

int run_verify_window(const VerifyArraysRun&, const ViewOptions&) {
  throw Error("gui: this nbscope was built without the window (NBSCOPE_GUI=OFF)");
}

int run_verify_gui(Args&) { throw Error("gui: this nbscope was built without the window (NBSCOPE_GUI=OFF)"); }

const char* window_build_line() { return "window: no (built with NBSCOPE_GUI=OFF: no window, no screenshots)"; }

int run_gui(Args&) { throw Error("gui: this nbscope was built without the window (NBSCOPE_GUI=OFF)"); }

}  // namespace nbscope
