// The overlays without GL: traced lists rebuilt from detector events match lists computed
// independently from the elements' cells, and a recording DrawSink sees the arrow chains, the
// grid window, the mask and the violation markers that the flags ask for (and none when off).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "core/cells.hpp"
#include "core/detector.hpp"
#include "core/traced_lists.hpp"
#include "core/stepper.hpp"
#include "render/overlays.hpp"
#include "support/generators.hpp"
#include "support/draw_recorder.hpp"

namespace nbscope::render {
namespace {

using testdraw::Recorder;  // support/draw_recorder.hpp

TraceLog trace_of(const std::string& algorithm, const Elements& e, PairList& pairs, Grid& grid) {
  auto d = make_detector(algorithm);
  TraceLog log;
  d->detect_traced(e, {}, pairs, log);
  grid = *d->last_grid();
  return log;
}

TEST(TracedLists, NbsListsAreTheRowsAndCellsInPushOrder) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const Elements e = testdata::make_layout(testdata::Layout::Dense, 400, 2, seed);
    PairList pairs;
    Grid g;
    const TraceLog log = trace_of("nbs", e, pairs, g);
    const auto lists = traced_lists(log, static_cast<std::size_t>(e.size()));

    // Independent expectation. y-lists: elements pushed in id order onto the head, so a row's
    // list runs from its largest id down. x-lists of row iy are built walking that y-list, so a
    // cell's list runs from its smallest id up; the copies for row iy+1 (B[1]) likewise.
    std::map<std::int32_t, std::vector<ElementId>> rows;
    std::map<std::pair<std::int32_t, std::int32_t>, std::vector<ElementId>> cells;
    for (ElementId k = 0; k < static_cast<ElementId>(e.size()); ++k) {
      rows[g.cell(e.y[k], 1)].insert(rows[g.cell(e.y[k], 1)].begin(), k);
      cells[{g.cell(e.x[k], 0), g.cell(e.y[k], 1)}].push_back(k);
    }
    std::size_t y_lists = 0, x_lists = 0, below = 0;
    for (const TracedList& l : lists) {
      if (l.kind == "y-list") {
        ++y_lists;
        EXPECT_EQ(l.chain, rows.at(l.cell[1])) << "row " << l.cell[1];
      } else {
        ASSERT_EQ(l.kind, "x-list");
        EXPECT_EQ(l.chain, cells.at({l.cell[0], l.cell[1]})) << "cell " << l.cell[0] << "," << l.cell[1];
        if (l.secondary) {
          ++below;
          EXPECT_EQ(l.phase_index, l.cell[1] + 1);  // built while processing the row above
        } else {
          ++x_lists;
          EXPECT_EQ(l.phase_index, l.cell[1]);
        }
      }
    }
    EXPECT_EQ(y_lists, rows.size());
    EXPECT_EQ(x_lists, cells.size());
    std::size_t expected_below = 0;
    for (const auto& [cell, members] : cells) expected_below += rows.contains(cell.second + 1) ? 1 : 0;
    EXPECT_EQ(below, expected_below);
  }
}

TEST(TracedLists, EveryListBasedDetectorGivesEachElementOneListPerKind) {
  const Elements e = testdata::make_layout(testdata::Layout::Loose, 300, 2, 9);
  for (const DetectorInfo& info : detector_infos()) {
    if (!info.dim2) continue;
    auto d = info.make();
    TraceLog log;
    PairList pairs;
    d->detect_traced(e, {}, pairs, log);
    const auto lists = traced_lists(log, static_cast<std::size_t>(e.size()));
    if (lists.empty()) continue;  // brute, box2d: no lists
    std::map<std::string, std::vector<int>> seen;
    for (const TracedList& l : lists) {
      if (l.secondary) continue;
      auto& s = seen[l.kind];
      s.resize(static_cast<std::size_t>(e.size()), 0);
      for (ElementId k : l.chain) ++s[static_cast<std::size_t>(k)];
      EXPECT_FALSE(l.cut) << info.name;
    }
    for (const auto& [kind, counts] : seen)
      for (ElementId k = 0; k < static_cast<ElementId>(e.size()); ++k)
        EXPECT_EQ(counts[static_cast<std::size_t>(k)], 1) << info.name << " " << kind << " element " << k;
  }
}

