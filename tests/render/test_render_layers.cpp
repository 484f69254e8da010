// The layer view of a 3D frame, through a recording DrawSink (no pixels): the elements of the layer
// below ghosted and styled apart from the layer's own, those above and further not drawn at all,
// picking blind to them, a pair across layers drawn with the mark of its partner's layer, the 3D
// mask's cells, the grid's title and shading of one layer, and the lists each layer's pass keeps —
// at every operation of a 3D trace (nbs, screen, tree) the lists the view keeps are the Stepper's
// arrays, and what is drawn is exactly what is kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "core/detector.hpp"
#include "core/layers.hpp"
#include "core/stepper.hpp"
#include "core/traced_lists.hpp"
#include "render/overlays.hpp"
#include "support/ui_fixture.hpp"

namespace nbscope::render {
namespace {

struct Recorder final : DrawSink {
  struct Circle {
    Layer layer;
    Vec2 centre;
    float radius;
    Rgba fill, outline;
  };
  struct Line {
    Layer layer;
    Vec2 from, to;
    Rgba colour;
  };
  struct Rect {
    Layer layer;
    Vec2 min, max;
    Rgba colour;
  };
  struct Text {
    Vec2 at;
    std::string text;
    Rgba colour;
  };
  std::vector<Circle> circles;
  std::vector<Line> lines, arrows;
  std::vector<Rect> rects;
  std::vector<Text> texts;
  void circle(Layer layer, Vec2 c, float r, Rgba fill, Rgba outline, float, float) override {
    circles.push_back({layer, c, r, fill, outline});
  }
  void polygon(Layer, std::span<const Vec2>, Rgba, Rgba) override {}
  void line(Layer layer, Vec2 a, Vec2 b, Rgba c, float) override { lines.push_back({layer, a, b, c}); }
  void arrow(Layer layer, Vec2 a, Vec2 b, Rgba c, float) override { arrows.push_back({layer, a, b, c}); }
  void rect(Layer layer, Vec2 lo, Vec2 hi, Rgba c) override { rects.push_back({layer, lo, hi, c}); }
  void text(Vec2 at, std::string_view t, Rgba c) override { texts.push_back({at, std::string(t), c}); }

