// nbscope core: the book's singly connected lists (a heads array + a next array, -1 for an empty
// list and for the end of a list) and the traced operations every list-based detector performs on
// them, plus the phase labels that readers of a trace (the stepper, `nbscope dump`) look for.
//
// Index: phase labels | ListArrays | push_front (eq. 3.21) | clear_head | test_list.
#pragma once
#include <cstdint>

#include "core/elements.hpp"
#include "core/pairs.hpp"

namespace nbscope {

// Labels of TraceOp::Phase events. A phase's first event is the state when the previous phase is
// complete: e.g. at "contacts" every list of a screen/tree run is built and none is cleared yet.
namespace phase_label {
inline constexpr const char* kMap = "map onto cells";            // screen, sort: integerise, push
inline constexpr const char* kBuildTree = "build tree";           // tree: descend, create nodes, push
inline constexpr const char* kSort = "sort by cell";              // sort
inline constexpr const char* kContacts = "contacts";              // screen, tree, sort: lists complete
inline constexpr const char* kClear = "clear lists";              // screen: heads reset to -1
inline constexpr const char* kYLists = "y-lists";                 // nbs 2D: rows
inline constexpr const char* kZLists = "z-lists";                 // nbs 3D: layers
inline constexpr const char* kYListsOfLayer = "y-lists of layer";  // nbs 3D: rows of layer iz, iz-1
inline constexpr const char* kXListsOfRow = "x-lists of row";      // nbs: cells of the mask's rows
inline constexpr const char* kContactsOfRow = "contacts of row";   // nbs: x-lists of the row complete
inline constexpr const char* kClearXLists = "clear x-lists of row";
inline constexpr const char* kClearYListsOfLayer = "clear y-lists of layer";  // nbs 3D: y-lists complete
inline constexpr const char* kClearYLists = "clear y-lists";  // nbs 2D: y-lists complete
inline constexpr const char* kClearZLists = "clear z-lists";  // nbs 3D: z-lists complete
}  // namespace phase_label

// One family of lists: heads[list] is the first element of a list, next[k] the element after k.
struct ListArrays {
  std::int32_t* heads = nullptr;
  std::int32_t* next = nullptr;
  int heads_id = -1;      // TraceLog array ids (declare_array); -1 when untraced
  int next_id = -1;
  const char* kind = "";  // list kind named in Push/Clear events, e.g. "cell list", "y-list"
};

// Adds element k at the head of list `list` (eq. 3.21: E[k] = HEAD; HEAD = k) and reports it with
// the cell (ix, iy, iz) the list belongs to (-1 for an axis it does not fix).
template <class Trace>
inline void push_front(Trace& trace, std::uint8_t line, const ListArrays& l, std::int64_t list, ElementId k,
                       std::int32_t ix, std::int32_t iy, std::int32_t iz) {
  trace.push(line, l.kind, l.heads_id, list, l.next_id, k, l.heads[list], l.next[k], ix, iy, iz);
  l.next[k] = l.heads[list];
  l.heads[list] = k;
}

// Empties list `list` by resetting its head to -1 (once: a head already -1 is left alone).
template <class Trace>
inline void clear_head(Trace& trace, std::uint8_t line, const ListArrays& l, std::int64_t list) {
  if (l.heads[list] == -1) return;
  trace.clear(line, l.kind, l.heads_id, list, l.heads[list]);
  l.heads[list] = -1;
}

// Checks element k against every element of the list that starts at m (walking `next`), under `touching`.
template <class Trace>
inline void test_list(Trace& trace, std::uint8_t line, const Elements& e, Touching touching, ElementId k,
                      std::int32_t m, const std::int32_t* next, PairCollector& pairs) {
  for (; m != -1; m = next[m]) {
    const bool contact = in_contact(e, k, m, touching);
    trace.test_pair(line, k, m, contact);
    if (contact) pairs.add(k, m);
  }
}

}  // namespace nbscope