// Five elements in one row of 1 m cells from (0.5, 0.5): y-list 4 3 2 1 0, x-lists per cell.
struct Small {
  Elements e = make_elements_2d((Eigen::ArrayXd(5) << 0.5, 0.9, 2.5, 3.5, 3.6).finished(),
                                (Eigen::ArrayXd(5) << 0.5, 0.5, 0.5, 0.5, 0.5).finished(),
                                Eigen::ArrayXd::Constant(5, 0.5));
  PairList pairs;
  Grid grid;
  std::vector<TracedList> lists;
  Camera camera;
  Small() {
    const TraceLog log = trace_of("nbs", e, pairs, grid);
    lists = traced_lists(log, 5);
    camera.set_viewport(400, 200);
    camera.fit({{0, 0}, {5, 1}});
  }
  OverlayScene scene() const {
    OverlayScene s;
    s.elements = &e;
    s.grid = &grid;
    s.pairs = &pairs;
    s.lists = &lists;
    return s;
  }
};

TEST(Overlays, ListArrowsFollowTheNextArrayAndVanishWhenTheOverlayIsOff) {
  Small t;
  OverlayFlags on;
  set_overlay(on, &OverlayFlags::lists, true);  // L: the lists, and their ids with them
  on.grid = false;  // its axis labels are numbers too
  Recorder rec;
  draw_scene(t.scene(), on, t.camera, rec);
  // Each list: one arrow from its head, then one per link.
  std::size_t expected = 0;
  for (const TracedList& l : t.lists) expected += l.secondary ? 0 : l.chain.size();
  EXPECT_EQ(rec.arrows.size(), expected);
  // The y-list's links point from element k to the next element in the chain: 4 -> 3 -> 2 -> 1 -> 0.
  // Each is an arc inside the row's band ending in an arrow at the next element; these run leftwards,
  // so they bow below the row's middle (rightward links bow above).
  const auto y = std::find_if(t.lists.begin(), t.lists.end(), [](const TracedList& l) { return l.kind == "y-list"; });
  ASSERT_NE(y, t.lists.end());
  EXPECT_EQ(y->chain, (std::vector<ElementId>{4, 3, 2, 1, 0}));
  // The row's band: the centres lie on its lower edge here, so the leftward arcs have no room to bow
  // and run along it.
  const float lo = float(t.grid.origin[1]), hi = lo + float(t.grid.cell_size);
  std::size_t matched = 0;
  for (std::size_t i = 0; i + 1 < y->chain.size(); ++i) {
    const Vec2 a(float(t.e.x[y->chain[i]]), 0.5f), b(float(t.e.x[y->chain[i + 1]]), 0.5f);
    for (const auto& arrow : rec.arrows)
      if (arrow.colour == palette::kYList && (arrow.to - b).norm() < 0.35f && arrow.from.x() > b.x() && arrow.from.x() < a.x() &&
          arrow.from.y() >= lo - 1e-4f && arrow.from.y() <= 0.5f + 1e-4f)
        ++matched;
  }
  EXPECT_EQ(matched, y->chain.size() - 1);
  for (const auto& line : rec.lines) {
    if (line.colour == palette::kYList && line.layer == Layer::Overlay) {
      EXPECT_TRUE(line.from.y() >= lo && line.from.y() <= hi) << "an arc left the row's band";
    }
  }
  // Ids are drawn with the lists, but never over each other: 3 and 4 are 8 px apart here, so
  // only the first of them is labelled.
  const auto drawn = [&](const char* id) { return rec.text_count(id); };
  EXPECT_EQ(drawn("2"), 1);
  EXPECT_EQ(drawn("3"), 1);
  EXPECT_EQ(drawn("4"), 0);

  OverlayFlags off = on;
  off.lists = false;
  Recorder none;
  draw_scene(t.scene(), off, t.camera, none);
  EXPECT_TRUE(none.arrows.empty());
  EXPECT_FALSE(none.has_text("4"));
}

// I alone draws the ids: L turns them on with the lists (the checkbox shows it), and I turns them
// off again while the lists stay (a student pressing I saw nothing change).
TEST(Overlays, IdsAreDrawnOnlyWhileTheirOverlayIsOn) {
  Small t;
  OverlayFlags f;
  f.grid = false;  // its axis labels are numbers too
  ASSERT_FALSE(f.ids);
  set_overlay(f, &OverlayFlags::lists, true);
  EXPECT_TRUE(f.ids) << "turning the lists on turns their ids on";
  set_overlay(f, &OverlayFlags::ids, false);
  EXPECT_TRUE(f.lists);
  Recorder rec;
  draw_scene(t.scene(), f, t.camera, rec);
  EXPECT_FALSE(rec.arrows.empty()) << "the lists are drawn";
  for (const char* id : {"0", "1", "2", "3", "4"}) EXPECT_EQ(rec.text_count(id), 0) << "id " << id;
  // The lists turned off and on again bring the ids back; already on, they stay as they are.
  set_overlay(f, &OverlayFlags::lists, false);
  set_overlay(f, &OverlayFlags::lists, true);
  EXPECT_TRUE(f.ids);
  set_overlay(f, &OverlayFlags::ids, false);
  set_overlay(f, &OverlayFlags::lists, true);
  EXPECT_FALSE(f.ids);
}

