// FrameLoop: owns the frame source (a Box2D world, or recorded frames), the detector, the checker,
// the frame's results and the run's history (shown and resumed in frame_loop_history.cpp).
//
// Index: scene | recording | configuration | one frame | accessors | drag.
#include "app/frame_loop_impl.hpp"
#include "io/scene_json.hpp"

namespace nbscope {

namespace {
const PairList kNoPairs;
}  // namespace

FrameLoop::FrameLoop(FrameLoopOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}
FrameLoop::~FrameLoop() = default;

// ---- scene ---------------------------------------------------------------------------------

void FrameLoop::load_scene_file(const std::string& path) { impl_->build(read_scene_json(path)); }
void FrameLoop::load_scene(const Scene& scene) { impl_->build(scene); }
void FrameLoop::restart() {
  if (impl_->world) impl_->build(Scene(impl_->scene));
  else if (impl_->recording) impl_->start();
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
bool FrameLoop::replaying() const { return impl_->recording != nullptr; }
std::int64_t FrameLoop::recorded_frames() const {
  return impl_->recording ? static_cast<std::int64_t>(impl_->recording->frames.size()) : 0;
}
bool FrameLoop::carries_pairs() const { return impl_->recording && impl_->recording->has_pairs; }
int FrameLoop::pair_base() const { return impl_->recording ? impl_->recording->pair_base : 0; }
bool FrameLoop::at_end() const { return impl_->recording && impl_->recorded + 1 >= impl_->recording->frames.size(); }

// ---- configuration -------------------------------------------------------------------------

void FrameLoop::set_algorithm(std::string_view name) {
  Lane fresh(name);
  if (fresh.recorded_pairs) {
    // Refused here, not on the next frame: the old algorithm stays.
    check_recorded_fault(impl_->options.fault);
    if (impl_->loaded()) Impl::check_recorded_source(true, impl_->recording.get(), impl_->scene.path);
  }
  fresh.report = impl_->main.report;
  impl_->main = std::move(fresh);
  impl_->options.algorithm = std::string(name);
  redetect();
}
const std::string& FrameLoop::algorithm() const { return impl_->options.algorithm; }

void FrameLoop::set_fault(Fault fault) {
  if (impl_->has_recorded_lane()) check_recorded_fault(fault);
  impl_->options.fault = fault;
  redetect();
}
Fault FrameLoop::fault() const { return impl_->options.fault; }

void FrameLoop::set_checks_enabled(bool on) {
  impl_->options.checks = on;
  redetect();
}
bool FrameLoop::checks_enabled() const { return impl_->options.checks; }
std::string FrameLoop::reference_policy() const { return impl_->checker.reference_policy(); }
std::string FrameLoop::scope_note() { return FrameChecker::scope_note(); }

void FrameLoop::set_comparison_algorithms(const std::vector<std::string>& names) {
  std::vector<Lane> lanes;
  for (const std::string& name : names) {
    lanes.emplace_back(name);
    if (lanes.back().recorded_pairs) {
      check_recorded_fault(impl_->options.fault);
      if (impl_->loaded()) Impl::check_recorded_source(true, impl_->recording.get(), impl_->scene.path);
    }
  }
  impl_->others = std::move(lanes);
  impl_->other_names = names;
  impl_->other_reports.clear();
  redetect();
}
const std::vector<std::string>& FrameLoop::comparison_algorithms() const { return impl_->other_names; }
const std::vector<FrameReport>& FrameLoop::comparison_reports() const { return impl_->other_reports; }

// ---- one frame -----------------------------------------------------------------------------

void FrameLoop::step() {
  Impl& m = *impl_;
  if (m.settle()) return;  // the frame begin_step() started
  if (m.resume_world) return;
  if (m.kept) {
    // A past frame: the next one is the run's own, kept (or the live one).
    if (const auto next = neighbour(1)) show_frame(*next);
    return;
  }
  if (m.recording) {
    if (at_end()) return;
    m.stale = m.now();
    ++m.recorded;
    m.stale_for = m.frame_number();
    m.set_physics_ms(0);  // no physics: the frame was read with the file
    m.detect_and_check();
    return;
  }
  if (!m.world) return;
  m.stale = m.world->elements();
  m.stale_for = m.world->frame() + 1;
  const Impl::Unwatch unwatch{m.watch};
  m.watch_physics();
  const auto t0 = std::chrono::steady_clock::now();
  m.world->step();
  m.set_physics_ms(ms_since(t0));
  m.detect_and_check();
}

void FrameLoop::redetect() {
  if (impl_->settle()) return;  // a step in flight is adopted, and so detected with what is set now
  if (impl_->loaded()) impl_->detect_and_check();
}

// ---- accessors -----------------------------------------------------------------------------

std::int64_t FrameLoop::frame() const { return impl_->loaded() ? impl_->frame_number() : 0; }
double FrameLoop::time() const { return impl_->loaded() ? impl_->time_now() : 0; }

const Elements& FrameLoop::elements() const {
  static const Elements kNone;
  return impl_->loaded() ? impl_->now() : kNone;
}
const std::vector<ElementSource>& FrameLoop::element_sources() const {
  static const std::vector<ElementSource> kNone;
  if (impl_->pending()) return impl_->shown.sources;
  return impl_->world ? impl_->world->sources() : kNone;
}
std::int64_t FrameLoop::body_count() const {
  if (impl_->pending()) return impl_->shown.bodies;
  return impl_->world ? impl_->box2d()->body_count() : 0;
}
const PairList& FrameLoop::pairs() const { return impl_->main.pairs; }
const Grid& FrameLoop::grid() const { return impl_->main.grid; }
const std::vector<CellIndex>& FrameLoop::cells() const { return impl_->main.cells; }
const FrameReport& FrameLoop::report() const { return impl_->main.report; }
const PairList& FrameLoop::reference_pairs() const { return impl_->options.checks ? impl_->main_reference : kNoPairs; }
const PairList& FrameLoop::box2d_pairs() const { return impl_->options.checks ? impl_->checker.box2d_pairs() : kNoPairs; }
const PairList& FrameLoop::touching_pairs() const { return impl_->options.checks ? impl_->checker.touching_pairs() : kNoPairs; }
const PairList& FrameLoop::tight_aabb_pairs() const { return impl_->options.checks ? impl_->checker.tight_aabb_pairs() : kNoPairs; }

void FrameLoop::body_shapes(std::vector<BodyShape>& out) const {
  out.clear();
  if (impl_->pending()) {
    out = impl_->shown.shapes;
  } else if (impl_->world) {
    impl_->box2d()->shapes(out);
  } else if (impl_->recording) {
    // No bodies: each recorded element is drawn as a dynamic circle.
    const Elements& e = impl_->now();
    out.resize(static_cast<std::size_t>(e.size()));
    for (Eigen::Index k = 0; k < e.size(); ++k) {
      BodyShape& b = out[static_cast<std::size_t>(k)];
      b.element = static_cast<ElementId>(k);
      b.centre = Vec2{e.x[k], e.y[k]};
      b.radius = e.r[k];
    }
  }
}

const Detector& FrameLoop::detector() const { return *impl_->main.detector; }

std::shared_ptr<const FrameTrace> FrameLoop::frame_trace() {
  Impl& m = *impl_;
  if (!m.loaded()) return nullptr;
  if (!m.trace && m.main.recorded_pairs) {
    // Read, not detected: nothing to step through, said in the panels' words.
    auto none = std::make_shared<FrameTrace>(refused_trace(m.frame_number(), m.main.detector->name()));
    none->refusal = recorded_trace_refusal();
    m.trace = std::move(none);
  }
  if (!m.trace) {
    try {
      m.trace = trace_frame(*m.main.detector, m.detector_input(), m.detect_options, m.frame_number(), grid());
    } catch (const Error& e) {
      // The detection itself refused the frame (as step() would say): kept as the trace's reason, so
      // the panels show it and it is not tried again every UI frame.
      auto refused = std::make_shared<FrameTrace>(refused_trace(m.frame_number(), m.main.detector->name()));
      refused->refusal = e.what();
      m.trace = std::move(refused);
    }
  }
  return m.trace;
}

// ---- drag ----------------------------------------------------------------------------------

bool FrameLoop::begin_drag(double x, double y) {
  Impl& m = *impl_;
  m.settle();  // the drag acts on the newest frame
  if (!m.world || m.kept || m.resume_world) return false;
  m.inputs.push_back({Impl::DragInput::Kind::Begin, m.world->frame(), x, y});
  return m.world->begin_drag(x, y);
}
void FrameLoop::drag_to(double x, double y) {
  Impl& m = *impl_;
  m.settle();
  if (!m.world || m.kept || m.resume_world || !m.world->dragging()) return;
  m.inputs.push_back({Impl::DragInput::Kind::To, m.world->frame(), x, y});
  m.world->drag_to(x, y);
}
void FrameLoop::end_drag() {
  Impl& m = *impl_;
  m.settle();
  if (!m.world || m.kept || m.resume_world || !m.world->dragging()) return;
  m.inputs.push_back({Impl::DragInput::Kind::End, m.world->frame(), 0, 0});
  m.world->end_drag();
}
bool FrameLoop::dragging() const {
  if (impl_->pending()) return impl_->shown.dragging;
  return impl_->world && !impl_->kept && impl_->world->dragging();
}

}  // namespace nbscope
