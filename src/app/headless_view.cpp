#include "app/headless_view.hpp"

#include "app/clock.hpp"

#include <cstdio>

#include "app/gl_view.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "render/gl_context.hpp"

namespace nbscope {

namespace {

class OffscreenView final : public HeadlessView {
 public:
  OffscreenView(const ViewOptions& options, const FrameLoop& loop)
      : options_(options),
        context_(render::make_offscreen_context(options.width, options.height, options.gl)),
        view_(*context_, nullptr, options, loop) {  // the scene as loaded: the camera fits it
    session_.scene_path = loop.source().scene().path;
    session_.scene_files = bundled_scene_files();
    if (loop.source().has_scene()) {  // (a world that stopped at load has no elements to select)
      view_.check_selection(loop);
      view_.check_layer(loop);
    }
  }

  void focus_violation(const FrameLoop& loop, const Violation& violation) override {
    view_.focus_violation(loop, violation);
    view_.state().layer = view_.layer_option();  // --layer K still wins over the pair's layer (auto: the pair's)
  }

  void show_stopped(const std::string& message, const std::string& scene_path) override {
    session_.scene_path = scene_path;  // (a world that stopped at load left the loop without its scene)
    session_.error = message;
    session_.paused = true;
    view_.state().panel_open[kScenesPanel] = true;
  }

  std::string write_screenshot(FrameLoop& loop) override {
    auto t0 = Clock::now();
    view_.frame(loop, session_, false, 1.0f / 60.0f);
    const double first_ms = ms_since(t0);
    const double trace_ms = view_.last_cost().trace_ms;  // the traced detection runs in the first frame only
    t0 = Clock::now();
    // The settled layout, as the window's scripted screenshot shows it.
    for (int i = 1; i < GlView::kSettleFrames; ++i) view_.frame(loop, session_, false, 1.0f / 60.0f);
    const double render_ms = ms_since(t0) / (GlView::kSettleFrames - 1);
    if (session_.error.empty()) view_.check_step();  // a stopped world's picture is of its message
    const GlView::Cost cost = view_.last_cost();
    auto t1 = Clock::now();
    const Image image = view_.screenshot();
    const double read_ms = ms_since(t1);
    t1 = Clock::now();
    write_png(*options_.screenshot, image);
    const double png_ms = ms_since(t1);
    char line[512];
    std::snprintf(line, sizeof line,
                  "screenshot %s (%dx%d, %s): render %.1f ms a frame (overlays %.1f, GL submit %.1f, panels %.1f); "
                  "first frame %.1f ms incl. traced lists %.1f; readback %.1f ms, png %.1f ms",
                  options_.screenshot->c_str(), image.width, image.height, context_->kind(), render_ms, cost.overlay_ms,
                  cost.render_ms, cost.ui_ms, first_ms, trace_ms, read_ms, png_ms);
    return line;
  }

 private:
  ViewOptions options_;
  std::unique_ptr<render::GlContext> context_;
  GlView view_;
  Session session_;
};

}  // namespace

std::unique_ptr<HeadlessView> make_headless_view(const ViewOptions& options, const FrameLoop& loop) {
  if (!options.screenshot) throw Error("internal: make_headless_view without --screenshot");
  // Fail before simulating any frame, not after.
  check_output_path(*options.screenshot);
  return std::make_unique<OffscreenView>(options, loop);
}

}  // namespace nbscope
