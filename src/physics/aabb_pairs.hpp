// nbscope physics: every pair of overlapping AABBs of one frame, for the ground truth G of the
// cross-check (docs/architecture.md "Invariants"). Independent of every detector under test: its own
// uniform grid over the boxes themselves (not the elements' bounding circles), and Box2D's own
// inclusive test (b2TestOverlap, in float) decides each pair, so the set is exactly
// { (i, j) : i < j, b2TestOverlap(box i, box j) } — what a brute-force loop over all pairs gives.
//
// How: the cell size is the largest box extent among the boxes of about typical size (at most
// twice the mean extent), grown until the grid has O(N) cells. Each box is entered in every cell
// it covers; a pair sharing several cells is tested only in the cell holding the lower corner of
// the two boxes' intersection (the larger of the two lower cell indices on each axis), so it is
// found once. Boxes covering many cells, and boxes with a non-finite coordinate (b2TestOverlap
// calls a NaN box overlapping everything), are tested against every other box instead.
#pragma once
#include <box2d/box2d.h>

#include <cstdint>
#include <vector>

#include "core/pairs.hpp"

namespace nbscope {

class AabbPairFinder {
 public:
  // Every pair i < j of boxes[0..n) that b2TestOverlap calls overlapping (touching counts), sorted
  // by (i, j), into `out` (cleared first). Keeps its buffers between calls.
  void find(const b2AABB* boxes, std::size_t n, PairList& out);

 private:
  struct Range {
    std::int32_t x0, y0, x1, y1;  // cells covered, inclusive
  };
  std::vector<Range> range_;         // per box (unused for the boxes tested against all)
  std::vector<std::uint8_t> wide_;   // per box: tested against every other box, not in the grid
  std::vector<std::int32_t> wide_ids_;
  std::vector<std::int32_t> start_;  // per cell, where its boxes start in items_ (cells + 1 entries)
  std::vector<std::int32_t> items_;  // box ids, cell by cell, ascending within a cell
  std::vector<std::int32_t> range_fill_;  // scratch: next free slot of each cell while filling items_
};

}  // namespace nbscope
