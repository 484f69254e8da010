// nbscope ui: what the Stepper, Arrays and Pseudocode panels share — the traced detection of one
// paused frame (the frame loop's own trace, shared through the SimView), the core Stepper over it,
// the user's breakpoint and element filter, and the book-style wording of events and array entries.
// No ImGui in here, so it is unit-tested without a GL context.
//
// Index: StepperConfig | StepperSession (capture, per-frame update, shared view settings) |
// describe_event / entry_name / window_range (text and layout helpers).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/elements.hpp"
#include "core/frame_trace.hpp"
#include "core/grid.hpp"
#include "core/locate.hpp"
#include "core/stepper.hpp"
#include "ui/model.hpp"

namespace nbscope::ui {

// How the stepper starts (headless `--step K`, or the window's defaults).
struct StepperConfig {
  std::optional<std::size_t> step;  // show the state after this many events of the captured frame
  bool book_numbering = false;      // show indices and element numbers 1-based, as the book prints them
};

// One captured detection and the view settings of the stepper panels.
class StepperSession {
 public:
  explicit StepperSession(StepperConfig config = {});

  // Once per UI frame `ui_frame` (every stepper panel calls it; repeats are ignored): takes the
  // frame loop's trace in `sim` when the stepper wants one (wants_trace) and it is not the one held,
  // then advances playback by `dt_seconds`.
  void update(const SimView& sim, double dt_seconds, int ui_frame);
  // True when the stepper would take frame `frame`'s trace: paused, a configured step (headless
  // --step K), or a violation's pair to find on that frame. The app makes the trace only then (or
  // for the lists overlay), so a running simulation does not pay for tracing every frame.
  [[nodiscard]] bool wants_trace(std::int64_t frame, bool paused) const;
  // Takes the traced detection in `sim` (its SimView::trace) now, also while running.
  void capture(const SimView& sim);
  // True when a detection is held and it is the frame `sim` shows (the scene overlay is valid).
  [[nodiscard]] bool current_for(const SimView& sim) const;
  // current_for() as of the last update() (for scene drawing done before the panels fill the view).
  [[nodiscard]] bool was_current() const { return was_current_; }
  // True when a detection is held (current or not).
  [[nodiscard]] bool has_capture() const { return captured_; }
  // Why nothing can be stepped through ("" when a detection is held).
  [[nodiscard]] const std::string& message() const { return message_; }

  // The cursor over the held detection, and the elements it was run on (a copy of that frame's).
  [[nodiscard]] Stepper& stepper() { return stepper_; }
  [[nodiscard]] const Stepper& stepper() const { return stepper_; }
  [[nodiscard]] const Elements& elements() const { return trace_ ? trace_->elements : kNoElements; }
  // The captured detector's grid; nullptr for a detector without one.
  [[nodiscard]] const Grid* grid() const { return trace_ && trace_->detector_grid ? &trace_->grid : nullptr; }
  // The held trace (shared with the lists overlay), or null.
  [[nodiscard]] const std::shared_ptr<const FrameTrace>& frame_trace() const { return trace_; }
  // The algorithm and frame number of the held detection.
  [[nodiscard]] const std::string& algorithm() const { return algorithm_; }
  [[nodiscard]] std::int64_t frame() const { return frame_; }
  // The detector's pseudocode lines (TraceEvent::line indexes them).
  [[nodiscard]] const std::vector<const char*>& pseudocode() const { return trace_ ? trace_->pseudocode : kNoLines; }
  // The list that holds cell `cell`'s elements at the current position: the target of the latest
  // push onto that cell so far (NBS: B[1] of the row below during row iy), or nullopt.
  struct ListRef {
    int heads = -1;
    std::int64_t list = -1;
    const char* kind = "";
  };
  [[nodiscard]] std::optional<ListRef> list_of_cell(const std::int32_t cell[3]) const;
  // Every pair tested with element k, in event order: (event index, the other element, contact).
  struct TestedPair {
    std::size_t event = 0;
    std::int32_t other = -1;
    bool contact = false;
  };
  [[nodiscard]] const std::vector<TestedPair>& tests_of(std::int32_t k);
  // False for an entry the detection has not written yet at the current position, in an array whose
  // initial contents mean nothing (a next array, sort's keys): the panels show it as unset. List
  // heads always count as set: their initial -1 is the book's empty list.
  [[nodiscard]] bool is_set(int array, std::int64_t index) const { return is_set_after(array, index, stepper_.position()); }
  // is_set() after the first `position` events.
  [[nodiscard]] bool is_set_after(int array, std::int64_t index, std::size_t position) const;
  // True for arrays whose values are element ids (list heads and next arrays), shifted by one in
  // book numbering like the indices.
  [[nodiscard]] bool holds_elements(int array) const;
  // Element `k` of the held frame as the step texts name it: a dump's atom by its id with the row
  // beside it where they differ ("923 (row 922)"), else its row (shifted in book numbering).
  [[nodiscard]] std::string element_text(std::int64_t k) const;

