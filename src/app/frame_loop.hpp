// nbscope app: the per-frame pipeline shared by the headless loop and the window.
//
//   load_scene*() -> frame 0: elements at the initial poses, detected and checked (no Box2D step yet)
//   step()        -> frame k+1: Box2D step (emitters first) -> elements -> detection with the chosen
//                    algorithm (+ injected fault) -> cross-check (check/check.hpp)
//   begin_step() / step() -> the same frame k+1, its Box2D step run on a worker thread while the
//                    window draws frame k (frame_loop_overlap.cpp); the window adopts it (step())
//                    once source().step_ready(), so it never waits; headless keeps the plain step()
//   load_recording*() / step() -> the same on recorded frames (io/recording.hpp) instead of a world:
//                    no physics, and the check runs only A==R (there is no Box2D world to compare with)
//   show_frame()  -> a kept past frame (check/history.hpp) made current: its elements, shapes and Box2D
//                    sets rebuilt from the history (physics/kept_frame.hpp), detected and checked again
//   resume().begin() / advance() -> the simulation continued from the shown past frame: a fresh
//                    world re-simulated from the scene with the same steps and drags arrives at that
//                    frame bit for bit (Box2D is deterministic), and the later frames are replaced
//
// After load and after every step() the parts describe one consistent frame: source() (elements,
// shapes, frame number), result() (A, the grid and cells, the report, the check's sets),
// pipeline() (the detector, the trace). Nothing here exposes Box2D: render and ui include this header only.
//
// Errors: load_scene_file() throws Error "file:line: field: what" and keeps the previous scene;
// redetect_with_algorithm() throws Error for an unknown or 3D-only name and keeps the previous one; `recorded`
// (the recording's own pairs) is refused with a scene, a recording without pairs, and the faults
// that act on detection's input (check/recorded_lane.hpp: check_recorded_fault), wherever it comes in; step()
// and redetect() throw Error when detection refuses the frame (pair limit, a grid too large), with
// the frame number in the message; so does any call that adopts a step begun by begin_step()
// (show_frame, the drags, a configuration change). The window should show these and stay open.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "check/cell_changes.hpp"
#include "check/history.hpp"
#include "check/faults.hpp"
#include "check/frame_result.hpp"
#include "check/report.hpp"
#include "core/detector.hpp"
#include "core/grid.hpp"
#include "core/pairs.hpp"
#include "core/frame_trace.hpp"
#include "io/frame_source.hpp"
#include "io/recorded_frames.hpp"
#include "io/recording.hpp"
#include "physics/scene.hpp"
#include "physics/shapes.hpp"
#include "app/frame_loop_parts.hpp"

namespace nbscope {

struct FrameLoopOptions {
  std::string algorithm = "nbs";  // registry name (core/detector.hpp), or "recorded" (check/recorded_lane.hpp)
  Fault fault = Fault::None;
  bool checks = true;             // run the cross-check every frame
  std::int64_t brute_limit = 2000;  // R is brute force up to this many elements (CheckOptions)
  // Bytes of past world states the history keeps (FrameHistory::kDefaultBudget in the window); 0
  // keeps none (headless runs that never go back), summaries are kept either way.
  std::size_t history_budget = FrameHistory::kDefaultBudget;
  // Box2D contacts a frame may create, over the scene's "max_contacts" (--max-contacts).
  std::optional<std::int64_t> max_contacts;
  // Most frame summaries kept (FrameHistory::set_max_summaries): headless runs that draw no timeline
  // and never go back keep a few, so memory does not grow with --frames. A recording needs them all.
  std::size_t max_summaries = FrameHistory::kMaxSummaries;
  // Every frame's violations into violation_log() (the Violations panel, --violation N); the same
  // headless runs log none (each frame's report still lists its own).
  bool log_violations = true;
  // Which element changed cell at which step (cell_changes(): the window's flashes); headless runs
  // that draw nothing keep none (20 bytes an element a frame saved).
  bool track_cell_changes = true;
  // Whether a pair at exactly zero gap is a contact, for every detector and the check (--touching).
  Touching touching = Touching::inclusive;
  // Threads each detection of the run may use (--threads; DetectOptions::threads); the traced run
  // the stepper and the lists overlay show stays on one.
  int threads = 1;
};

// What the loop last did to the frame shown, with a counter: views compare it with the generation
// they last followed and derive their trails, flashes and camera from it (GlView::follow) instead of
// being told. Published once the frame is detected and checked (a step whose detection throws
// publishes nothing: the picture stays on the last whole frame).
struct FrameChange {
  enum class Kind {
    none,        // nothing yet (an empty loop, or a world that stopped at load)
    loaded,      // a new source: load_scene, load_recording, restart
    stepped,     // a step forwards (live, recorded, an adopted begin_step, or the next kept frame)
    shown,       // another frame of the history: show_frame, step_back, a resume that arrived
    redetected,  // the same frame detected again (algorithm, fault, checks, redetect)
  };
  std::uint64_t generation = 0;  // bumped by every change
  Kind kind = Kind::none;        // the latest change
  std::int64_t frame = 0;        // the frame shown after it
  std::uint64_t loaded_at = 0;   // the generation of the last load: a view behind it missed a new source
  std::uint64_t moved_at = 0;    // the generation that last moved the frame shown (all kinds but redetected)
};

// Coordinates one run: loads, steps, travels in time, and hands out its parts (app/frame_loop_parts.hpp):
// source() the frame shown, pipeline() what detects and checks it, result() what was found, history()
// the run's frames, resume() and drag() the live world's.
class FrameLoop {
 public:
  // An empty loop (no scene): configure, then load a scene. Throws Error for an unknown algorithm.
  explicit FrameLoop(FrameLoopOptions options = {});
  ~FrameLoop();
  FrameLoop(const FrameLoop&) = delete;
  FrameLoop& operator=(const FrameLoop&) = delete;

