// The algorithms of the book's chapter 3 beyond brute force: tree, sort, screen and nbs in 3D.
// The pair sets are property-tested against brute force in test_detectors.cpp; here: memory
// formulas, the screen limit, the shared grid code, and the lists each trace shows when they are
// complete, compared with lists computed independently from the elements' cells.
//
// Index: helpers | shared cell code | memory formulas | screen limit | lists at their snapshots
// (screen, tree, sort, nbs 3D) and the checker's own fault tests | 3D layers and pinned grids |
// pseudocode lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <random>

#include "core/brute.hpp"
#include "core/cells.hpp"
#include "core/error.hpp"
#include "core/lists.hpp"
#include "core/nbs.hpp"
#include "core/screen.hpp"
#include "core/sort.hpp"
#include "core/tree.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

using testdata::Layout;
using Lists = std::map<std::int64_t, std::vector<ElementId>>;  // list index -> members, in list order

PairList sorted_detect(Detector& d, const Elements& e, const DetectOptions& o = {}) {
  PairList p;
  d.detect(e, o, p);
  sort_pairs(p);
  return p;
}

// Index of the first Phase event labelled `label` at or after `from` (events().size() if none).
std::size_t phase_at(const TraceLog& log, const char* label, std::size_t from = 0) {
  for (std::size_t i = from; i < log.events().size(); ++i) {
    const TraceEvent& ev = log.events()[i];
    if (ev.op == TraceOp::Phase && std::strcmp(ev.label, label) == 0) return i;
  }
  return log.events().size();
}

int array_id(const TraceLog& log, const std::string& name) {
  for (std::size_t i = 0; i < log.arrays().size(); ++i)
    if (log.arrays()[i].name == name) return static_cast<int>(i);
  ADD_FAILURE() << "no traced array " << name;
  return 0;
}

// Every non-empty list of heads[first, first + count), walked through `next` (at most N steps).
Lists walk(const std::vector<std::int32_t>& heads, const std::vector<std::int32_t>& next, std::int64_t first = 0,
           std::int64_t count = -1) {
  Lists out;
  if (count < 0) count = static_cast<std::int64_t>(heads.size()) - first;
  for (std::int64_t l = first; l < first + count; ++l) {
    std::size_t steps = 0;
    for (std::int32_t k = heads[static_cast<std::size_t>(l)]; k != -1 && steps <= next.size(); k = next[k], ++steps)
      out[l - first].push_back(k);
  }
  return out;
}

// The lists are exactly `expected` (members in any order there), each holding its elements in
// reverse push order: pushed by ascending id (the head is the largest) unless `ascending`, for
// lists built by walking a list that is itself in descending order (nbs 3D's y-lists).
::testing::AssertionResult lists_are(const Lists& actual, Lists expected, bool ascending = false) {
  for (auto& [l, members] : expected) {
    std::sort(members.begin(), members.end());
    if (!ascending) std::reverse(members.begin(), members.end());
  }
  for (const auto& [l, members] : actual) {
    auto it = expected.find(l);
    if (it == expected.end()) return ::testing::AssertionFailure() << "list " << l << " should be empty";
    if (members != it->second) {
      auto f = ::testing::AssertionFailure() << "list " << l << " holds";
      for (ElementId k : members) f << " " << k;
      f << ", expected";
      for (ElementId k : it->second) f << " " << k;
      return f;
    }
  }
  for (const auto& [l, members] : expected)
    if (!actual.count(l)) return ::testing::AssertionFailure() << "list " << l << " is empty, expected " << members.size();
  return ::testing::AssertionSuccess();
}

std::array<std::int32_t, 3> cell_of(const Grid& g, const Elements& e, ElementId k) {
  return {g.cell(e.x[k], 0), g.cell(e.y[k], 1), e.dim == 3 ? g.cell(e.z[k], 2) : 0};
}

// ---------------------------------------------------------------------------------------------
// Shared cell code.