TEST(Overlays, GridDrawsOnlyTheCellsInView) {
  Small t;
  OverlayFlags f;
  Recorder whole;
  draw_scene(t.scene(), f, t.camera, whole);
  Camera zoomed = t.camera;
  zoomed.set({0.5, 0.5}, 400.0);  // one cell fills the view
  Recorder close;
  draw_scene(t.scene(), f, zoomed, close);
  EXPECT_LT(close.lines.size(), whole.lines.size());
  EXPECT_LT(close.rects.size(), whole.rects.size());
  EXPECT_TRUE(whole.has_text_containing("4 x 1 cells"));
}

TEST(Overlays, MaskCoversTheCellAndItsHalfMaskInsideTheGrid) {
  Grid g;
  g.n[0] = 4;
  g.n[1] = 3;
  EXPECT_EQ(mask_cells(g, 2, 1).size(), 5u);
  EXPECT_EQ(mask_cells(g, 0, 0).size(), 1u);  // no neighbours before (0, 0)
  const auto edge = mask_cells(g, 3, 2);       // (4, 1) is outside
  EXPECT_EQ(edge.size(), 4u);
  Small t;
  OverlayScene s = t.scene();
  s.hovered_cell = std::array<std::int32_t, 2>{2, 0};
  Recorder with, without;
  draw_scene(s, OverlayFlags{}, t.camera, with);
  s.hovered_cell.reset();
  draw_scene(s, OverlayFlags{}, t.camera, without);
  EXPECT_EQ(with.rects.size() - without.rects.size(), 2u);  // (2,0) and (1,0); the row below does not exist
  EXPECT_EQ(Recorder::count(without.rects, palette::kMaskCentre), 0);
  // Nothing hovered (headless): the selected element's cell's mask, so --select shows it.
  s.selected = 2;  // at x = 2.5: cell (2, 0) of the grid from (0.5, 0.5)
  Recorder selected;
  draw_scene(s, OverlayFlags{}, t.camera, selected);
  EXPECT_EQ(Recorder::count(selected.rects, palette::kMaskCentre), 1);
  EXPECT_EQ(Recorder::count(selected.rects, palette::kMaskCell), 1);
  OverlayFlags no_mask;
  no_mask.mask = false;
  Recorder off;
  draw_scene(s, no_mask, t.camera, off);
  EXPECT_EQ(Recorder::count(off.rects, palette::kMaskCentre), 0);
}

TEST(Overlays, ViolationsGetMarkersThatStayVisibleWhenZoomedOut) {
  Small t;
  CheckDraw checks;
  checks.violations = {{0, 2}};
  OverlayScene s = t.scene();
  s.checks = &checks;
  Recorder rec;
  draw_scene(s, OverlayFlags{}, t.camera, rec);
  ASSERT_EQ(rec.min_px_of(Layer::Top).size(), 1u);
  EXPECT_GE(rec.min_px_of(Layer::Top)[0], 8.0f);
  OverlayFlags off;
  off.checks = false;
  Recorder none;
  draw_scene(s, off, t.camera, none);
  EXPECT_TRUE(none.min_px_of(Layer::Top).empty());
}

TEST(Overlays, PickingFindsTheCellAndTheSmallestElementUnderThePoint) {
  Small t;
  // The grid starts at the minimum corner of the centres, (0.5, 0.5), with d = 1: 4 x 1 cells.
  ASSERT_EQ(t.grid.n[0], 4);
  EXPECT_EQ(cell_at(t.grid, {2.7, 0.6}), (std::array<std::int32_t, 2>{2, 0}));
  EXPECT_FALSE(cell_at(t.grid, {2.7, 0.4}).has_value());
  EXPECT_FALSE(cell_at(t.grid, {4.6, 0.6}).has_value());
  EXPECT_EQ(element_at(t.e, {0.7, 0.5}), 0);  // inside 0 and 1 (equal radii): the lower id
  EXPECT_EQ(element_at(t.e, {1.35, 0.5}), 1);
  EXPECT_EQ(element_at(t.e, {1.7, 0.5}), -1);
}

}  // namespace
}  // namespace nbscope::render

