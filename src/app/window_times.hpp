// nbscope app: what a scripted window run (gui --frames N) measures, and its summary line on stderr.
#pragma once
#include <cstdint>

#include "app/clock.hpp"

namespace nbscope {

class FrameLoop;

// What a scripted run (--frames N) measures: the simulation's frames and their pipeline times, the
// frames drawn meanwhile (the window does not wait for the worker, so there are more), and --back's
// frames apart.
struct ScriptedTimes {
  Clock::time_point started = Clock::now();
  Clock::time_point simulated = started;        // when the last simulated frame was adopted
  std::int64_t stepped = 0;                     // simulated frames adopted
  double sum_physics = 0, sum_detect = 0, sum_check = 0, sum_view = 0;
  bool any_overlapped = false;                  // physics ran on the worker thread, beside the drawing
  bool detection_overlapped = false;            // so did detection and the check
  double sum_back_show = 0, sum_back_view = 0;  // --back: showing a kept frame again, and drawing it

  // One simulated frame made: its pipeline's times.
  void add_step(const FrameLoop& loop);
  // One frame drawn in `view_ms` (`back`: one of --back's).
  void add_drawn(double view_ms, bool back) {
    if (back) sum_back_view += view_ms;
    sum_view += view_ms;
  }

  // The simulation's rate and the window's frame rate, and where the time went. --frames N is N
  // steps, as in headless; every frame drawn counts in FPS (the start and the settling layout
  // included). A recording's frame 0 is one of its frames, as in headless replay.
  // `frames`: --frames; `back`: --back; `screenshot`: its path or null.
  void print(std::int64_t frames, std::int64_t back, const char* screenshot, const FrameLoop& loop, std::int64_t rendered) const;
};

}  // namespace nbscope
