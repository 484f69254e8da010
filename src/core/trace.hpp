// nbscope core: trace events, one per book operation, and the two trace sinks.
//
// Index: TraceOp/ArrayWrite/TraceEvent (what one event says) | TraceLog (records, replays) |
// NullTrace (the zero-cost sink every untraced detection uses).
//
// Detectors are templates over the sink. With NullTrace every call is an empty inline function and
// `if constexpr (Trace::enabled)` removes the bookkeeping, so tracing costs nothing when off.
#pragma once
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/elements.hpp"

namespace nbscope {

// What one trace event records.
enum class TraceOp : std::uint8_t {
  Phase,      // a phase of the algorithm begins (label, index: e.g. "x-lists", row iy)
  Push,       // element k pushed onto list L: next[k] = head[L]; head[L] = k (eq. 3.21)
  Clear,      // one list head reset to -1
  VisitCell,  // a cell visited under the contact mask of element k
  TestPair,   // pair (k, other) tested; `contact` holds the result
  Set,        // one array entry set: an integerised coordinate, a sorted position, a tree link
};

// "phase", "push", "clear", "visit-cell", "test-pair" or "write": an operation's kind in messages and reports.
[[nodiscard]] const char* trace_op_name(TraceOp op);

// One integer written into one traced array.
struct ArrayWrite {
  std::int32_t array = -1;  // index into TraceLog::arrays()
  std::int32_t old_value = -1;
  std::int32_t new_value = -1;
  std::int64_t index = 0;   // flat index into the array
};

// One book operation. Fields not meaningful for `op` keep their defaults.
struct TraceEvent {
  TraceOp op = TraceOp::Phase;
  std::uint8_t line = 0;          // pseudocode line of the detector this operation belongs to
  std::uint8_t write_count = 0;   // how many of `writes` are used
  bool contact = false;           // TestPair: result
  std::int32_t element = -1;      // k
  std::int32_t other = -1;        // TestPair: the element tested against k
  std::int32_t index = -1;        // Phase: row/layer/leaf index; Push/Clear: list index (head slot)
  std::int32_t cell[3] = {-1, -1, -1};  // Push/VisitCell: the cell (ix, iy, iz)
  const char* label = "";         // Phase: static string naming the phase; Push/Clear: list kind
  ArrayWrite writes[2];
};

// A named integer array of a detector (heads or next), as the book draws it.
struct TracedArray {
  std::string name;                 // e.g. "y_heads", "B", "X", "C", "E"
  std::vector<std::int64_t> shape;  // e.g. {2, nx} for B, {nx, ny} for C; flat row-major
  std::vector<std::int32_t> initial;  // contents before the first event
};

// Records every event of one detection, and replays array state at any step.
class TraceLog {
 public:
  static constexpr bool enabled = true;

