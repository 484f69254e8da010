// FrameLoop: owns the Box2D world, the detector, the checker and the frame's results.
//
// Index: Impl (state) | scene | configuration | one frame (detect_and_check) | accessors | drag.
#include "app/frame_loop.hpp"

#include <chrono>

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

struct FrameLoop::Impl {
  FrameLoopOptions options;
  Scene scene;
  std::unique_ptr<PhysicsWorld> world;
  std::unique_ptr<Detector> detector;
  FrameChecker checker;
  DetectOptions detect_options;
  Elements stale;             // last frame's elements (stale-positions fault)
  Elements detected_on;       // what the detector was given this frame (when not the world's elements)
  bool detected_on_world = true;
  PairList pairs;
  Grid grid;
  std::vector<CellIndex> cells;
  FrameReport report;

  explicit Impl(FrameLoopOptions o) : options(std::move(o)), checker(CheckOptions{options.brute_limit}) {
    detector = make_2d_detector(options.algorithm);
  }

  const Elements& detector_input() const { return detected_on_world ? world->elements() : detected_on; }

  // Detection (with the fault) and the check of the world's current frame; physics_ms is kept.
  void detect_and_check() {
    const Elements& now = world->elements();
    detected_on_world = true;
    if (options.fault == Fault::StalePositions && world->frame() > 0) {
      // Last frame's positions; elements that did not exist then (emitted now) at their new ones.
      detected_on = now;
      const Eigen::Index old_n = std::min(stale.size(), now.size());
      detected_on.x.head(old_n) = stale.x.head(old_n);
      detected_on.y.head(old_n) = stale.y.head(old_n);
      detected_on_world = false;
    }
    const Elements& input = detector_input();
    try {
      const auto t0 = std::chrono::steady_clock::now();
      detector->detect(input, detect_options, pairs);
      sort_pairs(pairs);
      const Grid* own = detector->last_grid();
      grid = own != nullptr ? *own : make_grid(input, detect_options.grid);
      integerise_cells(input, grid, cells);
      apply_output_fault(options.fault, grid, cells, pairs);
      report.timings.detection_ms = ms_since(t0);
    } catch (const Error& e) {
      throw Error(scene.path + ": frame " + std::to_string(world->frame()) + ": " + detector->name().data() + ": " + e.what());
    }
    report.frame = world->frame();
    if (!options.checks) {
      const FrameTimings keep = report.timings;
      report = FrameReport{};
      report.frame = world->frame();
      report.timings = keep;
      report.timings.check_ms = 0;
      report.counts.elements = now.size();
      report.counts.a = static_cast<std::int64_t>(pairs.size());
      return;
    }
    const auto t0 = std::chrono::steady_clock::now();
    CheckInput in;
    in.frame = world->frame();
    in.world = world.get();
    in.algorithm = detector->name();
    in.pairs = &pairs;
    in.cells = &cells;
    in.options = &detect_options;
    in.drop_box2d_contact = options.fault == Fault::DropBox2dContact;
    checker.check(in, report);
    report.timings.check_ms = ms_since(t0);
  }

  void build(const Scene& s) {
    DetectOptions opts;
    if (s.cell_size) opts.grid.cell_size = *s.cell_size;
    if (s.origin) opts.grid.origin = std::array<double, 3>{s.origin->x, s.origin->y, 0};
    auto fresh = std::make_unique<PhysicsWorld>(s);
    // A pinned cell size must hold the largest element from the start (the grid would refuse it).
    if (s.cell_size && fresh->elements().size() > 0 && *s.cell_size < 2 * fresh->elements().max_radius())
      throw Error(s.cell_size_where + "smaller than the largest element's diameter " + std::to_string(2 * fresh->elements().max_radius()));
    Scene kept = s;
    scene = std::move(kept);
    world = std::move(fresh);
    detect_options = opts;
    report = FrameReport{};
    stale = world->elements();
    detect_and_check();
  }
};

FrameLoop::FrameLoop(FrameLoopOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}
FrameLoop::~FrameLoop() = default;

// ---- scene ---------------------------------------------------------------------------------

void FrameLoop::load_scene_file(const std::string& path) { impl_->build(read_scene_json(path)); }
void FrameLoop::load_scene(const Scene& scene) { impl_->build(scene); }
void FrameLoop::restart() {
  if (impl_->world) impl_->build(Scene(impl_->scene));
}
bool FrameLoop::has_scene() const { return impl_->world != nullptr; }
const Scene& FrameLoop::scene() const { return impl_->scene; }

// ---- configuration -------------------------------------------------------------------------

void FrameLoop::set_algorithm(std::string_view name) {
  impl_->detector = make_2d_detector(name);
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

// ---- one frame -----------------------------------------------------------------------------

void FrameLoop::step() {
  if (!impl_->world) return;
  impl_->stale = impl_->world->elements();
  const auto t0 = std::chrono::steady_clock::now();
  impl_->world->step();
  impl_->report.timings.physics_ms = ms_since(t0);
  impl_->detect_and_check();
}

void FrameLoop::redetect() {
  if (impl_->world) impl_->detect_and_check();
}

// ---- accessors -----------------------------------------------------------------------------

std::int64_t FrameLoop::frame() const { return impl_->world ? impl_->world->frame() : 0; }
double FrameLoop::time() const { return impl_->world ? impl_->world->time() : 0; }

const Elements& FrameLoop::elements() const {
  static const Elements kNone;
  return impl_->world ? impl_->world->elements() : kNone;
}
const std::vector<ElementSource>& FrameLoop::element_sources() const {
  static const std::vector<ElementSource> kNone;
  return impl_->world ? impl_->world->sources() : kNone;
}
std::int64_t FrameLoop::body_count() const { return impl_->world ? impl_->world->body_count() : 0; }
const PairList& FrameLoop::pairs() const { return impl_->pairs; }
const Grid& FrameLoop::grid() const { return impl_->grid; }
const std::vector<CellIndex>& FrameLoop::cells() const { return impl_->cells; }
const FrameReport& FrameLoop::report() const { return impl_->report; }
const PairList& FrameLoop::reference_pairs() const { return impl_->options.checks ? impl_->checker.reference_pairs() : kNoPairs; }
const PairList& FrameLoop::box2d_pairs() const { return impl_->options.checks ? impl_->checker.box2d_pairs() : kNoPairs; }
const PairList& FrameLoop::touching_pairs() const { return impl_->options.checks ? impl_->checker.touching_pairs() : kNoPairs; }
const PairList& FrameLoop::tight_aabb_pairs() const { return impl_->options.checks ? impl_->checker.tight_aabb_pairs() : kNoPairs; }

void FrameLoop::body_shapes(std::vector<BodyShape>& out) const {
  if (impl_->world) impl_->world->shapes(out);
  else out.clear();
}

const Detector& FrameLoop::detector() const { return *impl_->detector; }

void FrameLoop::trace_frame(TraceLog& out_trace, PairList& out_pairs) {
  if (!impl_->world) {
    out_trace.reset();
    out_pairs.clear();
    return;
  }
  impl_->detector->detect_traced(impl_->detector_input(), impl_->detect_options, out_pairs, out_trace);
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
