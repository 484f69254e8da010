// nbscope app: the parts FrameLoop hands out (app/frame_loop.hpp), grouped by what they are about,
// so that FrameLoop itself keeps only the coordination (load, step, time travel).
//
// Who owns what: LoopSource owns the frame source, LoopPipeline the pipeline (and, while a step is
// detected on the worker, the copy of the shown frame's result the views read), LoopHistory the
// run's frames and its violation log. Each reads only its own state and the parts it was given
// (the pipeline and the history read the source); only the loop's coordination changes them
// (app/frame_loop_impl.hpp). LoopResume and LoopDrag own nothing: they are the simulation's verbs,
// and each says what it costs (a step in flight is adopted first, waiting for the worker). They live
// as long as their FrameLoop.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "check/faults.hpp"
#include "check/history.hpp"
#include "check/pipeline.hpp"
#include "check/report.hpp"
#include "core/detector.hpp"
#include "core/frame_trace.hpp"
#include "core/pairs.hpp"
#include "io/frame_source.hpp"
#include "physics/scene.hpp"
#include "physics/shapes.hpp"

namespace nbscope {

struct FrameLoopState;
class Simulation;

// The frame shown and where it comes from (a Box2D world, or a recording: io/recording.hpp).
struct Recording;

class LoopSource {
 public:
  // True when a scene or a recording is loaded.
  [[nodiscard]] bool has_scene() const;
  // The loaded scene (an empty default Scene before the first load; for a recording: its path, its
  // file's stem as name, its pinned grid, no bodies).
  [[nodiscard]] const Scene& scene() const;
  // True when the frames come from a recording.
  [[nodiscard]] bool replaying() const;
  // The number of recorded frames (0 for a scene).
  [[nodiscard]] std::int64_t recorded_frames() const;
  // True when the recording's frames carry the user's contact pairs (a `pairs` block each), which
  // the algorithm `recorded` (check/recorded_lane.hpp) returns; false for a scene.
  [[nodiscard]] bool carries_pairs() const;
  // The recording replayed: its header (path, grid, comment, pairs' base; no frames: they are read
  // as they are shown), null for a scene.
  [[nodiscard]] const Recording* recording() const;
  // The frame shown's recorded pairs (0-based, as given) when the recording carries them, else null.
  [[nodiscard]] const PairList* recorded_pairs() const;
  // The recording's `base`: its pairs number elements from 0 or 1 (0 for a scene). Element ids
  // here stay 0-based rows either way.
  [[nodiscard]] int pair_base() const;
  // True on a recording's last frame, where step() does nothing (always false for a scene; false
  // for a watched run until it has ended).
  [[nodiscard]] bool at_end() const;
  // When the frame shown was written by the code that writes it (seconds since the epoch), where
  // known (a watched run): the latency from its write to its check.
  [[nodiscard]] std::optional<double> written_at() const;
  // True between FrameLoop::begin_step() and the call that adopts its frame.
  [[nodiscard]] bool step_pending() const;
  // True when the pending step's physics is done, so adopting it (step()) does not wait for the
  // worker: the window adopts a step only then, and draws the frame it has meanwhile.
  [[nodiscard]] bool step_ready() const;
  // True when the current frame's physics ran on the worker thread, beside the drawing of the
  // frame before (its physics_ms is the worker's own time).
  [[nodiscard]] bool physics_overlapped() const;
  // True when its detection and check ran on the worker too (the worker's own times in its report).
  [[nodiscard]] bool detection_overlapped() const;
  // 0 after load, +1 per step(); a recording's own numbers.
  [[nodiscard]] std::int64_t frame() const;
  // Simulated seconds (a recording's own times).
  [[nodiscard]] double time() const;
  // Bounding circles at the current poses (element k = fixture k, see element_sources()).
  [[nodiscard]] const Elements& elements() const;
  // The MPI rank whose file held each row (per-rank dumps), or null.
  [[nodiscard]] const std::vector<std::int32_t>* ranks() const;
  // Each rank's subdomain (per-rank dumps, when the split was found), or null.
  [[nodiscard]] const Subdomains* subdomains() const;
  // Element -> (body, fixture).
  [[nodiscard]] const std::vector<ElementSource>& element_sources() const;
  // Bodies of the frame shown.
  [[nodiscard]] std::int64_t body_count() const;
  // Every fixture at the current poses in world coordinates, for drawing (fills `out`); for a
  // recording one dynamic circle per element.
  void body_shapes(std::vector<BodyShape>& out) const;

