// The lists overlay and the grid where the debugging loop met them in the window (issue 23, part
// B), without GL: a large scene in `row` mode with no row chosen draws no lists and says how to
// choose one; the stepper's row wins over the hovered one mid-frame; a rail longer than fits shows
// its numbered ends and "... N more ..."; the overview numbers its major lines; the heat map is not
// buried under pair segments.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/detector.hpp"
#include "core/traced_lists.hpp"
#include "render/overlays.hpp"
#include "support/generators.hpp"
#include "support/draw_recorder.hpp"

namespace nbscope::render {
namespace {

using testdraw::Recorder;  // support/draw_recorder.hpp

// A detection's lists, pairs and grid of `e`, as the window's trace gives them.
struct Traced {
  Elements e;
  PairList pairs;
  Grid grid;
  std::vector<TracedList> lists;
  explicit Traced(Elements elements, const char* algorithm = "nbs") : e(std::move(elements)) {
    auto d = make_detector(algorithm);
    TraceLog log;
    d->detect_traced(e, {}, pairs, log);
    grid = *d->last_grid();
    lists = traced_lists(log, static_cast<std::size_t>(e.size()));
  }
  [[nodiscard]] OverlayScene scene() const {
    OverlayScene s;
    s.elements = &e;
    s.grid = &grid;
    s.pairs = &pairs;
    s.lists = &lists;
    return s;
  }
};

OverlayFlags lists_only() {
  OverlayFlags f;
  f.lists = true;
  f.grid = false;
  f.pairs = f.checks = false;
  return f;
}

TEST(ListsOverlay, RowModeWithNoRowChosenDrawsNoListsOfALargeScene) {
  // pile.json's 1,621 elements drew every list in `row` mode until a row was hovered: a hairball.
  const Traced big(testdata::make_layout(testdata::Layout::Dense, 1621, 2, 3));
  Camera camera;
  camera.set_viewport(1280, 720);
  camera.fit({{big.grid.origin[0], big.grid.origin[1]},
              {big.grid.origin[0] + big.grid.cell_size * double(big.grid.n[0]), big.grid.origin[1] + big.grid.cell_size * double(big.grid.n[1])}});
  OverlayScene s = big.scene();
  s.list_filter = ListFilter::Row;
  Recorder none;
  draw_scene(s, lists_only(), camera, none);
  EXPECT_TRUE(none.arrows.empty()) << none.arrows.size() << " list arrows with no row chosen";
  // One row chosen: that row's lists only.
  s.focus_row = big.grid.n[1] / 2;
  Recorder row;
  draw_scene(s, lists_only(), camera, row);
  EXPECT_FALSE(row.arrows.empty());
  std::size_t in_row = 0;
  for (const TracedList& l : big.lists) in_row += l.cell[1] == *s.focus_row && !l.secondary ? l.chain.size() : 0;
  EXPECT_LE(row.arrows.size(), 2 * in_row + big.lists.size());
  // A small scene still draws all of them while no row is chosen.
  const Traced small(testdata::make_layout(testdata::Layout::Dense, 200, 2, 3));
  OverlayScene t = small.scene();
  t.list_filter = ListFilter::Row;
  Recorder all;
  draw_scene(t, lists_only(), camera, all);
  EXPECT_FALSE(all.arrows.empty());
}

TEST(ListsOverlay, TheSteppersRowWinsOverTheHoveredOneMidFrame) {
  const std::array<std::int32_t, 2> hovered{3, 7};
  EXPECT_EQ(list_focus_row(4, hovered, 9), 4) << "hovering the scene moved the lists off the stepper's row";
  EXPECT_EQ(list_focus_row(std::nullopt, hovered, 9), 7);
  EXPECT_EQ(list_focus_row(std::nullopt, std::nullopt, 9), 9);
  EXPECT_EQ(list_focus_row(std::nullopt, std::nullopt, std::nullopt), std::nullopt);
}

TEST(ListsOverlay, ARailLongerThanFitsShowsItsNumberedEndsAndHowManyAreBetween) {
  // 800 elements in one row of a 40-cell-wide grid, seen whole at 1280 px: 800 slots would be 1 px
  // apart, a solid band.
  const int n = 800;
  Eigen::ArrayXd x(n), y = Eigen::ArrayXd::Constant(n, 0.5);
  for (int k = 0; k < n; ++k) x[k] = 0.25 + 0.05 * double((k * 37) % n);
  Traced t(make_elements_2d(x, y, Eigen::ArrayXd::Constant(n, 0.02)));
  Camera camera;
  camera.set_viewport(1280, 400);
  camera.fit({{-2, -1}, {42, 2}});
  OverlayScene s = t.scene();
  s.list_filter = ListFilter::All;
  OverlayFlags f = lists_only();
  Recorder rec;
  draw_scene(s, f, camera, rec);
  std::vector<float> slots;
  for (const auto& c : rec.circles)
    if (c.fill == palette::kYList) slots.push_back(c.centre.x());
  std::sort(slots.begin(), slots.end());
  ASSERT_GE(slots.size(), 4u);
  EXPECT_LT(slots.size(), static_cast<std::size_t>(n)) << "every slot drawn: a solid band";
  const double ppm = camera.pixels_per_metre();
  for (std::size_t i = 1; i < slots.size(); ++i) EXPECT_GE((slots[i] - slots[i - 1]) * ppm, 9.9) << "slots run together";
  const std::string more = "... " + std::to_string(n - static_cast<int>(slots.size())) + " more ...";
  EXPECT_TRUE(rec.has_text_containing(more)) << "no '" << more << "'";
  // Its ends are numbered: the list's first and last elements (the y-list runs from the highest id down).
  const auto y_list = std::find_if(t.lists.begin(), t.lists.end(), [](const TracedList& l) { return l.kind == "y-list"; });
  ASSERT_NE(y_list, t.lists.end());
  EXPECT_TRUE(rec.has_text_containing(std::to_string(y_list->chain.front())));
  EXPECT_TRUE(rec.has_text_containing(std::to_string(y_list->chain.back())));
}

// large.json's shape: 20,000 elements in a wide box whose cells are a few pixels at the fitted view.
struct Overview {
  Traced t{testdata::make_layout(testdata::Layout::Dense, 20'000, 2, 5)};
  Camera camera;
  Overview() {
    camera.set_viewport(1280, 720);
    const double w = t.grid.cell_size * double(t.grid.n[0]), h = t.grid.cell_size * double(t.grid.n[1]);
    camera.fit({{t.grid.origin[0], t.grid.origin[1]}, {t.grid.origin[0] + w, t.grid.origin[1] + h}}, 0.1);
  }
};

TEST(GridOverview, KeepsAxisNumbersAtItsMajorLines) {
  Overview o;
  ASSERT_LT(o.t.grid.cell_size * o.camera.pixels_per_metre(), kHeatMapBelowPx) << "not the overview";
  OverlayFlags f;
  Recorder rec;
  draw_scene(o.t.scene(), f, o.camera, rec);
  ASSERT_TRUE(rec.has_text_containing("lines every ")) << "the title names the major lines' step";
  std::string title;
  for (const auto& t : rec.texts)
    if (t.text.find("lines every ") != std::string::npos) title = t.text;
  const int step = std::stoi(title.substr(title.find("lines every ") + 12));
  // Dim numbers, each a multiple of the step, sitting on its line (x or y of the line).
  int columns = 0, rows = 0;
  const double x0 = o.t.grid.origin[0], y0 = o.t.grid.origin[1], d = o.t.grid.cell_size;
  for (const auto& t : rec.texts) {
    if (!(t.colour == palette::kTextDim) || t.text.empty() || !std::all_of(t.text.begin(), t.text.end(), ::isdigit)) continue;
    const int k = std::stoi(t.text);
    EXPECT_EQ(k % step, 0) << t.text << " is not at a major line";
    if (std::abs(double(t.at.x()) - (x0 + d * k)) < 1e-3 * d * step) ++columns;
    else if (std::abs(double(t.at.y()) - (y0 + d * k)) < 1e-3 * d * step) ++rows;
  }
  EXPECT_GE(columns, 3) << "the overview lost its column numbers";
  EXPECT_GE(rows, 2) << "the overview lost its row numbers";
}

TEST(GridOverview, TheHeatMapIsNotBuriedUnderPairsAndChecks) {
  Overview o;
  CheckDraw checks;
  checks.confirmed = o.t.pairs;  // every pair confirmed: green segments, as a settled run shows
  checks.violations = {o.t.pairs.front()};
  OverlayScene s = o.t.scene();
  s.checks = &checks;
  OverlayFlags f;  // pairs and checks on, as by default
  f.broadphase = true;
  Recorder rec;
  draw_scene(s, f, o.camera, rec);
  EXPECT_GT(rec.rects.size(), 100u) << "no heat map";
  EXPECT_EQ(rec.count(rec.lines, palette::kPair), 0) << "pair segments over the heat map";
  EXPECT_EQ(rec.count(rec.lines, palette::kConfirmedPair), 0) << "confirmed pairs over the heat map";
  EXPECT_TRUE(rec.has_text_containing("zoom in")) << "the legend does not say where the pairs went";
  // Zoomed in past the overview, pairs are drawn again.
  Camera close = o.camera;
  close.zoom_at(Eigen::Vector2d(640, 360), 8.0);
  Recorder near;
  draw_scene(s, f, close, near);
  EXPECT_GT(near.count(near.lines, palette::kConfirmedPair), 0);
}

}  // namespace
}  // namespace nbscope::render
