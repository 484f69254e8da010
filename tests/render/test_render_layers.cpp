// The layer view of a 3D frame, through a recording DrawSink (no pixels): the elements of the layer
// below ghosted and styled apart from the layer's own, those above and further not drawn at all,
// picking blind to them, a pair across layers drawn with the mark of its partner's layer, the 3D
// mask's cells, and the grid's title and shading of one layer. The lists each layer's pass keeps
// are in test_render_layer_lists.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/detector.hpp"
#include "core/layers.hpp"
#include "render/overlays.hpp"
#include "support/layer_draw.hpp"
#include "support/ui_fixture.hpp"

namespace nbscope::render {
namespace {

using namespace testlayers;


TEST(LayerView, TheLayerBelowIsGhostedApartAndTheLayersAboveAreNotDrawn) {
  const Column col;
  const LayerSlice slice = slice_layer(col.e, col.grid, 2);
  OverlayScene s;
  s.elements = &col.e;
  s.grid = &col.grid;
  s.shapes = col.shapes;
  s.layer = &slice;
  OverlayFlags f;
  f.elements = true;
  f.ids = true;
  f.grid = false;
  f.mask = false;
  Recorder rec;
  draw_scene(s, f, camera_over(-0.5, 4.5), rec);
  // Here (element 2): a solid body and a plain bounding circle, no dashes.
  const auto here = rec.circles_at(at(col.e, 2));
  ASSERT_EQ(here.size(), 2u) << "its body and its bounding circle";
  EXPECT_EQ(here[0].fill.a, 255);
  EXPECT_EQ(rec.dashes_around(at(col.e, 2), 0.3f), 0);
  // Below (element 1): a faint fill and dashed outlines (body and bounding circle), no solid outline.
  const auto below = rec.circles_at(at(col.e, 1));
  ASSERT_EQ(below.size(), 1u) << "the faint fill only: its outlines are dashes";
  EXPECT_LT(below[0].fill.a, 100);
  EXPECT_EQ(below[0].outline.a, 0);
  // Under the layer's bodies, dashes included (within a draw layer every line comes after every circle).
  EXPECT_LT(static_cast<int>(below[0].layer), static_cast<int>(here[0].layer));
  for (const auto& l : rec.lines)
    if (std::abs((l.from - at(col.e, 1)).norm() - 0.3f) < 1e-4f) {
      EXPECT_LT(static_cast<int>(l.layer), static_cast<int>(Layer::Bodies));
    }
  EXPECT_GE(rec.dashes_around(at(col.e, 1), 0.3f), 2 * 6);
  // Above (3) and two below (0): nothing at all, not even a line ending there.
  for (const ElementId k : {0, 3}) {
    EXPECT_TRUE(rec.circles_at(at(col.e, k)).empty()) << k;
    EXPECT_EQ(rec.dashes_around(at(col.e, k), 0.3f), 0) << k;
  }
  // Ids: the layer's in full, the ghost's faded, none of the hidden layers'.
  std::map<std::string, Rgba> ids;
  for (const auto& t : rec.texts) ids[t.text] = t.colour;
  ASSERT_TRUE(ids.contains("2"));
  ASSERT_TRUE(ids.contains("1"));
  EXPECT_LT(ids["1"].a, ids["2"].a);
  EXPECT_FALSE(ids.contains("0"));
  EXPECT_FALSE(ids.contains("3"));
  // Flashes and the selection of a hidden element are not drawn either.
  const std::pair<ElementId, float> flash[] = {{3, 1.0f}, {2, 1.0f}};
  s.flashes = flash;
  s.selected = 3;
  Recorder rec2;
  draw_scene(s, f, camera_over(-0.5, 4.5), rec2);
  EXPECT_TRUE(rec2.circles_at(at(col.e, 3)).empty());
  EXPECT_EQ(rec2.circles_at(at(col.e, 2)).size(), 3u) << "body, bounding circle, flash";
}

// A periodic x: the images across the edge are the layer's elements' only.
TEST(LayerView, PeriodicImagesAreTheLayersOnly) {
  Elements e;
  e.dim = 3;
  e.push_back(0.3, 0.5, 0.5, 0.3);  // 0: layer 0, near x's edge
  e.push_back(0.3, 3.0, 2.5, 0.3);  // 1: layer 2, near x's edge
  e.push_back(5.0, 1.5, 1.5, 0.3);  // 2: layer 1
  e.box.periodic[0] = true;
  e.box.lo[0] = 0.0;
  e.box.hi[0] = 10.0;
  GridOptions o;
  o.cell_size = 1.0;
  const Grid g = make_grid(e, o);
  ASSERT_EQ(g.n[2], 3);
  const LayerSlice slice = slice_layer(e, g, 0);
  OverlayScene s;
  s.elements = &e;
  s.grid = &g;
  s.layer = &slice;
  OverlayFlags f;
  f.elements = true;
  f.grid = false;
  Recorder rec;
  draw_scene(s, f, camera_over(-1.0, 11.0), rec);
  EXPECT_FALSE(rec.circles_at({10.3f, 0.5f}).empty()) << "the layer's element, again across the edge";
  EXPECT_TRUE(rec.circles_at({10.3f, 3.0f}).empty()) << "an element two layers up has no image either";
}

TEST(LayerView, PickingSeesOnlyTheLayerShown) {
  Elements e;
  e.dim = 3;
  e.push_back(1.0, 1.0, 1.5, 0.4);  // 0: layer 1, under element 1
  e.push_back(1.1, 1.0, 2.5, 0.45); // 1: layer 2
  e.push_back(3.0, 3.0, 3.5, 0.3);  // 2: layer 3, alone at (3, 3)
  e.push_back(3.0, 1.0, 1.5, 0.3);  // 3: layer 1, alone at (3, 1)
  const Grid g = make_grid(e, unit_cells(4, 4, 4));
  const LayerSlice two = slice_layer(e, g, 2);
  EXPECT_EQ(element_at(e, {1.0, 1.0}, nullptr), 0) << "2D rule: the smallest circle";
  EXPECT_EQ(element_at(e, {1.0, 1.0}), 0);
  EXPECT_EQ(element_at(e, {1.0, 1.0}, &two), 1) << "the layer's element, not the ghost under it";
  EXPECT_EQ(element_at(e, {3.0, 3.0}, &two), -1) << "an element of the layer above";
  EXPECT_EQ(element_at(e, {3.0, 1.0}, &two), -1) << "a ghost of the layer below";
  const LayerSlice one = slice_layer(e, g, 1);
  EXPECT_EQ(element_at(e, {3.0, 1.0}, &one), 3);
}

// The window's click (ui/host.cpp) picks through the layer shown.
TEST(LayerView, AClickInTheWindowPicksOnlyTheLayersElement) {
  ui::testui::ImGuiScope scope;
  ui::UiHost host;
  ui::testui::BookFrame f;
  Elements e;
  e.dim = 3;
  e.push_back(5.0, 5.0, 2.5, 0.4);  // 0: layer 2, hidden in layer 1's view
  e.push_back(6.0, 5.0, 1.5, 0.4);  // 1: layer 1
  const Grid g = make_grid(e, unit_cells(10, 10, 4));
  const LayerSlice slice = slice_layer(e, g, 1);
  f.elements = e;
  f.sim.layer = &slice;
  ImGuiIO& io = ImGui::GetIO();
  const auto click = [&](double x, double y) {
    const Eigen::Vector2d px = f.camera.to_screen({x, y});
    io.MousePos = ImVec2(static_cast<float>(px.x()), static_cast<float>(px.y()));
    io.MouseDown[0] = false;
    ui::testui::run_frame(host, f);
    io.MouseDown[0] = true;
    ui::testui::run_frame(host, f);
    io.MouseDown[0] = false;
    ui::testui::run_frame(host, f);
    return f.state.selected;
  };
  EXPECT_EQ(click(6.0, 5.0), 1);
  EXPECT_EQ(click(5.0, 5.0), -1) << "an element of the layer above";
}

TEST(LayerView, APairAcrossLayersIsDrawnInBothWithItsPartnersLayerMarked) {
  const Column col;
  Elements e = col.e;
  const LayerSlice slice = slice_layer(e, col.grid, 2);
  // (1, 2): below-here; (2, 3): here-above; (0, 1): two ghosts/hidden; (0, 3): hidden-hidden.
  const PairList pairs = {{0, 1}, {0, 3}, {1, 2}, {2, 3}};
  CheckDraw checks;
  checks.violations = {{1, 2}};
  OverlayScene s;
  s.elements = &e;
  s.grid = &col.grid;
  s.pairs = &pairs;
  s.layer = &slice;
  OverlayFlags f;
  f.grid = false;
  f.bodies = false;
  f.checks = false;
  Recorder rec;
  draw_scene(s, f, camera_over(-0.5, 4.5), rec);
  const auto segment_in = [&](const Recorder& r, ElementId i, ElementId j, Rgba colour) {
    return std::count_if(r.lines.begin(), r.lines.end(), [&](const Recorder::Line& l) {
      return l.colour == colour && (((l.from - at(e, i)).norm() < 1e-4f && (l.to - at(e, j)).norm() < 1e-4f) ||
                                    ((l.from - at(e, j)).norm() < 1e-4f && (l.to - at(e, i)).norm() < 1e-4f));
    });
  };
  const auto segment = [&](ElementId i, ElementId j, Rgba colour) { return segment_in(rec, i, j, colour); };
  EXPECT_EQ(segment(1, 2, palette::kPair), 1);
  EXPECT_EQ(segment(2, 3, palette::kPair), 1) << "to the hidden partner's (x, y)";
  EXPECT_EQ(segment(0, 1, palette::kPair), 0) << "no element of the layer shown";
  EXPECT_EQ(segment(0, 3, palette::kPair), 0);
  // The marks: a chevron (two strokes meeting over the partner's centre) and its layer beside it.
  const auto chevron = [&](const Recorder& r, ElementId k, bool down, Rgba colour = palette::kPair) {
    // Two strokes over the partner's centre meeting at its x: below the centre for a "v", above for a "^".
    const Vec2 c = at(e, k);
    int strokes = 0;
    for (const auto& l : r.lines)
      if (l.colour == colour && (std::abs(l.to.x() - c.x()) < 1e-5f || std::abs(l.from.x() - c.x()) < 1e-5f)) {
        const float tip_y = std::abs(l.to.x() - c.x()) < 1e-5f ? l.to.y() : l.from.y();
        if (std::abs(tip_y - c.y()) > 1e-6f && std::abs(tip_y - c.y()) < 0.2f && (tip_y < c.y()) == down) ++strokes;
      }
    return strokes == 2;
  };
  EXPECT_TRUE(chevron(rec, 1, true)) << "v at the partner below";
  EXPECT_TRUE(chevron(rec, 3, false)) << "^ at the partner above";
  EXPECT_FALSE(chevron(rec, 2, true) || chevron(rec, 2, false)) << "none at the layer's own end";
  EXPECT_TRUE(rec.has_text("iz-1"));
  EXPECT_TRUE(rec.has_text("iz+1"));
  // A violation across layers keeps its red, and its mark is red too.
  s.checks = &checks;
  f.checks = true;
  Recorder red;
  draw_scene(s, f, camera_over(-0.5, 4.5), red);
  EXPECT_EQ(segment_in(red, 1, 2, palette::kViolation), 1);
  EXPECT_TRUE(chevron(red, 1, true, palette::kViolation));
  EXPECT_TRUE(std::any_of(red.texts.begin(), red.texts.end(), [](const auto& t) { return t.text == "iz-1" && t.colour == palette::kViolation; }));
  // A violation gone to (the focus pair): its partner's end marked too, in the focus's white.
  s.checks = nullptr;
  s.pairs = nullptr;
  s.focus_pair = Pair{1, 2};
  Recorder focus;
  draw_scene(s, f, camera_over(-0.5, 4.5), focus);
  EXPECT_TRUE(chevron(focus, 1, true, palette::kSelection));
  s.focus_pair.reset();
  s.pairs = &pairs;
  // Seen from layer 3: (2, 3) with a "v" at 2, and (0, 3), a wrong pair three layers apart, with
  // "iz-3"; (1, 2) is not drawn (neither element is in layer 3).
  const LayerSlice three = slice_layer(e, col.grid, 3);
  s.layer = &three;
  s.checks = nullptr;
  Recorder up;
  draw_scene(s, f, camera_over(-0.5, 4.5), up);
  EXPECT_EQ(segment_in(up, 2, 3, palette::kPair), 1);
  EXPECT_EQ(segment_in(up, 0, 3, palette::kPair), 1);
  EXPECT_EQ(segment_in(up, 1, 2, palette::kPair), 0);
  EXPECT_TRUE(chevron(up, 2, true));
  EXPECT_TRUE(chevron(up, 0, true));
  EXPECT_TRUE(up.has_text("iz-1"));
  EXPECT_TRUE(up.has_text("iz-3"));
  EXPECT_FALSE(up.has_text("iz+1"));
}

TEST(LayerView, TheMaskIsTheCellsOwnLayersFiveAndTheNineBelow) {
  Elements e;
  e.dim = 3;
  e.push_back(0.5, 0.5, 0.5, 0.3);
  const Grid g = make_grid(e, unit_cells(5, 5, 4));
  // Inside: own cell, (ix-1, iy), (ix-1..ix+1, iy-1) in layer 2, the nine around (ix, iy) in layer 1.
  auto cells = mask_cells_3d(g, 2, 2, 2);
  ASSERT_EQ(cells.size(), 14u);
  EXPECT_EQ(cells.front(), (std::array<std::int32_t, 3>{2, 2, 2}));
  std::set<std::array<std::int32_t, 3>> expected{{2, 2, 2}, {1, 2, 2}, {1, 1, 2}, {2, 1, 2}, {3, 1, 2}};
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy) expected.insert({2 + dx, 2 + dy, 1});
  EXPECT_EQ(std::set(cells.begin(), cells.end()), expected);
  // At the edges: fewer.
  EXPECT_EQ(mask_cells_3d(g, 0, 0, 0).size(), 1u) << "the first cell of the first layer reaches nothing";
  EXPECT_EQ(mask_cells_3d(g, 0, 0, 1).size(), 5u) << "own cell and four below";
  EXPECT_EQ(mask_cells_3d(g, 4, 4, 3).size(), 1u + 3u + 4u) << "the last cell: three of its layer's, four below";

