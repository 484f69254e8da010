// nbscope core: the stepper — a cursor over the trace of one paused frame's detection, so the
// user can walk through the building of the singly connected lists one book operation at a time,
// forwards and backwards, and always see the exact array state.
//
// Index: ArrayState/Breakpoint/PhaseMark/LoopVars (what the UI asks for) | Stepper (the cursor:
// load, seek and step, phases, breakpoints, play, highlighting queries).
//
// Position p means "the first p events have been applied": 0 is the state before the detection,
// size() the state after it, and the current event is event p-1. The state after p events is
// exact whichever way p was reached: single steps apply or undo one event's writes, long jumps
// restore the nearest checkpoint and replay forward. load() checks that every recorded write
// found the old value it claims, so undo is exact too (a corrupted trace is refused).
// Pure C++: no ImGui, no GL; the Stepper, Arrays and Pseudocode panels are built on it.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/trace.hpp"

namespace nbscope {

// Contents of every traced array, indexed like TraceLog::arrays().
using ArrayState = std::vector<std::vector<std::int32_t>>;

// What a breakpoint stops at.
enum class BreakKind : std::uint8_t {
  Element,      // any event about the element: pushed, written for, its mask visited, a pair with it tested
  Cell,         // any event naming cell (ix, iy, iz) (a push onto it, a mask visit, ...); iz = -1 in 2D
  List,         // a write to one list head: heads array `array`, flat index `list`
  FirstPairOf,  // a pair tested that involves the element
};

// One breakpoint; only the fields its kind names are read.
struct Breakpoint {
  BreakKind kind = BreakKind::Element;
  std::int32_t element = -1;
  std::int32_t cell[3] = {-1, -1, -1};
  std::int32_t array = -1;
  std::int64_t list = -1;
};

// True when event `e` is one that breakpoint `b` stops at.
[[nodiscard]] bool breakpoint_matches(const Breakpoint& b, const TraceEvent& e);

// Where a phase of the algorithm begins: a Phase event.
struct PhaseMark {
  std::size_t event = 0;     // index of the Phase event
  const char* label = "";    // e.g. "x-lists of row"
  std::int32_t index = -1;   // e.g. the row iy; -1 when the phase has no index
};

// The detector's loop variables at the current event, as the Pseudocode panel shows them.
// -1 (or "") where the current event does not define the variable.
struct LoopVars {
  const char* phase = "";           // label of the phase the current event belongs to
  std::int32_t phase_index = -1;    // its index (row iy, layer iz, leaf)
  std::int32_t k = -1;              // the element of the event
  std::int32_t j = -1;              // TestPair: the element k is tested against
  std::int32_t ix = -1, iy = -1, iz = -1;  // the event's cell (TestPair: the mask cell being scanned)
  const char* list_kind = "";       // Push/Clear: kind of list ("y-list", "x-list", ...)
  std::int32_t heads_array = -1;    // Push/Clear: the heads array written
  std::int64_t list = -1;           // Push/Clear: flat index of the list's head
  std::int32_t head = -1;           // Push/Clear: that head's value now
};

// A cursor over one detection's trace with exact array state at every position.
class Stepper {
 public:
  // Takes the trace of one detection and rewinds to position 0. Throws Error when an event writes
  // outside its array or a recorded old value is not what the array held (the trace is corrupt).
  void load(TraceLog trace);
  // As load(TraceLog), sharing a trace others also read (the frame loop's: the lists overlay draws it).
  void load(std::shared_ptr<const TraceLog> trace);
  // Drops the trace; the stepper is empty (size() == 0).
  void clear();

  // The loaded trace (arrays declared, events) and its events.
  [[nodiscard]] const TraceLog& trace() const { return *trace_; }
  [[nodiscard]] const std::vector<TraceEvent>& events() const { return trace_->events(); }
  // Number of events.
  [[nodiscard]] std::size_t size() const { return trace_->events().size(); }
  // Number of events applied.
  [[nodiscard]] std::size_t position() const { return position_; }
  // Every array after position() events.
  [[nodiscard]] const ArrayState& state() const { return state_; }
  // The last event applied (event position()-1), nullptr at position 0.
  [[nodiscard]] const TraceEvent* current() const;

