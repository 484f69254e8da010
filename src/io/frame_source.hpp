// nbscope io: the frame-source contract. A run of frames the loop (app/frame_loop.hpp) steps, shows
// again and keeps: everything it asks of a frame comes through here, so that no code outside a
// source names a concrete one. The sources: a simulated scene (app/frame_sources.cpp: the live Box2D
// world, its kept past frames, drags and resume) and recorded frames (io/recording_source.hpp: a
// .nbsrec or a dump). Adding one is one class plus one line in app/frame_sources.cpp.
//
// What a source can do beyond showing and stepping frames it declares, as Box2D's debug-draw flags
// do: recording() (the recorded facts), entries() (frames known in advance), simulation() (a world
// stepped here: the overlapped step, drags, resume). The loop asks before it calls.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "check/history.hpp"
#include "io/recorded_frames.hpp"
#include "io/recording.hpp"
#include "physics/frame.hpp"
#include "physics/scene.hpp"

namespace nbscope {

class Simulation;

// What the history keeps of a frame so that the source can show it again, and its bytes.
struct KeptState {
  std::shared_ptr<const WorldState> state;
  std::size_t bytes = 0;
};

class FrameSource : public Frame {
 public:
  // ---- the run ----
  // The run as panels and reports name it: the scene, or for recorded frames their path, the file's
  // stem as name, the pinned grid and the recorded time per frame (no bodies).
  [[nodiscard]] virtual const Scene& scene() const = 0;
  // The recording's facts (path, grid, comment, pairs' base, has_pairs; no frames), or null when the
  // frames are simulated.
  [[nodiscard]] virtual const Recording* recording() const { return nullptr; }
  // Frames known before they are shown (number, time, elements), in order; empty when the run makes
  // them as it goes. Each is showable from the start, checked when first shown. A run still being
  // written (a watched one) adds to them at a step(): the loop takes the new ones in then.
  [[nodiscard]] virtual const std::vector<RecordedEntry>& entries() const;
  // True on the run's first frame: the stale-positions fault has nothing older to give.
  [[nodiscard]] virtual bool first() const = 0;
  // The newest frame of the run (the one shown while a step is pending).
  [[nodiscard]] virtual std::int64_t newest_frame() const = 0;

  // ---- moving ----
  // True when step() can make a next frame from the frame shown.
  [[nodiscard]] virtual bool can_step() const = 0;
  // Makes the next frame; returns the milliseconds spent simulating it (0 when nothing is
  // simulated). Error, unmoved, for a frame refused.
  virtual double step() = 0;
  // Makes `frame` the one shown: the newest, a frame of entries(), or a past frame the history kept
  // (`kept`: what keep() gave for it). Error, unmoved, for a frame refused.
  virtual void show(std::int64_t frame, const std::shared_ptr<const WorldState>& kept) = 0;
  // The run's first frame shown again as it was at the start (a restart).
  virtual void rewind() = 0;
  // True while the frame shown is a past one the history kept rather than the newest.
  [[nodiscard]] virtual bool showing_past() const { return false; }

  // ---- what the history keeps ----
  // What keeps the newest frame showable later (with Box2D's contacts when given), or nothing
  // when the source shows its frames by number.
  [[nodiscard]] virtual KeptState keep(const PairList* box2d_contacts) const {
    (void)box2d_contacts;
    return {};
  }
  // When the frame shown was written by the code that writes it (seconds since the epoch), where
  // known (a watched run): the latency from a frame's write to its check.
  [[nodiscard]] virtual std::optional<double> written_at() const { return std::nullopt; }
  // The elements of the frame before the one shown, from what the history kept of it (`kept_before`,
  // maybe null); the shown frame's own when nothing older can be had.
  [[nodiscard]] virtual Elements previous_elements(const std::shared_ptr<const WorldState>& kept_before) const = 0;
  // Element row `k` of frame `to` followed through the frames of `history` in [from, to]: its centre
  // at each that can be had without reading a file, oldest first (a dump's atom followed by its id).
  // Called while a step is in flight too: it reads only what the source holds, never waits for it.
  virtual void element_path(const FrameHistory& history, ElementId k, std::int64_t from, std::int64_t to,
                            std::vector<std::array<double, 2>>& out) const = 0;
  // Bytes of frames held beside the one shown, within a budget the history's sets.
  [[nodiscard]] virtual std::size_t held_bytes() const { return 0; }
  virtual void set_budget(std::size_t bytes) { (void)bytes; }
  // What the next step() is doing, for the slow-frame note (app/frame_watch.hpp); empty when it is
  // not worth a note (reading a recorded frame).
  [[nodiscard]] virtual std::function<std::string()> step_note() const { return {}; }

