// nbscope app: the per-frame pipeline shared by the headless loop and the window.
//
//   load_scene*() -> frame 0: elements at the initial poses, detected and checked (no Box2D step yet)
//   step()        -> frame k+1: Box2D step (emitters first) -> elements -> detection with the chosen
//                    algorithm (+ injected fault) -> cross-check (check/check.hpp)
//   begin_step() / step() -> the same frame k+1, its Box2D step run on a worker thread while the
//                    window draws frame k (frame_loop_overlap.cpp); headless keeps the plain step()
//   load_recording*() / step() -> the same on recorded frames (io/recording.hpp) instead of a world:
//                    no physics, and the check runs only A==R (there is no Box2D world to compare with)
//   show_frame()  -> a kept past frame (check/history.hpp) made current: its elements, shapes and Box2D
//                    sets rebuilt from the history (physics/kept_frame.hpp), detected and checked again
//   begin_resume() / continue_resume() -> the simulation continued from the shown past frame: a fresh
//                    world re-simulated from the scene with the same steps and drags arrives at that
//                    frame bit for bit (Box2D is deterministic), and the later frames are replaced
//
// After load and after every step() the accessors describe one consistent frame: elements(),
// pairs() (A), grid() and cells() (the detector's integerisation), report() (counts, timings,
// violations), the pair sets of the check, and body_shapes() for drawing. Nothing here exposes
// Box2D: render and ui include this header only.
//
// Errors: load_scene_file() throws Error "file:line: field: what" and keeps the previous scene;
// set_algorithm() throws Error for an unknown or 3D-only name and keeps the previous one; `recorded`
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

#include "check/history.hpp"
#include "check/faults.hpp"
#include "check/frame_result.hpp"
#include "check/report.hpp"
#include "core/detector.hpp"
#include "core/grid.hpp"
#include "core/pairs.hpp"
#include "core/frame_trace.hpp"
#include "io/recording.hpp"
#include "physics/scene.hpp"
#include "physics/shapes.hpp"

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
};

class FrameLoop {
 public:
  // An empty loop (no scene): configure, then load a scene. Throws Error for an unknown algorithm.
  explicit FrameLoop(FrameLoopOptions options = {});
  ~FrameLoop();
  FrameLoop(const FrameLoop&) = delete;
  FrameLoop& operator=(const FrameLoop&) = delete;

  // ---- scene ----
  // Reads, validates and builds the scene, then computes frame 0. On error the old scene stays.
  void load_scene_file(const std::string& path);
  // Same for a scene already in memory.
  void load_scene(const Scene& scene);
  // Rebuilds the current scene from its description (frame 0 again); no effect without a scene.
  void restart();
  // True when a scene or a recording is loaded.
  [[nodiscard]] bool has_scene() const;
  // The loaded scene (an empty default Scene before the first load; for a recording: its path, its
  // file's stem as name, its pinned grid, no bodies).
  [[nodiscard]] const Scene& scene() const;

  // ---- recorded frames (io/recording.hpp), instead of a Box2D world ----
  // Reads a .nbsrec file (at most max_frames frames) and detects and checks its first frame. The
  // check has no Box2D world then: only A==R runs (report().box2d_checks is false). On error the
  // old scene or recording stays. Loading a scene afterwards replaces the recording.
  void load_recording_file(const std::string& path, std::int64_t max_frames = INT64_MAX);
  // Same for a recording already in memory (at least one frame).
  void load_recording(Recording recording);
  // True when the frames come from a recording.
  [[nodiscard]] bool replaying() const;
  // The number of recorded frames (0 for a scene).
  [[nodiscard]] std::int64_t recorded_frames() const;
  // True when the recording's frames carry the user's contact pairs (a `pairs` block each), which
  // the algorithm `recorded` (check/recorded_lane.hpp) returns; false for a scene.
  [[nodiscard]] bool carries_pairs() const;
  // The recording's `base`: its pairs number elements from 0 or 1 (0 for a scene). Element ids
  // here stay 0-based rows either way.
  [[nodiscard]] int pair_base() const;
  // True on a recording's last frame, where step() does nothing (always false for a scene).
  [[nodiscard]] bool at_end() const;