TEST(Cells, VectorisedIntegerisationIsGridCell) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-30, 130);
  Elements e;
  e.dim = 2;
  for (int i = 0; i < 2000; ++i) e.push_back(u(rng), u(rng), 0, 0.5);
  e.push_back(0.0, 100.0, 0, 0.5);  // exactly on cell borders
  e.push_back(-1e300, 1e300, 0, 0.5);
  Grid g;
  g.dim = 2;
  g.cell_size = 1.5;
  g.inv_cell_size = 1 / 1.5;
  g.n[0] = 67;
  g.n[1] = 40;
  for (int a = 0; a < 2; ++a) {
    std::vector<std::int32_t> cells(static_cast<std::size_t>(e.size()));
    integerise(e, g, a, cells);
    for (ElementId k = 0; k < e.size(); ++k) ASSERT_EQ(cells[k], g.cell(e.axis(a)[k], a)) << "axis " << a << " k " << k;
  }
}

TEST(Cells, HalfMasksMeetEveryNeighbourPairOnce) {
  // Of every offset o != 0 within one cell, exactly one of o and -o is in the mask.
  for (int dim : {2, 3}) {
    const auto mask = contact_mask(dim);
    int count = 0;
    for (int dz = dim == 3 ? -1 : 0; dz <= (dim == 3 ? 1 : 0); ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          if (dx == 0 && dy == 0 && dz == 0) continue;
          auto has = [&](int x, int y, int z) {
            return std::any_of(mask.begin(), mask.end(), [&](const CellOffset& o) { return o.dx == x && o.dy == y && o.dz == z; });
          };
          EXPECT_NE(has(dx, dy, dz), has(-dx, -dy, -dz)) << dim << "D " << dx << "," << dy << "," << dz;
          EXPECT_EQ(has(dx, dy, dz), in_half_mask(dx, dy, dz)) << dim << "D " << dx << "," << dy << "," << dz;
          count += has(dx, dy, dz);
        }
      }
    }
    EXPECT_EQ(count, dim == 3 ? 13 : 4);
  }
}

// ---------------------------------------------------------------------------------------------
// Memory formulas: own_bytes against the book's (or the header's) count of integers.

TEST(Memory, SortIsThreeNIn2DAndFourNIn3D) {
  SortDetector sort;
  for (int dim : {2, 3}) {
    for (Layout layout : {Layout::Loose, Layout::Dense, Layout::Clustered, Layout::FarAway}) {
      const Elements e = testdata::make_layout(layout, 1234, dim, 2);
      sorted_detect(sort, e);
      EXPECT_EQ(sort.own_bytes(), sizeof(std::int32_t) * (dim == 2 ? 3 : 4) * 1234u) << dim << "D " << testdata::layout_name(layout);
    }
  }
}

TEST(Memory, ScreenIsOneHeadPerCellPlusN) {
  ScreenDetector screen;
  for (int dim : {2, 3}) {
    const Elements e = testdata::make_layout(Layout::Loose, 800, dim, 5);
    sorted_detect(screen, e);
    const Grid& g = *screen.last_grid();
    EXPECT_EQ(screen.own_bytes(), sizeof(std::int32_t) * static_cast<std::size_t>(g.n[0] * g.n[1] * g.n[2] + 800));
  }
}

TEST(Memory, NbsIn3DIsNzPlusTwoNyPlusFiveNxPlusThreeN) {
  NbsDetector nbs;
  for (Layout layout : {Layout::Loose, Layout::Dense, Layout::Clustered, Layout::OnLine}) {
    const Elements e = testdata::make_layout(layout, 900, 3, 4);
    sorted_detect(nbs, e);
    const Grid& g = *nbs.last_grid();
    EXPECT_EQ(nbs.book_bytes(), sizeof(std::int32_t) * static_cast<std::size_t>(g.n[2] + 2 * g.n[1] + 5 * g.n[0] + 3 * 900))
        << testdata::layout_name(layout);
  }
  // And back to 2D with the same instance: the 3D arrays no longer count.
  const Elements flat = testdata::make_layout(Layout::Dense, 500, 2, 4);
  sorted_detect(nbs, flat);
  const Grid& g = *nbs.last_grid();
  EXPECT_EQ(nbs.book_bytes(), sizeof(std::int32_t) * static_cast<std::size_t>(g.n[1] + 2 * g.n[0] + 2 * 500));
}

