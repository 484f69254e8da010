// nbscope app: what every window loop shares — whether there is a display (and where its picture goes without one), Ctrl+C / SIGTERM closing
// the window like its close button, and sleeping while nothing moves instead of redrawing the same
// frame as fast as the GPU allows.
#pragma once
#include <cstdint>
#include <deque>
#include <string>
#include <utility>

#include "app/clock.hpp"
#include "io/signals.hpp"  // install_stop_handlers, stop_requested: Ctrl+C and SIGTERM close the window
#include "render/gl_window.hpp"
#include "ui/model.hpp"

namespace nbscope {

// True when $DISPLAY or $WAYLAND_DISPLAY names a display to open a window on.
[[nodiscard]] bool have_display();

// Where a window run without a display puts its screenshot: $TMPDIR (else /tmp)/nbscope-STEM.png.
[[nodiscard]] std::string fallback_screenshot_path(const std::string& stem);

class FrameLoop;

// A window's frame split: each frame from the top of one to the top of the next, cut where the
// loop does its parts (the wait for input, the view's parts, the pipeline's runs, the swap), summed
// over about half a second and published as an average, as FPS is: the parts then add up to the
// frame time shown, and the numbers hold still long enough to be read.
class FrameSplitClock {
 public:
  static constexpr double kAverageSeconds = 0.5;
  // The top of a frame, before its wait for input: closes the frame before it (if presented).
  void frame_start(Clock::time_point now);
  // The wait for input ended at `now`; `idle`: the loop slept until input or its timeout.
  void waited(Clock::time_point now, bool idle);
  // The frame was presented, its swap taking `swap_ms`; `parts`: the view's (trace, overlays,
  // render, panels) and the pipeline's runs during the frame (physics, detection, check; 0 if none).
  void presented(double swap_ms, const ui::DrawTimings& parts);
  // The last average (`measured` false until a first half second of frames was seen); `idle` is
  // the latest frame's, so a window that falls asleep says so at once.
  [[nodiscard]] const ui::DrawTimings& average() const { return average_; }

 private:
  ui::DrawTimings sum_, frame_, average_;
  Clock::time_point frame_started_{}, window_started_{};
  int frames_ = 0;
  bool started_ = false, presented_ = false;
};

// Events at the top of each frame: polled while something moves and a few frames after (ImGui
// settles hover states, popups and auto-sized panels over them); else a wait for input of at most
// kIdleWaitSeconds, after which one frame is drawn anyway (a tooltip's delay, a text cursor). It
// keeps the frame split: the wait here, the swap in present().
class IdlePacer {
 public:
  static constexpr double kIdleWaitSeconds = 0.25;
  static constexpr int kFramesBeforeSleep = 3;
  // Polls or waits for `window`'s events; `moving`: this frame must not wait.
  void pace(render::GlfwWindow& window, bool moving);
  // Presents `window`'s frame, timing the swap, with the view's parts `view` and what `loop`'s
  // pipeline ran during it (a change of its generation: a frame detected and checked).
  void present(render::GlfwWindow& window, const ui::DrawTimings& view, const FrameLoop& loop);
  // The window's frame split, averaged (ui::DrawTimings: what the Stats panel shows).
  [[nodiscard]] const ui::DrawTimings& split() const { return clock_.average(); }

 private:
  int frames_before_sleep_ = kFramesBeforeSleep;
  FrameSplitClock clock_;
  std::uint64_t seen_generation_ = 0;
};

// The simulation's own rate beside the display's FPS (the window never waits for the worker, so the
// two differ): frames completed per second over the last kWindowSeconds, from a running count.
class SimRate {
 public:
  static constexpr double kWindowSeconds = 2.0;
  // `frames`: frames completed so far at `seconds` (any clock); a count that goes down (a new run)
  // starts the measurement again.
  void sample(std::int64_t frames, double seconds);
  // Frames a second over the samples of the last kWindowSeconds; 0 before two samples.
  [[nodiscard]] double rate() const;

 private:
  std::deque<std::pair<double, std::int64_t>> samples_;  // (seconds, frames), oldest first
};

}  // namespace nbscope
