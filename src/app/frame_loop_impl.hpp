// nbscope app: FrameLoop's private state (Lane, FrameLoop::Impl), shared by the .cpp files that
// implement the loop (frame_loop.cpp: frames, configuration, accessors; frame_loop_history.cpp:
// showing kept frames and resuming). Not for anyone else: it includes Box2D.
//
// Index: helpers | Lane (one detector's view of a frame) | ShownFrame (the frame on screen while the
// next one's physics runs) | Impl (the frame source, the lanes, the checker, the history, the resume
// in progress, the step in flight; detect_and_check and record_frame).
#pragma once
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/clock.hpp"
#include "app/frame_loop.hpp"
#include "app/frame_watch.hpp"
#include "app/recorded_pairs.hpp"
#include "check/check.hpp"
#include "core/error.hpp"
#include "physics/kept_frame.hpp"
#include "physics/world.hpp"

namespace nbscope {

struct Lane {
  std::string name;
  std::unique_ptr<Detector> detector;
  RecordedPairsDetector* recorded_pairs = nullptr;  // `detector` when it is the recording's own pairs (fed each frame)
  PairList pairs;
  Grid grid;
  std::vector<CellIndex> cells;
  FrameReport report;

  explicit Lane(std::string_view algorithm) : name(algorithm), detector(make_lane_detector(algorithm)) {
    if (algorithm == kRecordedAlgorithm) recorded_pairs = static_cast<RecordedPairsDetector*>(detector.get());
  }

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

// What the accessors read of the current frame while a worker thread steps the world to the next
// one (FrameLoop::begin_step): copies of everything PhysicsWorld::step changes that they would
// otherwise read from the world. The rest of the frame (pairs, grid, cells, report, the check's
// sets, the history) lives outside the world and stays as it is until the step is adopted.
struct ShownFrame {
  std::int64_t frame = 0;
  double time = 0;
  std::int64_t bodies = 0;
  bool dragging = false;
  Elements elements;
  std::vector<ElementSource> sources;
  std::vector<BodyShape> shapes;
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
  Elements stale;             // the elements of the frame before stale_for (stale-positions fault)
  std::int64_t stale_for = -1;  // the frame `stale` serves; another frame fetches its own when needed
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
  std::shared_ptr<const FrameTrace> trace;  // this frame's traced detection, once asked for (frame_trace)

  // ---- the step in flight (frame_loop_overlap.cpp) ----
  // While `stepping` is valid a worker thread owns `world` (Box2D is not thread-safe, and keeps
  // global counters): this thread calls no Box2D at all and reads the current frame from `shown`.
  // Declared after `world`, so it is destroyed (waited for) first.
  std::future<double> stepping;  // the worker's world->step(); its result: the step's own milliseconds
  ShownFrame shown;
  bool physics_overlapped = false;  // the current frame's physics ran on the worker

  // The slow-frame note (app/frame_watch.hpp). Declared last: its thread, which may read the world's
  // counters, is joined before anything else goes.
  FrameWatch watch;
  // The frame world->step() is making: the note describes Box2D's step.
  void watch_physics() {
    const PhysicsWorld* w = world.get();
    watch.arm(w->frame() + 1, [w] {
      return "Box2D step: " + grouped(w->bodies_now()) + " bodies, about " + grouped(w->estimated_contacts()) + " contacts";
    });
  }
  // Disarms the note when a frame is done, returned or thrown.
  struct Unwatch {
    FrameWatch& watch;
    ~Unwatch() { watch.disarm(); }
  };
  // The current frame's detection and check: the note describes them (when the frame was stepped).
  void watch_detection() {
    const std::string what = "detection (" + main.name + ") and the check of " + grouped(now().size()) + " elements";
    watch.next_phase(frame_number(), [what] { return what; });
  }

