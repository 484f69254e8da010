#include "app/window_pacing.hpp"

#include <cstdlib>

#include "app/frame_loop.hpp"

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

void FrameSplitClock::frame_start(Clock::time_point now) {
  if (!started_) {
    started_ = true;
    window_started_ = now;
  } else if (presented_) {
    frame_.frame_ms = std::chrono::duration<double, std::milli>(now - frame_started_).count();
    const auto add = [](double& sum, double v) { sum += v; };
    add(sum_.frame_ms, frame_.frame_ms);
    add(sum_.wait_ms, frame_.wait_ms);
    add(sum_.swap_ms, frame_.swap_ms);
    add(sum_.trace_ms, frame_.trace_ms);
    add(sum_.overlay_ms, frame_.overlay_ms);
    add(sum_.render_ms, frame_.render_ms);
    add(sum_.ui_ms, frame_.ui_ms);
    add(sum_.physics_ms, frame_.physics_ms);
    add(sum_.detection_ms, frame_.detection_ms);
    add(sum_.check_ms, frame_.check_ms);
    sum_.physics_overlapped = sum_.physics_overlapped || frame_.physics_overlapped;
    sum_.detection_overlapped = sum_.detection_overlapped || frame_.detection_overlapped;
    ++frames_;
    if (std::chrono::duration<double>(now - window_started_).count() >= kAverageSeconds) {
      const double n = frames_;
      for (double* v : {&sum_.frame_ms, &sum_.wait_ms, &sum_.swap_ms, &sum_.trace_ms, &sum_.overlay_ms, &sum_.render_ms,
                        &sum_.ui_ms, &sum_.physics_ms, &sum_.detection_ms, &sum_.check_ms})
        *v /= n;
      const bool idle = average_.idle;
      average_ = sum_;
      average_.measured = true;
      average_.idle = idle;
      sum_ = ui::DrawTimings{};
      frames_ = 0;
      window_started_ = now;
    }
  }
  frame_ = ui::DrawTimings{};
  frame_started_ = now;
  presented_ = false;
}

void FrameSplitClock::waited(Clock::time_point now, bool idle) {
  frame_.wait_ms = std::chrono::duration<double, std::milli>(now - frame_started_).count();
  average_.idle = idle;
}

void FrameSplitClock::presented(double swap_ms, const ui::DrawTimings& parts) {
  const double wait = frame_.wait_ms;
  frame_ = parts;
  frame_.wait_ms = wait;
  frame_.swap_ms = swap_ms;
  presented_ = true;
}

void IdlePacer::pace(render::GlfwWindow& window, bool moving) {
  clock_.frame_start(Clock::now());
  if (moving) frames_before_sleep_ = kFramesBeforeSleep;
  const bool idle = frames_before_sleep_ == 0;
  if (!idle) {
    window.poll_events();
    --frames_before_sleep_;
  } else if (window.wait_events(kIdleWaitSeconds)) {
    frames_before_sleep_ = kFramesBeforeSleep;
  }
  clock_.waited(Clock::now(), idle);
}

void IdlePacer::present(render::GlfwWindow& window, const ui::DrawTimings& view, const FrameLoop& loop) {
  ui::DrawTimings parts = view;
  // A new generation: the loop detected and checked a frame during this one (a step, a past frame
  // shown, a redetect); its physics, detection and check ran here unless they overlapped the frame
  // before on a worker.
  const std::uint64_t generation = loop.change().generation;
  if (generation != seen_generation_) {
    seen_generation_ = generation;
    const FrameTimings& t = loop.result().report().timings;
    parts.physics_overlapped = loop.source().physics_overlapped();
    parts.physics_ms = parts.physics_overlapped ? 0.0 : t.physics_ms;
    parts.detection_overlapped = loop.source().detection_overlapped();
    parts.detection_ms = parts.detection_overlapped ? 0.0 : t.detection_ms;
    parts.check_ms = parts.detection_overlapped ? 0.0 : t.check_ms;
  }
  const auto t0 = Clock::now();
  window.present();
  clock_.presented(ms_since(t0), parts);
}

void SimRate::sample(std::int64_t frames, double seconds) {
  if (!samples_.empty() && (frames < samples_.back().second || seconds < samples_.back().first)) samples_.clear();
  samples_.emplace_back(seconds, frames);
  // Keep one sample at or before the window's start, so the span covers the whole window.
  while (samples_.size() > 2 && samples_[1].first <= seconds - kWindowSeconds) samples_.pop_front();
}

double SimRate::rate() const {
  if (samples_.size() < 2) return 0;
  const double span = samples_.back().first - samples_.front().first;
  return span > 0 ? static_cast<double>(samples_.back().second - samples_.front().second) / span : 0;
}

}  // namespace nbscope
