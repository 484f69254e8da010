// nbscope core: the checker behind first_broken_contract (contracts.hpp), shared by its two files:
// contracts.cpp walks the events in order, contracts_end.cpp checks what the frame never did
// (coverage, the mask). Private to those two files.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/contracts.hpp"

namespace nbscope::contract_detail {

using Cell = std::array<std::int32_t, 3>;
inline constexpr std::size_t kNone = static_cast<std::size_t>(-1);

// Offset (-1..1 per axis) as a bit of a 27-bit mask: bit sum (o_a + 1) * 3^a.
inline int offset_bit(const Cell& o, int dim) {
  int bit = 0, scale = 1;
  for (int a = 0; a < dim; ++a, scale *= 3) bit += (o[static_cast<std::size_t>(a)] + 1) * scale;
  return bit;
}
// The sign of an offset's last nonzero axis: -1 for the book's half mask (the cells before k's own, row
// by row and layer by layer), +1 for its mirror, 0 for the own cell.
inline int lean(const Cell& o, int dim) {
  for (int a = dim - 1; a >= 0; --a)
    if (o[static_cast<std::size_t>(a)] != 0) return o[static_cast<std::size_t>(a)] < 0 ? -1 : 1;
  return 0;
}
inline Cell offset_of_bit(int bit, int dim) {
  Cell o{0, 0, 0};
  for (int a = 0; a < dim; ++a, bit /= 3) o[static_cast<std::size_t>(a)] = bit % 3 - 1;
  return o;
}

class ContractChecker {
 public:
  // Each element's cell under the trace's grid, and the pairs it reported.
  // `complete`: the trace holds the whole detection, so what it never did can be checked.
  ContractChecker(const FrameTrace& t, const ContractNames& names, bool complete);
  // The first broken contract: the events in order, then what the frame never did.
  std::optional<BrokenContract> run();

 private:
  // test-once and test-reported, over every test at once.
  void check_tests();
  // --- naming
  std::string id(std::int64_t k) const { return names_.element(k); }
  std::string cell_text(const Cell& c) const {
    const auto index = [&](std::int32_t v) { return std::to_string(names_.book_numbering && v >= 0 ? v + 1 : v); };
    std::string out = "(" + index(c[0]) + "," + index(c[1]);
    if (dim_ == 3) out += "," + index(c[2]);
    return out + ")";
  }
  std::string list_text(const TraceEvent& e, int heads) const {
    const std::vector<TracedArray>& arrays = t_.log.arrays();
    const std::string name = heads >= 0 && static_cast<std::size_t>(heads) < arrays.size() ? arrays[static_cast<std::size_t>(heads)].name : "?";
    return std::string(e.label[0] != '\0' ? e.label : "list") + " " + name + "[" + std::to_string(e.index) + "]";
  }
  static std::int64_t key(std::int32_t i, std::int32_t j) {
    const std::int32_t a = std::min(i, j), b = std::max(i, j);
    return (std::int64_t{a} << 32) | static_cast<std::uint32_t>(b);
  }
  std::int64_t flat(const Cell& c) const { return (std::int64_t{c[0]} * g_.n[1] + c[1]) * g_.n[2] + std::max(c[2], 0); }
  bool in_range(std::int32_t k) const { return k >= 0 && k < n_; }
  std::int64_t row_key(const Cell& c) const { return dim_ == 3 ? std::int64_t{c[2]} * g_.n[1] + c[1] : c[1]; }

  void breaks(Contract c, std::size_t at, std::string text, std::vector<Pair> cost = {}, std::int64_t cost_count = 0);

  // --- the lists, per heads array: the head each list has in this frame, and who is on which build
  struct Model {
    std::size_t level = 0;                   // order of its first push: 0 holds the first-level lists
    std::vector<std::int32_t> head;          // per slot: the head as the frame built it (-1 at the start)
    std::vector<std::int32_t> actual;        // per slot: the head as the detector really left it
    std::vector<std::size_t> last_push;      // per slot: the event of its last push (kNone: none)
    std::vector<std::int64_t> count;         // per slot: pushes onto its current build
    std::vector<std::int64_t> build;         // per slot: bumped by every clear
    std::vector<std::int64_t> member_slot;   // per element: the slot of its last push, -1 none
    std::vector<std::int64_t> member_build;  // and that slot's build then
    std::vector<Cell> member_cell;           // and the cell that push was keyed to
    std::vector<std::size_t> member_at;      // and that push's event
  };
  Model& model(int heads);
  std::int32_t initial_head(int heads, std::int64_t slot) const {
    const std::vector<TracedArray>& arrays = t_.log.arrays();
    if (heads < 0 || static_cast<std::size_t>(heads) >= arrays.size()) return -1;
    const std::vector<std::int32_t>& init = arrays[static_cast<std::size_t>(heads)].initial;
    return slot >= 0 && static_cast<std::size_t>(slot) < init.size() ? init[static_cast<std::size_t>(slot)] : -1;
  }