  explicit Impl(FrameLoopOptions o)
      : options(std::move(o)), main(options.algorithm), checker(CheckOptions{options.brute_limit}) {
    if (main.recorded_pairs) check_recorded_fault(options.fault);
    history.set_budget(options.history_budget);
    history.set_max_summaries(options.max_summaries);
  }
  ~Impl() { wait_for_worker(); }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  // True while a step begun by FrameLoop::begin_step() has not been adopted.
  bool pending() const { return stepping.valid(); }
  // Returns once the worker is done with the world (the world then holds the next frame; the
  // accessors still show the current one). Anything that calls Box2D while a step is pending waits here.
  void wait_for_worker() const {
    if (stepping.valid()) stepping.wait();
  }
  // The step in flight made the current frame (detected and checked, as step() does); true if there
  // was one. Throws Error as step() does.
  bool settle();
  // The step in flight forgotten, its world about to be replaced (a load or restart).
  void discard_step();

  // ---- the frame source ----
  bool loaded() const { return world != nullptr || recording != nullptr; }
  // Box2D's side of the frame shown: a kept past frame or the live world (null when replaying).
  const Box2dFrame* box2d() const { return kept ? static_cast<const Box2dFrame*>(kept.get()) : world.get(); }
  const Elements& now() const {
    if (pending()) return shown.elements;
    return world ? box2d()->elements() : recording->frames[recorded].elements;
  }
  std::int64_t frame_number() const {
    if (pending()) return shown.frame;
    return world ? box2d()->frame() : recording->frames[recorded].number;
  }
  double time_now() const {
    if (pending()) return shown.time;
    return world ? box2d()->time() : recording->frames[recorded].time;
  }
  bool first_frame() const { return world ? frame_number() == 0 : recorded == 0; }
  // The live world's frame: the newest of the run (the one shown while a step is pending).
  std::int64_t live_frame() const { return pending() ? shown.frame : world->frame(); }

  const Elements& detector_input() const { return detected_on_world ? now() : detected_on; }