namespace nbscope::render {
namespace {

// The lists overlay agrees with the stepper: at every operation of the book's Fig. 3.15 under each
// algorithm with lists, each list not yet cleared is exactly the chain the stepper's arrays hold at
// that operation; before any push there are none; and at the end the lists are the finished ones.
TEST(Overlays, ListsMidTraceAreTheStepperArraysAtThatOperation) {
  const Elements e = testdata::book_nine();
  DetectOptions o;
  o.grid = testdata::book_grid();
  for (const char* algorithm : {"nbs", "screen", "tree"}) {
    PairList pairs;
    TraceLog log;
    make_detector(algorithm)->detect_traced(e, o, pairs, log);
    Stepper st;
    st.load(log);
    std::size_t checked = 0;
    for (std::size_t p = 0; p <= st.size(); ++p) {
      st.seek(p);
      const auto lists = traced_lists(log, 9, p);
      if (p == 0) {
        EXPECT_TRUE(lists.empty()) << algorithm;
      }
      for (const TracedList& l : lists) {
        const auto& head = st.state()[static_cast<std::size_t>(l.heads_array)];
        // Lists still standing at p (their head not cleared) are read off the stepper's arrays.
        if (head[static_cast<std::size_t>(l.slot)] == -1 || head[static_cast<std::size_t>(l.slot)] != l.chain.front()) continue;
        EXPECT_EQ(l.chain, st.list_members(l.heads_array, l.slot)) << algorithm << " at operation " << p;
        ++checked;
      }
    }
    EXPECT_GT(checked, 9u) << algorithm;
    const auto finished = traced_lists(log, 9);
    const auto at_end = traced_lists(log, 9, st.size());
    ASSERT_EQ(finished.size(), at_end.size()) << algorithm;
    for (std::size_t i = 0; i < finished.size(); ++i) EXPECT_EQ(finished[i].chain, at_end[i].chain) << algorithm;
  }
  // NBS after 3 operations (the phase, then elements 0 and 1 pushed onto the y-list of row 6): one
  // list, 1 -> 0, as the Arrays panel shows it.
  PairList pairs;
  TraceLog log;
  make_detector("nbs")->detect_traced(e, o, pairs, log);
  const auto three = traced_lists(log, 9, 3);
  ASSERT_EQ(three.size(), 1u);
  EXPECT_EQ(three.front().kind, "y-list");
  EXPECT_EQ(three.front().chain, (std::vector<ElementId>{1, 0}));
}

}  // namespace
}  // namespace nbscope::render

namespace nbscope::render {
namespace {

// A y-list too long for arcs is a rail along its row: one arrow per link, left to right in list
// order, at one height inside the row's band, and a leader from each slot to its element.
TEST(Overlays, LongYListsAreARailInListOrderWithLeadersToTheirElements) {
  const int n = 20;
  Eigen::ArrayXd x(n), y = Eigen::ArrayXd::Constant(n, 0.5);
  for (int k = 0; k < n; ++k) x[k] = 0.5 + double((k * 7) % n);  // list order unrelated to x
  const Elements e = make_elements_2d(x, y, Eigen::ArrayXd::Constant(n, 0.4));
  PairList pairs;
  Grid grid;
  const TraceLog log = trace_of("nbs", e, pairs, grid);
  const std::vector<TracedList> lists = traced_lists(log, n);
  Camera camera;
  camera.set_viewport(1600, 300);
  camera.fit({{-1, -1}, {21, 2}});
  OverlayScene s;
  s.elements = &e;
  s.grid = &grid;
  s.lists = &lists;
  OverlayFlags f;
  f.lists = true;
  f.grid = false;
  Recorder rec;
  draw_scene(s, f, camera, rec);
  std::vector<Recorder::Line> rail;
  for (const auto& a : rec.arrows)
    if (a.colour == palette::kYList) rail.push_back(a);
  ASSERT_EQ(rail.size(), static_cast<std::size_t>(n)) << "the head's arrow and one per element";
  const float lo = float(grid.origin[1]), hi = lo + float(grid.cell_size);
  for (std::size_t i = 0; i < rail.size(); ++i) {
    EXPECT_FLOAT_EQ(rail[i].from.y(), rail.front().from.y());
    EXPECT_TRUE(rail[i].from.y() > lo && rail[i].from.y() < hi);
    EXPECT_LT(rail[i].from.x(), rail[i].to.x()) << "the rail runs left to right";
    if (i > 0) {
      EXPECT_GT(rail[i].from.x(), rail[i - 1].from.x());
    }
  }
  // Each element of the list has a leader from its slot (the arrow's tip) to its centre.
  const auto y_list = std::find_if(lists.begin(), lists.end(), [](const TracedList& l) { return l.kind == "y-list"; });
  ASSERT_NE(y_list, lists.end());
  for (std::size_t i = 0; i < y_list->chain.size(); ++i) {
    const Vec2 c(float(e.x[y_list->chain[i]]), float(e.y[y_list->chain[i]]));
    const bool led = std::any_of(rec.lines.begin(), rec.lines.end(), [&](const Recorder::Line& l) {
      return (l.to - c).norm() < 1e-4f && std::abs(l.from.x() - rail[i].to.x()) < 0.2f;
    });
    EXPECT_TRUE(led) << "element " << y_list->chain[i] << " (list position " << i << ") has no leader from its slot";
  }
}

}  // namespace
}  // namespace nbscope::render