  // Drawn: this layer's cells as full cells (the own one stronger), the layer below's inside them.
  const LayerSlice slice = slice_layer(e, g, 2);
  OverlayScene s;
  s.elements = &e;
  s.grid = &g;
  s.layer = &slice;
  s.hovered_cell = std::array<std::int32_t, 2>{2, 2};
  OverlayFlags f;
  f.grid = false;
  Recorder rec;
  draw_scene(s, f, camera_over(-0.5, 5.5), rec);
  int own = 0, layer = 0, below = 0;
  for (const auto& r : rec.rects) {
    if (r.layer != Layer::Cells) continue;
    const float w = r.max.x() - r.min.x();
    if (r.colour == palette::kMaskCentre) ++own;
    else if (r.colour == palette::kMaskCell) ++layer;
    else if (w < 0.9f && w > 0.3f) {
      ++below;
      // Inside a cell of rows 1..3, columns 1..3.
      EXPECT_GE(r.min.x(), 1.0f);
      EXPECT_LE(r.max.x(), 4.0f);
    }
  }
  EXPECT_EQ(own, 1);
  EXPECT_EQ(layer, 4);
  EXPECT_EQ(below, 9);
  EXPECT_TRUE(std::any_of(rec.texts.begin(), rec.texts.end(), [](const auto& t) { return t.text.find("inner squares") != std::string::npos; }))
      << "the legend says what the inner squares are";
}

TEST(LayerView, TheGridNamesItsLayerAndShadesOnlyItsElements) {
  const Column col;
  Elements e = col.e;
  e.push_back(2.6, 0.5, 2.2, 0.3);  // 4: a second element of layer 2, in another cell
  const Grid g = make_grid(e, unit_cells(4, 4, 4));
  const LayerSlice slice = slice_layer(e, g, 2);
  OverlayScene s;
  s.elements = &e;
  s.grid = &g;
  s.layer = &slice;
  OverlayFlags f;
  f.mask = false;
  f.bodies = false;
  Recorder rec;
  draw_scene(s, f, camera_over(-1.0, 5.0), rec);
  EXPECT_TRUE(std::any_of(rec.texts.begin(), rec.texts.end(), [](const auto& t) {
    return t.text.find("layer iz = 2 of 4") != std::string::npos && t.text.find("[2, 3)") != std::string::npos;
  }));
  std::set<std::pair<int, int>> shaded;
  for (const auto& r : rec.rects)
    if (r.layer == Layer::Cells) shaded.insert({static_cast<int>(std::floor(r.min.x() + 0.5f)), static_cast<int>(std::floor(r.min.y() + 0.5f))});
  EXPECT_EQ(shaded, (std::set<std::pair<int, int>>{{2, 2}, {2, 0}})) << "the layer's two cells only";
}

// A settled pack has a cross-layer mark at most contacts: past a few dozen in view the chevrons
// stay and their labels go (the legend says what they mean).
TEST(LayerView, ManyCrossLayerMarksGoWithoutTheirLabels) {
  Elements e;
  e.dim = 3;
  PairList pairs;
  for (int k = 0; k < 60; ++k) {
    e.push_back(0.5 + (k % 10), 0.5 + (k / 10), 1.5, 0.4);  // layer 1
    e.push_back(0.85 + (k % 10), 0.5 + (k / 10), 0.7, 0.4);  // layer 0, under it
    pairs.push_back({2 * k, 2 * k + 1});
  }
  const Grid g = make_grid(e, unit_cells(10, 6, 2));
  const LayerSlice slice = slice_layer(e, g, 1);
  const auto draw = [&](std::size_t count) {
    const PairList some(pairs.begin(), pairs.begin() + static_cast<std::ptrdiff_t>(count));
    OverlayScene s;
    s.elements = &e;
    s.grid = &g;
    s.pairs = &some;
    s.layer = &slice;
    OverlayFlags f;
    f.grid = false;
    Recorder rec;
    draw_scene(s, f, camera_over(-0.5, 10.5), rec);
    std::size_t labels = 0, strokes = 0;
    for (const auto& t : rec.texts) labels += t.text == "iz-1" ? 1 : 0;
    for (const auto& l : rec.lines) strokes += l.colour == palette::kPair && (l.to - l.from).norm() < 0.2f ? 1 : 0;
    return std::pair{labels, strokes};
  };
  const auto [few_labels, few_strokes] = draw(10);
  EXPECT_EQ(few_labels, 10u);
  EXPECT_EQ(few_strokes, 20u);
  const auto [many_labels, many_strokes] = draw(60);
  EXPECT_EQ(many_labels, 0u);
  EXPECT_EQ(many_strokes, 120u) << "every chevron still drawn";
}

}  // namespace
}  // namespace nbscope::render
