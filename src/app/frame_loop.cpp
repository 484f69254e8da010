// FrameLoop: owns the frame source (a Box2D world, or recorded frames), the detector, the checker,
// the frame's results and the run's history.
//
// Index: Impl (state) | scene | recording | configuration | one frame (detect_and_check) | history |
// resume | accessors | drag.
#include "app/frame_loop.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "check/check.hpp"
#include "core/error.hpp"
#include "physics/kept_frame.hpp"
#include "physics/world.hpp"

namespace nbscope {

namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::unique_ptr<Detector> make_2d_detector(std::string_view name) {
  auto d = make_detector(name);
  if (!d->supports_dim(2)) throw Error("algorithm '" + std::string(name) + "' does not handle 2D scenes");
  return d;
}

const PairList kNoPairs;

}  // namespace

// One detector's view of the frame: its pairs, grid, cells and check report.
struct Lane {
  std::string name;
  std::unique_ptr<Detector> detector;
  PairList pairs;
  Grid grid;
  std::vector<CellIndex> cells;
  FrameReport report;

  explicit Lane(std::string_view algorithm) : name(algorithm), detector(make_2d_detector(algorithm)) {}

  // Detection on `input` with the output side of `fault`; timed into report.timings.detection_ms.
  void detect(const Elements& input, const DetectOptions& options, Fault fault, const std::string& where) {
    try {
      const auto t0 = std::chrono::steady_clock::now();
      detector->detect(input, options, pairs);
      sort_pairs(pairs);
      const Grid* own = detector->last_grid();
      grid = own != nullptr ? *own : make_grid(input, options.grid);
      integerise_cells(input, grid, cells);
      apply_output_fault(fault, grid, cells, pairs);
      report.timings.detection_ms = ms_since(t0);
    } catch (const Error& e) {
      throw Error(where + name + ": " + e.what());
    }
  }
};

struct FrameLoop::Impl {
  FrameLoopOptions options;
  Scene scene;
  std::unique_ptr<PhysicsWorld> world;          // the frame source for a scene; null when replaying
  std::shared_ptr<const Recording> recording;   // the frame source when replaying; null for a scene
  std::size_t recorded = 0;                     // index of the current recorded frame
  Lane main;
  std::vector<Lane> others;               // comparison algorithms
  std::vector<std::string> other_names;
  std::vector<FrameReport> other_reports;
  FrameChecker checker;
  PairList main_reference;    // R of the main lane this frame
  DetectOptions detect_options;
  Elements stale;             // last frame's elements (stale-positions fault)
  Elements detected_on;       // what the detectors were given this frame when not the world's elements
  bool detected_on_world = true;

  // ---- history ----
  FrameHistory history;
  ViolationLog violations;
  std::unique_ptr<KeptWorldFrame> kept;  // the past frame shown, or null for the live world's

  // A drag call, with the frame it was made on (before that frame's successor was stepped).
  struct DragInput {
    enum class Kind : std::uint8_t { Begin, To, End } kind = Kind::Begin;
    std::int64_t frame = 0;
    double x = 0, y = 0;
  };
  std::vector<DragInput> inputs;

  // ---- resume ----
  std::unique_ptr<PhysicsWorld> resume_world;  // re-simulating towards resume_target
  std::int64_t resume_target = -1;
  std::size_t resume_input = 0;                // next input to replay
  Elements resume_stale;                       // the re-simulated frame before the target
  std::optional<std::int64_t> divergence;

  explicit Impl(FrameLoopOptions o)
      : options(std::move(o)), main(options.algorithm), checker(CheckOptions{options.brute_limit}) {
    history.set_budget(options.history_budget);
  }

  // ---- the frame source ----
  bool loaded() const { return world != nullptr || recording != nullptr; }
  // Box2D's side of the frame shown: a kept past frame or the live world (null when replaying).
  const Box2dFrame* box2d() const { return kept ? static_cast<const Box2dFrame*>(kept.get()) : world.get(); }
  const Elements& now() const { return world ? box2d()->elements() : recording->frames[recorded].elements; }
  std::int64_t frame_number() const { return world ? box2d()->frame() : recording->frames[recorded].number; }
  double time_now() const { return world ? box2d()->time() : recording->frames[recorded].time; }
  bool first_frame() const { return world ? box2d()->frame() == 0 : recorded == 0; }

  const Elements& detector_input() const { return detected_on_world ? now() : detected_on; }