 private:
  friend struct FrameLoopState;
  friend class FrameLoop;
  friend class LoopPipeline;
  friend class LoopHistory;
  [[nodiscard]] bool loaded() const { return frames_ != nullptr; }
  // The source's simulation (the overlapped step, drags, resume), or null.
  [[nodiscard]] Simulation* simulation() const { return frames_ ? frames_->simulation() : nullptr; }
  // True while a step begun by FrameLoop::begin_step() has not been adopted.
  [[nodiscard]] bool pending() const;
  // Returns once the worker is done with the world (the accessors still show the current frame).
  void wait_for_worker() const;

  std::unique_ptr<FrameSource> frames_;  // null before the first load
  bool physics_overlapped_ = false;      // the current frame's physics ran on the worker
  bool detection_overlapped_ = false;    // so did its detection and check
};

// What detects and checks each frame, read (the calls that change it are FrameLoop's
// redetect_with_*: each detects the frame shown again), and the frame's trace.
class LoopPipeline {
 public:
  // The pipeline of `options`, detecting `source`'s frames with up to `threads` threads.
  LoopPipeline(const LoopSource& source, const PipelineOptions& options, int threads)
      : source_(source), pipeline_(options), threads_(threads) {}
  // The chosen detector's registry name (or "recorded"); FrameLoop::redetect_with_algorithm changes it.
  [[nodiscard]] const std::string& algorithm() const;
  // The injected fault (check/faults.hpp).
  [[nodiscard]] Fault fault() const;
  // True when the cross-check runs.
  [[nodiscard]] bool checks_enabled() const;
  // Whether a pair at exactly zero gap is a contact (--touching), for every lane and the check.
  [[nodiscard]] Touching touching() const;
  // Threads each detection may use (--threads; the traced run uses one).
  [[nodiscard]] int threads() const;
  // How R is chosen, in words (for the UI and reports).
  [[nodiscard]] std::string reference_policy() const;
  // Which pairs A-in-F applies to, in words.
  [[nodiscard]] static std::string scope_note();
  // The comparison detectors, in the order given.
  [[nodiscard]] const std::vector<std::string>& comparison_algorithms() const;
  // The bytes the detector in use keeps between frames (Detector::own_bytes), as of the frame shown.
  [[nodiscard]] std::size_t detector_bytes() const;
  // The current detector's traced run on the elements it was given this frame (faults not
  // applied): the one trace the stepper and the lists overlay both show. Made on the first request
  // and kept until the frame or the detector changes; its `refusal` says why it holds no operations
  // (too many elements, a detector without a trace). Null without a scene; while the worker detects
  // the next frame, the shown frame's trace if its detection recorded one, else null.
  [[nodiscard]] std::shared_ptr<const FrameTrace> frame_trace();
  // Whether the frames to come record their trace in their one detection (Pipeline::set_record_traces),
  // so that frame_trace() calls the detector no second time. Re-runs nothing; asked while the worker
  // detects a step in flight, it holds from the frame after.
  void record_traces(bool on);
  [[nodiscard]] bool record_traces() const;

 private:
  friend struct FrameLoopState;
  friend class FrameLoop;
  // The shown frame's result: the pipeline's, or while the worker detects a step, the copy lent().
  [[nodiscard]] const FrameResult& shown() const { return on_worker() ? *shown_result_ : pipeline_.result(); }
  // True while the pipeline is the worker's (a step in flight detected there).
  [[nodiscard]] bool on_worker() const { return shown_result_ != nullptr && source_.pending(); }
  // The worker takes the pipeline for a step in flight: the shown frame's result, detector bytes and
  // detect options are copied for the views meanwhile.
  void lend();
  // The pipeline is this thread's again (the step adopted, discarded or never begun): the copy goes
  // and a record_traces() wish made meanwhile applies.
  void take_back();
  // The shown frame's trace while the pipeline is the worker's: its detection's own, else made by a
  // fresh detector of the same kind (a built-in keeps nothing between frames); null under the
  // stale-positions fault, whose input the worker holds.
  std::shared_ptr<const FrameTrace> shown_trace();

