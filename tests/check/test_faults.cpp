// Fault injection (check/faults.hpp): the names round-trip, and each output fault leaves exactly the
// pairs a detector with that bug would return: on hand-placed cells (pairs worked out here), and on
// random elements, where every pair the fault drops and every pair it keeps is held to the bug's own
// description. The faults through the pipeline's lanes are in test_pipeline.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "check/faults.hpp"
#include "core/cells.hpp"
#include "core/error.hpp"
#include "support/check_context.hpp"

namespace nbscope {
namespace {

// Every fault's name parses back to it; an unknown name is an Error; the list names them all.
TEST(Faults, NamesRoundTrip) {
  for (Fault f : {Fault::None, Fault::DropMaskCell, Fault::OffByOneCell, Fault::StalePositions, Fault::DropPair,
                  Fault::DropBox2dContact}) {
    EXPECT_EQ(parse_fault(fault_name(f)), f);
    if (f != Fault::None) {
      EXPECT_NE(fault_names().find(fault_name(f)), std::string::npos) << fault_name(f);
      EXPECT_STRNE(fault_description(f), "") << fault_name(f);
    }
  }
  EXPECT_THROW(parse_fault("drop-everything"), Error);
}

// Four elements in cells (1,1), (0,0), (2,2), (2,1) of a 4x4 grid, and four pairs among them.
struct FaultCase {
  Grid grid;
  std::vector<CellIndex> cells{{1, 1}, {0, 0}, {2, 2}, {2, 1}};
  PairList pairs{{0, 1}, {0, 2}, {0, 3}, {1, 2}};
  FaultCase() {
    grid.n[0] = 4;
    grid.n[1] = 4;
  }
};

// (0,1): element 1 is down-left of 0; (0,2): element 2 is up-right of 0. Both are that mask cell.
TEST(Faults, DropMaskCellRemovesTheDiagonalNeighbours) {
  FaultCase c;
  apply_output_fault(Fault::DropMaskCell, c.grid, c.cells, c.pairs);
  EXPECT_EQ(c.pairs, (PairList{{0, 3}, {1, 2}}));
}

// Columns 2 and 3 move right by one; only (0,1), both left of the seam, stays neighbours.
TEST(Faults, OffByOneCellShiftsTheRightHalfAndLosesPairsAcrossTheSeam) {
  FaultCase c;
  apply_output_fault(Fault::OffByOneCell, c.grid, c.cells, c.pairs);
  EXPECT_EQ(c.cells, (std::vector<CellIndex>{{1, 1}, {0, 0}, {3, 2}, {3, 1}}));
  EXPECT_EQ(c.pairs, (PairList{{0, 1}}));
}

// Of four pairs, index 4/2 = 2, (0,3), goes; of none, nothing.
TEST(Faults, DropPairRemovesTheMiddlePair) {
  FaultCase c;
  apply_output_fault(Fault::DropPair, c.grid, c.cells, c.pairs);
  EXPECT_EQ(c.pairs, (PairList{{0, 1}, {0, 2}, {1, 2}}));
  PairList none;
  apply_output_fault(Fault::DropPair, c.grid, c.cells, none);
  EXPECT_TRUE(none.empty());
}

// stale-positions and drop-box2d-contact act before detection or on Box2D's side: the output stays.
TEST(Faults, InputFaultsLeaveTheOutputAlone) {
  for (Fault f : {Fault::None, Fault::StalePositions, Fault::DropBox2dContact}) {
    FaultCase c;
    apply_output_fault(f, c.grid, c.cells, c.pairs);
    EXPECT_EQ(c.pairs.size(), 4u) << fault_name(f);
    EXPECT_EQ(c.cells, FaultCase().cells) << fault_name(f);
  }
}

// In 3D the missing mask cell is of the same layer: a diagonal neighbour one layer up stays.
TEST(Faults, DropMaskCellIn3dDropsOnlyTheSameLayersDiagonal) {
  Grid grid;
  grid.n[0] = grid.n[1] = grid.n[2] = 4;
  std::vector<CellIndex> cells{{1, 1, 1}, {0, 0, 1}, {0, 0, 2}, {2, 2, 1}};
  PairList pairs{{0, 1}, {0, 2}, {0, 3}};
  apply_output_fault(Fault::DropMaskCell, grid, cells, pairs);
  EXPECT_EQ(pairs, (PairList{{0, 2}}));
}

// Dense random circles (many pairs, some across every cell border), the grid's cells and brute
// force's pairs: the input of a faulty detector's output.
struct RandomFrame {
  Elements e = make_layout(Layout::Dense, 600, 2, 31);
  Grid grid = make_grid(e, GridOptions{});
  std::vector<CellIndex> cells;
  PairList pairs = testcheck::touching_pairs(e);
  RandomFrame() { integerise_cells(e, grid, cells); }
};

bool neighbours(const CellIndex& a, const CellIndex& b) { return std::abs(a.ix - b.ix) <= 1 && std::abs(a.iy - b.iy) <= 1; }

// On random elements: a pair goes exactly when one is the other's (ix-1, iy-1) neighbour.
TEST(Faults, DropMaskCellOnRandomElementsDropsExactlyTheDiagonalPairs) {
  RandomFrame f;
  const std::vector<CellIndex> cells = f.cells;
  PairList kept = f.pairs;
  apply_output_fault(Fault::DropMaskCell, f.grid, f.cells, kept);
  EXPECT_EQ(f.cells, cells) << "the cells stay the grid's";
  std::size_t dropped = 0;
  for (const Pair& p : f.pairs) {
    const CellIndex& a = cells[static_cast<std::size_t>(p.i)];
    const CellIndex& b = cells[static_cast<std::size_t>(p.j)];
    const bool diagonal = (b.ix - a.ix == 1 && b.iy - a.iy == 1) || (a.ix - b.ix == 1 && a.iy - b.iy == 1);
    EXPECT_EQ(std::binary_search(kept.begin(), kept.end(), p), !diagonal) << p.i << "," << p.j;
    dropped += diagonal ? 1 : 0;
  }
  EXPECT_GT(dropped, 0u) << "the frame must hold a pair to lose";
  EXPECT_EQ(kept.size() + dropped, f.pairs.size());
}

// On random elements: cells from the middle column on move right; the pairs lost are those across the seam.
TEST(Faults, OffByOneCellOnRandomElementsLosesOnlyPairsAcrossTheSeam) {
  RandomFrame f;
  const std::vector<CellIndex> cells = f.cells;
  PairList kept = f.pairs;
  apply_output_fault(Fault::OffByOneCell, f.grid, f.cells, kept);
  const std::int32_t middle = static_cast<std::int32_t>(f.grid.n[0] / 2);
  for (std::size_t k = 0; k < cells.size(); ++k)
    EXPECT_EQ(f.cells[k].ix, cells[k].ix + (cells[k].ix >= middle ? 1 : 0)) << "element " << k;
  std::size_t lost = 0;
  for (const Pair& p : f.pairs) {
    const CellIndex& a = cells[static_cast<std::size_t>(p.i)];
    const CellIndex& b = cells[static_cast<std::size_t>(p.j)];
    const bool across = (a.ix < middle) != (b.ix < middle) && std::abs(a.ix - b.ix) == 1;
    EXPECT_EQ(std::binary_search(kept.begin(), kept.end(), p), !across) << p.i << "," << p.j;
    lost += across ? 1 : 0;
  }
  EXPECT_GT(lost, 0u) << "the frame must hold a pair across the seam";
  for (const Pair& p : kept) EXPECT_TRUE(neighbours(f.cells[static_cast<std::size_t>(p.i)], f.cells[static_cast<std::size_t>(p.j)]));
}

}  // namespace
}  // namespace nbscope