  // Detection (with the fault) and the check of the world's current frame, for every lane;
  // physics_ms is kept.
  void detect_and_check() {
    const Elements& now = this->now();
    detected_on_world = true;
    if (options.fault == Fault::StalePositions && !first_frame()) {
      // Last frame's positions; elements that did not exist then (emitted now) at their new ones.
      detected_on = now;
      const Eigen::Index old_n = std::min(stale.size(), now.size());
      detected_on.x.head(old_n) = stale.x.head(old_n);
      detected_on.y.head(old_n) = stale.y.head(old_n);
      detected_on_world = false;
    }
    const std::string where = scene.path + ": frame " + std::to_string(frame_number()) + ": ";
    const Elements& input = detector_input();
    main.detect(input, detect_options, options.fault, where);
    for (Lane& lane : others) lane.detect(input, detect_options, options.fault, where);

    if (!options.checks) {
      for (Lane* lane : lanes()) {
        const double detection_ms = lane->report.timings.detection_ms, physics_ms = lane->report.timings.physics_ms;
        lane->report = FrameReport{};
        lane->report.frame = frame_number();
        lane->report.timings = {physics_ms, detection_ms, 0};
        lane->report.counts.elements = now.size();
        lane->report.counts.bodies = world ? box2d()->body_count() : 0;
        lane->report.counts.a = static_cast<std::int64_t>(lane->pairs.size());
      }
    } else {
      // The first lane's check time includes the sets every lane shares (F, G, T).
      auto t0 = std::chrono::steady_clock::now();
      if (world) checker.begin_frame(*box2d(), detect_options);
      else checker.begin_frame(now, frame_number(), detect_options);
      for (Lane* lane : lanes()) {
        CheckInput in;
        in.algorithm = lane->detector->name();
        in.pairs = &lane->pairs;
        in.cells = &lane->cells;
        in.drop_box2d_contact = options.fault == Fault::DropBox2dContact;
        checker.check(in, lane->report);
        if (lane == &main) main_reference = checker.reference_pairs();
        lane->report.timings.check_ms = ms_since(t0);
        t0 = std::chrono::steady_clock::now();
      }
    }
    const std::uint64_t hash = hash_elements(now);
    for (Lane* lane : lanes()) lane->report.hash = hash;
    other_reports.clear();
    for (const Lane& lane : others) other_reports.push_back(lane.report);
    record_frame();
  }

  // The shown frame's summary into the history (a new live frame is pushed with its kept state; a
  // frame shown again has its counts replaced), and its violations into the run's log.
  void record_frame() {
    const FrameReport& r = main.report;
    FrameSummary s;
    s.frame = frame_number();
    s.time = time_now();
    s.hash = r.hash;
    s.kept = true;
    s.checked = r.checked;
    s.elements = now().size();
    s.pairs = static_cast<std::int64_t>(main.pairs.size());
    s.violations = r.violation_count();
    s.physics_ms = static_cast<float>(r.timings.physics_ms);
    s.detection_ms = static_cast<float>(r.timings.detection_ms);
    s.check_ms = static_cast<float>(r.timings.check_ms);
    if (const auto index = history.find(s.frame)) {
      s.physics_ms = history.at(*index).physics_ms;  // a frame shown again is not simulated again
      history.update(*index, s);
    } else {
      std::shared_ptr<WorldState> state;
      if (world && history.budget() > 0) {
        state = std::make_shared<WorldState>();
        world->capture(*state, options.checks ? &checker.box2d_pairs() : nullptr);
      }
      history.push(s, state, state ? state->bytes() : 0);
    }
    violations.set_frame(r);
  }

  std::vector<Lane*> lanes() {
    std::vector<Lane*> all{&main};
    for (Lane& lane : others) all.push_back(&lane);
    return all;
  }

  void set_physics_ms(double ms) {
    for (Lane* lane : lanes()) lane->report.timings.physics_ms = ms;
  }

  void build(const Scene& s) {
    DetectOptions opts;
    if (s.cell_size) opts.grid.cell_size = *s.cell_size;
    if (s.origin) opts.grid.origin = std::array<double, 3>{s.origin->x, s.origin->y, 0};
    if (s.cells) opts.grid.cells = std::array<std::int64_t, 3>{(*s.cells)[0], (*s.cells)[1], 1};
    auto fresh = std::make_unique<PhysicsWorld>(s);
    // A pinned cell size must hold the largest element from the start and every element an
    // emitter will add (the grid would refuse it mid-run, far from the field to fix).
    if (s.cell_size) {
      char d[64];
      if (fresh->elements().size() > 0 && *s.cell_size < 2 * fresh->elements().max_radius()) {
        std::snprintf(d, sizeof d, "%.6g", 2 * fresh->elements().max_radius());
        throw Error(s.cell_size_where + "smaller than the largest element's diameter " + d);
      }
      std::string emitter;
      if (const double r = fresh->largest_emitted_radius(emitter); *s.cell_size < 2 * r) {
        std::snprintf(d, sizeof d, "%.6g", 2 * r);
        throw Error(s.cell_size_where + "smaller than the diameter " + d + " of the elements emitted by " +
                    emitter.substr(0, emitter.size() - 2));
      }
    }
    Scene copy = s;
    scene = std::move(copy);
    kept.reset();  // it points into the old world
    world = std::move(fresh);
    recording.reset();
    detect_options = opts;
    start();
  }

