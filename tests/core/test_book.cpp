// The book's worked examples (Munjiza, ch. 3; pages in ../shared/seeds/) as tests. Expected values
// are typed from the figures (1-based there, shifted to 0-based here), never taken from the code.
//
// Index: Figs 3.13-3.14 (one push, eq. 3.21) | Figs 3.15/3.20 (the nine elements through screen,
// tree and nbs) | eq. 3.54 (sort's memory).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "core/lists.hpp"
#include "core/nbs.hpp"
#include "core/screen.hpp"
#include "core/sort.hpp"
#include "core/tree.hpp"
#include "io/csv.hpp"
#include "support/paths.hpp"

namespace nbscope {
namespace {

// Book numbers (1-based, -1 kept) to 0-based ids.
std::vector<std::int32_t> zero_based(std::vector<std::int32_t> book) {
  for (std::int32_t& v : book)
    if (v != -1) v -= 1;
  return book;
}

std::vector<std::int32_t> walk(std::int32_t head, const std::vector<std::int32_t>& next) {
  std::vector<std::int32_t> out;
  for (std::int32_t k = head; k != -1 && out.size() <= next.size(); k = next[k]) out.push_back(k);
  return out;
}

std::size_t phase_at(const TraceLog& log, const char* label) {
  for (std::size_t i = 0; i < log.events().size(); ++i)
    if (log.events()[i].op == TraceOp::Phase && std::strcmp(log.events()[i].label, label) == 0) return i;
  return log.events().size();
}

// Fig. 3.13: a list 9 -> 7 -> 5 -> 3 held by HEAD and the integer array E (N = 12 drawn).
// Eq. 3.21 adds element 1: E[1] = HEAD (i.e. 9); HEAD = 1. Fig. 3.14 shows the result.
TEST(Book, Fig3_13To3_14PushingElementOneOntoTheList) {
  const std::vector<std::int32_t> fig_3_13 = zero_based({-1, -1, -1, -1, 3, -1, 5, -1, 7, -1, -1, -1});
  const std::vector<std::int32_t> fig_3_14 = zero_based({9, -1, -1, -1, 3, -1, 5, -1, 7, -1, -1, -1});
  std::vector<std::int32_t> head = {9 - 1};
  std::vector<std::int32_t> e = fig_3_13;
  ASSERT_EQ(walk(head[0], e), zero_based({9, 7, 5, 3}));

  TraceLog log;
  ListArrays list{head.data(), e.data(), log.declare_array("HEAD", {1}, head), log.declare_array("E", {12}, e), "leaf list"};
  push_front(log, 0, list, 0, 1 - 1, -1, -1, -1);
  EXPECT_EQ(e, fig_3_14);
  EXPECT_EQ(head[0], 1 - 1);
  EXPECT_EQ(walk(head[0], e), zero_based({1, 9, 7, 5, 3}));

  // The trace event says the same, and undoing it gives Fig. 3.13 back.
  ASSERT_EQ(log.events().size(), 1u);
  const TraceEvent& ev = log.events()[0];
  EXPECT_EQ(ev.op, TraceOp::Push);
  EXPECT_EQ(ev.element, 0);
  auto state = log.state_after(1);
  EXPECT_EQ(state[1], fig_3_14);
  EXPECT_EQ(state[0][0], 0);
  TraceLog::undo(ev, state);
  EXPECT_EQ(state[1], fig_3_13);
  EXPECT_EQ(state[0][0], 9 - 1);
}


// The book's grid of Fig. 3.15: cells of size 1 from (0, 0), 10 x 10 of them.
DetectOptions book_grid() {
  DetectOptions o;
  o.grid.cell_size = 1.0;
  o.grid.origin = std::array<double, 3>{0, 0, 0};
  o.grid.cells = std::array<std::int64_t, 3>{10, 10, 1};
  return o;
}

// Fig. 3.15: the cell (1-based) of each of the nine elements, read off the figure.
TEST(Book, Fig3_15TheNineElementsLieInTheBooksCells) {
  const Elements e = read_elements_csv(testpaths::nine_csv());
  ASSERT_EQ(e.size(), 9);
  NbsDetector nbs;
  PairList p;
  nbs.detect(e, book_grid(), p);
  const Grid& g = *nbs.last_grid();
  const int book_cell[9][2] = {{5, 7}, {5, 7}, {2, 7}, {5, 7}, {2, 7}, {5, 6}, {2, 7}, {6, 6}, {2, 7}};
  for (ElementId k = 0; k < 9; ++k) {
    EXPECT_EQ(g.cell(e.x[k], 0) + 1, book_cell[k][0]) << "element " << k + 1;
    EXPECT_EQ(g.cell(e.y[k], 1) + 1, book_cell[k][1]) << "element " << k + 1;
  }
}

// Fig. 3.20 and eq. 3.31: C[5][7] = 4, C[5][6] = 6, C[6][6] = 8, C[2][7] = 9 and
// E = -1 1 -1 2 3 -1 5 -1 7 (1-based); 96 of the 100 cells empty.
TEST(Book, Fig3_20ScreenArrayAndNextArrayOfTheNineElements) {
  const Elements e = read_elements_csv(testpaths::nine_csv());
  ScreenDetector screen;
  PairList p;
  TraceLog log;
  screen.detect_traced(e, book_grid(), p, log);
  const Grid& g = *screen.last_grid();
  ASSERT_EQ(g.n[0], 10);
  ASSERT_EQ(g.n[1], 10);
  ASSERT_EQ(log.arrays()[0].name, "C");
  ASSERT_EQ(log.arrays()[0].shape, (std::vector<std::int64_t>{10, 10}));
  const auto state = log.state_after(phase_at(log, phase_label::kContacts));  // every list built
  const std::vector<std::int32_t>& c = state[0];
  const std::vector<std::int32_t>& next = state[1];
  auto C = [&](int ix_book, int iy_book) { return c[static_cast<std::size_t>((ix_book - 1) * 10 + (iy_book - 1))]; };
  EXPECT_EQ(C(5, 7), 4 - 1);
  EXPECT_EQ(C(5, 6), 6 - 1);
  EXPECT_EQ(C(6, 6), 8 - 1);
  EXPECT_EQ(C(2, 7), 9 - 1);
  EXPECT_EQ(std::count(c.begin(), c.end(), -1), 96);
  EXPECT_EQ(next, zero_based({-1, 1, -1, 2, 3, -1, 5, -1, 7}));
  // The four lists of Fig. 3.20: {4,2,1}, {6}, {8}, {9,7,5,3}.
  EXPECT_EQ(walk(C(5, 7), next), zero_based({4, 2, 1}));
  EXPECT_EQ(walk(C(5, 6), next), zero_based({6}));
  EXPECT_EQ(walk(C(6, 6), next), zero_based({8}));
  EXPECT_EQ(walk(C(2, 7), next), zero_based({9, 7, 5, 3}));
  // Memory: one head per cell and one next per element.
  EXPECT_EQ(screen.own_bytes(), (100u + 9u) * sizeof(std::int32_t));
  // Only elements 1 and 2 (0-based 0 and 1) touch.
  sort_pairs(p);
  EXPECT_EQ(p, (PairList{{0, 1}}));
}

// The binary tree of the same nine elements: its leaves are the four occupied cells, and the leaf
// of cell (2,7) holds the list 9 -> 7 -> 5 -> 3 of Fig. 3.12.
TEST(Book, Fig3_12TheTreesLeavesHoldTheSameLists) {
  const Elements e = read_elements_csv(testpaths::nine_csv());
  TreeDetector tree;
  PairList p;
  TraceLog log;
  tree.detect_traced(e, book_grid(), p, log);
  const auto state = log.state_after(phase_at(log, phase_label::kContacts));
  const std::vector<TreeLeaf> leaves = tree_leaves(*tree.last_grid(), state[0], state[1]);
  ASSERT_EQ(leaves.size(), 4u);
  EXPECT_EQ(state[2], zero_based({-1, 1, -1, 2, 3, -1, 5, -1, 7}));  // E, as Fig. 3.20's
  for (const TreeLeaf& leaf : leaves) {
    const int ix = leaf.cell[0] + 1, iy = leaf.cell[1] + 1;
    if (ix == 2 && iy == 7) {
      EXPECT_EQ(walk(leaf.head, state[2]), zero_based({9, 7, 5, 3}));
    } else if (ix == 5 && iy == 7) {
      EXPECT_EQ(walk(leaf.head, state[2]), zero_based({4, 2, 1}));
    } else {
      EXPECT_TRUE((ix == 5 && iy == 6 && leaf.head == 6 - 1) || (ix == 6 && iy == 6 && leaf.head == 8 - 1))
          << "unexpected leaf (" << ix << "," << iy << ") head " << leaf.head;
    }
  }
}

// nbs on the nine elements: y-lists of rows 6 and 7 (1-based) and memory ny + 2nx + 2N.
TEST(Book, NbsOnTheNineElements) {
  const Elements e = read_elements_csv(testpaths::nine_csv());
  NbsDetector nbs;
  PairList p;
  TraceLog log;
  nbs.detect_traced(e, book_grid(), p, log);
  const auto state = log.state_after(phase_at(log, phase_label::kClearYLists));
  EXPECT_EQ(walk(state[0][7 - 1], state[1]), zero_based({9, 7, 5, 4, 3, 2, 1}));
  EXPECT_EQ(walk(state[0][6 - 1], state[1]), zero_based({8, 6}));
  EXPECT_EQ(std::count(state[0].begin(), state[0].end(), -1), 8);
  EXPECT_EQ(nbs.book_bytes(), (10u + 2 * 10u + 2 * 9u) * sizeof(std::int32_t));
}

// Eq. 3.54: the sorting algorithm needs M = 3N in 2D and 4N in 3D.
TEST(Book, Eq3_54SortingNeedsThreeNIn2DAndFourNIn3D) {
  const Elements e = read_elements_csv(testpaths::nine_csv());
  SortDetector sort;
  PairList p;
  sort.detect(e, book_grid(), p);
  EXPECT_EQ(sort.own_bytes(), 3u * 9u * sizeof(std::int32_t));
  Elements e3;
  e3.dim = 3;
  for (ElementId k = 0; k < 9; ++k) e3.push_back(e.x[k], e.y[k], 0.5 * k, e.r[k]);
  sort.detect(e3, {}, p);
  EXPECT_EQ(sort.own_bytes(), 4u * 9u * sizeof(std::int32_t));
}

}  // namespace
}  // namespace nbscope
