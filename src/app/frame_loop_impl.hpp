// nbscope app: FrameLoop's private state, shared by the .cpp files that implement the loop
// (frame_loop.cpp: frames, configuration, accessors; frame_loop_history.cpp: showing kept frames and
// resuming; frame_loop_overlap.cpp: the overlapped step). Not for anyone else.
//
// Who owns what: the frame source (io/frame_source.hpp; made in app/frame_sources.cpp) makes frames
// and shows past ones; the pipeline (check/pipeline.hpp) detects and checks them into a FrameResult;
// the history and the violation log keep the run; FrameLoopState coordinates them and names no
// concrete source.
#pragma once
#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/clock.hpp"
#include "app/frame_loop.hpp"
#include "app/frame_watch.hpp"
#include "check/cell_changes.hpp"
#include "check/pipeline.hpp"
#include "core/error.hpp"
#include "io/frame_source.hpp"

namespace nbscope {

struct FrameLoopState {
  FrameLoopOptions options;
  // The run's frames: a simulated scene or recorded frames, or null before the first load.
  std::unique_ptr<FrameSource> frames;
  Pipeline pipeline;

  // ---- history ----
  FrameHistory history;
  ViolationLog violations;

  FrameChange change;               // what the last detect_and_check() published (FrameLoop::change)
  CellChanges cell_changes;         // which element changed cell at which step, as published
  bool load_unpublished = false;    // a new source whose first detection threw: the next change carries it
  bool physics_overlapped = false;  // the current frame's physics ran on the worker (frame_loop_overlap.cpp)
  bool detection_overlapped = false;  // so did its detection and check
  // While a step in flight is detected on the worker (it owns the pipeline until settle()): the
  // shown frame's result and detector bytes as they were, and a record_traces() wish for the next.
  std::unique_ptr<FrameResult> shown_result;
  std::size_t shown_detector_bytes = 0;
  DetectOptions shown_detect;  // the pipeline's detect options for the shown frame (its trace's)
  std::optional<bool> wanted_traces;

  // The slow-frame note (app/frame_watch.hpp). Declared last: its thread, which may read the world's
  // counters, is joined before anything else goes.
  FrameWatch watch;
  // The frame the source's step() is making, when the source says what that is (Box2D's step).
  void watch_step() {
    if (auto note = frames->step_note()) watch.arm(frames->newest_frame() + 1, std::move(note));
  }
  // Disarms the note when a frame is done, returned or thrown.
  struct Unwatch {
    FrameWatch& watch;
    ~Unwatch() { watch.disarm(); }
  };

  explicit FrameLoopState(FrameLoopOptions o);
  ~FrameLoopState();
  FrameLoopState(const FrameLoopState&) = delete;
  FrameLoopState& operator=(const FrameLoopState&) = delete;

  // The source's simulation (the overlapped step, drags, resume), or null.
  [[nodiscard]] Simulation* simulation() const { return frames ? frames->simulation() : nullptr; }
  // True while a step begun by FrameLoop::begin_step() has not been adopted.
  [[nodiscard]] bool pending() const {
    const Simulation* sim = simulation();
    return sim != nullptr && sim->pending();
  }
  // True while a resume re-simulates towards the past frame shown.
  [[nodiscard]] bool resuming() const {
    const Simulation* sim = simulation();
    return sim != nullptr && sim->resuming();
  }
  // Returns once the worker is done with the world (the accessors still show the current frame).
  void wait_for_worker() const {
    if (const Simulation* sim = simulation()) sim->wait();
  }
  // The step in flight made the current frame (detected and checked, as step() does); true if there
  // was one. Throws Error as step() does.
  bool settle();
  // The step in flight forgotten, its world about to be replaced (a load or restart).
  void discard_step() {
    if (Simulation* sim = simulation()) sim->discard_step();
    shown_result.reset();
    apply_wanted_traces();
  }
  // The shown frame's trace while the pipeline is the worker's: its detection's own, else made by a
  // fresh detector of the same kind (a built-in keeps nothing between frames); null under the
  // stale-positions fault, whose input the worker holds.
  std::shared_ptr<const FrameTrace> shown_trace();
  // True while the pipeline is the worker's (a step in flight detected there).
  [[nodiscard]] bool pipeline_on_worker() const { return shown_result != nullptr && pending(); }
  // A record_traces() wish made while the pipeline was the worker's, applied once it is back.
  void apply_wanted_traces() {
    if (wanted_traces) pipeline.set_record_traces(*wanted_traces);
    wanted_traces.reset();
  }

  // ---- the frame source ----
  [[nodiscard]] bool loaded() const { return frames != nullptr; }
  // The frame shown (loaded() first).
  [[nodiscard]] const FrameSource& source() const { return *frames; }
  [[nodiscard]] const Elements& now() const { return source().elements(); }
  [[nodiscard]] std::int64_t frame_number() const { return source().frame(); }

  // The shown frame through the pipeline (lanes, faults, check), then into the history; then
  // published as a change of `kind` (a redetect that finds another frame shown moved it too).
  void detect_and_check(FrameChange::Kind kind);
  // The frame a step in flight made, through the pipeline on the worker (frame_loop_overlap.cpp).
  void detect_on_worker(const Frame& next);
  // True when every lane's detector may run on the worker (no plugin: a plugin stays on its thread).
  [[nodiscard]] bool detection_can_leave_thread() const;
  // The detected frame into the history, then published as a change of `kind`.
  void publish(FrameChange::Kind kind);
  // The current frame detected and checked again (a step in flight is adopted instead).
  void redetect();
  // The shown frame's summary into the history (a new frame is pushed with what the source keeps of
  // it; a frame shown again has its counts replaced), and its violations into the run's log.
  void record_frame();
  // The current frame's physics time, measured on this thread (settle() marks the worker's).
  void set_physics_ms(double ms) {
    pipeline.set_physics_ms(ms);
    physics_overlapped = false;
    detection_overlapped = false;
  }
  // Error unless `rec` (null: a scene) gives pairs to check for a `recorded` lane (`wanted`).
  static void check_recorded_source(bool wanted, const Recording* rec, const std::string& path);
  // Refuses a `recorded` lane where the fault or the frame source gives it nothing to check.
  void accept_recorded() const;
  // Replaces the frame source by `fresh` at its first frame; on error (a `recorded` lane it cannot
  // feed) the old one stays.
  void load(std::unique_ptr<FrameSource> fresh);
  // The frame source's first frame, detected and checked; a new run: the history starts again.
  void start();
  // The elements of the frame before `frame` when it can be had, else `frame`'s own (the
  // stale-positions fault then has nothing older to give).
  Elements elements_before(std::int64_t frame) const;
};

}  // namespace nbscope
