// nbscope app: FrameLoop's private state, shared by the .cpp files that implement the loop
// (frame_loop.cpp: frames, configuration, accessors; frame_loop_history.cpp: showing kept frames and
// resuming; frame_loop_overlap.cpp: the overlapped step). Not for anyone else: it includes Box2D.
//
// Who owns what: the frame sources (physics/live_world.hpp, physics/kept_frame.hpp,
// io/recording_source.hpp) make frames; the pipeline (check/pipeline.hpp) detects and checks them
// into a FrameResult; the history and the violation log keep the run; FrameLoopState coordinates them.
#pragma once
#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/clock.hpp"
#include "app/frame_loop.hpp"
#include "app/frame_watch.hpp"
#include "check/pipeline.hpp"
#include "core/error.hpp"
#include "io/recording_source.hpp"
#include "physics/kept_frame.hpp"
#include "physics/live_world.hpp"
#include "physics/resume.hpp"

namespace nbscope {

struct FrameLoopState {
  FrameLoopOptions options;
  Scene scene;
  // The frame sources: the live world for a scene, or a recording (the other null); `kept` when a
  // past frame is shown. source() is the one shown.
  std::unique_ptr<LiveWorld> live;
  std::unique_ptr<RecordingSource> replay;
  std::unique_ptr<KeptWorldFrame> kept;  // the past frame shown, or null for the live world's
  // The recorded frame LoopSource::element_ids() last looked up, held while its ids are used.
  mutable std::shared_ptr<const RecordedFrame> looked_up;
  Pipeline pipeline;

  // ---- history ----
  FrameHistory history;
  ViolationLog violations;

  // ---- resume ----
  Resume resume;  // a fresh world re-simulated to the past frame shown (physics/resume.hpp)

  FrameChange change;               // what the last detect_and_check() published (FrameLoop::change)
  bool load_unpublished = false;    // a new source whose first detection threw: the next change carries it
  bool physics_overlapped = false;  // the current frame's physics ran on the worker (frame_loop_overlap.cpp)

  // The slow-frame note (app/frame_watch.hpp). Declared last: its thread, which may read the world's
  // counters, is joined before anything else goes.
  FrameWatch watch;
  // The frame the live world's step() is making: the note describes Box2D's step.
  void watch_physics() {
    const PhysicsWorld* w = &live->world();
    watch.arm(w->frame() + 1, [w] {
      return "Box2D step: " + grouped(w->bodies_now()) + " bodies, about " + grouped(w->estimated_contacts()) + " contacts";
    });
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

  // True while a step begun by FrameLoop::begin_step() has not been adopted.
  [[nodiscard]] bool pending() const { return live && live->pending(); }
  // Returns once the worker is done with the world (the accessors still show the current frame).
  void wait_for_worker() const {
    if (live) live->wait();
  }
  // The step in flight made the current frame (detected and checked, as step() does); true if there
  // was one. Throws Error as step() does.
  bool settle();
  // The step in flight forgotten, its world about to be replaced (a load or restart).
  void discard_step();

  // ---- the frame source ----
  [[nodiscard]] bool loaded() const { return live != nullptr || replay != nullptr; }
  // The frame shown: a kept past frame, the live world's (its snapshot while a step is pending), or
  // the recording's.
  [[nodiscard]] const FrameSource& source() const {
    if (kept) return *kept;
    if (live) return *live;
    return *replay;
  }
  [[nodiscard]] const Elements& now() const { return source().elements(); }
  [[nodiscard]] std::int64_t frame_number() const { return source().frame(); }
  // The live world's frame: the newest of the run (the one shown while a step is pending).
  [[nodiscard]] std::int64_t live_frame() const { return live->newest_frame(); }

  // The shown frame through the pipeline (lanes, faults, check), then into the history; then
  // published as a change of `kind` (a redetect that finds another frame shown moved it too).
  void detect_and_check(FrameChange::Kind kind);
  // The current frame detected and checked again (a step in flight is adopted instead).
  void redetect();
  // The shown frame's summary into the history (a new live frame is pushed with its kept state; a
  // frame shown again has its counts replaced), and its violations into the run's log.
  void record_frame();
  // The current frame's physics time, measured on this thread (settle() marks the worker's).
  void set_physics_ms(double ms) {
    pipeline.set_physics_ms(ms);
    physics_overlapped = false;
  }
  // Error unless `rec` (null: a scene) gives pairs to check for a `recorded` lane (`wanted`).
  static void check_recorded_source(bool wanted, const Recording* rec, const std::string& path);
  // Refuses a `recorded` lane where the fault or the frame source gives it nothing to check.
  void accept_recorded() const;
  // A new world from `s` (frame 0); on error the old scene stays.
  void build(const Scene& s);
  // Replays `frames` instead of a world: its grid pins as a scene's would, its name the file's stem.
  void build(std::unique_ptr<RecordedFrames> frames);
  // The frame source's first frame, detected and checked; a new run: the history starts again.
  void start();
  // The elements of the frame before `frame` when it can be shown, else `frame`'s own (the
  // stale-positions fault then has nothing older to give).
  Elements elements_before(std::int64_t frame) const;
};

}  // namespace nbscope