  void on_phase(std::size_t at, const TraceEvent& e);

  void on_push(std::size_t at, const TraceEvent& e);

  void on_clear(std::size_t at, const TraceEvent& e);

  void on_visit(std::size_t at, const TraceEvent& e);
  // The offset of cell `c` from k's own (periodic wrap folded in); false when it is not next to it.
  bool offset_from(std::int32_t k, const Cell& c, Cell& o) const;
  // The half mask the trace's visits keep, from the book: -1 (the book's), +1 (its mirror) when nearly
  // every visit leans that way, else 0 (a full mask, or none: the offsets are then read off the trace).
  int half_of_visits() const;
  // The mask's offsets as bits: the whole half the visits keep, else every offset visited.
  std::uint32_t mask_bits() const;
  // row-processed, in order: a row phase of a row that holds elements whose segment (up to `at`) did
  // nothing, where that line's segments visit cells elsewhere: its contacts were due at the phase's next operation.
  void close_phase(std::size_t at);

  void on_test(std::size_t at, const TraceEvent& e);

  static std::string number(double v);
  std::string grid_text() const;

  // --- the end of the frame
  // Where a row that was never processed was due: the start of the first processed row after it
  // (2D rows go up; 3D's order is the layer lists', so its first later key), else the last row's start.
  std::size_t row_due(std::int64_t row) const;
  std::size_t row_due_3d(std::int64_t row) const;
  std::string row_text(const Cell& c) const;
  // Contacts of element k with the elements of cell `c` (the cost of a skipped cell).
  void cost_of_cell(std::int32_t k, const Cell& c, std::vector<Pair>& cost, std::int64_t& count) const;

  void end_of_frame();

  void coverage(std::size_t end);
  // heads-cleared: every head the frame set is -1 again when it ends.
  void heads_cleared(std::size_t end);

  void mask(std::size_t end);

  // True when offset `o` leans the way the mask's visited offsets do: on its last nonzero axis, the
  // sign most visited offsets have there.
  bool leans_to(const Cell& o) const;
  std::string offset_text(const Cell& o) const;
  bool neighbour(const Cell& c, const Cell& o, Cell& out) const;

  struct CellPush {
    std::size_t at;
    std::int32_t k;
    bool full;
  };