  // ---- a violation's pair to find (the Violations panel, headless --stop-at-violation) ----
  // What the stepper is asked to find: pair (i, j) of frame `frame` and the check that flagged it.
  struct PairTarget {
    std::int64_t frame = -1;
    Pair pair;
    Invariant invariant = Invariant::AEqualsR;
    const char* what = "";
  };
  // Once the stepper holds `target.frame` (captured even while running), it moves to the operation
  // that decided the pair (core/locate.hpp) and target_status() says which, and why it matters.
  void set_target(const PairTarget& target);
  // True while a target waits for its frame.
  [[nodiscard]] bool target_pending() const { return target_.has_value(); }
  // Where the last target was found, in words ("" before any).
  [[nodiscard]] const std::string& target_status() const { return target_status_; }
  // The location found for the last target (nullopt before any, or when nothing was recorded).
  [[nodiscard]] const std::optional<PairLocation>& target_location() const { return target_location_; }

  // ---- long traces ----
  // The next (direction +1) or previous (-1) operation touching element k (BreakKind::Element) or
  // cell (ix, iy) (BreakKind::Cell; of layer `layer` in 3D, -1 in 2D), moved to; false (unmoved)
  // when there is none. Sets status.
  bool seek_touching(BreakKind kind, std::int32_t element, const std::array<std::int32_t, 2>& cell, int direction,
                     std::int32_t layer = -1);
  // The world point of the current operation: its element's centre, else its cell's centre; nullopt
  // at position 0 or without one.
  [[nodiscard]] std::optional<Eigen::Vector2d> focus_point() const;

  // ---- 3D ----
  // The layer iz the current operation works on, for the view to show: the phase's layer (NBS 3D:
  // the layer whose rows are processed), else the nearest earlier operation's of this phase with a
  // cell in 3D (the z-list pushes, screen's and tree's cells). nullopt in 2D, with nothing held or
  // before the first such operation.
  [[nodiscard]] std::optional<std::int32_t> current_layer() const { return current_axis(2); }
  // The row iy the current operation works on (the phase's row, else as current_layer()); nullopt
  // in 2D or when no operation so far fixes one.
  [[nodiscard]] std::optional<std::int32_t> current_row() const { return current_axis(1); }

  // View settings shared by the panels.
  bool book_numbering = false;
  std::int32_t focus_element = -1;  // the Arrays panel's element filter (-1: none)
  Breakpoint breakpoint;            // the Stepper panel's breakpoint fields
  bool break_while_playing = true;  // playback stops at the breakpoint
  std::string status;               // the last action's outcome ("no later event for element 7")

 private:
  struct Key {
    std::string scene, algorithm;
    std::int64_t frame = -1, bodies = -1;
    friend bool operator==(const Key&, const Key&) = default;
  };
  static Key key_of(const SimView& sim);

  std::optional<std::size_t> pending_step_;
  bool captured_ = false;
  Key key_;
  std::string message_;
  bool has_trace_grid() const { return trace_ != nullptr; }
  inline static const Elements kNoElements{};
  inline static const std::vector<const char*> kNoLines{};