  // Circles centred on `at` (within a hair).
  [[nodiscard]] std::vector<Circle> circles_at(Vec2 at) const {
    std::vector<Circle> out;
    for (const Circle& c : circles)
      if ((c.centre - at).norm() < 1e-4f) out.push_back(c);
    return out;
  }
  // Segments with both ends on the circle of radius r around `at` (a dashed outline's dashes).
  [[nodiscard]] int dashes_around(Vec2 at, float r) const {
    int n = 0;
    for (const Line& l : lines)
      if (std::abs((l.from - at).norm() - r) < 1e-4f && std::abs((l.to - at).norm() - r) < 1e-4f) ++n;
    return n;
  }
  [[nodiscard]] bool has_text(const std::string& t) const {
    return std::any_of(texts.begin(), texts.end(), [&](const Text& x) { return x.text == t; });
  }
};

Vec2 at(const Elements& e, ElementId k) { return {static_cast<float>(e.x[k]), static_cast<float>(e.y[k])}; }

// Unit cells from the origin, nx x ny x nz of them.
GridOptions unit_cells(std::int64_t nx, std::int64_t ny, std::int64_t nz) {
  GridOptions o;
  o.cell_size = 1.0;
  o.origin = {0.0, 0.0, 0.0};
  o.cells = {{nx, ny, nz}};
  return o;
}

// Four spheres one above the other's layer, each at its own (x, y) in a 4 x 4 x 4 grid: element k
// in layer k (0: two below the layer shown, 1: below, 2: the layer shown, 3: above).
struct Column {
  Elements e;
  Grid grid;
  std::vector<ShapeDraw> shapes;
  Column() {
    e.dim = 3;
    e.push_back(0.5, 0.5, 0.5, 0.3);
    e.push_back(1.5, 1.5, 1.5, 0.3);
    e.push_back(2.5, 2.5, 2.5, 0.3);
    e.push_back(3.5, 3.5, 3.5, 0.3);
    grid = make_grid(e, unit_cells(4, 4, 4));
    for (ElementId k = 0; k < 4; ++k) {
      ShapeDraw s;
      s.centre = at(e, k);
      s.radius = 0.3f;
      s.element = k;
      s.spoke = false;
      shapes.push_back(s);
    }
  }
};

Camera camera_over(double lo, double hi) {
  Camera c;
  c.set_viewport(1280, 720);
  c.fit({{lo, lo}, {hi, hi}});
  return c;
}

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

// ---- lists: the 3D twin of Overlays.ListsMidTraceAreTheStepperArraysAtThatOperation ---------------

// Forty spheres of radius 0.45 scattered in a 4 x 4 x 4 grid of unit cells: pairs within and across layers.
struct Scatter {
  Elements e;
  GridOptions options = unit_cells(4, 4, 4);
  Grid grid;
  Scatter() {
    e.dim = 3;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.05, 3.95);
    for (int k = 0; k < 40; ++k) e.push_back(u(rng), u(rng), u(rng), 0.45);
    grid = make_grid(e, options);
  }
};

// The layer the stepper is in: its phase's (NBS 3D's passes name theirs), else its event's cell's,
// else the last one seen.
std::int32_t stepper_layer(const Stepper& st, std::int32_t last) {
  const std::int64_t ph = st.current_phase();
  if (ph >= 0) {
    const TraceEvent& e = st.events()[st.phases()[static_cast<std::size_t>(ph)].event];
    if (e.cell[2] >= 0) return e.cell[2];
  }
  const LoopVars lv = st.loop_vars();
  return lv.iz >= 0 ? lv.iz : last;
}

TEST(LayerView, ListsMidTraceAreTheStepperArraysInTheStepperLayer) {
  const Scatter sc;
  const auto n = static_cast<std::size_t>(sc.e.size());
  DetectOptions o;
  o.grid = sc.options;
  for (const char* algorithm : {"nbs", "screen", "tree"}) {
    SCOPED_TRACE(algorithm);
    PairList pairs;
    TraceLog log;
    make_detector(algorithm)->detect_traced(sc.e, o, pairs, log);
    Stepper st;
    st.load(log);
    std::size_t checked = 0, pushes = 0, below = 0;
    std::int32_t layer = 0;
    for (std::size_t p = 1; p <= st.size(); ++p) {
      st.seek(p);
      layer = stepper_layer(st, layer);
      const LayerSlice slice = slice_layer(sc.e, sc.grid, layer);
      const auto lists = traced_lists(log, n, p);
      const auto kept = lists_in_layer(lists, slice);
      for (const LayerList& k : kept) {
        const TracedList& l = lists[k.index];
        if (k.style == ListLayerStyle::Below) ++below;
        const auto& head = st.state()[static_cast<std::size_t>(l.heads_array)];
        // Still standing at p (its head not cleared since): the Arrays panel shows the same chain.
        if (head[static_cast<std::size_t>(l.slot)] != l.chain.front()) continue;
        EXPECT_EQ(l.chain, st.list_members(l.heads_array, l.slot)) << "at operation " << p << ", layer " << layer;
        ++checked;
      }
      // The list the stepper is writing is in the layer view that follows it (z-lists: the Layers panel's).
      const TraceEvent& ev = *st.current();
      if (ev.op != TraceOp::Push || std::string(ev.label) == "z-list") continue;
      ++pushes;
      const auto members = st.list_members(ev.writes[1].array, ev.writes[1].index);
      EXPECT_TRUE(std::any_of(kept.begin(), kept.end(), [&](const LayerList& k) {
        const TracedList& l = lists[k.index];
        return l.heads_array == ev.writes[1].array && l.slot == ev.writes[1].index && l.chain == members;
      })) << "operation " << p << " pushes onto a list the view of layer " << layer << " leaves out";
    }
    EXPECT_GT(checked, n);
    EXPECT_GE(pushes, n);
    EXPECT_GT(below, 0u) << "lists of the layer below were kept, ghosted";
  }
}

// What NBS 3D's pass of layer L builds, counted from the elements alone: the y-lists of L's rows
// (B[0]) and of L-1's (B[1]); for each row iy of L, the x-lists of rows (iy, L) and (iy-1, L), and
// of rows iy-1..iy+1 of L-1.
std::map<std::pair<std::string, ListLayerStyle>, std::size_t> nbs_pass(const Elements& e, const Grid& g, std::int32_t layer) {
  std::map<std::int32_t, std::set<std::int32_t>> rows;                      // layer -> rows
  std::map<std::pair<std::int32_t, std::int32_t>, std::set<std::int32_t>> cells;  // (layer, row) -> columns
  for (ElementId k = 0; k < static_cast<ElementId>(e.size()); ++k) {
    const std::int32_t ix = g.cell(e.x[k], 0), iy = g.cell(e.y[k], 1), iz = g.cell(e.z[k], 2);
    rows[iz].insert(iy);
    cells[{iz, iy}].insert(ix);
  }
  std::map<std::pair<std::string, ListLayerStyle>, std::size_t> count;
  if (rows[layer].empty()) return count;
  const std::int32_t below = layer - 1;
  count[{"y-list", ListLayerStyle::Here}] = rows[layer].size();
  if (below >= 0 && !rows[below].empty()) count[{"y-list", ListLayerStyle::Below}] = rows[below].size();
  for (const std::int32_t iy : rows[layer]) {
    for (const std::int32_t r : {iy, iy - 1}) count[{"x-list", ListLayerStyle::Here}] += cells[{layer, r}].size();
    if (below < 0 || rows[below].empty()) continue;
    for (const std::int32_t r : {iy - 1, iy, iy + 1}) count[{"x-list", ListLayerStyle::Below}] += cells[{below, r}].size();
  }
  std::erase_if(count, [](const auto& kv) { return kv.second == 0; });
  return count;
}

TEST(LayerView, EachLayerKeepsTheListsOfItsOwnPass) {
  const Scatter sc;
  DetectOptions o;
  o.grid = sc.options;
  PairList pairs;
  TraceLog log;
  make_detector("nbs")->detect_traced(sc.e, o, pairs, log);
  const auto lists = traced_lists(log, static_cast<std::size_t>(sc.e.size()));
  for (std::int32_t layer = 0; layer < 4; ++layer) {
    const LayerSlice slice = slice_layer(sc.e, sc.grid, layer);
    std::map<std::pair<std::string, ListLayerStyle>, std::size_t> kept;
    for (const LayerList& k : lists_in_layer(lists, slice)) ++kept[{lists[k.index].kind, k.style}];
    EXPECT_EQ(kept, nbs_pass(sc.e, sc.grid, layer)) << "layer " << layer;
  }
  // Screen 3D: each cell's list once, in its own layer's view and ghosted in the one above's.
  PairList screen_pairs;
  TraceLog screen;
  make_detector("screen")->detect_traced(sc.e, o, screen_pairs, screen);
  const auto cell_lists = traced_lists(screen, static_cast<std::size_t>(sc.e.size()));
  std::map<std::int32_t, std::set<std::pair<std::int32_t, std::int32_t>>> cells;
  for (ElementId k = 0; k < static_cast<ElementId>(sc.e.size()); ++k)
    cells[sc.grid.cell(sc.e.z[k], 2)].insert({sc.grid.cell(sc.e.x[k], 0), sc.grid.cell(sc.e.y[k], 1)});
  for (std::int32_t layer = 0; layer < 4; ++layer) {
    std::size_t here = 0, below = 0;
    for (const LayerList& k : lists_in_layer(cell_lists, slice_layer(sc.e, sc.grid, layer)))
      ++(k.style == ListLayerStyle::Here ? here : below);
    EXPECT_EQ(here, cells[layer].size()) << layer;
    EXPECT_EQ(below, layer > 0 ? cells[layer - 1].size() : 0u) << layer;
  }
}

// The lists drawn, from the heads' squares (6 px rects on the overlay layer in a list's colour):
// (style, row, column or -1 for a row's head left of the grid).
using HeadKey = std::tuple<int, std::int32_t, std::int32_t>;
std::multiset<HeadKey> drawn_heads(const Recorder& rec, const Grid& g, double ppm) {
  std::multiset<HeadKey> out;
  for (const auto& r : rec.rects) {
    if (r.layer != Layer::Overlay || std::abs((r.max.x() - r.min.x()) * ppm - 6.0) > 0.1) continue;
    const Vec2 c = 0.5f * (r.min + r.max);
    const bool below = r.colour.a < 255;
    const auto row = static_cast<std::int32_t>(std::floor((c.y() - g.origin[1]) / g.cell_size));
    const std::int32_t col = c.x() < g.origin[0] ? -1 : static_cast<std::int32_t>(std::floor((c.x() - g.origin[0]) / g.cell_size));
    out.insert({below ? 1 : 0, row, col});
  }
  return out;
}

TEST(LayerView, TheListsDrawnAreExactlyTheListsKept) {
  const Scatter sc;
  const auto n = static_cast<std::size_t>(sc.e.size());
  DetectOptions o;
  o.grid = sc.options;
  const Camera camera = camera_over(-1.0, 5.0);
  for (const char* algorithm : {"nbs", "screen", "tree"}) {
    SCOPED_TRACE(algorithm);
    PairList pairs;
    TraceLog log;
    make_detector(algorithm)->detect_traced(sc.e, o, pairs, log);
    // Mid-trace (the middle operation) and at the end.
    Stepper st;
    st.load(log);
    for (const std::size_t p : {st.size() / 2, st.size()}) {
      st.seek(p);
      const std::int32_t layer = stepper_layer(st, 1);
      const LayerSlice slice = slice_layer(sc.e, sc.grid, layer);
      const auto lists = traced_lists(log, n, p);
      std::multiset<HeadKey> expected;
      for (const LayerList& k : lists_in_layer(lists, slice)) {
        const TracedList& l = lists[k.index];
        expected.insert({k.style == ListLayerStyle::Below ? 1 : 0, l.cell[1], l.cell[0] >= 0 ? l.cell[0] : -1});
      }
      OverlayScene s;
      s.elements = &sc.e;
      s.grid = &sc.grid;
      s.lists = &lists;
      s.layer = &slice;
      OverlayFlags f;
      f.lists = true;
      f.grid = false;
      f.mask = false;
      f.pairs = false;
      Recorder rec;
      draw_scene(s, f, camera, rec);
      EXPECT_FALSE(expected.empty()) << "operation " << p;
      EXPECT_EQ(drawn_heads(rec, sc.grid, camera.pixels_per_metre()), expected) << "operation " << p << ", layer " << layer;
      // The legend names the kinds drawn, never the z-lists (the Layers panel's).
      EXPECT_FALSE(std::any_of(rec.texts.begin(), rec.texts.end(), [](const auto& t) { return t.text == "z-list"; }));
    }
  }
}

// The row filter in a layer: the lists NBS 3D uses for that row — its y-list and the one of the row
// under it in the layer below, and the x-lists built for the row: the cells of rows iy and iy-1 of
// the layer, and of rows iy-1..iy+1 of the layer below (ghosted).
TEST(LayerView, TheRowFilterKeepsTheListsOfOneRowsPass) {
  const Scatter sc;
  DetectOptions o;
  o.grid = sc.options;
  PairList pairs;
  TraceLog log;
  make_detector("nbs")->detect_traced(sc.e, o, pairs, log);
  const auto lists = traced_lists(log, static_cast<std::size_t>(sc.e.size()));
  const Grid& g = sc.grid;
  std::map<std::pair<std::int32_t, std::int32_t>, std::set<std::int32_t>> cells;  // (layer, row) -> columns
  for (ElementId k = 0; k < static_cast<ElementId>(sc.e.size()); ++k)
    cells[{g.cell(sc.e.z[k], 2), g.cell(sc.e.y[k], 1)}].insert(g.cell(sc.e.x[k], 0));
  const Camera camera = camera_over(-1.0, 5.0);
  std::size_t rows_checked = 0;
  for (std::int32_t layer = 1; layer < 4; ++layer)
    for (std::int32_t row = 0; row < 4; ++row) {
      if (cells[{layer, row}].empty() || cells[{layer - 1, row}].empty()) continue;
      ++rows_checked;
      std::multiset<HeadKey> expected{{0, row, -1}, {1, row, -1}};
      for (const std::int32_t r : {row, row - 1})
        for (const std::int32_t ix : cells[{layer, r}]) expected.insert({0, r, ix});
      for (const std::int32_t r : {row - 1, row, row + 1})
        for (const std::int32_t ix : cells[{layer - 1, r}]) expected.insert({1, r, ix});
      const LayerSlice slice = slice_layer(sc.e, g, layer);
      OverlayScene s;
      s.elements = &sc.e;
      s.grid = &g;
      s.lists = &lists;
      s.layer = &slice;
      s.list_filter = ListFilter::Row;
      s.focus_row = row;
      OverlayFlags f;
      f.lists = true;
      f.grid = false;
      f.mask = false;
      f.pairs = false;
      Recorder rec;
      draw_scene(s, f, camera, rec);
      EXPECT_EQ(drawn_heads(rec, g, camera.pixels_per_metre()), expected) << "layer " << layer << ", row " << row;
    }
  EXPECT_GT(rows_checked, 2u);
}

// NBS 3D rebuilds a head A[r][ix] for each row of a layer's pass, not in row order: the list the
// stepper is writing is highlighted along the build of its row, never an older build of the head.
TEST(LayerView, TheStepperListIsTheBuildOfItsRow) {
  const Scatter sc;
  const auto n = static_cast<std::size_t>(sc.e.size());
  DetectOptions o;
  o.grid = sc.options;
  PairList pairs;
  TraceLog log;
  make_detector("nbs")->detect_traced(sc.e, o, pairs, log);
  Stepper st;
  st.load(log);
  std::int32_t layer = 0;
  std::size_t tried = 0;
  for (std::size_t p = 1; p <= st.size(); ++p) {
    st.seek(p);
    layer = stepper_layer(st, layer);
    const TraceEvent& ev = *st.current();
    if (ev.op != TraceOp::Push || std::string(ev.label) != "x-list") continue;
    const LayerSlice slice = slice_layer(sc.e, sc.grid, layer);
    const auto lists = traced_lists(log, n, p);
    const auto kept = lists_in_layer(lists, slice);
    const auto builds = std::count_if(kept.begin(), kept.end(), [&](const LayerList& k) {
      return lists[k.index].heads_array == ev.writes[1].array && lists[k.index].slot == ev.writes[1].index;
    });
    if (builds < 2) continue;
    ++tried;
    OverlayScene s;
    s.elements = &sc.e;
    s.grid = &sc.grid;
    s.lists = &lists;
    s.layer = &slice;
    s.active_list = std::pair{static_cast<int>(ev.writes[1].array), static_cast<std::int64_t>(ev.writes[1].index)};
    s.focus_row = st.phases()[static_cast<std::size_t>(st.current_phase())].index;  // the row whose pass this is
    OverlayFlags f;
    f.lists = true;
    f.grid = false;
    f.mask = false;
    Recorder rec;
    draw_scene(s, f, camera_over(-1.0, 5.0), rec);
    const auto chain = st.list_members(ev.writes[1].array, ev.writes[1].index);
    std::size_t highlighted = 0;
    for (const auto& l : rec.lines) {
      if (l.colour != palette::kActiveList) continue;
      ++highlighted;
      EXPECT_TRUE(std::any_of(chain.begin(), chain.end(), [&](ElementId k) { return (l.to - at(sc.e, k)).norm() < sc.e.r[k]; }))
          << "operation " << p << ": a highlighted link ends off the list being written";
    }
    EXPECT_EQ(highlighted, chain.size()) << "operation " << p << ": one highlighted link per element";
  }
  EXPECT_GT(tried, 0u) << "no x-list pushed onto a head built before in the same layer";
}

}  // namespace
}  // namespace nbscope::render
