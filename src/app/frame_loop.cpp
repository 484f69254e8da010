// FrameLoop: the coordination of one run (loading, stepping, time travel). Its state is
// FrameLoopState (app/frame_loop_impl.hpp); the parts it hands out are in frame_loop_parts.cpp, the
// history and resume in frame_loop_history.cpp, the overlapped step in frame_loop_overlap.cpp.
//
// Index: loading | one frame | time travel | the parts.
#include "app/frame_loop_impl.hpp"
#include "app/frame_sources.hpp"
#include "io/scene_json.hpp"

namespace nbscope {

FrameLoop::FrameLoop(FrameLoopOptions options)
    : impl_(std::make_unique<FrameLoopState>(std::move(options))),
      source_(*impl_),
      pipeline_(*impl_),
      history_(*impl_),
      resume_(*impl_),
      drag_(*impl_) {}
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
  load(recorded_source(std::move(frames), impl_->options.history_budget));
}
void FrameLoop::restart() {
  FrameLoopState& m = *impl_;
  if (!m.loaded()) return;
  m.watch.disarm();  // its note describes the old world
  m.watch.reset();   // a new run
  m.discard_step();
  m.frames->rewind();
  m.start();
}

// ---- one frame -----------------------------------------------------------------------------

void FrameLoop::step() {
  FrameLoopState& m = *impl_;
  if (m.settle()) return;  // the frame begin_step() started
  if (m.resuming()) return;
  if (!m.loaded()) return;
  if (m.frames->showing_past()) {
    // A past frame: the next one is the run's own, kept (or the newest).
    if (const auto next = history_.neighbour(1)) show(*next, FrameChange::Kind::stepped);  // forwards through the run's own frames: a step, to the views
    return;
  }
  if (!m.frames->can_step()) return;
  const FrameLoopState::Unwatch unwatch{m.watch};
  // The stale-positions fault detects the next frame on this one's positions: kept now, when it is
  // on (else a source reads the frame before again if the fault is turned on later).
  const bool stale = m.pipeline.options().fault == Fault::StalePositions;
  Elements previous = stale ? m.now() : Elements{};
  m.watch_step();
  m.set_physics_ms(m.frames->step());  // 0 when nothing is simulated
  if (stale) m.pipeline.remember_previous(m.frame_number(), std::move(previous));
  m.detect_and_check(FrameChange::Kind::stepped);
}

void FrameLoop::redetect() { impl_->redetect(); }

void FrameLoop::redetect_with_algorithm(std::string_view name) {
  FrameLoopState& m = *impl_;
  if (name == m.pipeline.options().algorithm) return;  // the same detector: nothing to detect again
  m.settle();  // the step in flight adopted first: the pipeline may be the worker's
  m.pipeline.set_algorithm(name, [&m] { m.accept_recorded(); });
  m.redetect();
}

void FrameLoop::redetect_with_fault(Fault fault) {
  FrameLoopState& m = *impl_;
  if (fault == m.pipeline.options().fault) return;
  m.settle();
  if (m.pipeline.has_recorded_lane()) check_recorded_fault(fault);
  m.pipeline.set_fault(fault);
  m.redetect();
}

void FrameLoop::redetect_with_checks(bool on) {
  FrameLoopState& m = *impl_;
  if (on == m.pipeline.options().checks) return;
  m.settle();
  m.pipeline.set_checks(on);
  m.redetect();
}

void FrameLoop::redetect_with_comparisons(const std::vector<std::string>& names) {
  FrameLoopState& m = *impl_;
  if (names == m.pipeline.comparison_algorithms()) return;  // nothing changes: no detector is called again
  m.settle();
  m.pipeline.set_comparison_algorithms(names, [&m] { m.accept_recorded(); });
  m.redetect();
}

// ---- time travel ---------------------------------------------------------------------------

void FrameLoop::show_frame(std::int64_t frame) { show(frame, FrameChange::Kind::shown); }

void FrameLoop::show(std::int64_t frame, FrameChange::Kind kind) {
  FrameLoopState& m = *impl_;
  if (!m.loaded()) return;
  m.settle();  // the newest frame first, so that the run (and its history) is whole
  if (m.resuming()) throw Error("frame " + std::to_string(frame) + ": the simulation is being resumed; wait or cancel");
  if (!history_.can_show(frame)) {
    const auto first = m.history.first_kept();
    const std::int64_t newest = history_.newest_frame();
    throw Error("frame " + std::to_string(frame) + " is not kept (frames " +
                (first ? std::to_string(*first) : std::to_string(newest)) + ".." + std::to_string(newest) +
                " are; a larger history budget keeps more)");
  }
  if (frame == m.frame_number()) return;
  const auto index = m.history.find(frame);
  m.frames->show(frame, index ? m.history.state(*index) : nullptr);
  m.set_physics_ms(0);  // nothing was simulated to show it
  m.detect_and_check(kind);
}

bool FrameLoop::step_back() {
  const auto previous = history_.neighbour(-1);
  if (!previous) return false;
  show_frame(*previous);
  return true;
}

// ---- the parts -----------------------------------------------------------------------------

const FrameChange& FrameLoop::change() const { return impl_->change; }
const CellChanges& FrameLoop::cell_changes() const { return impl_->cell_changes; }
const FrameResult& FrameLoop::result() const {
  return impl_->pipeline_on_worker() ? *impl_->shown_result : impl_->pipeline.result();  // the shown frame's either way
}
const LoopSource& FrameLoop::source() const { return source_; }
LoopPipeline& FrameLoop::pipeline() { return pipeline_; }
const LoopPipeline& FrameLoop::pipeline() const { return pipeline_; }
LoopHistory& FrameLoop::history() { return history_; }
const LoopHistory& FrameLoop::history() const { return history_; }
LoopResume& FrameLoop::resume() { return resume_; }
const LoopResume& FrameLoop::resume() const { return resume_; }
LoopDrag& FrameLoop::drag() { return drag_; }
const LoopDrag& FrameLoop::drag() const { return drag_; }

}  // namespace nbscope