TEST(Memory, TreeIsThreeIntegersPerNodePlusN) {
  TreeDetector tree;
  for (int dim : {2, 3}) {
    const Elements e = testdata::make_layout(Layout::Loose, 1000, dim, 8);
    sorted_detect(tree, e);
    const std::size_t m = static_cast<std::size_t>(tree.node_count());
    EXPECT_EQ(tree.own_bytes(), sizeof(std::int32_t) * (3 * m + 1000));
    // Nodes exist only where elements are: at most one path of log2(cells) nodes per element.
    const Grid& g = *tree.last_grid();
    const double depth = std::ceil(std::log2(static_cast<double>(g.n[0])) + std::log2(static_cast<double>(g.n[1])) +
                                   std::log2(static_cast<double>(g.n[2])));
    EXPECT_LE(static_cast<double>(m), 1 + 1000 * depth);
    EXPECT_LT(static_cast<double>(m), static_cast<double>(g.cell_count()) * 2);
  }
}

// ---------------------------------------------------------------------------------------------
// The screen array's limit.

Elements two_specks(double apart, int dim) {
  Elements e;
  e.dim = dim;
  e.push_back(0, 0, 0, 0.5);
  e.push_back(apart, apart, apart, 0.5);
  return e;
}

TEST(Screen, RefusesAScreenArrayBeyondTheLimitBeforeAllocatingIt) {
  for (int dim : {2, 3}) {
    const Elements e = two_specks(dim == 2 ? 1e4 : 400, dim);  // 1e8 cells in 2D, 6.4e7 in 3D
    ScreenDetector screen;
    PairList p;
    try {
      screen.detect(e, {}, p);
      FAIL() << "expected an Error";
    } catch (const Error& err) {
      const std::string what = err.what();
      EXPECT_NE(what.find("nbs"), std::string::npos) << what;
      EXPECT_NE(what.find(" MB"), std::string::npos) << what;
      EXPECT_NE(what.find(std::to_string(kScreenMaxCells)), std::string::npos) << what;
    }
    EXPECT_EQ(screen.own_bytes(), 0u);  // nothing was allocated
    NbsDetector nbs;                    // the suggested way out works, in memory linear in the side
    EXPECT_TRUE(sorted_detect(nbs, e).empty());
    EXPECT_LT(nbs.own_bytes(), 1'000'000u);
  }
}

TEST(Screen, AcceptsTheLargestGridWithinTheLimit) {
  Grid g;
  g.n[0] = 4096;
  g.n[1] = 8192;  // exactly 2^25 cells
  EXPECT_NO_THROW(check_screen_array_size(g, 10));
  g.n[1] = 8193;
  EXPECT_THROW(check_screen_array_size(g, 10), Error);
  g.dim = 3;  // three sides at the per-side limit overflow int64: still refused, not wrapped
  g.n[0] = g.n[1] = g.n[2] = kMaxCellsPerSide;
  EXPECT_THROW(check_screen_array_size(g, 10), Error);
}

// ---------------------------------------------------------------------------------------------
// Lists at their snapshots, against lists computed from the elements' cells.

// Elements grouped by cell, keyed by Grid::flat.
Lists expected_cell_lists(const Grid& g, const Elements& e) {
  Lists out;
  for (ElementId k = 0; k < e.size(); ++k) {
    const auto c = cell_of(g, e, k);
    out[g.flat(c[0], c[1], c[2])].push_back(k);
  }
  return out;
}

