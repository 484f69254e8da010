// locate_pair: the operation of a detection's trace that decided a pair — the test of a pair every
// grid detector and brute force tests, the visit of a cell when a test was lost, the last mask
// visit when a cell visit was lost, the pushes of two elements in cells that are not neighbours.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core/detector.hpp"
#include "core/locate.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

using testdata::Layout;

PairCells cells_of(const Grid& g, const Elements& e, std::int32_t i, std::int32_t j) {
  PairCells c;
  for (int a = 0; a < e.dim; ++a) {
    c.i[static_cast<std::size_t>(a)] = g.cell(e.axis(a)[i], a);
    c.j[static_cast<std::size_t>(a)] = g.cell(e.axis(a)[j], a);
  }
  if (e.dim == 2) c.i[2] = c.j[2] = -1;
  return c;
}

bool neighbours(const PairCells& c, int dim) {
  for (int a = 0; a < dim; ++a)
    if (std::abs(c.i[static_cast<std::size_t>(a)] - c.j[static_cast<std::size_t>(a)]) > 1) return false;
  return true;
}

struct Traced {
  Elements e;
  Grid grid;
  TraceLog log;
  PairList pairs;
};

Traced traced(const std::string& algorithm, Layout layout, std::int64_t n, int dim, std::uint64_t seed) {
  Traced t;
  t.e = testdata::make_layout(layout, n, dim, seed);
  auto d = make_detector(algorithm);
  d->detect_traced(t.e, DetectOptions{}, t.pairs, t.log);
  t.grid = d->last_grid() != nullptr ? *d->last_grid() : make_grid(t.e, GridOptions{});
  return t;
}

// Every pair of neighbouring cells is tested by every grid detector (and every pair by brute force),
// and the test found is that pair's, with the detector's result.
TEST(LocatePair, FindsTheTestOfEveryNeighbourPair) {
  for (const DetectorInfo& info : detector_infos()) {
    if (info.name == "box2d") continue;  // records no trace
    for (const int dim : {2, 3}) {
      if ((dim == 2 && !info.dim2) || (dim == 3 && !info.dim3)) continue;
      for (const Layout layout : {Layout::Dense, Layout::Clustered, Layout::Touching}) {
        SCOPED_TRACE(info.name + " " + std::to_string(dim) + "D " + testdata::layout_name(layout));
        const Traced t = traced(info.name, layout, 60, dim, 5);
        const std::set<Pair> found(t.pairs.begin(), t.pairs.end());
        int checked = 0;
        for (std::int32_t i = 0; i < t.e.size(); ++i) {
          for (std::int32_t j = i + 1; j < t.e.size(); ++j) {
            const PairCells c = cells_of(t.grid, t.e, i, j);
            const PairLocation at = locate_pair(t.log.events(), i, j, c, dim);
            if (!neighbours(c, dim) && info.name != "brute") {
              EXPECT_EQ(at.finding, PairFinding::NotNeighbours) << i << "," << j;
              continue;
            }
            ASSERT_EQ(at.finding, PairFinding::Tested) << i << "," << j;
            const TraceEvent& ev = t.log.events()[*at.event];
            EXPECT_EQ(ev.op, TraceOp::TestPair);
            EXPECT_TRUE((ev.element == i && ev.other == j) || (ev.element == j && ev.other == i));
            EXPECT_EQ(at.contact, found.count({i, j}) == 1);
            ++checked;
          }
        }
        EXPECT_GT(checked, 0);
      }
    }
  }
}

