// FrameLoop: the coordination of one run (loading, stepping, time travel). Its state is
// FrameLoopState (app/frame_loop_impl.hpp); the parts it hands out are in frame_loop_parts.cpp, the
// history and resume in frame_loop_history.cpp, the overlapped step in frame_loop_overlap.cpp.
//
// Index: loading | one frame | time travel | the parts.
#include "app/frame_loop_impl.hpp"
#include "app/frame_sources.hpp"
#include "io/scene_json.hpp"

namespace nbscope {

FrameLoop::FrameLoop(FrameLoopOptions options) : impl_(std::make_unique<FrameLoopState>(std::move(options))) {}
FrameLoop::~FrameLoop() = default;

// ---- loading -------------------------------------------------------------------------------

void load_scene_file(FrameLoop& loop, const std::string& path) { loop.load_scene(read_scene_json(path)); }
void load_recording_file(FrameLoop& loop, const std::string& path, std::int64_t max_frames) {
  loop.load_recording(read_recording(path, max_frames));
}

void FrameLoop::load(std::unique_ptr<FrameSource> source) { impl_->load(std::move(source)); }
void FrameLoop::load_scene(const Scene& scene) {
  impl_->wait_for_worker();  // no Box2D call beside the worker's; a scene refused leaves its step pending
  load(simulated_source(scene, impl_->options.max_contacts));
}
void FrameLoop::load_recording(Recording recording) { load_recording(held_frames(std::move(recording))); }
void FrameLoop::load_recording(std::unique_ptr<RecordedFrames> frames) {
  load(recorded_source(std::move(frames), impl_->history.budget()));
}
void FrameLoop::restart() {
  FrameLoopState& m = *impl_;
  if (!m.loaded()) return;
  m.watch.disarm();  // its note describes the old world
  m.watch.reset();   // a new run
  m.discard_step();
  m.frames().rewind();
  m.start();
}

// ---- one frame -----------------------------------------------------------------------------

void FrameLoop::step() {
  FrameLoopState& m = *impl_;
  if (m.settle()) return;  // the frame begin_step() started
  if (m.resuming()) return;
  if (!m.loaded()) return;
  if (m.frames().showing_past()) {
    // A past frame: the next one is the run's own, kept (or the newest).
    if (const auto next = m.history.neighbour(1)) show(*next, FrameChange::Kind::stepped);  // forwards through the run's own frames: a step, to the views
    return;
  }
  if (!m.frames().can_step()) return;
  const FrameLoopState::Unwatch unwatch{m.watch};
  // The stale-positions fault detects the next frame on this one's positions: kept now, when it is
  // on (else a source reads the frame before again if the fault is turned on later).
  const bool stale = m.lanes().options().fault == Fault::StalePositions;
  Elements previous = stale ? m.now() : Elements{};
  m.watch_step();
  const std::int64_t before = m.frame_number();
  const double physics_ms = m.frames().step();  // 0 when nothing is simulated
  m.take_new_entries();                          // a watched run's frames that arrived
  if (m.frame_number() == before) return;        // no frame yet (a watched run's next is not whole)
  m.set_physics_ms(physics_ms);
  if (stale) m.lanes().remember_previous(m.frame_number(), std::move(previous));
  m.detect_and_check(FrameChange::Kind::stepped);
}

void FrameLoop::redetect() { impl_->redetect(); }

void FrameLoop::redetect_with_algorithm(std::string_view name) {
  FrameLoopState& m = *impl_;
  if (name == m.lanes().options().algorithm) return;  // the same detector: nothing to detect again
  m.settle();  // the step in flight adopted first: the pipeline may be the worker's
  m.lanes().set_algorithm(name, [&m] { m.accept_recorded(); });
  m.redetect();
}

void FrameLoop::redetect_with_fault(Fault fault) {
  FrameLoopState& m = *impl_;
  if (fault == m.lanes().options().fault) return;
  m.settle();
  if (m.lanes().has_recorded_lane()) check_recorded_fault(fault);
  m.lanes().set_fault(fault);
  m.redetect();
}

void FrameLoop::redetect_with_checks(bool on) {
  FrameLoopState& m = *impl_;
  if (on == m.lanes().options().checks) return;
  m.settle();
  m.lanes().set_checks(on);
  m.redetect();
}

void FrameLoop::redetect_with_comparisons(const std::vector<std::string>& names) {
  FrameLoopState& m = *impl_;
  if (names == m.lanes().comparison_algorithms()) return;  // nothing changes: no detector is called again
  m.settle();
  m.lanes().set_comparison_algorithms(names, [&m] { m.accept_recorded(); });
  m.redetect();
}

// ---- time travel ---------------------------------------------------------------------------

void FrameLoop::show_frame(std::int64_t frame) { show(frame, FrameChange::Kind::shown); }

void FrameLoop::show(std::int64_t frame, FrameChange::Kind kind) {
  FrameLoopState& m = *impl_;
  if (!m.loaded()) return;
  m.settle();  // the newest frame first, so that the run (and its history) is whole
  if (m.resuming()) throw Error("frame " + std::to_string(frame) + ": the simulation is being resumed; wait or cancel");
  if (!m.history.can_show(frame)) {
    const auto first = m.kept().first_kept();
    const std::int64_t newest = m.history.newest_frame();
    throw Error("frame " + std::to_string(frame) + " is not kept (frames " +
                (first ? std::to_string(*first) : std::to_string(newest)) + ".." + std::to_string(newest) +
                " are; a larger history budget keeps more)");
  }
  if (frame == m.frame_number()) return;
  const auto index = m.kept().find(frame);
  m.frames().show(frame, index ? m.kept().state(*index) : nullptr);
  m.set_physics_ms(0);  // nothing was simulated to show it
  m.detect_and_check(kind);
}

bool FrameLoop::step_back() {
  const auto previous = impl_->history.neighbour(-1);
  if (!previous) return false;
  show_frame(*previous);
  return true;
}

// ---- the parts -----------------------------------------------------------------------------

const FrameChange& FrameLoop::change() const { return impl_->change; }
const CellChanges& FrameLoop::cell_changes() const { return impl_->cell_changes; }
const FrameResult& FrameLoop::result() const {
  return impl_->pipeline.shown();  // the pipeline's, or while the worker detects the next frame, its copy
}
const LoopSource& FrameLoop::source() const { return impl_->source; }
LoopPipeline& FrameLoop::pipeline() { return impl_->pipeline; }
const LoopPipeline& FrameLoop::pipeline() const { return impl_->pipeline; }
LoopHistory& FrameLoop::history() { return impl_->history; }
const LoopHistory& FrameLoop::history() const { return impl_->history; }
LoopResume& FrameLoop::resume() { return impl_->resume; }
const LoopResume& FrameLoop::resume() const { return impl_->resume; }
LoopDrag& FrameLoop::drag() { return impl_->drag; }
const LoopDrag& FrameLoop::drag() const { return impl_->drag; }

}  // namespace nbscope