TEST(Screen, AtTheContactPhaseEveryCellListHoldsExactlyItsElements) {
  for (int dim : {2, 3}) {
    for (Layout layout : {Layout::Dense, Layout::Clustered, Layout::OneCell, Layout::Touching}) {
      const Elements e = testdata::make_layout(layout, 600, dim, 6);
      ScreenDetector screen;
      PairList p;
      TraceLog log;
      screen.detect_traced(e, {}, p, log);
      const auto state = log.state_after(phase_at(log, phase_label::kContacts));
      EXPECT_TRUE(lists_are(walk(state[array_id(log, "C")], state[array_id(log, "E")]), expected_cell_lists(*screen.last_grid(), e)))
          << dim << "D " << testdata::layout_name(layout);
      // And every head is -1 again at the end.
      const auto end = log.state_after(log.events().size());
      EXPECT_TRUE(walk(end[array_id(log, "C")], end[array_id(log, "E")]).empty());
    }
  }
}

TEST(ListChecker, CatchesAMovedElementAWrongOrderAndAMissingList) {
  const Elements e = testdata::make_layout(Layout::Dense, 200, 2, 1);
  ScreenDetector screen;
  PairList p;
  TraceLog log;
  screen.detect_traced(e, {}, p, log);
  const Lists good = expected_cell_lists(*screen.last_grid(), e);
  auto state = log.state_after(phase_at(log, phase_label::kContacts));
  const Lists actual = walk(state[0], state[1]);
  ASSERT_TRUE(lists_are(actual, good));
  Lists moved = actual;
  const auto a = moved.begin(), b = std::next(moved.begin());
  b->second.push_back(a->second.back());
  a->second.pop_back();
  EXPECT_FALSE(lists_are(moved, good));
  Lists reordered = actual;
  for (auto& [l, m] : reordered) {
    if (m.size() > 1) {
      std::swap(m[0], m[1]);
      break;
    }
  }
  EXPECT_FALSE(lists_are(reordered, good));
  Lists missing = actual;
  missing.erase(missing.begin());
  EXPECT_FALSE(lists_are(missing, good));
}

TEST(Tree, AtTheContactPhaseEachLeafIsOneOccupiedCellHoldingItsElements) {
  for (int dim : {2, 3}) {
    for (Layout layout : {Layout::Loose, Layout::Clustered, Layout::OnLine, Layout::OneCell}) {
      const Elements e = testdata::make_layout(layout, 500, dim, 2);
      TreeDetector tree;
      PairList p;
      TraceLog log;
      tree.detect_traced(e, {}, p, log);
      const Grid& g = *tree.last_grid();
      const auto state = log.state_after(phase_at(log, phase_label::kContacts));
      const auto& child = state[array_id(log, "child")];
      const auto& head = state[array_id(log, "HEAD")];
      const auto& next = state[array_id(log, "E")];
      Lists actual;
      for (const TreeLeaf& leaf : tree_leaves(g, child, head)) {
        const Lists one = walk(head, next, leaf.node, 1);
        ASSERT_FALSE(one.empty()) << "an empty leaf";
        ASSERT_FALSE(actual.count(g.flat(leaf.cell[0], leaf.cell[1], leaf.cell[2]))) << "two leaves for one cell";
        actual[g.flat(leaf.cell[0], leaf.cell[1], leaf.cell[2])] = one.begin()->second;
      }
      EXPECT_TRUE(lists_are(actual, expected_cell_lists(g, e))) << dim << "D " << testdata::layout_name(layout);
      EXPECT_EQ(static_cast<std::size_t>(tree.node_count()), head.size());
    }
  }
}

TEST(Sort, AtTheContactPhaseOrderIsAPermutationSortedByCell) {
  for (int dim : {2, 3}) {
    const Elements e = testdata::make_layout(Layout::Clustered, 700, dim, 3);
    SortDetector sort;
    PairList p;
    TraceLog log;
    sort.detect_traced(e, {}, p, log);
    const Grid& g = *sort.last_grid();
    const auto state = log.state_after(phase_at(log, phase_label::kContacts));
    const auto& order = state[array_id(log, "order")];
    std::vector<ElementId> seen(order.begin(), order.end());
    std::sort(seen.begin(), seen.end());
    for (ElementId k = 0; k < e.size(); ++k) ASSERT_EQ(seen[k], k);
    const char* names[3] = {"ix", "iy", "iz"};
    for (ElementId k = 0; k < e.size(); ++k) {
      const auto c = cell_of(g, e, k);
      for (int a = 0; a < dim; ++a) ASSERT_EQ(state[array_id(log, names[a])][k], c[a]);
    }
    for (std::size_t i = 1; i < order.size(); ++i) {
      const auto a = cell_of(g, e, order[i - 1]), b = cell_of(g, e, order[i]);
      ASSERT_TRUE(a < b || (a == b && order[i - 1] < order[i])) << "position " << i;
    }
  }
}