// A trace that lost a pair's test (as a broken detector would) points at the visit of the cell
// that holds the other element; one that also lost that visit points at the scanner's last visit.
TEST(LocatePair, FindsWhereAMissedPairShouldHaveBeenTested) {
  for (const char* algorithm : {"nbs", "screen", "tree", "sort"}) {
    SCOPED_TRACE(algorithm);
    const Traced t = traced(algorithm, Layout::Dense, 80, 2, 11);
    ASSERT_FALSE(t.pairs.empty());
    int cases = 0;
    for (const Pair& p : t.pairs) {
      const PairCells c = cells_of(t.grid, t.e, p.i, p.j);
      if (c.i == c.j) continue;  // a pair in one cell: no mask cell between them
      std::vector<TraceEvent> events = t.log.events();
      std::erase_if(events, [&](const TraceEvent& e) {
        return e.op == TraceOp::TestPair && ((e.element == p.i && e.other == p.j) || (e.element == p.j && e.other == p.i));
      });
      const PairLocation visited = locate_pair(events, p.i, p.j, c, 2);
      ASSERT_EQ(visited.finding, PairFinding::CellVisited);
      const TraceEvent& v = events[*visited.event];
      EXPECT_EQ(v.op, TraceOp::VisitCell);
      EXPECT_EQ(v.element, visited.scanner);
      EXPECT_EQ(v.cell[0], visited.cell[0]);
      EXPECT_EQ(v.cell[1], visited.cell[1]);
      const std::array<std::int32_t, 3>& other_cell = visited.other == p.j ? c.j : c.i;
      EXPECT_EQ(visited.cell, other_cell);

      // The visit itself lost too (the drop-mask-cell kind of bug): the scanner's last visit.
      const std::int32_t scanner = visited.scanner;
      std::erase_if(events, [&](const TraceEvent& e) {
        return e.op == TraceOp::VisitCell && e.element == scanner && e.cell[0] == visited.cell[0] && e.cell[1] == visited.cell[1];
      });
      const PairLocation lost = locate_pair(events, p.i, p.j, c, 2);
      ASSERT_EQ(lost.finding, PairFinding::CellNotVisited);
      EXPECT_EQ(lost.scanner, scanner);
      const TraceEvent& last = events[*lost.event];
      EXPECT_TRUE(last.op == TraceOp::VisitCell || last.op == TraceOp::Push || last.op == TraceOp::Set);
      EXPECT_EQ(last.element, scanner);
      for (std::size_t n = *lost.event + 1; n < events.size(); ++n)
        EXPECT_FALSE(events[n].op == TraceOp::VisitCell && events[n].element == scanner);
      if (++cases == 10) break;
    }
    EXPECT_GT(cases, 0);
  }
}

// Every built-in pushes each element onto lists of its own cell only: no element is ever located
// on a wrong list (so WrongList never stands in for another finding).
TEST(LocatePair, NoBuiltInPushesOntoAnotherCellsList) {
  for (const DetectorInfo& info : detector_infos()) {
    if (info.name == "box2d") continue;
    for (const int dim : {2, 3}) {
      if ((dim == 2 && !info.dim2) || (dim == 3 && !info.dim3)) continue;
      SCOPED_TRACE(info.name + " " + std::to_string(dim) + "D");
      const Traced t = traced(info.name, Layout::Clustered, 60, dim, 7);
      for (std::int32_t k = 0; k < t.e.size(); ++k) {
        const PairCells c = cells_of(t.grid, t.e, k, k);
        EXPECT_NE(locate_pair(t.log.events(), k, k, c, dim).finding, PairFinding::WrongList) << k;
      }
    }
  }
}

// An element pushed onto the list of the next column (as a detector with its own, wrong
// integerisation does): the element alone (a cells violation) and every untested pair of it are
// located at that push; a tested pair stays at its test.
TEST(LocatePair, FindsThePushOntoAWrongList) {
  const Traced t = traced("nbs", Layout::Dense, 80, 2, 11);
  std::vector<TraceEvent> events = t.log.events();
  const auto push = std::find_if(events.begin(), events.end(), [](const TraceEvent& e) { return e.op == TraceOp::Push && e.cell[0] >= 0; });
  ASSERT_NE(push, events.end());
  const std::int32_t k = push->element;
  push->cell[0] += 1;
  const auto at_push = static_cast<std::size_t>(push - events.begin());
  const PairCells alone = cells_of(t.grid, t.e, k, k);
  const PairLocation wrong = locate_pair(events, k, k, alone, 2);
  ASSERT_EQ(wrong.finding, PairFinding::WrongList);
  EXPECT_EQ(wrong.event, at_push);
  EXPECT_EQ(wrong.scanner, k);
  EXPECT_EQ(wrong.cell[0], alone.i[0] + 1);
  EXPECT_EQ(wrong.cell[1], alone.i[1]);
  EXPECT_EQ(wrong.cell[2], -1);
  EXPECT_EQ(locate_pair(t.log.events(), k, k, alone, 2).finding, PairFinding::NotInTrace);  // the true trace

  const std::int32_t other = k == 0 ? 1 : 0;
  std::erase_if(events, [&](const TraceEvent& e) {
    return e.op == TraceOp::TestPair && ((e.element == k && e.other == other) || (e.element == other && e.other == k));
  });
  for (const auto& [i, j] : {std::pair{k, other}, std::pair{other, k}}) {
    const PairLocation missed = locate_pair(events, i, j, cells_of(t.grid, t.e, i, j), 2);
    EXPECT_EQ(missed.finding, PairFinding::WrongList);
    EXPECT_EQ(missed.event, at_push);
    EXPECT_EQ(missed.scanner, k);
    EXPECT_EQ(missed.other, other);
  }
}