  // Detection (with the fault) and the check of the world's current frame, for every lane;
  // physics_ms is kept.
  void detect_and_check() {
    const Elements& now = this->now();
    detected_on_world = true;
    if (options.fault == Fault::StalePositions && !first_frame()) {
      // Last frame's positions; elements that did not exist then (emitted now) at their new ones.
      // A step leaves them ready; a frame shown from the history fetches them only here, when asked.
      if (stale_for != frame_number()) {
        stale = elements_before(frame_number());
        stale_for = frame_number();
      }
      detected_on = now;
      const Eigen::Index old_n = std::min(stale.size(), now.size());
      detected_on.x.head(old_n) = stale.x.head(old_n);
      detected_on.y.head(old_n) = stale.y.head(old_n);
      detected_on_world = false;
    }
    watch_detection();
    const Unwatch unwatch{watch};
    const std::string where = scene.path + ": frame " + std::to_string(frame_number()) + ": ";
    const Elements& input = detector_input();
    trace.reset();  // made again on request, for this frame and detector
    for (Lane* lane : lanes())
      if (lane->recorded_pairs) lane->recorded_pairs->set_frame(recording ? &recording->frames[recorded] : nullptr);
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
      if (world) checker.begin_frame(*box2d(), detect_options, main.detector->name());  // R beside F, G, T
      else checker.begin_frame(now, frame_number(), detect_options);
      for (Lane* lane : lanes()) {
        CheckInput in;
        in.algorithm = lane->detector->name();
        in.pairs = &lane->pairs;
        in.cells = &lane->cells;
        in.drop_box2d_contact = options.fault == Fault::DropBox2dContact;
        in.recorded = lane->recorded_pairs != nullptr;
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
    s.checked = r.checked;
    s.elements = now().size();
    s.pairs = static_cast<std::int64_t>(main.pairs.size());
    s.violations = r.violation_count();
    s.physics_ms = static_cast<float>(r.timings.physics_ms);
    s.detection_ms = static_cast<float>(r.timings.detection_ms);
    s.check_ms = static_cast<float>(r.timings.check_ms);
    if (const auto index = history.find(s.frame)) {
      const FrameSummary& before = history.at(*index);
      s.physics_ms = before.physics_ms;  // a frame shown again is not simulated again
      if (!r.checked && before.checked) {
        // Checks switched off: what the frame's last check found stays (summary and violations).
        s.checked = true;
        s.violations = before.violations;
        s.check_ms = before.check_ms;
        history.update(*index, s);
        return;
      }
      history.update(*index, s);  // (update keeps its `kept`)
    } else {
      std::shared_ptr<WorldState> state;
      if (world && history.budget() > 0) {
        state = std::make_shared<WorldState>();
        world->capture(*state, options.checks ? &checker.box2d_pairs() : nullptr);
      }
      s.kept = state != nullptr;  // with no budget only the live frame itself can be shown
      history.push(s, state, state ? state->bytes() : 0);
    }
    if (r.checked && options.log_violations) violations.set_frame(r);
  }

  // True when a lane checks the recording's own pairs.
  bool has_recorded_lane() const {
    return main.recorded_pairs || std::any_of(others.begin(), others.end(), [](const Lane& l) { return l.recorded_pairs != nullptr; });
  }
  // Error unless `rec` (null: a scene) gives pairs to check for a `recorded` lane (`wanted`).
  static void check_recorded_source(bool wanted, const Recording* rec, const std::string& path) {
    if (!wanted) return;
    if (rec == nullptr)
      throw Error(std::string(kRecordedAlgorithm) + ": the pairs a recording carries (nbscope replay FILE.nbsrec); the scene " + path +
                  " has none: choose a detector, e.g. nbs");
    if (!rec->has_pairs)
      throw Error(std::string(kRecordedAlgorithm) + ": " + rec->path +
                  " carries no pairs (no frame has a 'pairs' block): choose a detector, e.g. --algorithm nbs");
  }

  std::vector<Lane*> lanes() {
    std::vector<Lane*> all{&main};
    for (Lane& lane : others) all.push_back(&lane);
    return all;
  }

  // The current frame's physics time, measured on this thread (settle() marks the worker's).
  void set_physics_ms(double ms) {
    for (Lane* lane : lanes()) lane->report.timings.physics_ms = ms;
    physics_overlapped = false;
  }

  void build(const Scene& s) {
    check_recorded_source(has_recorded_lane(), nullptr, s.path);
    DetectOptions opts;
    opts.grid = s.grid;
    // No Box2D call beside the worker's; if the new scene is refused, the step in flight stays pending.
    wait_for_worker();
    Scene copy = s;
    if (options.max_contacts) copy.max_contacts = *options.max_contacts;  // the flag over the scene's key
    auto fresh = std::make_unique<PhysicsWorld>(copy);
    // A pinned cell size must hold the largest element from the start and every element an
    // emitter will add (the grid would refuse it mid-run, far from the field to fix).
    if (s.grid.cell_size) {
      char d[64];
      if (fresh->elements().size() > 0 && *s.grid.cell_size < 2 * fresh->elements().max_radius()) {
        std::snprintf(d, sizeof d, "%.6g", 2 * fresh->elements().max_radius());
        throw Error(s.cell_size_where + "smaller than the largest element's diameter " + d);
      }
      std::string emitter;
      if (const double r = fresh->largest_emitted_radius(emitter); *s.grid.cell_size < 2 * r) {
        std::snprintf(d, sizeof d, "%.6g", 2 * r);
        throw Error(s.cell_size_where + "smaller than the diameter " + d + " of the elements emitted by " +
                    emitter.substr(0, emitter.size() - 2));
      }
    }
    scene = std::move(copy);
    watch.disarm();  // its note describes the old world
    watch.reset();   // a new run
    kept.reset();  // it points into the old world
    discard_step();
    world = std::move(fresh);
    recording.reset();
    detect_options = opts;
    start();
  }

  // The frame source's first frame, detected and checked; a new run: the history starts again.
  void start() {
    for (Lane* lane : lanes()) lane->report = FrameReport{};
    physics_overlapped = false;
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
    stale_for = frame_number();
    detect_and_check();
  }

  // Ends a drag of the live world, recording the end as the user's own would be, so that a resume
  // replays it (a drag cannot continue where the live frame is left).
  void release_drag() {
    if (!world || !world->dragging()) return;
    inputs.push_back({DragInput::Kind::End, world->frame(), 0, 0});
    world->end_drag();
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
    check_recorded_source(has_recorded_lane(), rec.get(), rec->path);
    discard_step();  // the world it steps goes
    DetectOptions opts;
    Scene s;
    s.path = rec->path;
    s.name = std::filesystem::path(rec->path).stem().string();
    opts.grid = s.grid = rec->grid;
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

}  // namespace nbscope
