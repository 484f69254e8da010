// tests/support: the window's view (GlView, offscreen under OSMesa) on a recording's frames through
// the frame loop, paused, as the replay window runs them: the rig of the window tests of dumps and
// 3D frames.
#pragma once
#include <cstdint>
#include <memory>

#include "app/gl_view.hpp"
#include "render/gl_context.hpp"

namespace nbscope::testapp {

// N spheres of radius 0.4 scattered (a fixed LCG from `seed`) in a 12 x 12 x 12 box: a few
// layers, many pairs, some between layers.
inline Recording scattered_spheres(int n, std::uint32_t seed) {
  Recording rec;
  rec.path = "spheres3d.nbsrec";
  RecordedFrame& f = rec.frames.emplace_back();
  f.elements.dim = 3;
  std::uint32_t s = seed;
  const auto next = [&s] {
    s = s * 1664525u + 1013904223u;
    return 12.0 * static_cast<double>(s >> 8) / static_cast<double>(1u << 24);
  };
  for (int k = 0; k < n; ++k) {
    const double x = next(), y = next(), z = next();
    f.elements.push_back(x, y, z, 0.4);
  }
  return rec;
}

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
    view = std::make_unique<GlView>(*context, nullptr, options, loop);
  }
  // Draws n frames (no input), as the window does while paused.
  void frames(int n) {
    for (int k = 0; k < n; ++k) view->frame(loop, session, false, 1.0f / 60.0f);
  }
};

}  // namespace nbscope::testapp