  // Starts a new recording (drops previous events and arrays).
  void reset();
  // Declares an array with its contents before the first event; returns its id.
  int declare_array(std::string name, std::vector<std::int64_t> shape, std::span<const std::int32_t> initial);
  // Marks the beginning of a phase; `label` must be a string literal.
  void phase(std::uint8_t line, const char* label, std::int32_t index);
  // As phase(), naming the cell, row (ix = -1) or layer (ix = iy = -1) the phase works on.
  void phase(std::uint8_t line, const char* label, std::int32_t index, std::int32_t ix, std::int32_t iy,
             std::int32_t iz);
  // Element k pushed onto list `list_index` of heads array `heads`, linking through array `next`.
  void push(std::uint8_t line, const char* kind, int heads, std::int64_t list_index, int next, ElementId k,
            std::int32_t old_head, std::int32_t old_next, std::int32_t ix, std::int32_t iy, std::int32_t iz);
  // As push(), with the values the detector really wrote (a plugin's buggy push may write next[k] =
  // -1): next[k] from old_next to new_next, heads[list] from old_head to new_head.
  void push_written(std::uint8_t line, const char* kind, int heads, std::int64_t list_index, int next, ElementId k,
                    std::int32_t old_head, std::int32_t old_next, std::int32_t new_head, std::int32_t new_next,
                    std::int32_t ix, std::int32_t iy, std::int32_t iz);
  // Head `list_index` of array `heads` reset from old_head to -1.
  void clear(std::uint8_t line, const char* kind, int heads, std::int64_t list_index, std::int32_t old_head);
  // As clear(), with the value the detector really wrote (a plugin's buggy clear may not write -1).
  void clear_written(std::uint8_t line, const char* kind, int heads, std::int64_t list_index, std::int32_t old_head,
                     std::int32_t new_head);
  // Cell (ix, iy, iz) visited under the contact mask of element k.
  void visit_cell(std::uint8_t line, ElementId k, std::int32_t ix, std::int32_t iy, std::int32_t iz);
  // Pair (k, other) tested; contact is the result.
  void test_pair(std::uint8_t line, ElementId k, ElementId other, bool contact);
  // Entry `index` of array `array` set from old_value to new_value on behalf of element k (-1: none);
  // `label` (a string literal) says what the entry is, e.g. "cell", "sorted", "tree node".
  void set(std::uint8_t line, const char* label, int array, std::int64_t index, std::int32_t old_value,
           std::int32_t new_value, ElementId k);
  // When false, VisitCell and TestPair events are not recorded (every array write still is), so a
  // large detection can be replayed for its arrays (`nbscope dump`) in memory O(writes). Survives reset().
  void set_keep_tests(bool keep) { keep_tests_ = keep; }
  // False when VisitCell and TestPair events are dropped (set_keep_tests).
  [[nodiscard]] bool keeps_tests() const { return keep_tests_; }
  // Records `e`, made by another TraceLog (a plugin's host process), as if it happened here; its arrays
  // must be declared here first, in the same order.
  void append(const TraceEvent& e) { record(e); }
  // The same for many, in order (one copy when no probe or consumer watches).
  void append(std::span<const TraceEvent> events);
  // Test hook: called just before each event is recorded with its position, the event, and the
  // detector's arrays as they really are at that moment, which a faithful trace makes equal to
  // state_after(position). The detector's arrays must not move while it runs. Survives reset().
  using Probe = std::function<void(std::size_t position, const TraceEvent& upcoming,
                                   const std::vector<std::vector<std::int32_t>>& live)>;
  void set_probe(Probe probe) { probe_ = std::move(probe); }

  // When set, each event is handed to `consumer` as it happens instead of being kept (events() stays
  // empty): a reader of one pass over a large detection (`nbscope dump`) holds no O(events) log. Survives reset().
  using Consumer = std::function<void(const TraceEvent& event)>;
  void set_consumer(Consumer consumer) { consumer_ = std::move(consumer); }

  [[nodiscard]] const std::vector<TraceEvent>& events() const { return events_; }
  [[nodiscard]] const std::vector<TracedArray>& arrays() const { return arrays_; }
  // Id of the declared array called `name`, or -1 (none yet: a run declares its arrays as it starts).
  [[nodiscard]] int array_id(std::string_view name) const;
  // Contents of every array after the first `count` events (count clamped to the event count).
  [[nodiscard]] std::vector<std::vector<std::int32_t>> state_after(std::size_t count) const;
  // Applies (forward) or undoes (backward) the writes of one event on `state`.
  static void apply(const TraceEvent& e, std::vector<std::vector<std::int32_t>>& state);
  static void undo(const TraceEvent& e, std::vector<std::vector<std::int32_t>>& state);

 private:
  // Appends `e`, first showing the probe the live arrays.
  void record(const TraceEvent& e);

  std::vector<TraceEvent> events_;
  std::vector<TracedArray> arrays_;
  std::vector<std::span<const std::int32_t>> live_;  // the detector's arrays, during its run
  bool keep_tests_ = true;
  Probe probe_;
  Consumer consumer_;
};

// The sink of untraced runs: every call compiles to nothing.
struct NullTrace {
  static constexpr bool enabled = false;
  void reset() {}
  int declare_array(const char*, std::vector<std::int64_t>, std::span<const std::int32_t>) { return -1; }
  void phase(std::uint8_t, const char*, std::int32_t) {}
  void phase(std::uint8_t, const char*, std::int32_t, std::int32_t, std::int32_t, std::int32_t) {}
  void push(std::uint8_t, const char*, int, std::int64_t, int, ElementId, std::int32_t, std::int32_t, std::int32_t,
            std::int32_t, std::int32_t) {}
  void clear(std::uint8_t, const char*, int, std::int64_t, std::int32_t) {}
  void visit_cell(std::uint8_t, ElementId, std::int32_t, std::int32_t, std::int32_t) {}
  void test_pair(std::uint8_t, ElementId, ElementId, bool) {}
  void set(std::uint8_t, const char*, int, std::int64_t, std::int32_t, std::int32_t, ElementId) {}
};

}  // namespace nbscope