  bool complete_;
  const FrameTrace& t_;
  const Elements& e_;
  const Grid& g_;
  int dim_;
  std::int64_t n_;
  const ContractNames& names_;
  std::vector<Cell> cells_;
  std::unordered_map<std::int64_t, std::vector<std::int32_t>> members_;  // per occupied cell: its elements
  std::unordered_map<int, Model> models_;
  std::vector<CellPush> cell_pushes_;
  std::vector<std::pair<std::size_t, std::int64_t>> row_starts_;  // (event, row key) where a row's phases begin
  std::vector<std::uint32_t> visits_;     // per element: offsets its mask visited (bits)
  std::vector<std::size_t> last_visit_;   // per element: its last visit's event
  std::vector<std::int32_t> first_level_; // per element: pushes onto first-level lists
  std::vector<bool> on_cell_list_;        // per element: pushed onto a list keyed to all its axes
  std::uint32_t union_ = 0;               // offsets any mask visited
  std::int32_t visitor_ = -1;
  Cell visited_{-1, -1, -1};
  std::vector<std::pair<std::int64_t, std::size_t>> tested_;  // every test's pair key and event, in order
  std::vector<std::int64_t> reported_;                         // the reported pairs' keys, sorted
  // Where the clear of a list that was pushed onto at `pushed` was due: the first phase after it of the
  // pseudocode line that clears heads array `heads` elsewhere in the trace, if one comes before `before`.
  [[nodiscard]] std::optional<std::size_t> clear_due(int heads, std::size_t pushed, std::size_t before) const;
  // Where the clear of a list pushed onto at `pushed` and reused at `at` was due: clear_due's phase (its
  // first operation when that clearing cleared nothing of the array), else the phase before `at`'s own.
  [[nodiscard]] std::size_t clear_was_due(int heads, std::size_t pushed, std::size_t at) const;
  // The walk of a cell the current visit began (not k's own: the whole list is walked there).
  struct Walk {
    std::size_t visit;
    std::int32_t k;
    Cell cell;
    std::int64_t tested;
  };
  struct CellList {
    int heads;
    std::int64_t slot;
  };
  // Ends the current walk at event `at`: list-complete and walk-complete.
  void end_walk(std::size_t at);
  std::optional<Walk> walk_;
  std::unordered_map<std::int64_t, CellList> cell_list_;  // per cell: the list of its last full-keyed push
  std::unordered_map<std::int64_t, std::size_t> last_row_push_;  // per row: the event of its last full-keyed push
  std::unordered_map<int, std::vector<std::uint8_t>> clear_lines_;  // per heads array: the lines of its Clear events
  std::vector<std::size_t> phases_;                            // every Phase event, in order
  int half_ = 0;                                                // half_of_visits(), fixed before the events
  std::vector<std::uint8_t> visit_lines_;                      // lines of the phases whose segments visit cells
  std::unordered_map<std::int64_t, std::int32_t> row_member_;  // per row that holds elements: one of them
  std::size_t open_phase_ = kNone;
  bool builds_cell_lists_ = false;        // the trace builds row lists, so each row builds its cells' lists
  std::vector<std::size_t> cell_listed_at_;  // per element: its last push onto a list keyed to its whole cell
  std::size_t last_cell_push_ = kNone;    // the last such push of any element
  std::size_t rows_checked_at_ = kNone;   // the row start whose neighbour rows' builds were checked
  // list-complete, at a row's first visit: every row its half mask reaches that holds elements was built
  // into cell lists since the row began; due at the phase before the visit, where the build ended.
  void check_rows_built(std::size_t at, const Cell& own);
  // 3D list-complete, at a layer's first row phase (or its next phase, when it has no row): every row of this layer, and every row of the layer
  // its half mask reaches next to one of this layer's rows, had all its elements pushed onto the y-lists
  // since the layer's phase; due after the last push onto that layer's lists (the loop that stopped).
  void check_layer_built(std::size_t at, std::int32_t layer);
  std::vector<std::uint8_t> layer_build_lines_;                // lines of the phases that build a layer's y-lists (3D)
  std::size_t layer_start_ = kNone;                            // the phase of the layer being built (3D)
  bool layer_checked_ = false;                                 // its build was checked at its first row phase
  std::unordered_map<std::int64_t, std::int64_t> layer_row_pushes_;  // per row key: y-list pushes since layer_start_
  std::unordered_map<std::int32_t, std::size_t> layer_last_push_;   // per layer: its last y-list push since layer_start_
  std::unordered_map<std::int64_t, std::int64_t> row_count_;         // per row key: elements it holds
  std::unordered_map<std::int32_t, std::vector<std::int32_t>> layer_rows_;  // per layer: its rows that hold elements
  // list-complete, at a row's second phase (its build done): every element of the row itself went onto a cell list.
  void check_own_row_built(std::size_t at);
  std::int64_t own_row_pushes_ = 0;          // pushes of the row's own elements onto cell lists since its start
  std::size_t own_row_last_push_ = kNone;    // and the last of them
  std::size_t own_row_checked_at_ = kNone;   // the row start whose own row was checked
  // True when row key `row` is `building` itself or a row its half mask reaches.
  bool row_reaches(std::int64_t building, std::int64_t row) const;
  std::unordered_map<std::size_t, Cell> phase_cells_;          // 3D: per phase, the row (-1,iy,iz) or layer (-1,-1,iz) it works on
  // 3D plugins' phases name only an index: infers each phase's row or layer (phase_cells_).
  void infer_phase_cells();
  Cell phase_cell(std::size_t at) const {
    const auto found = phase_cells_.find(at);
    if (found != phase_cells_.end()) return found->second;
    const TraceEvent& e = t_.log.events()[at];
    return Cell{e.cell[0], e.cell[1], e.cell[2]};
  }
  // True when the phase at `at` itself says its work is at `value` on axis a (its cell, or its index:
  // a row's on y, a layer's on z), not only a cell inferred from the operations after it.
  bool phase_names(std::size_t at, int a, std::int32_t value) const {
    const TraceEvent& e = t_.log.events()[at];
    if (e.cell[0] >= 0 || e.cell[1] >= 0 || e.cell[2] >= 0) return e.cell[a] == value;
    const Cell c = phase_cell(at);
    return e.index == value && a == (c[1] >= 0 || dim_ == 2 ? 1 : 2);
  }
  Pair subject_{-1, -1};  // the elements the event being checked names (BrokenContract::subject)
  std::optional<BrokenContract> first_;
};

}  // namespace nbscope::contract_detail
