// nbscope core: where in one detection's trace a pair was decided — the operation a debugger shows
// for a check's violation. A pair the detector reported was tested somewhere; a pair it missed was
// either tested and found apart, or its cells met under a contact mask that skipped the other
// element, or the mask that should have reached the other element's cell never visited it, or one
// of the two was pushed onto the list of a cell that is not its own (as is any element whose cell
// the detector integerised wrongly: a `cells` violation names it as the pair (k, k)).
//
// Index: PairFinding (what was found) | locate_pair (the search, O(events)).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "core/trace.hpp"

namespace nbscope {

// How a pair stands in a trace.
enum class PairFinding : std::uint8_t {
  Tested,          // `event` tests the pair (TestPair; `contact` its result)
  CellVisited,     // never tested, but `event` visits the other element's cell under `scanner`'s mask
  CellNotVisited,  // never tested, and `scanner`'s mask never visits the other's cell; `event` is the
                   // last mask visit of `scanner` (where that visit should have been), or its push
  WrongList,       // never tested (or i == j), and `event` pushes `scanner` onto a list keyed to `cell`,
                   // which is not its own cell
  NotNeighbours,   // the two cells are not neighbours: no mask relates them; `event` pushes `first`
  StaleLink,       // (locate_stray) `event` pushes `scanner` onto the list of `cell` while that list
                   // ran on into `other`, an element of another cell: next[scanner] = other
  NotInTrace,      // the trace says nothing about either element
};

// The answer of locate_pair.
struct PairLocation {
  PairFinding finding = PairFinding::NotInTrace;
  std::optional<std::size_t> event;  // index into the trace's events: the operation to show
  bool contact = false;              // Tested: the test's result
  std::int32_t scanner = -1;         // the element whose contact mask reaches the other's cell
  std::int32_t other = -1;           // the element in that cell
  std::array<std::int32_t, 3> cell{-1, -1, -1};  // the cell of `other` (iz = -1 in 2D)
};

// Cells of the two elements of a pair under the detector's grid (iz = -1 in 2D).
struct PairCells {
  std::array<std::int32_t, 3> i{-1, -1, -1};
  std::array<std::int32_t, 3> j{-1, -1, -1};
  // The grid's cell count on each periodic axis (Grid::periodic), 0 on an open one: there cells
  // n-1 and 0 are neighbours, as nbs's wrapped mask visits them.
  std::array<std::int64_t, 3> wrap{0, 0, 0};
};

// Finds the operation that put `stray` on a list the walk of `finder` tested it from (a `cells`
// violation (stray, finder): a list holding an element of another cell). The first test of finder
// against stray; in the same walk the element tested just before it, p; the push of p that linked
// next[p] = stray (StaleLink, `scanner` p, `cell` the list's). With no such p (stray heads the list):
// its push onto that list (WrongList); else, or when the visited cell is `stray_cell` (no stray at
// all), the test itself (Tested).
[[nodiscard]] PairLocation locate_stray(std::span<const TraceEvent> events, std::int32_t stray, std::int32_t finder,
                                        const std::array<std::int32_t, 3>& stray_cell, int dim);

// Finds the operation of `events` (one detection, dimension `dim`) that decided pair (i, j), given
// both elements' cells under the grid. Deterministic: the first test of the pair, else the first
// push of i (then j) onto a list of another cell, else the first visit of the other's cell by the
// scanning element, else its last mask visit. With i == j: the first push of i onto a wrong list.
[[nodiscard]] PairLocation locate_pair(std::span<const TraceEvent> events, std::int32_t i, std::int32_t j,
                                       const PairCells& cells, int dim);

}  // namespace nbscope