  // The frame source's first frame, detected and checked; a new run: the history starts again.
  void start() {
    for (Lane* lane : lanes()) lane->report = FrameReport{};
    recorded = 0;
    kept.reset();
    resume_world.reset();
    resume_target = -1;
    divergence.reset();
    inputs.clear();
    history.clear();
    violations.clear();
    if (recording) {
      // Every recorded frame is showable from the start; each is checked when first shown.
      for (const RecordedFrame& f : recording->frames) {
        FrameSummary s;
        s.frame = f.number;
        s.time = f.time;
        s.kept = true;
        s.elements = f.elements.size();
        history.push(s, nullptr, 0);
      }
    }
    stale = now();
    detect_and_check();
  }

  // Index of recorded frame number `frame` (it must exist).
  std::size_t recorded_index(std::int64_t frame) const {
    const auto& frames = recording->frames;
    const auto it = std::lower_bound(frames.begin(), frames.end(), frame,
                                     [](const RecordedFrame& f, std::int64_t n) { return f.number < n; });
    return static_cast<std::size_t>(it - frames.begin());
  }

  // The elements of the frame before `frame` when it can be shown, else `frame`'s own (the
  // stale-positions fault then has nothing older to give).
  Elements elements_before(std::int64_t frame) {
    if (recording) return recording->frames[recorded > 0 ? recorded - 1 : 0].elements;
    const auto index = history.find(frame - 1);
    if (index && history.state(*index)) return KeptWorldFrame(*world, history.state(*index)).elements();
    return now();
  }

  // Replays `rec` instead of a world: its grid pins as a scene's would, its name the file's stem.
  void build(std::shared_ptr<const Recording> rec) {
    DetectOptions opts;
    Scene s;
    s.path = rec->path;
    s.name = std::filesystem::path(rec->path).stem().string();
    if (rec->grid.cell_size) opts.grid.cell_size = s.cell_size = *rec->grid.cell_size;
    if (rec->grid.origin) {
      s.origin = Vec2{(*rec->grid.origin)[0], (*rec->grid.origin)[1]};
      opts.grid.origin = std::array<double, 3>{s.origin->x, s.origin->y, 0};
    }
    if (rec->grid.cells) {
      s.cells = rec->grid.cells;
      opts.grid.cells = std::array<std::int64_t, 3>{(*s.cells)[0], (*s.cells)[1], 1};
    }
    // The recorded time per frame, for the panels (the recording's own times are shown per frame).
    const RecordedFrame& first = rec->frames.front();
    const RecordedFrame& last = rec->frames.back();
    if (last.number > first.number && last.time > first.time)
      s.time_step = (last.time - first.time) / static_cast<double>(last.number - first.number);
    scene = std::move(s);
    kept.reset();
    world.reset();
    recording = std::move(rec);
    detect_options = opts;
    start();
  }
};

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
bool FrameLoop::at_end() const { return impl_->recording && impl_->recorded + 1 >= impl_->recording->frames.size(); }

// ---- configuration -------------------------------------------------------------------------

void FrameLoop::set_algorithm(std::string_view name) {
  Lane fresh(name);
  fresh.report = impl_->main.report;
  impl_->main = std::move(fresh);
  impl_->options.algorithm = std::string(name);
  redetect();
}
const std::string& FrameLoop::algorithm() const { return impl_->options.algorithm; }

void FrameLoop::set_fault(Fault fault) {
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
  for (const std::string& name : names) lanes.emplace_back(name);
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
    m.set_physics_ms(0);  // no physics: the frame was read with the file
    m.detect_and_check();
    return;
  }
  if (!m.world) return;
  m.stale = m.world->elements();
  const auto t0 = std::chrono::steady_clock::now();
  m.world->step();
  m.set_physics_ms(ms_since(t0));
  m.detect_and_check();
}

void FrameLoop::redetect() {
  if (impl_->loaded()) impl_->detect_and_check();
}

// ---- history -------------------------------------------------------------------------------

