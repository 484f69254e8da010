#include "app/window_times.hpp"

#include <algorithm>
#include <cstdio>

#include "app/frame_loop.hpp"
#include "app/headless.hpp"
#include "core/detector.hpp"
#include "io/plural.hpp"

namespace nbscope {

void ScriptedTimes::add_step(const FrameLoop& loop) {
  ++stepped;
  simulated = Clock::now();
  const FrameTimings& t = loop.result().report().timings;
  sum_physics += t.physics_ms;
  any_overlapped = any_overlapped || loop.source().physics_overlapped();
  detection_overlapped = detection_overlapped || loop.source().detection_overlapped();
  sum_detect += t.detection_ms;
  sum_check += t.check_ms;
}

void ScriptedTimes::print(std::int64_t frames, std::int64_t back, const char* screenshot, const FrameLoop& loop,
                          std::int64_t rendered) const {
  const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
  const double sim_seconds = std::chrono::duration<double>(simulated - started).count();
  const double drawn = static_cast<double>(rendered + 1);
  const double steps = static_cast<double>(std::max<std::int64_t>(stepped, 1));
  const std::int64_t counted = frames + (loop.source().replaying() ? 1 : 0);
  std::fprintf(stderr,
               "nbscope: window: %s (simulated in %.2f s = sim %.1f frames/s), %lld drawn in %.2f s = %.1f FPS; "
               "ms a simulated frame: physics %.2f%s, detection %.2f%s, check %.2f%s; ms a drawn frame: render+panels %.2f; "
               "algorithm %s%s%s\n",
               plural(counted, "frame").c_str(), sim_seconds, sim_seconds > 0 ? static_cast<double>(stepped) / sim_seconds : 0.0,
               static_cast<long long>(rendered + 1), seconds, drawn / seconds, sum_physics / steps,
               any_overlapped ? " (overlapped)" : "", sum_detect / steps, detection_overlapped ? " (overlapped)" : "",
               sum_check / steps, detection_overlapped ? " (overlapped)" : "", sum_view / drawn,
               detector_label(loop.pipeline().algorithm()).c_str(),
               screenshot != nullptr ? "; screenshot " : "", screenshot != nullptr ? screenshot : "");
  if (back > 0) {
    const double k = static_cast<double>(back);
    std::fprintf(stderr,
                 "nbscope: window: went back %s to %s: %.2f ms a frame (the kept frame rebuilt, "
                 "detected and checked again %.2f, render+panels %.2f)\n",
                 plural(back, "frame").c_str(), frame_label(frame_unit_of(loop.source()), loop.source().frame()).c_str(), (sum_back_show + sum_back_view) / k,
                 sum_back_show / k, sum_back_view / k);
  }
}

}  // namespace nbscope
