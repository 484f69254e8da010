// check/cell_changes: which element changed cell at which step, as the frame loop publishes frames.
#include "check/cell_changes.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace nbscope {
namespace {

std::vector<CellIndex> cells(std::initializer_list<int> ix) {
  std::vector<CellIndex> out;
  for (int x : ix) out.push_back(CellIndex{x, 0, 0});
  return out;
}

CellChanges::Ids ids(std::vector<std::int64_t> v) { return std::make_shared<const std::vector<std::int64_t>>(std::move(v)); }

TEST(CellChanges, AStepMarksTheElementsWhoseCellChangedAndTheirFlashFadesEachStep) {
  CellChanges c;
  c.start(0, cells({0, 1, 2}), nullptr);
  EXPECT_EQ(c.changed_at(0), CellChanges::kNever);
  c.show(1, cells({0, 2, 2}), nullptr, true);
  EXPECT_EQ(c.steps(), 1u);
  EXPECT_EQ(c.changed_at(1), 1u);
  EXPECT_EQ(c.changed_at(0), CellChanges::kNever);
  EXPECT_FLOAT_EQ(c.flash(1, 0.8f), 1.0f);
  c.show(2, cells({0, 2, 2}), nullptr, true);
  c.show(3, cells({0, 2, 2}), nullptr, true);
  EXPECT_FLOAT_EQ(c.flash(1, 0.8f), 0.8f * 0.8f) << "1, then times the decay each step";
  EXPECT_FLOAT_EQ(c.flash(0, 0.8f), 0.0f);
  EXPECT_FLOAT_EQ(c.flash(7, 0.8f), 0.0f) << "no such row";
}

TEST(CellChanges, ANeighbourShownStepsAJumpStartsAgain) {
  CellChanges c;
  c.start(10, cells({0, 1}), nullptr);
  c.show(9, cells({1, 1}), nullptr, false);  // one frame back: a neighbour
  EXPECT_EQ(c.changed_at(0), 1u);
  c.show(3, cells({5, 5}), nullptr, false);  // a jump: nothing known changed
  EXPECT_EQ(c.steps(), 0u);
  EXPECT_EQ(c.changed_at(0), CellChanges::kNever);
  EXPECT_EQ(c.changed_at(1), CellChanges::kNever);
  c.show(20, cells({5, 6}), nullptr, true);  // forwards through kept frames: a step whatever the gap
  EXPECT_EQ(c.changed_at(1), 1u);
}

TEST(CellChanges, RowsFollowTheirAtomsAcrossADumpsFrames) {
  CellChanges c;
  c.start(0, cells({0, 1, 2}), ids({10, 20, 30}));
  c.show(1, cells({0, 1, 2}), ids({10, 20, 30}), true);
  c.show(2, cells({0, 9, 2}), ids({10, 20, 30}), true);  // atom 20 changed cell at step 2
  // Atom 10 is gone and atom 5 comes in first: atom 20 is now row 1 still, atom 30 row 2.
  c.show(3, cells({4, 9, 2}), ids({5, 20, 30}), true);
  EXPECT_EQ(c.changed_at(0), CellChanges::kNever) << "an inserted atom has no change";
  EXPECT_EQ(c.changed_at(1), 2u) << "atom 20 keeps its change";
  EXPECT_EQ(c.changed_at(2), CellChanges::kNever);
  // Rows shift: atom 20 moves to row 0 and changes cell again; atom 30 to row 1, unchanged.
  c.show(4, cells({8, 2}), ids({20, 30}), true);
  EXPECT_EQ(c.changed_at(0), 4u);
  EXPECT_EQ(c.changed_at(1), CellChanges::kNever) << "atom 30 compared with its own cell, not row 1's";
}

TEST(RowOfAtom, FindsTheAtomsNewRowOrNone) {
  const std::vector<std::int64_t> before{3, 5, 7}, after{1, 5, 7, 9};
  EXPECT_EQ(row_of_atom(before, after, 1), 1);
  EXPECT_EQ(row_of_atom(before, after, 2), 2);
  EXPECT_EQ(row_of_atom(before, after, 0), -1) << "atom 3 is gone";
  EXPECT_EQ(row_of_atom(before, after, -1), -1);
  EXPECT_EQ(row_of_atom(before, after, 3), -1);
}

}  // namespace
}  // namespace nbscope
