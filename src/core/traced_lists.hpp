// nbscope core: the singly connected lists of one traced detection, rebuilt from its events for
// the overlays, the panels and verify (the list model). A detector clears its heads before it
// returns, so the final arrays hold no lists: each list is captured from the replayed arrays just
// before its head is cleared (or at the end of the run if it never is). A list rebuilt several
// times (NBS: the x-lists of every row) gives one TracedList per build. Sort, which has no lists,
// gives its runs of equal cell keys instead.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/elements.hpp"
#include "core/trace.hpp"

namespace nbscope {

// One list as the detector built it.
struct TracedList {
  std::string kind;              // the events' list kind ("y-list", "x-list", "cell list", "run", ...)
  std::string heads_name;        // the heads array ("y_heads", "B", "C", ...; "order" for sort runs)
  std::string next_name;         // the next array it links through ("Y", "X", "E", ...)
  int heads_array = -1;          // index into TraceLog::arrays()
  std::int64_t slot = -1;        // flat index of the head in that array
  std::vector<std::int64_t> heads_shape;  // that array's shape, to name the head as the book does (B[1][8])
  std::int32_t phase_index = -1; // index of the phase it was built in (NBS: row iy of the x-lists)
  std::int32_t phase_layer = -1; // the layer iz that phase works on (NBS 3D: the layer whose rows are processed; -1: none)
  std::int32_t cell[3] = {-1, -1, -1};  // the cell of its pushes (-1 for an axis the list does not fix)
  bool secondary = false;        // a copy built for a neighbour row (NBS B[1]: x-lists of row iy-1)
  std::vector<ElementId> chain;  // head first, in the order of the next array
  bool cut = false;              // the walk stopped after N elements (the next array had a cycle)
  std::string head_label;        // drawn beside the head when given, as the book names it ("C[5][7]"; verify's lists)
};

// True when slot `slot` of heads array `heads` holds a copy of the row below: NBS's B[2][nx] keeps
// them in its second half (screen's C[nx][ny] has that shape when nx == 2, hence the name).
[[nodiscard]] bool is_row_below(const TracedArray& heads, std::int64_t slot);

// Every list of the traced run in `log` over `element_count` elements, ordered by heads array,
// build phase and slot, as they stand after the first `upto` events (the stepper's position): the
// lists whose head was cleared before then as they were when cleared, the others from the arrays at
// that moment (sort: its runs once its permutation is complete). Past the last event: the finished
// lists.
std::vector<TracedList> traced_lists(const TraceLog& log, std::size_t element_count, std::size_t upto = SIZE_MAX);

}  // namespace nbscope
