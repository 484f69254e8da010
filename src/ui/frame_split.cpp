#include "ui/frame_split.hpp"

#include <algorithm>
#include <cstdio>

namespace nbscope::ui {

std::vector<FrameSplitRow> frame_split_rows(const DrawTimings& d, const FrameTimings& pipeline) {
  if (!d.measured) {
    return {{"physics", pipeline.physics_ms, !d.physics_overlapped, d.physics_overlapped ? "overlapped" : ""},
            {"detection", pipeline.detection_ms, !d.detection_overlapped, d.detection_overlapped ? "overlapped" : ""},
            {"check", pipeline.check_ms, !d.detection_overlapped, d.detection_overlapped ? "overlapped" : ""},
            {"trace (lists)", d.trace_ms, true, ""},
            {"overlays", d.overlay_ms, true, ""},
            {"render", d.render_ms, true, ""},
            {"panels", d.ui_ms, true, ""}};
  }
  std::vector<FrameSplitRow> rows = {
      {d.idle ? "idle sleep" : "event wait", d.wait_ms, true, ""},
      {"physics", d.physics_ms, true, d.physics_overlapped ? "overlapped" : ""},
      {"detection", d.detection_ms, true, d.detection_overlapped ? "overlapped" : ""},
      {"check", d.check_ms, true, d.detection_overlapped ? "overlapped" : ""},
      {"trace (lists)", d.trace_ms, true, ""},
      {"overlays", d.overlay_ms, true, ""},
      {"render", d.render_ms, true, ""},
      {"panels (ImGui)", d.ui_ms, true, ""},
      {"swap", d.swap_ms, true, ""}};
  double named = 0;
  for (const FrameSplitRow& r : rows) named += r.ms;
  // The loop's own work between them (adopting a step, requests, following the frame): the rest,
  // never below 0 (timers read at different instants may overlap by a few microseconds).
  rows.push_back({"other (loop)", std::max(0.0, d.frame_ms - named), true, ""});
  return rows;
}

std::string frame_rate_line(const DrawTimings& d, double fps) {
  char buf[96];
  if (d.measured && d.idle) return "idle: waiting for input";
  if (d.measured && d.frame_ms > 0) {
    std::snprintf(buf, sizeof buf, "%.1f FPS   frame %.1f ms", 1000.0 / d.frame_ms, d.frame_ms);
    return buf;
  }
  if (fps > 0) {
    std::snprintf(buf, sizeof buf, "%.1f FPS   frame %.1f ms", fps, d.frame_ms);
    return buf;
  }
  return "off-screen frame (no FPS)";
}

std::string sim_rate_text(const DrawTimings& d, double rate) {
  if (rate < 0 || (d.measured && d.idle)) return "";
  char buf[48];
  std::snprintf(buf, sizeof buf, "sim %.1f frames/s", rate);
  return buf;
}

}  // namespace nbscope::ui