// nbs 3D: the z-lists, each layer's y-lists (B[0] layer iz, B[1] layer iz-1) and each row's five
// x-lists (A[r]) at the moment they are complete. z-lists are pushed by ascending id, y-lists by
// walking a z-list (so they come out ascending), x-lists by walking a y-list (descending again).
TEST(Nbs3d, ZYAndXListsHoldExactlyTheirElementsWhenComplete) {
  for (Layout layout : {Layout::Dense, Layout::Clustered, Layout::Touching, Layout::OnLine}) {
    const Elements e = testdata::make_layout(layout, 700, 3, 7);
    NbsDetector nbs;
    PairList p;
    TraceLog log;
    nbs.detect_traced(e, {}, p, log);
    const Grid& g = *nbs.last_grid();
    const std::int64_t nx = g.n[0], ny = g.n[1];
    const int C = array_id(log, "C"), Z = array_id(log, "Z"), B = array_id(log, "B"), Y = array_id(log, "Y"),
              A = array_id(log, "A"), X = array_id(log, "X");
    SCOPED_TRACE(testdata::layout_name(layout));
    Lists layers;
    std::map<std::pair<std::int32_t, std::int32_t>, std::vector<ElementId>> rows;                 // (iy, iz)
    std::map<std::array<std::int32_t, 3>, std::vector<ElementId>> cells;                            // (ix, iy, iz)
    for (ElementId k = 0; k < e.size(); ++k) {
      const auto c = cell_of(g, e, k);
      layers[c[2]].push_back(k);
      rows[{c[1], c[2]}].push_back(k);
      cells[c].push_back(k);
    }
    auto state = log.state_after(phase_at(log, phase_label::kClearZLists));
    EXPECT_TRUE(lists_are(walk(state[C], state[Z]), layers));
    std::size_t rows_seen = 0;
    for (std::size_t i = 0; i < log.events().size(); ++i) {
      const TraceEvent& ev = log.events()[i];
      if (ev.op != TraceOp::Phase) continue;
      if (std::strcmp(ev.label, phase_label::kClearYListsOfLayer) == 0) {
        state = log.state_after(i);
        const std::int32_t iz = ev.index;
        for (int s = 0; s < 2; ++s) {
          Lists expected;
          if (s == 0 || layers.count(iz - 1)) {
            for (const auto& [row, members] : rows)
              if (row.second == iz - s) expected[row.first] = members;
          }
          EXPECT_TRUE(lists_are(walk(state[B], state[Y], s * ny, ny), expected, true)) << "layer " << iz << " B[" << s << "]";
        }
      }
      if (std::strcmp(ev.label, phase_label::kContactsOfRow) == 0) {
        ++rows_seen;
        state = log.state_after(i);
        const std::int32_t iy = ev.cell[1], iz = ev.cell[2];
        const std::int32_t dy[5] = {0, -1, -1, 0, 1}, dz[5] = {0, 0, -1, -1, -1};
        for (int r = 0; r < 5; ++r) {
          Lists expected;
          for (const auto& [c, members] : cells)
            if (c[1] == iy + dy[r] && c[2] == iz + dz[r]) expected[c[0]] = members;
          EXPECT_TRUE(lists_are(walk(state[A], state[X], r * nx, nx), expected)) << "row " << iy << "," << iz << " A[" << r << "]";
        }
      }
    }
    EXPECT_EQ(rows_seen, rows.size());
    const auto end = log.state_after(log.events().size());
    for (int heads : {C, B, A}) EXPECT_TRUE(walk(end[heads], end[X]).empty()) << "heads left set at the end";
  }
}

