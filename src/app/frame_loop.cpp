// FrameLoop: owns the frame source (a Box2D world, or recorded frames), the detector, the checker,
// the frame's results and the run's history (shown and resumed in frame_loop_history.cpp).
//
// Index: scene | recording | configuration | one frame | accessors | drag.
#include "app/frame_loop_impl.hpp"
#include "io/scene_json.hpp"

namespace nbscope {

FrameLoop::FrameLoop(FrameLoopOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}
FrameLoop::~FrameLoop() = default;

// ---- scene ---------------------------------------------------------------------------------

void FrameLoop::load_scene_file(const std::string& path) { impl_->build(read_scene_json(path)); }
void FrameLoop::load_scene(const Scene& scene) { impl_->build(scene); }
void FrameLoop::restart() {
  if (impl_->live) impl_->build(Scene(impl_->scene));
  else if (impl_->replay) impl_->start();
}
bool FrameLoop::has_scene() const { return impl_->loaded(); }
const Scene& FrameLoop::scene() const { return impl_->scene; }

// ---- recording -----------------------------------------------------------------------------

void FrameLoop::load_recording_file(const std::string& path, std::int64_t max_frames) {
  load_recording(read_recording(path, max_frames));
}
void FrameLoop::load_recording(Recording recording) {
  if (recording.frames.empty()) throw Error(recording.path + ": no frames");
  impl_->build(std::make_shared<const Recording>(std::move(recording)));
}
bool FrameLoop::replaying() const { return impl_->replay != nullptr; }
std::int64_t FrameLoop::recorded_frames() const {
  return impl_->replay ? static_cast<std::int64_t>(impl_->replay->recording().frames.size()) : 0;
}
bool FrameLoop::carries_pairs() const { return impl_->replay && impl_->replay->recording().has_pairs; }
int FrameLoop::pair_base() const { return impl_->replay ? impl_->replay->recording().pair_base : 0; }
bool FrameLoop::at_end() const { return impl_->replay && !impl_->replay->can_step(); }

// ---- configuration -------------------------------------------------------------------------

void FrameLoop::set_algorithm(std::string_view name) {
  impl_->pipeline.set_algorithm(name, [this] { impl_->accept_recorded(); });
  redetect();
}
const std::string& FrameLoop::algorithm() const { return impl_->pipeline.options().algorithm; }

void FrameLoop::set_fault(Fault fault) {
  if (impl_->pipeline.has_recorded_lane()) check_recorded_fault(fault);
  impl_->pipeline.set_fault(fault);
  redetect();
}
Fault FrameLoop::fault() const { return impl_->pipeline.options().fault; }

void FrameLoop::set_checks_enabled(bool on) {
  impl_->pipeline.set_checks(on);
  redetect();
}
bool FrameLoop::checks_enabled() const { return impl_->pipeline.options().checks; }
std::string FrameLoop::reference_policy() const { return impl_->pipeline.reference_policy(); }
std::string FrameLoop::scope_note() { return FrameChecker::scope_note(); }

void FrameLoop::set_comparison_algorithms(const std::vector<std::string>& names) {
  impl_->pipeline.set_comparison_algorithms(names, [this] { impl_->accept_recorded(); });
  redetect();
}
const std::vector<std::string>& FrameLoop::comparison_algorithms() const { return impl_->pipeline.comparison_algorithms(); }
const std::vector<FrameReport>& FrameLoop::comparison_reports() const { return impl_->pipeline.comparison_reports(); }

// ---- one frame -----------------------------------------------------------------------------

void FrameLoop::step() {
  Impl& m = *impl_;
  if (m.settle()) return;  // the frame begin_step() started
  if (m.resume.active()) return;
  if (m.kept) {
    // A past frame: the next one is the run's own, kept (or the live one).
    if (const auto next = neighbour(1)) show_frame(*next);
    return;
  }
  if (!m.loaded() || !m.source().can_step()) return;
  Elements previous = m.now();  // the stale-positions fault's positions for the next frame
  const Impl::Unwatch unwatch{m.watch};
  if (m.live) m.watch_physics();
  m.set_physics_ms(m.live ? m.live->step() : m.replay->step());  // a recorded frame was read with the file: 0
  m.pipeline.remember_previous(m.frame_number(), std::move(previous));
  m.detect_and_check();
}

void FrameLoop::redetect() {
  if (impl_->settle()) return;  // a step in flight is adopted, and so detected with what is set now
  if (impl_->loaded()) impl_->detect_and_check();
}

// ---- accessors -----------------------------------------------------------------------------

std::int64_t FrameLoop::frame() const { return impl_->loaded() ? impl_->frame_number() : 0; }
double FrameLoop::time() const { return impl_->loaded() ? impl_->source().time() : 0; }

const Elements& FrameLoop::elements() const {
  static const Elements kNone;
  return impl_->loaded() ? impl_->now() : kNone;
}
const std::vector<ElementSource>& FrameLoop::element_sources() const {
  static const std::vector<ElementSource> kNone;
  return impl_->loaded() ? impl_->source().element_sources() : kNone;
}
std::int64_t FrameLoop::body_count() const { return impl_->loaded() ? impl_->source().body_count() : 0; }
std::uint64_t FrameLoop::generation() const { return impl_->generation; }
const FrameResult& FrameLoop::result() const { return impl_->pipeline.result(); }
const PairList& FrameLoop::pairs() const { return impl_->pipeline.result().selected().pairs; }
const Grid& FrameLoop::grid() const { return impl_->pipeline.result().selected().grid; }
const std::vector<CellIndex>& FrameLoop::cells() const { return impl_->pipeline.result().selected().cells; }
const FrameReport& FrameLoop::report() const { return impl_->pipeline.result().report(); }
const PairList& FrameLoop::reference_pairs() const { return impl_->pipeline.result().reference; }
const PairList& FrameLoop::box2d_pairs() const { return impl_->pipeline.result().box2d; }
const PairList& FrameLoop::touching_pairs() const { return impl_->pipeline.result().touching; }
const PairList& FrameLoop::tight_aabb_pairs() const { return impl_->pipeline.result().tight_aabb; }

void FrameLoop::body_shapes(std::vector<BodyShape>& out) const {
  out.clear();
  if (impl_->loaded()) impl_->source().body_shapes(out);
}

const Detector& FrameLoop::detector() const { return impl_->pipeline.detector(); }

std::shared_ptr<const FrameTrace> FrameLoop::frame_trace() {
  if (!impl_->loaded()) return nullptr;
  return impl_->pipeline.trace(impl_->source());
}

// ---- drag ----------------------------------------------------------------------------------

bool FrameLoop::begin_drag(double x, double y) {
  Impl& m = *impl_;
  m.settle();  // the drag acts on the newest frame
  if (!m.live || m.kept || m.resume.active()) return false;
  return m.live->begin_drag(x, y);
}
void FrameLoop::drag_to(double x, double y) {
  Impl& m = *impl_;
  m.settle();
  if (m.live && !m.kept && !m.resume.active()) m.live->drag_to(x, y);
}
void FrameLoop::end_drag() {
  Impl& m = *impl_;
  m.settle();
  if (m.live && !m.kept && !m.resume.active()) m.live->end_drag();
}
bool FrameLoop::dragging() const { return impl_->live && !impl_->kept && impl_->live->dragging(); }

}  // namespace nbscope