  // ---- configuration (each takes effect at once: the current frame is detected and checked again) ----
  // Switches the detector; throws Error (old one kept) for an unknown or 3D-only name, or `recorded`
  // where it has no pairs or the fault cannot act on them.
  void set_algorithm(std::string_view name);
  [[nodiscard]] const std::string& algorithm() const;
  void set_fault(Fault fault);
  [[nodiscard]] Fault fault() const;
  void set_checks_enabled(bool on);
  [[nodiscard]] bool checks_enabled() const;
  // How R is chosen, in words (for the UI and reports).
  [[nodiscard]] std::string reference_policy() const;
  // Which pairs A-in-F applies to, in words.
  [[nodiscard]] static std::string scope_note();
  // More detectors to run and check on every frame beside the chosen one, on the same elements
  // with the same fault (headless --algorithm a,b,c compares them on identical frames; the window
  // leaves this empty). Throws Error for an unknown or 3D-only name and keeps the previous list.
  void set_comparison_algorithms(const std::vector<std::string>& names);
  [[nodiscard]] const std::vector<std::string>& comparison_algorithms() const;
  // This frame's report of each comparison algorithm, in the order given.
  [[nodiscard]] const std::vector<FrameReport>& comparison_reports() const;

  // ---- advancing ----
  // Advances one frame: while a past frame is shown, to the next kept frame (nothing is simulated:
  // the later frames are the run's own); else physics (or the next recorded frame), elements,
  // detection, check. No effect without a scene, at a recording's end or while resuming.
  void step();
  // Detects and checks the current frame again without stepping (e.g. while paused).
  void redetect();

  // ---- advancing with the physics overlapped (the window) ----
  // Starts the next frame's physics (Box2D's step) on a worker thread and returns at once, so that
  // the caller can draw the current frame meanwhile; the next step() adopts it (waits for the
  // worker, then detects and checks), giving exactly the frame a plain step() would have. Until
  // then every accessor keeps describing the current frame (a snapshot of what the step changes),
  // and every call that needs the world (configuration, history, resume, drags, loads) adopts the
  // step first. Does nothing on a past frame, a recording, while resuming or with a step pending.
  void begin_step();
  // True between begin_step() and the call that adopts its frame.
  [[nodiscard]] bool step_pending() const;
  // True when the current frame's physics ran on the worker thread, beside the drawing of the
  // frame before (its physics_ms is the worker's own time).
  [[nodiscard]] bool physics_overlapped() const;

  // ---- history: every frame of the run (check/history.hpp) ----
  // The run's frames: a summary of each, and the kept states that show past ones again.
  [[nodiscard]] const FrameHistory& history() const;
  // Bytes of world states to keep; older states are dropped at once when the budget shrinks.
  void set_history_budget(std::size_t bytes);
  // Every violation of the run, in frame order.
  [[nodiscard]] const ViolationLog& violation_log() const;
  // True while the frame shown is a kept past frame rather than the newest one.
  [[nodiscard]] bool showing_past() const;
  // The newest frame of the run: the live world's, or a recording's last.
  [[nodiscard]] std::int64_t newest_frame() const;
  // True when frame `frame` can be shown (kept, the newest, or recorded).
  [[nodiscard]] bool can_show(std::int64_t frame) const;
  // Makes frame `frame` current, with detection and every check run on it again (the overlays,
  // panels and stepper then show it as they show a live frame). Throws Error when it is not kept.
  void show_frame(std::int64_t frame);
  // Shows the kept frame before the shown one (detected and checked again); false, unmoved, at the
  // oldest showable frame.
  bool step_back();
  // The showable frame `delta` frames from the shown one (clamped to the first/newest showable), or
  // nullopt when there is none in that direction.
  [[nodiscard]] std::optional<std::int64_t> neighbour(std::int64_t delta) const;
  // Element k's centre at each showable frame in [from, to], oldest first (a past frame's trail).
  void element_path(ElementId k, std::int64_t from, std::int64_t to, std::vector<std::array<double, 2>>& out) const;