const FrameHistory& FrameLoop::history() const { return impl_->history; }
void FrameLoop::set_history_budget(std::size_t bytes) {
  impl_->options.history_budget = bytes;
  impl_->history.set_budget(bytes);
}
const ViolationLog& FrameLoop::violation_log() const { return impl_->violations; }
bool FrameLoop::showing_past() const { return impl_->kept != nullptr; }

std::int64_t FrameLoop::newest_frame() const {
  const Impl& m = *impl_;
  if (m.recording) return m.recording->frames.back().number;
  return m.world ? m.world->frame() : 0;
}

bool FrameLoop::can_show(std::int64_t frame) const {
  const Impl& m = *impl_;
  if (!m.loaded()) return false;
  if (m.world && frame == m.world->frame()) return true;
  const auto index = m.history.find(frame);
  return index && m.history.at(*index).kept && (m.recording || m.history.state(*index));
}

void FrameLoop::show_frame(std::int64_t frame) {
  Impl& m = *impl_;
  if (!m.loaded()) return;
  if (m.resume_world) throw Error("frame " + std::to_string(frame) + ": the simulation is being resumed; wait or cancel");
  if (!can_show(frame)) {
    const auto first = m.history.first_kept();
    throw Error("frame " + std::to_string(frame) + " is not kept (frames " +
                (first ? std::to_string(*first) : std::to_string(newest_frame())) + ".." + std::to_string(newest_frame()) +
                " are; a larger history budget keeps more)");
  }
  if (frame == m.frame_number()) return;
  const double physics_ms = 0;  // nothing was simulated to show it
  if (m.recording) {
    m.recorded = m.recorded_index(frame);
    m.stale = m.elements_before(frame);
  } else if (frame == m.world->frame()) {
    m.kept.reset();
    if (m.options.fault == Fault::StalePositions) m.stale = m.elements_before(frame);
  } else {
    m.kept = std::make_unique<KeptWorldFrame>(*m.world, m.history.state(*m.history.find(frame)));
    if (m.options.fault == Fault::StalePositions) m.stale = m.elements_before(frame);
  }
  m.set_physics_ms(physics_ms);
  m.detect_and_check();
}

bool FrameLoop::step_back() {
  const auto previous = neighbour(-1);
  if (!previous) return false;
  show_frame(*previous);
  return true;
}

std::optional<std::int64_t> FrameLoop::neighbour(std::int64_t delta) const {
  const Impl& m = *impl_;
  if (!m.loaded() || delta == 0 || m.history.empty()) return std::nullopt;
  const auto here = m.history.find(m.frame_number());
  if (!here) return std::nullopt;
  const auto last = static_cast<std::int64_t>(m.history.size()) - 1;
  std::int64_t index = std::clamp<std::int64_t>(static_cast<std::int64_t>(*here) + delta, 0, last);
  // Past frames whose states were dropped cannot be shown: stop at the oldest that can.
  const auto showable = [&](std::int64_t i) { return can_show(m.history.at(static_cast<std::size_t>(i)).frame); };
  while (index != static_cast<std::int64_t>(*here) && !showable(index)) index += delta > 0 ? -1 : 1;
  if (index == static_cast<std::int64_t>(*here)) return std::nullopt;
  return m.history.at(static_cast<std::size_t>(index)).frame;
}

void FrameLoop::element_path(ElementId k, std::int64_t from, std::int64_t to, std::vector<std::array<double, 2>>& out) const {
  out.clear();
  const Impl& m = *impl_;
  if (!m.loaded() || k < 0) return;
  for (std::size_t i = 0; i < m.history.size(); ++i) {
    const FrameSummary& f = m.history.at(i);
    if (f.frame < from || f.frame > to || k >= f.elements) continue;
    if (m.recording) {
      const Elements& e = m.recording->frames[m.recorded_index(f.frame)].elements;
      out.push_back({e.x[k], e.y[k]});
    } else if (const auto& state = m.history.state(i)) {
      std::array<double, 2> p{};
      m.world->element_centre(*state, k, p[0], p[1]);
      out.push_back(p);
    } else if (f.frame == m.world->frame()) {
      out.push_back({m.world->elements().x[k], m.world->elements().y[k]});
    }
  }
}

// ---- resume --------------------------------------------------------------------------------

void FrameLoop::begin_resume() {
  Impl& m = *impl_;
  if (!m.world || !m.kept || m.resume_world) return;
  m.resume_target = m.kept->frame();
  m.resume_world = std::make_unique<PhysicsWorld>(m.scene);
  m.resume_input = 0;
  m.divergence.reset();
}

