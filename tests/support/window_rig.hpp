// tests/support: the window's view (GlView, offscreen under OSMesa) on a recording's frames through
// the frame loop, paused, as the replay window runs them: the rig of the window tests of dumps and
// 3D frames.
#pragma once
#include <memory>

#include "app/gl_view.hpp"
#include "render/gl_context.hpp"

namespace nbscope::testapp {

// An 800 x 500 offscreen window on `rec`, paused on its first frame.
struct RecordingWindowRig {
  std::unique_ptr<render::GlContext> context = render::make_offscreen_context(800, 500, "osmesa");
  FrameLoop loop;
  Session session;
  std::unique_ptr<GlView> view;
  explicit RecordingWindowRig(Recording rec, ViewOptions options = {}, const FrameLoopOptions& loop_options = {})
      : loop(loop_options) {
    options.width = 800;
    options.height = 500;
    options.shader_dir = NBSCOPE_SHADER_DIR;
    loop.load_recording(std::move(rec));
    session.paused = true;
    view = std::make_unique<GlView>(*context, nullptr, options);
    view->follow(loop);
  }
  // Draws n frames (no input), as the window does while paused.
  void frames(int n) {
    for (int k = 0; k < n; ++k) view->frame(loop, session, false, 1.0f / 60.0f);
  }
};

}  // namespace nbscope::testapp
