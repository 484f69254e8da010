// nbscope app: the screenshot of `nbscope headless --screenshot`: the very frame the window would
// show (scene, overlays, ImGui panels), rendered off-screen (OSMesa or EGL, --gl). Without the GUI build,
// asking for one is refused with an error (exit 2).
#pragma once
#include <memory>
#include <string>

#include "app/frame_loop.hpp"
#include "app/view_options.hpp"

namespace nbscope {

class HeadlessView {
 public:
  virtual ~HeadlessView() = default;
  // Shows `violation` of the current frame as the Violations panel's choice does: both elements
  // selected, the camera on them, the Violations panel open and the stepper at the operation.
  virtual void focus_violation(const FrameLoop& loop, const Violation& violation) = 0;
  // The world of `scene_path` stopped (`message`: its refusal, at load or at a step): the picture
  // shows the line in red in the Scenes panel (opened for it) over the last good frame, or over
  // nothing at load.
  virtual void show_stopped(const std::string& message, const std::string& scene_path) = 0;
  // Renders the current frame and writes options.screenshot atomically; returns a one-line
  // summary (path, size, where the time went). Error when the file cannot be written.
  virtual std::string write_screenshot(FrameLoop& loop) = 0;
};

// Opens the off-screen context (`options.gl`) and loads the shaders for `loop`'s scene, so bad
// rendering options fail before any frame is simulated. Error when rendering is unavailable.
std::unique_ptr<HeadlessView> make_headless_view(const ViewOptions& options, const FrameLoop& loop);

}  // namespace nbscope