  Stepper stepper_;
  std::shared_ptr<const FrameTrace> trace_;  // the frame loop's, shared
  std::uint64_t held_serial_ = 0;            // the trace last taken (held or refused)
  bool capture_requested_ = false;           // capture() asked while no trace was made: take the next
  std::string algorithm_;
  std::int64_t frame_ = -1;
  std::vector<std::int64_t> ids_;  // the held frame's atom ids (a dump's), else empty
  std::vector<bool> element_valued_;
  std::vector<std::vector<std::uint32_t>> first_write_;  // per array and entry: first writing event (+1), 0 = never
  std::vector<std::pair<std::uint64_t, std::size_t>> cell_pushes_;  // (cell key, event), sorted
  std::int32_t tests_of_element_ = -1;
  std::vector<TestedPair> tests_;
  void apply_target(const SimView& sim);
  std::optional<std::int32_t> current_axis(int axis) const;
  std::optional<PairTarget> target_;
  std::string target_status_;
  std::optional<PairLocation> target_location_;
  int last_frame_count_ = -1;
  bool was_current_ = false;
};

// True when index `dim` of `array` picks one of a few parallel arrays rather than a cell or an element
// (NBS's B[0]/B[1] and A[0..4], the tree's child[m][0/1]): the book numbers those from 0 too.
[[nodiscard]] bool index_is_selector(const TracedArray& array, std::size_t dim);
// True when `array` is indexed by cells [ix][iy] (or [ix][iy][iz]) of `grid` (screen's C): the Arrays
// panel draws it as the scene shows the cells, ix across and iy upwards.
[[nodiscard]] bool is_cell_matrix(const TracedArray& array, const Grid* grid);
// "C[4][6]" for flat index `flat` of `array` (indices in the chosen numbering).
[[nodiscard]] std::string entry_name(const TracedArray& array, std::int64_t flat, bool book);
// What the Arrays panel's element section says about element k's entries at the current position,
// in the session's numbering, "·" for an entry the detection has not written yet: `next`, what each
// next array says after k ("Y[4] = 3,  X[4] = ·"); `own`, its entries of arrays indexed by element
// (sort's "ix[12] = 3,  iy[12] = 5"); `position`, where a permutation of element ids holds it (sort's
// "order[7] = 12", or "not in order yet").
struct ElementEntries {
  std::string next, own, position;
};
[[nodiscard]] ElementEntries element_entries(const StepperSession& session, std::int32_t k);
// One line saying what event `e` of the session's trace does, in the book's words and the session's
// numbering, e.g. "push k=3 onto cell list C[4][6]: E[3] = -1, C[4][6] = 3".
[[nodiscard]] std::string describe_event(const StepperSession& session, const TraceEvent& e);
// A value of `array` as shown: element ids shifted in book numbering, anything else as stored.
[[nodiscard]] std::int64_t shown_value(const StepperSession& session, int array, std::int32_t value);
// Every array of the session's trace with its shape as the book writes it, "C[nz=5]  Z[N=120]
// B[2][ny=6]  Y[N=120]  A[5][nx=6]  X[N=120]" for NBS 3D (p.123): an extent of N elements is "N",
// a cell axis is named (nx, ny, nz), a selector (B's 2, A's 5) is its number.
[[nodiscard]] std::string array_shapes_text(const StepperSession& session);
// The Stepper's name of phase `phase` (an index into Stepper::phases()): "x-lists of row 4", with
// the layer of a row of a 3D pass ("x-lists of row 4, layer 2"), in the session's numbering.
[[nodiscard]] std::string phase_text(const StepperSession& session, std::size_t phase);
// What a stepper panel says while nothing is held: why (the trace's refusal), or how to record.
[[nodiscard]] std::string idle_message(const StepperSession& session);
// The window [begin, end) of at most `width` entries of an array of `length` that keeps `focus`
// (clamped into the array) in view, centred where possible.
[[nodiscard]] std::pair<std::int64_t, std::int64_t> window_range(std::int64_t length, std::int64_t focus,
                                                                 std::int64_t width);

}  // namespace nbscope::ui
