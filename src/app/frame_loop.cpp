// FrameLoop: the coordination of one run (loading, stepping, time travel). Its state is
// FrameLoopState (app/frame_loop_impl.hpp); the parts it hands out are in frame_loop_parts.cpp, the
// history and resume in frame_loop_history.cpp, the overlapped step in frame_loop_overlap.cpp.
//
// Index: loading | one frame | time travel | the parts.
#include "app/frame_loop_impl.hpp"
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

void FrameLoop::load_scene(const Scene& scene) { impl_->build(scene); }
void FrameLoop::load_recording(Recording recording) { load_recording(held_frames(std::move(recording))); }
void FrameLoop::load_recording(std::unique_ptr<RecordedFrames> frames) { impl_->build(std::move(frames)); }
void FrameLoop::restart() {
  if (impl_->live) impl_->build(Scene(impl_->scene));
  else if (impl_->replay) impl_->start();
}

// ---- one frame -----------------------------------------------------------------------------

void FrameLoop::step() {
  FrameLoopState& m = *impl_;
  if (m.settle()) return;  // the frame begin_step() started
  if (m.resume.active()) return;
  if (m.kept) {
    // A past frame: the next one is the run's own, kept (or the live one).
    if (const auto next = history_.neighbour(1)) {
      show_frame(*next);
      m.change.kind = FrameChange::Kind::stepped;  // forwards through the run's own frames: a step, to the views
    }
    return;
  }
  if (!m.loaded() || !m.source().can_step()) return;
  const FrameLoopState::Unwatch unwatch{m.watch};
  if (m.replay) {
    // A recorded frame's predecessor is read again if the stale-positions fault asks for it: no copy per frame.
    m.set_physics_ms(m.replay->step());  // nothing is simulated: 0
    m.detect_and_check(FrameChange::Kind::stepped);
    return;
  }
  Elements previous = m.now();  // the stale-positions fault's positions for the next frame
  m.watch_physics();
  m.set_physics_ms(m.live->step());
  m.pipeline.remember_previous(m.frame_number(), std::move(previous));
  m.detect_and_check(FrameChange::Kind::stepped);
}

void FrameLoop::redetect() { impl_->redetect(); }

// ---- time travel ---------------------------------------------------------------------------

void FrameLoop::show_frame(std::int64_t frame) {
  FrameLoopState& m = *impl_;
  if (!m.loaded()) return;
  m.settle();  // the newest frame first, so that the run (and its history) is whole
  if (m.resume.active()) throw Error("frame " + std::to_string(frame) + ": the simulation is being resumed; wait or cancel");
  if (!history_.can_show(frame)) {
    const auto first = m.history.first_kept();
    const std::int64_t newest = history_.newest_frame();
    throw Error("frame " + std::to_string(frame) + " is not kept (frames " +
                (first ? std::to_string(*first) : std::to_string(newest)) + ".." + std::to_string(newest) +
                " are; a larger history budget keeps more)");
  }
  if (frame == m.frame_number()) return;
  const double physics_ms = 0;  // nothing was simulated to show it
  if (m.replay) {
    m.replay->show(frame);
  } else if (frame == m.live->world().frame()) {
    m.kept.reset();
  } else {
    m.live->release_drag();  // leaving the live frame: nobody holds a body in the past
    m.kept = std::make_unique<KeptWorldFrame>(m.live->world(), m.history.state(*m.history.find(frame)));
  }
  m.set_physics_ms(physics_ms);
  m.detect_and_check(FrameChange::Kind::shown);
}

bool FrameLoop::step_back() {
  const auto previous = history_.neighbour(-1);
  if (!previous) return false;
  show_frame(*previous);
  return true;
}

// ---- the parts -----------------------------------------------------------------------------

const FrameChange& FrameLoop::change() const { return impl_->change; }
const FrameResult& FrameLoop::result() const { return impl_->pipeline.result(); }
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
