// nbscope app: FrameLoop's private state, shared by the .cpp files that implement the loop
// (frame_loop.cpp: frames, configuration, accessors; frame_loop_history.cpp: showing kept frames and
// resuming; frame_loop_overlap.cpp: the overlapped step). Not for anyone else.
//
// Who owns what: the parts (app/frame_loop_parts.hpp) own the frame source, the pipeline and the
// history; FrameLoopState owns them and the coordination's own state (the change published, the
// cell changes, the slow-frame note), and is the only one that changes the parts. It names no
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
  LoopSource source;      // the frame source (null before the first load)
  LoopPipeline pipeline;  // the pipeline that detects and checks each frame
  LoopHistory history;    // the run's frames and its violation log
  LoopResume resume{*this};
  LoopDrag drag{*this};

  FrameChange change;               // what the last detect_and_check() published (FrameLoop::change)
  CellChanges cell_changes;         // which element changed cell at which step, as published
  bool load_unpublished = false;    // a new source whose first detection threw: the next change carries it

  // The slow-frame note (app/frame_watch.hpp). Declared last: its thread, which may read the world's
  // counters, is joined before anything else goes.
  FrameWatch watch;
  // The frame the source's step() is making, when the source says what that is (Box2D's step).
  void watch_step() {
    if (auto note = frames().step_note()) watch.arm(frames().newest_frame() + 1, std::move(note));
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

  // ---- the parts' own state, for the coordination ----
  [[nodiscard]] bool loaded() const { return source.loaded(); }
  // The frame source (loaded() first).
  [[nodiscard]] FrameSource& frames() const { return *source.frames_; }
  [[nodiscard]] const Elements& now() const { return frames().elements(); }
  [[nodiscard]] std::int64_t frame_number() const { return frames().frame(); }
  [[nodiscard]] Simulation* simulation() const { return source.simulation(); }
  [[nodiscard]] bool pending() const { return source.pending(); }
  // True while a resume re-simulates towards the past frame shown.
  [[nodiscard]] bool resuming() const {
    const Simulation* sim = simulation();
    return sim != nullptr && sim->resuming();
  }
  void wait_for_worker() const { source.wait_for_worker(); }
  [[nodiscard]] Pipeline& lanes() { return pipeline.pipeline_; }
  [[nodiscard]] const Pipeline& lanes() const { return pipeline.pipeline_; }
  [[nodiscard]] FrameHistory& kept() { return history.frames_; }
  [[nodiscard]] const FrameHistory& kept() const { return history.frames_; }
  [[nodiscard]] ViolationLog& violations() { return history.violations_; }

  // The step in flight made the current frame (detected and checked, as step() does); true if there
  // was one. Throws Error as step() does.
  bool settle();
  // The step in flight forgotten, its world about to be replaced (a load or restart).
  void discard_step() {
    if (Simulation* sim = simulation()) sim->discard_step();
    pipeline.take_back();
  }

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
    lanes().set_physics_ms(ms);
    source.physics_overlapped_ = false;
    source.detection_overlapped_ = false;
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
  // The source's frames known in advance that the history has not taken yet (all at start(); those
  // a watched run added at a step): each showable, checked when first shown.
  void take_new_entries();
  std::size_t entries_taken = 0;  // how many of frames().entries() the history has
  // The elements of the frame before `frame` when it can be had, else `frame`'s own (the
  // stale-positions fault then has nothing older to give).
  Elements elements_before(std::int64_t frame) const;
};

}  // namespace nbscope
