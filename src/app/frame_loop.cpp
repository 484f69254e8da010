// FrameLoop: owns the frame source (a Box2D world, or recorded frames), the detector, the checker
// and the frame's results.
//
// Index: Impl (state) | scene | recording | configuration | one frame (detect_and_check) | accessors | drag.
#include "app/frame_loop.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "check/check.hpp"
#include "core/error.hpp"
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

  explicit Impl(FrameLoopOptions o)
      : options(std::move(o)), main(options.algorithm), checker(CheckOptions{options.brute_limit}) {}

  // ---- the frame source ----
  bool loaded() const { return world != nullptr || recording != nullptr; }
  const Elements& now() const { return world ? world->elements() : recording->frames[recorded].elements; }
  std::int64_t frame_number() const { return world ? world->frame() : recording->frames[recorded].number; }
  bool first_frame() const { return world ? world->frame() == 0 : recorded == 0; }

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
        lane->report.counts.bodies = world ? world->body_count() : 0;
        lane->report.counts.a = static_cast<std::int64_t>(lane->pairs.size());
      }
    } else {
      // The first lane's check time includes the sets every lane shares (F, G, T).
      auto t0 = std::chrono::steady_clock::now();
      if (world) checker.begin_frame(*world, detect_options);
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
    other_reports.clear();
    for (const Lane& lane : others) other_reports.push_back(lane.report);
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
    Scene kept = s;
    scene = std::move(kept);
    world = std::move(fresh);
    recording.reset();
    detect_options = opts;
    start();
  }

  // The frame source's first frame, detected and checked.
  void start() {
    for (Lane* lane : lanes()) lane->report = FrameReport{};
    recorded = 0;
    stale = now();
    detect_and_check();
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
  if (impl_->recording) {
    if (at_end()) return;
    impl_->stale = impl_->now();
    ++impl_->recorded;
    impl_->set_physics_ms(0);  // no physics: the frame was read with the file
    impl_->detect_and_check();
    return;
  }
  if (!impl_->world) return;
  impl_->stale = impl_->world->elements();
  const auto t0 = std::chrono::steady_clock::now();
  impl_->world->step();
  impl_->set_physics_ms(ms_since(t0));
  impl_->detect_and_check();
}

void FrameLoop::redetect() {
  if (impl_->loaded()) impl_->detect_and_check();
}

// ---- accessors -----------------------------------------------------------------------------

std::int64_t FrameLoop::frame() const { return impl_->loaded() ? impl_->frame_number() : 0; }
double FrameLoop::time() const {
  if (impl_->recording) return impl_->recording->frames[impl_->recorded].time;
  return impl_->world ? impl_->world->time() : 0;
}

const Elements& FrameLoop::elements() const {
  static const Elements kNone;
  return impl_->loaded() ? impl_->now() : kNone;
}
const std::vector<ElementSource>& FrameLoop::element_sources() const {
  static const std::vector<ElementSource> kNone;
  return impl_->world ? impl_->world->sources() : kNone;
}
std::int64_t FrameLoop::body_count() const { return impl_->world ? impl_->world->body_count() : 0; }
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
    impl_->world->shapes(out);
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

bool FrameLoop::begin_drag(double x, double y) { return impl_->world && impl_->world->begin_drag(x, y); }
void FrameLoop::drag_to(double x, double y) {
  if (impl_->world) impl_->world->drag_to(x, y);
}
void FrameLoop::end_drag() {
  if (impl_->world) impl_->world->end_drag();
}
bool FrameLoop::dragging() const { return impl_->world && impl_->world->dragging(); }

}  // namespace nbscope