  // Moves to `position` (clamped to [0, size()]); cost bounded by the checkpoint interval.
  void seek(std::size_t position);
  // Applies the next event; false at the end.
  bool step_forward();
  // Undoes the current event; false at position 0.
  bool step_back();

  // Every phase, in event order.
  [[nodiscard]] const std::vector<PhaseMark>& phases() const { return phases_; }
  // Index into phases() of the phase the current event belongs to, or -1 before the first.
  [[nodiscard]] std::int64_t current_phase() const;
  // Moves onto the Phase event of phases()[n] (position = its event + 1).
  void seek_phase(std::size_t n);
  // Moves onto the next phase's Phase event; false (unmoved) when there is none. At position 0 a
  // phase marked at event 0 counts as the current one: the first move goes past it (not one event).
  bool next_phase();
  // Moves onto the current phase's Phase event, or the previous phase's when already on one;
  // false (unmoved) when there is none.
  bool prev_phase();

  // First event at index >= from that `b` stops at.
  [[nodiscard]] std::optional<std::size_t> find_next(const Breakpoint& b, std::size_t from) const;
  // Last event at index < before that `b` stops at.
  [[nodiscard]] std::optional<std::size_t> find_prev(const Breakpoint& b, std::size_t before) const;
  // Runs forward until the first later event `b` stops at is the current one; false (unmoved) if none.
  bool run_to(const Breakpoint& b);
  // Runs backward until the latest earlier event `b` stops at is the current one; false (unmoved) if none.
  bool run_back_to(const Breakpoint& b);

  // Playback speed in events per second (clamped to > 0).
  void set_speed(double events_per_second);
  // The playback speed in events per second.
  [[nodiscard]] double speed() const { return speed_; }
  // Starts playing (from the start when at the end); pause() stops.
  void play();
  // Stops playback where it is.
  void pause() { playing_ = false; }
  // True while playback advances.
  [[nodiscard]] bool playing() const { return playing_; }
  // While playing, stops at the first event this breakpoint matches (nullopt: play to the end).
  void set_play_breakpoint(std::optional<Breakpoint> b) { play_break_ = b; }
  // Advances playback by `dt_seconds` of wall time; returns the events stepped. Stops at the end
  // or at the play breakpoint.
  std::size_t advance(double dt_seconds);

  // The writes of the current event (empty for Phase/VisitCell/TestPair and at position 0).
  [[nodiscard]] std::span<const ArrayWrite> current_writes() const;
  // Index of the latest event at or before the current one that wrote an array.
  [[nodiscard]] std::optional<std::size_t> last_write_event() const;
  // The loop variables at the current event.
  [[nodiscard]] LoopVars loop_vars() const;
  // The next array that lists of heads array `heads_array` link through (from its pushes), or -1.
  [[nodiscard]] int next_array_of(int heads_array) const;
  // Elements of list `list` of `heads_array` in the current state, head first (bounded: a cycle
  // stops after every element once).
  [[nodiscard]] std::vector<std::int32_t> list_members(int heads_array, std::int64_t list) const;
  // Id of the traced array called `name`, or -1.
  [[nodiscard]] int array_id(const std::string& name) const;
  // Events between checkpoints (for tests of both seek paths).
  [[nodiscard]] std::size_t checkpoint_interval() const { return interval_; }

 private:
  void restore_checkpoint(std::size_t n);

  static std::shared_ptr<const TraceLog> empty_trace();

  std::shared_ptr<const TraceLog> trace_ = empty_trace();
  ArrayState state_;
  std::size_t position_ = 0;
  std::size_t interval_ = 1024;
  std::vector<ArrayState> checkpoints_;     // checkpoints_[c] = state after c * interval_ events
  std::vector<PhaseMark> phases_;
  std::vector<std::int32_t> phase_of_;      // per event: index into phases_, -1 before the first
  std::vector<std::int32_t> last_write_;    // per event: latest event <= it with writes, -1 if none
  std::vector<int> next_of_heads_;          // per array: the next array its pushes link through
  double speed_ = 10;
  double carry_ = 0;                        // fractional events owed by advance()
  bool playing_ = false;
  std::optional<Breakpoint> play_break_;
};

}  // namespace nbscope