namespace nbscope::render {
namespace {

// One numbering across panels: a dump's rail slots are numbered by row, in the book's numbering
// when chosen, as the Arrays panel and the Stepper name the list's elements; never by atom id (the
// ids overlay, off here, is where atom ids are drawn).
TEST(Overlays, ARailOfADumpIsNumberedByRowsAsInArrays) {
  const int n = 20;
  Eigen::ArrayXd x(n), y = Eigen::ArrayXd::Constant(n, 0.5);
  for (int k = 0; k < n; ++k) x[k] = 0.5 + double((k * 7) % n);
  const Elements e = make_elements_2d(x, y, Eigen::ArrayXd::Constant(n, 0.4));
  PairList pairs;
  Grid grid;
  const TraceLog log = trace_of("nbs", e, pairs, grid);
  const std::vector<TracedList> lists = traced_lists(log, n);
  std::vector<std::int64_t> atom_ids;
  for (int k = 0; k < n; ++k) atom_ids.push_back(5000 + 7 * k);
  Camera camera;
  camera.set_viewport(1600, 300);
  camera.fit({{-1, -1}, {21, 2}});
  OverlayScene s;
  s.elements = &e;
  s.grid = &grid;
  s.lists = &lists;
  s.ids = &atom_ids;
  s.book_numbering = true;
  OverlayFlags f;
  f.lists = true;
  f.grid = false;
  f.ids = false;
  Recorder rec;
  draw_scene(s, f, camera, rec);
  const auto y_list = std::find_if(lists.begin(), lists.end(), [](const TracedList& l) { return l.kind == "y-list"; });
  ASSERT_NE(y_list, lists.end());
  for (const ElementId k : y_list->chain) EXPECT_TRUE(rec.has_text(std::to_string(k + 1))) << "row " << k << " (book " << k + 1 << ")";
  for (const std::int64_t id : atom_ids) EXPECT_FALSE(rec.has_text(std::to_string(id))) << "atom id " << id << " on the rail";
}

}  // namespace
}  // namespace nbscope::render

namespace nbscope::render {
namespace {

// Only NBS's B[2][nx] has copies of the row below: screen's C[nx][ny] with nx == 2 has the same
// shape, and its second column's lists are its own (drawn, not hidden as B[1] copies).
TEST(Overlays, ScreenListsOfATwoColumnGridAreNotRowBelowCopies) {
  const Elements e = make_elements_2d((Eigen::ArrayXd(4) << 0.5, 2.1, 0.5, 2.1).finished(),
                                      (Eigen::ArrayXd(4) << 0.5, 0.5, 2.1, 2.1).finished(), Eigen::ArrayXd::Constant(4, 0.5));
  PairList pairs;
  Grid grid;
  const TraceLog log = trace_of("screen", e, pairs, grid);
  ASSERT_EQ(grid.n[0], 2);
  const auto lists = traced_lists(log, 4);
  ASSERT_EQ(lists.size(), 4u);
  for (const TracedList& l : lists) EXPECT_FALSE(l.secondary) << l.heads_name << " slot " << l.slot;
}

}  // namespace
}  // namespace nbscope::render