  // ---- resuming the simulation from a past frame ----
  // Starts continuing the simulation from the shown past frame K: a fresh world is built from the
  // scene and stepped to K with the drags recorded before K (continue_resume). No effect on the live
  // frame or a recording.
  void begin_resume();
  // Re-simulates for about `budget_ms` of wall time (at least one step); true once the world is at
  // K: the frames after K are dropped and K is the live frame. Throws Error as step() does.
  bool continue_resume(double budget_ms);
  // Stops a resume before it arrives; the history is unchanged.
  void cancel_resume();
  [[nodiscard]] bool resuming() const;
  // Frames re-simulated so far and the frame being resumed from.
  [[nodiscard]] std::pair<std::int64_t, std::int64_t> resume_progress() const;
  // After a resume: the first re-simulated frame whose element hash differed from what the history
  // kept for it (nullopt: every kept frame on the way was reproduced exactly).
  [[nodiscard]] std::optional<std::int64_t> resume_divergence() const;

  // ---- the current frame ----
  // Bumped whenever the frame shown or what was found in it changes (load, restart, step, a past
  // frame shown, redetect or a configuration change, a resume's arrival): views compare it with the
  // last one they drew, and frame() with theirs (a jump that is not +1 starts trails again).
  [[nodiscard]] std::uint64_t generation() const;
  [[nodiscard]] std::int64_t frame() const;   // 0 after load, +1 per step(); a recording's own numbers
  [[nodiscard]] double time() const;          // simulated seconds (a recording's own times)
  // Bounding circles at the current poses (element k = fixture k, see element_sources()).
  [[nodiscard]] const Elements& elements() const;
  // Element -> (body, fixture).
  [[nodiscard]] const std::vector<ElementSource>& element_sources() const;
  [[nodiscard]] std::int64_t body_count() const;
  // A: the chosen algorithm's pairs (after any injected fault), sorted, i < j.
  [[nodiscard]] const PairList& pairs() const;
  // The grid of the frame: the detector's own (last_grid) or, for detectors without one, the grid
  // fitted to the same elements with the scene's cell_size/origin.
  [[nodiscard]] const Grid& grid() const;
  // The detector's cell of every element (under grid(); shifted by the off-by-one-cell fault).
  [[nodiscard]] const std::vector<CellIndex>& cells() const;
  // Everything the pipeline found in this frame (check/frame_result.hpp): hash, each lane's pairs,
  // grid, cells and report, the check's sets, the trace once asked for.
  [[nodiscard]] const FrameResult& result() const;
  // Counts, timings and violations of this frame (report().checked is false when checks are off).
  [[nodiscard]] const FrameReport& report() const;
  [[nodiscard]] const FrameTimings& timings() const { return report().timings; }
  // The check's sets of this frame, sorted (empty when checks are off): R, F (Box2D's contact list),
  // T (shapes touching now), G (tight-AABB pairs).
  [[nodiscard]] const PairList& reference_pairs() const;
  [[nodiscard]] const PairList& box2d_pairs() const;
  [[nodiscard]] const PairList& touching_pairs() const;
  [[nodiscard]] const PairList& tight_aabb_pairs() const;
  // Every fixture at the current poses in world coordinates, for drawing (fills `out`); for a
  // recording one dynamic circle per element.
  void body_shapes(std::vector<BodyShape>& out) const;
  // The detector in use (for its name, own_bytes(), pseudocode()).
  [[nodiscard]] const Detector& detector() const;
  // The current detector's traced run on the elements it was given this frame (faults not
  // applied): the one trace the stepper and the lists overlay both show. Made on the first request
  // and kept until the frame or the detector changes; its `refusal` says why it holds no operations
  // (too many elements, a detector without a trace). Null without a scene.
  [[nodiscard]] std::shared_ptr<const FrameTrace> frame_trace();

  // ---- mouse drag (world coordinates) ----
  // Each call is recorded with its frame, so that a resume replays it. Only on the live frame.
  // Grabs the dynamic body under (x, y) with a b2MouseJoint; false when there is none (or a past
  // frame is shown: resume first).
  bool begin_drag(double x, double y);
  // Moves the grabbed body's target.
  void drag_to(double x, double y);
  // Lets go (no effect when nothing is grabbed).
  void end_drag();
  [[nodiscard]] bool dragging() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace nbscope