TEST(LocatePair, SaysWhenTheTraceKnowsNothing) {
  const PairCells c{{0, 0, -1}, {5, 5, -1}};
  EXPECT_EQ(locate_pair({}, 1, 2, c, 2).finding, PairFinding::NotInTrace);
}

// A hand-made trace of a stale list: 5 pushed onto the list of cell (2,0); then 3 pushed onto the
// list of (2,1) while its head still held 5 (never cleared), then 4. The walk of (2,1) by 9 tests
// 4, 3 and then 5, which lies in (2,0): located at the push of 3 that linked next[3] = 5.
TEST(LocateStray, FindsThePushThatLinkedTheListOnToTheStray) {
  TraceLog log;
  const std::vector<std::int32_t> heads(4, -1), next(10, -1);
  const int b = log.declare_array("B", {4}, heads);
  const int x = log.declare_array("X", {10}, next);
  log.push(0, "x-list", b, 2, x, 5, -1, -1, 2, 0, -1);
  log.push(0, "x-list", b, 3, x, 3, 5, -1, 2, 1, -1);  // head 3 still held 5
  log.push(0, "x-list", b, 3, x, 4, 3, -1, 2, 1, -1);
  log.push(0, "x-list", b, 1, x, 7, -1, -1, 1, 1, -1);  // 7 heads the list of (1,1)
  log.visit_cell(1, 9, 2, 1, -1);
  log.test_pair(2, 9, 4, false);
  log.test_pair(2, 9, 3, false);
  log.test_pair(2, 9, 5, false);
  log.visit_cell(1, 9, 1, 1, -1);
  log.test_pair(2, 9, 7, false);
  const std::span<const TraceEvent> events = log.events();

  const PairLocation stale = locate_stray(events, 5, 9, {2, 0, -1}, 2);
  EXPECT_EQ(stale.finding, PairFinding::StaleLink);
  ASSERT_TRUE(stale.event.has_value());
  EXPECT_EQ(*stale.event, 1u);
  EXPECT_EQ(stale.scanner, 3);
  EXPECT_EQ(stale.other, 5);
  EXPECT_EQ(stale.cell[0], 2);
  EXPECT_EQ(stale.cell[1], 1);

  // A stray at the head of the walked list: its own push onto that list.
  const PairLocation head = locate_stray(events, 7, 9, {0, 1, -1}, 2);  // 7 lies in (0,1)
  EXPECT_EQ(head.finding, PairFinding::WrongList);
  ASSERT_TRUE(head.event.has_value());
  EXPECT_EQ(*head.event, 3u);

  // Never tested by that finder: nothing to show.
  EXPECT_EQ(locate_stray(events, 5, 8, {2, 0, -1}, 2).finding, PairFinding::NotInTrace);
}

// On a correct detector's trace every test names an element of the visited cell's list: asked
// about one, locate_stray finds only its test (no link is stale, no push wrong).
TEST(LocateStray, AnElementRightlyOnTheListIsOnlyItsTest) {
  const Traced t = traced("nbs", Layout::Dense, 80, 2, 3);
  const std::span<const TraceEvent> events = t.log.events();
  const auto test = std::find_if(events.begin(), events.end(), [](const TraceEvent& e) { return e.op == TraceOp::TestPair; });
  ASSERT_NE(test, events.end());
  const PairCells c = cells_of(t.grid, t.e, test->other, test->element);
  const PairLocation at = locate_stray(events, test->other, test->element, c.i, 2);
  EXPECT_EQ(at.finding, PairFinding::Tested);
  EXPECT_EQ(*at.event, static_cast<std::size_t>(test - events.begin()));
}

}  // namespace
}  // namespace nbscope