  const LoopSource& source_;
  Pipeline pipeline_;
  int threads_;
  std::unique_ptr<FrameResult> shown_result_;  // while lent: the shown frame's result
  std::size_t shown_detector_bytes_ = 0;
  DetectOptions shown_detect_;                 // the shown frame's detect options (its trace's)
  std::optional<bool> wanted_traces_;          // a record_traces() wish made while lent
};

// Every frame of the run (check/history.hpp) and which of them can be shown again.
class LoopHistory {
 public:
  // The history of `source`'s run: `budget` bytes of past states, at most `max_summaries` summaries.
  LoopHistory(LoopSource& source, std::size_t budget, std::size_t max_summaries);
  // The run's frames: a summary of each, and the kept states that show past ones again.
  [[nodiscard]] const FrameHistory& frames() const;
  // Bytes of world states (or of recorded frames read from files) to keep; older ones are dropped at
  // once when the budget shrinks.
  void set_budget(std::size_t bytes);
  [[nodiscard]] std::size_t budget() const { return frames_.budget(); }
  // The bytes the run's past holds: the summaries, the kept world states, the recorded frames kept
  // beside the one shown.
  [[nodiscard]] std::size_t bytes() const;
  // Every violation of the run, in frame order.
  [[nodiscard]] const ViolationLog& violation_log() const;
  // True while the frame shown is a kept past frame rather than the newest one.
  [[nodiscard]] bool showing_past() const;
  // The newest frame of the run: the live world's, or a recording's last.
  [[nodiscard]] std::int64_t newest_frame() const;
  // True when frame `frame` can be shown (kept, the newest, or recorded).
  [[nodiscard]] bool can_show(std::int64_t frame) const;
  // The showable frame `delta` frames from the shown one (clamped to the first/newest showable), or
  // nullopt when there is none in that direction.
  [[nodiscard]] std::optional<std::int64_t> neighbour(std::int64_t delta) const;
  // Element k's centre at each showable frame in [from, to], oldest first (a past frame's trail).
  void element_path(ElementId k, std::int64_t from, std::int64_t to, std::vector<std::array<double, 2>>& out) const;

 private:
  friend struct FrameLoopState;
  friend class FrameLoop;
  LoopSource& source_;
  FrameHistory frames_;
  ViolationLog violations_;
};

// Continuing the simulation from a past frame K: a fresh world is built from the scene and stepped
// to K with the drags recorded before K (Box2D is deterministic), and the later frames are replaced.
// Owns nothing (the simulation keeps the resume); acts through the loop's coordination.
class LoopResume {
 public:
  // The resume of `loop`'s simulation (FrameLoop makes it).
  explicit LoopResume(FrameLoopState& loop) : loop_(loop) {}
  // Starts from the shown past frame (a step in flight adopted first). No effect on the live frame or a recording.
  void begin();
  // Re-simulates for about `budget_ms` of wall time (at least one step); true once the world is at
  // K: the frames after K are dropped and K is the live frame. Throws Error as step() does.
  bool advance(double budget_ms);
  // Stops a resume before it arrives; the history is unchanged.
  void cancel();
  // True while resuming.
  [[nodiscard]] bool active() const;
  // Frames re-simulated so far and the frame being resumed from.
  [[nodiscard]] std::pair<std::int64_t, std::int64_t> progress() const;
  // After a resume: the first re-simulated frame whose element hash differed from what the history
  // kept for it (nullopt: every kept frame on the way was reproduced exactly).
  [[nodiscard]] std::optional<std::int64_t> divergence() const;

 private:
  FrameLoopState& loop_;
};

// The mouse drag (world coordinates). Each call is recorded with its frame, so that a resume replays
// it. Only on the live frame. Owns nothing (the simulation holds the joint); each call that acts
// adopts a step in flight first, waiting for the worker.
class LoopDrag {
 public:
  // The drag of `loop`'s simulation (FrameLoop makes it).
  explicit LoopDrag(FrameLoopState& loop) : loop_(loop) {}
  // Grabs the dynamic body under (x, y) with a b2MouseJoint; false when there is none (or a past
  // frame is shown: resume first).
  bool begin(double x, double y);
  // Moves the grabbed body's target.
  void move_to(double x, double y);
  // Lets go (no effect when nothing is grabbed).
  void end();
  // True while a body is held.
  [[nodiscard]] bool active() const;

 private:
  // The simulation when a drag can act on it (the newest frame shown, no resume), else null.
  [[nodiscard]] Simulation* live() const;
  FrameLoopState& loop_;
};

}  // namespace nbscope
