// nbscope app: a headless run going back through its history: --back (one kept frame at a time, the
// window's --back too), --violation N (the frame of the run's N-th violation) and --rewind FROM:TO
// (back to TO, the world re-simulated to it; headless.hpp).
#include <string>
#include <vector>

#include "app/frame_loop.hpp"
#include "app/headless.hpp"
#include "app/headless_view.hpp"
#include "check/report.hpp"
#include "core/error.hpp"
#include "io/plural.hpp"

namespace nbscope {

// --rewind FROM:TO at frame FROM: back to kept frame TO, the world re-simulated to it (the caller
// puts the report back as it stood after frame TO: the frames after it run again).
// --violation N: the run's N-th listed violation's frame shown again, and (drawing) the violation
// chosen as in the Violations panel.
void go_to_violation(FrameLoop& loop, std::int64_t n, HeadlessView* view) {
  const std::vector<Violation>& listed = loop.history().violation_log().listed();
  if (static_cast<std::size_t>(n) > listed.size())
    throw Error("--violation: " + std::to_string(n) + " is past the run's " + plural(static_cast<long long>(listed.size()), "listed violation"));
  const Violation v = listed[static_cast<std::size_t>(n - 1)];
  if (!loop.history().can_show(v.frame))
    throw Error("--violation: its " + frame_label(frame_unit_of(loop.source()), v.frame) + " is no longer kept (a larger --history-mb keeps more)");
  loop.show_frame(v.frame);
  if (view != nullptr) view->focus_violation(loop, v);  // (follows the frame shown first)
}

void rewind_for_flag(FrameLoop& loop, const HeadlessOptions::Rewind& r, RunReport& report) {
  if (!loop.history().can_show(r.to)) {
    const auto first = loop.history().frames().first_kept();
    throw Error("--rewind: frame " + std::to_string(r.to) + " is no longer kept (frames " +
                std::to_string(first.value_or(loop.history().newest_frame())) + ".." + std::to_string(loop.history().newest_frame()) +
                " are; a larger --history-mb keeps more)");
  }
  loop.show_frame(r.to);
  loop.resume().begin();
  while (!loop.resume().advance(1e9)) {
  }
  // Frames up to TO were compared while re-simulating; those after TO are compared as they run again.
  report.rewind = RunReport::Rewind{r.from, r.to, loop.resume().divergence()};
}

void step_back_for_flag(FrameLoop& loop) {
  if (!loop.step_back())
    throw Error("--back: " + frame_label(frame_unit_of(loop.source()), loop.source().frame()) + " is the oldest kept (a larger --history-mb keeps more)");
}

}  // namespace nbscope