  // ---- a world simulated here ----
  // The overlapped step, the drags and resume, or null when the frames are not simulated here.
  [[nodiscard]] virtual Simulation* simulation() { return nullptr; }
  [[nodiscard]] const Simulation* simulation() const { return const_cast<FrameSource*>(this)->simulation(); }
};

inline const std::vector<RecordedEntry>& FrameSource::entries() const {
  static const std::vector<RecordedEntry> kNone;
  return kNone;
}

// A world stepped by the source itself (physics/live_world.hpp says why the overlapped step is safe
// and gives the same frame; physics/resume.hpp how a resume arrives at the same frame).
class Simulation {
 public:
  virtual ~Simulation() = default;
  // ---- the overlapped step: the next frame's physics on a worker while the caller draws ----
  // Starts it, then `then` on the worker with the new frame (its detection and check); false
  // (nothing pending) when no thread can be had. Until finish_step() the caller touches nothing
  // `then` uses.
  virtual bool begin_step(std::function<void(const Frame& next)> then) = 0;
  // True between begin_step() and finish_step()/discard_step().
  [[nodiscard]] virtual bool pending() const = 0;
  // True when the pending step is done: finish_step() will not wait.
  [[nodiscard]] virtual bool step_ready() const = 0;
  // Makes the pending step's frame the newest (and the one shown); its milliseconds. Rethrows its Error.
  virtual double finish_step() = 0;
  // Forgets a pending step (the world is about to be replaced).
  virtual void discard_step() = 0;
  // Returns once the worker is done with the world.
  virtual void wait() const = 0;

  // ---- drags on the newest frame (world coordinates), each logged with its frame ----
  // Grabs the dynamic body under (x, y); false when there is none.
  virtual bool begin_drag(double x, double y) = 0;
  virtual void drag_to(double x, double y) = 0;
  virtual void end_drag() = 0;
  // True while a body is held.
  [[nodiscard]] virtual bool dragging() const = 0;

  // ---- resume: the simulation continued from the past frame shown ----
  // Starts re-simulating a fresh world to the past frame shown.
  virtual void begin_resume() = 0;
  // Re-simulates for about `budget_ms` (at least one step); true once arrived: the re-simulated
  // world is the newest frame, shown. `hash_of` gives the history's hash of a frame on the way.
  virtual bool advance_resume(double budget_ms, const std::function<std::uint64_t(std::int64_t)>& hash_of) = 0;
  // Stops a resume before it arrives.
  virtual void cancel_resume() = 0;
  [[nodiscard]] virtual bool resuming() const = 0;
  // Frames re-simulated so far and the frame being resumed to.
  [[nodiscard]] virtual std::pair<std::int64_t, std::int64_t> resume_progress() const = 0;
  // After a resume: the first re-simulated frame whose hash differed from the history's, if any.
  [[nodiscard]] virtual std::optional<std::int64_t> divergence() const = 0;
  // After a resume arrived: the elements of the frame before the one resumed to.
  [[nodiscard]] virtual Elements resumed_previous() const = 0;
};

}  // namespace nbscope