  // ---- loading ----
  // Runs `source`'s frames (app/frame_sources.hpp makes them): its first frame detected and checked,
  // a new run. On error (a `recorded` lane it cannot feed) the old source stays.
  void load(std::unique_ptr<FrameSource> source);
  // Builds the scene, then computes frame 0. On error the old scene stays.
  void load_scene(const Scene& scene);
  // Replays a recording (at least one frame) instead of a world: its first frame detected and checked,
  // only A==R (report().box2d_checks is false). On error the old scene or recording stays.
  void load_recording(Recording recording);
  // The same for frames read as they are shown (io/recorded_frames.hpp): at most the history budget
  // of them stays in memory beside the one shown.
  void load_recording(std::unique_ptr<RecordedFrames> frames);
  // Rebuilds the current scene from its description (frame 0 again); no effect without a scene.
  void restart();

  // ---- advancing ----
  // Advances one frame: while a past frame is shown, to the next kept frame (nothing is simulated:
  // the later frames are the run's own); else physics (or the next recorded frame), elements,
  // detection, check. No effect without a scene, at a recording's end or while resuming.
  void step();
  // Starts the next frame's physics (Box2D's step) on a worker thread and returns at once, so that
  // the caller can draw the current frame meanwhile; the next step() adopts it (waits for the
  // worker, then detects and checks), giving exactly the frame a plain step() would have. Until
  // then every accessor keeps describing the current frame (a snapshot of what the step changes),
  // and every call that needs the world (configuration, history, resume, drags, loads) adopts the
  // step first. Does nothing on a past frame, a recording, while resuming or with a step pending.
  void begin_step();
  // Detects and checks the current frame again without stepping (e.g. while paused).
  void redetect();

  // ---- what detects and checks: each call that changes something detects and checks the frame
  // shown again (each lane's detector called once more); one that changes nothing runs nothing ----
  // Switches the detector; Error (old one kept) for an unknown or 3D-only name, or `recorded` where
  // it has no pairs or the fault cannot act on them.
  void redetect_with_algorithm(std::string_view name);
  // Injects `fault` into detection (check/faults.hpp); Error, old kept, for one a `recorded` lane cannot take.
  void redetect_with_fault(Fault fault);
  // Runs the cross-check every frame, or not.
  void redetect_with_checks(bool on);
  // More detectors run and checked on every frame beside the chosen one, on the same elements with
  // the same fault (headless --algorithm a,b,c; the window leaves this empty). Error, old list kept,
  // for an unknown or 3D-only name.
  void redetect_with_comparisons(const std::vector<std::string>& names);

  // ---- time travel ----
  // Makes frame `frame` current, with detection and every check run on it again (the overlays,
  // panels and stepper then show it as they show a live frame). Throws Error when it is not kept.
  void show_frame(std::int64_t frame);
  // Shows the kept frame before the shown one (detected and checked again); false, unmoved, at the
  // oldest showable frame.
  bool step_back();

  // ---- the parts ----
  // What changed last and its generation (bumped by load, restart, step, a past frame shown, a
  // resume's arrival, redetect or a configuration change): views follow it instead of being told.
  [[nodiscard]] const FrameChange& change() const;
  // Which element changed cell at which step of the frames shown, kept at every change published:
  // the cell-change flashes of the frame shown, whenever a view draws it.
  [[nodiscard]] const CellChanges& cell_changes() const;
  // Everything the pipeline found in the frame shown (check/frame_result.hpp): hash, each lane's
  // pairs, grid, cells and report, the check's sets R, F, T, G.
  [[nodiscard]] const FrameResult& result() const;
  // The frame shown: scene, frame number, time, elements, shapes, a recording's facts.
  [[nodiscard]] const LoopSource& source() const;
  // The detection lanes, fault and checks (each change detects the frame again) and the trace.
  [[nodiscard]] LoopPipeline& pipeline();
  [[nodiscard]] const LoopPipeline& pipeline() const;
  // The run's frames, the violation log, and which frames can be shown.
  [[nodiscard]] LoopHistory& history();
  [[nodiscard]] const LoopHistory& history() const;
  // Continuing the simulation from the past frame shown.
  [[nodiscard]] LoopResume& resume();
  [[nodiscard]] const LoopResume& resume() const;
  // The mouse drag on the live world.
  [[nodiscard]] LoopDrag& drag();
  [[nodiscard]] const LoopDrag& drag() const;

 private:
  // show_frame(), published as a change of `kind` (a step forwards through kept frames is `stepped`).
  void show(std::int64_t frame, FrameChange::Kind kind);
  std::unique_ptr<FrameLoopState> impl_;  // the coordination's state and the parts (app/frame_loop_impl.hpp)
};

// Reads, validates and builds the scene file at `path`, then loop.load_scene(); throws Error
// "file:line: field: what" and keeps the previous scene.
void load_scene_file(FrameLoop& loop, const std::string& path);
// Reads a .nbsrec file (at most max_frames frames), then loop.load_recording(); on error the old scene
// or recording stays.
void load_recording_file(FrameLoop& loop, const std::string& path, std::int64_t max_frames = INT64_MAX);

}  // namespace nbscope
