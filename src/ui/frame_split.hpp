// nbscope ui: the Stats panel's frame split — every part of a window's frame named, so that the
// parts add up to the frame time shown beside FPS (what is not measured on its own is "other").
#pragma once
#include <string>
#include <vector>

#include "check/report.hpp"
#include "ui/model.hpp"

namespace nbscope::ui {

// One line of the split: its name, its milliseconds and a note ("overlapped": not in the sum).
struct FrameSplitRow {
  std::string name;
  double ms = 0;
  bool counted = true;  // part of the frame's sum (physics on a worker thread is not)
  std::string note;
};

// The split of `d`: a window's measured frame (d.measured) gives event wait, physics, detection,
// check, trace, overlays, render, panels, swap and other, whose counted rows sum to d.frame_ms;
// otherwise the view's parts and the pipeline's `pipeline` timings of the frame shown, as before.
std::vector<FrameSplitRow> frame_split_rows(const DrawTimings& d, const FrameTimings& pipeline);

// The line above the split: "26.3 FPS   frame 38.0 ms", or "idle: waiting for input" for a paused
// window that sleeps until input, or "off-screen frame (no FPS)".
std::string frame_rate_line(const DrawTimings& d, double fps);

// The simulation's own rate beside it, "sim 10.2 frames/s" ("" when not measured: `rate` < 0, or an
// idle window, whose simulation is paused anyway).
std::string sim_rate_text(const DrawTimings& d, double rate);

}  // namespace nbscope::ui