// ---------------------------------------------------------------------------------------------
// 3D layers and pinned grids: every detector against brute force.

TEST(Algorithms3d, LayersAndSingleLayerWorldsMatchBruteForce) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Elements> sets;
  for (double gap : {0.0, 0.999, 1.0, 5.0}) {  // layers touching, nearly touching, exactly touching, apart
    Elements e;
    e.dim = 3;
    for (int layer = 0; layer < 4; ++layer)
      for (int i = 0; i < 150; ++i) e.push_back(20 * u(rng), 20 * u(rng), layer * (1.0 + gap), 0.5);
    sets.push_back(e);
  }
  Elements plane;  // nz = 1
  plane.dim = 3;
  for (int i = 0; i < 400; ++i) plane.push_back(15 * u(rng), 15 * u(rng), 2.0, 0.3 + 0.2 * u(rng));
  sets.push_back(plane);
  BruteDetector brute;
  for (const DetectorInfo& info : detector_infos()) {
    if (!info.dim3 || info.name == "brute") continue;
    auto d = info.make();
    for (std::size_t s = 0; s < sets.size(); ++s) EXPECT_EQ(sorted_detect(*d, sets[s]), sorted_detect(brute, sets[s])) << info.name << " set " << s;
  }
}

TEST(Algorithms, PinnedGridsSmallerThanTheDataClampAndStayCorrect) {
  BruteDetector brute;
  for (int dim : {2, 3}) {
    const Elements e = testdata::make_layout(Layout::Dense, 800, dim, 12);
    DetectOptions o;
    o.grid.origin = std::array<double, 3>{e.x.mean(), e.y.mean(), dim == 3 ? e.z.mean() : 0.0};
    o.grid.cells = std::array<std::int64_t, 3>{3, 4, 2};
    const PairList ref = sorted_detect(brute, e);
    for (const DetectorInfo& info : detector_infos()) {
      if (!(dim == 2 ? info.dim2 : info.dim3)) continue;
      auto d = info.make();
      EXPECT_EQ(sorted_detect(*d, e, o), ref) << info.name << " " << dim << "D";
      if (const Grid* g = d->last_grid()) {
        EXPECT_EQ(g->n[0], 3) << info.name;
      }
    }
  }
  const Elements e = testdata::make_layout(Layout::Dense, 10, 2, 1);
  DetectOptions bad;
  bad.grid.cells = std::array<std::int64_t, 3>{0, 4, 1};
  PairList p;
  EXPECT_THROW(NbsDetector().detect(e, bad, p), Error);
}

// ---------------------------------------------------------------------------------------------
// Pseudocode: every traced event points at a line the detector shows; pushes at a line that says so.

TEST(Pseudocode, EveryEventLineIsALineOfTheDetectorsPseudocode) {
  for (const DetectorInfo& info : detector_infos()) {
    for (int dim : {2, 3}) {
      if (!(dim == 2 ? info.dim2 : info.dim3)) continue;
      auto d = info.make();
      const Elements e = testdata::make_layout(Layout::Dense, 150, dim, 1);
      PairList p;
      TraceLog log;
      d->detect_traced(e, {}, p, log);
      if (log.events().empty()) continue;  // a detector without a trace
      const auto& lines = d->pseudocode(dim);
      ASSERT_FALSE(lines.empty()) << info.name << " " << dim << "D";
      for (const TraceEvent& ev : log.events()) {
        ASSERT_LT(ev.line, lines.size()) << info.name << " " << dim << "D";
        if (ev.op == TraceOp::Push) {
          // A push line says what it pushes onto, in the book's words.
          EXPECT_NE(std::string(lines[ev.line]).find("add the discrete element"), std::string::npos)
              << info.name << " " << dim << "D line " << int{ev.line} << ": " << lines[ev.line];
        }
      }
    }
  }
}

}  // namespace
}  // namespace nbscope
