// nbscope app: `nbscope replay FILE.nbsrec`: recorded frames (io/recording.hpp) through the same
// frame loop, headless (checks, report, screenshot: app/headless.hpp) or in the window.
#pragma once
#include "app/headless.hpp"

namespace nbscope {

// True when this build has the window and there is a display to open it on.
[[nodiscard]] bool replay_window_available();
// The window on the recording `options.replay` (play/pause/step/restart through its frames);
// with --screenshot it plays to the last frame, saves and exits. Returns 1 when a check failed.
int run_replay_window(const HeadlessOptions& options);

// `gui --input FILE` without --arrays: the window on ELEMENTS.csv's one frame or a dump's frames, as
// a recording without pairs (input_window.cpp); without a display, headless into --screenshot.
int run_input_gui(Args& args);

}  // namespace nbscope