bool FrameLoop::continue_resume(double budget_ms) {
  Impl& m = *impl_;
  if (!m.resume_world) return true;
  PhysicsWorld& w = *m.resume_world;
  const auto t0 = std::chrono::steady_clock::now();
  do {
    if (w.frame() >= m.resume_target) break;
    // The drags made on this frame, in their order, then the step, as the original run did.
    while (m.resume_input < m.inputs.size() && m.inputs[m.resume_input].frame <= w.frame()) {
      const Impl::DragInput& in = m.inputs[m.resume_input++];
      if (in.kind == Impl::DragInput::Kind::Begin) w.begin_drag(in.x, in.y);
      else if (in.kind == Impl::DragInput::Kind::To) w.drag_to(in.x, in.y);
      else w.end_drag();
    }
    if (w.frame() + 1 == m.resume_target) m.resume_stale = w.elements();
    try {
      w.step();
    } catch (const Error& e) {
      cancel_resume();
      throw Error(m.scene.path + ": resuming at frame " + std::to_string(w.frame()) + ": " + e.what());
    }
    // Determinism check: every kept frame on the way must come back exactly.
    if (!m.divergence) {
      const auto index = m.history.find(w.frame());
      if (index && m.history.at(*index).hash != 0 && m.history.at(*index).hash != hash_elements(w.elements()))
        m.divergence = w.frame();
    }
  } while (ms_since(t0) < budget_ms);
  if (w.frame() < m.resume_target) return false;

  // Arrived: the re-simulated world is the live one at K, the later frames are gone.
  const std::int64_t k = m.resume_target;
  if (w.dragging()) w.end_drag();  // nobody holds the mouse now
  m.kept.reset();
  m.world = std::move(m.resume_world);
  m.resume_target = -1;
  m.history.truncate_after(k);
  m.violations.truncate_after(k);
  std::erase_if(m.inputs, [&](const Impl::DragInput& in) { return in.frame >= k; });
  m.stale = k > 0 ? m.resume_stale : m.world->elements();
  m.set_physics_ms(0);
  m.detect_and_check();
  return true;
}

void FrameLoop::cancel_resume() {
  impl_->resume_world.reset();
  impl_->resume_target = -1;
}

bool FrameLoop::resuming() const { return impl_->resume_world != nullptr; }

std::pair<std::int64_t, std::int64_t> FrameLoop::resume_progress() const {
  const Impl& m = *impl_;
  if (!m.resume_world) return {0, 0};
  return {m.resume_world->frame(), m.resume_target};
}

std::optional<std::int64_t> FrameLoop::resume_divergence() const { return impl_->divergence; }

// ---- accessors -----------------------------------------------------------------------------

std::int64_t FrameLoop::frame() const { return impl_->loaded() ? impl_->frame_number() : 0; }
double FrameLoop::time() const { return impl_->loaded() ? impl_->time_now() : 0; }

const Elements& FrameLoop::elements() const {
  static const Elements kNone;
  return impl_->loaded() ? impl_->now() : kNone;
}
const std::vector<ElementSource>& FrameLoop::element_sources() const {
  static const std::vector<ElementSource> kNone;
  return impl_->world ? impl_->world->sources() : kNone;
}
std::int64_t FrameLoop::body_count() const { return impl_->world ? impl_->box2d()->body_count() : 0; }
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
  if (impl_->world) {
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

void FrameLoop::trace_frame(TraceLog& out_trace, PairList& out_pairs) {
  if (!impl_->loaded()) {
    out_trace.reset();
    out_pairs.clear();
    return;
  }
  impl_->main.detector->detect_traced(impl_->detector_input(), impl_->detect_options, out_pairs, out_trace);
}

// ---- drag ----------------------------------------------------------------------------------

bool FrameLoop::begin_drag(double x, double y) {
  Impl& m = *impl_;
  if (!m.world || m.kept || m.resume_world) return false;
  m.inputs.push_back({Impl::DragInput::Kind::Begin, m.world->frame(), x, y});
  return m.world->begin_drag(x, y);
}
void FrameLoop::drag_to(double x, double y) {
  Impl& m = *impl_;
  if (!m.world || m.kept || m.resume_world || !m.world->dragging()) return;
  m.inputs.push_back({Impl::DragInput::Kind::To, m.world->frame(), x, y});
  m.world->drag_to(x, y);
}
void FrameLoop::end_drag() {
  Impl& m = *impl_;
  if (!m.world || m.kept || m.resume_world || !m.world->dragging()) return;
  m.inputs.push_back({Impl::DragInput::Kind::End, m.world->frame(), 0, 0});
  m.world->end_drag();
}
bool FrameLoop::dragging() const { return impl_->world && !impl_->kept && impl_->world->dragging(); }

}  // namespace nbscope
