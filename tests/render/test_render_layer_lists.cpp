// The lists each layer's pass keeps in the layer view of a 3D frame, through a recording DrawSink (no
// pixels): at every operation of a 3D trace (nbs, screen, tree) the lists the view keeps are the
// Stepper's arrays, each layer keeps the lists of its own pass, and what is drawn is exactly what is
// kept. The layer view's elements, picking, marks and mask are in test_render_layers.cpp.
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
#include "support/layer_draw.hpp"

namespace nbscope::render {
namespace {

// The lists overlay alone (no grid, mask or pairs), as the layer-list tests draw it.
OverlayFlags lists_only() {
  OverlayFlags f;
  f.lists = true;
  f.grid = false;
  f.mask = false;
  f.pairs = false;
  return f;
}

using namespace testlayers;

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
  // `algorithm`'s traced run over the scatter: the log the stepper and the lists read.
  [[nodiscard]] TraceLog trace(const char* algorithm) const {
    DetectOptions o;
    o.grid = options;
    PairList pairs;
    TraceLog log;
    make_detector(algorithm)->detect_traced(e, o, pairs, log);
    return log;
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
  for (const char* algorithm : {"nbs", "screen", "tree"}) {
    SCOPED_TRACE(algorithm);
    const TraceLog log = sc.trace(algorithm);
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
  const TraceLog log = sc.trace("nbs");
  const auto lists = traced_lists(log, static_cast<std::size_t>(sc.e.size()));
  for (std::int32_t layer = 0; layer < 4; ++layer) {
    const LayerSlice slice = slice_layer(sc.e, sc.grid, layer);
    std::map<std::pair<std::string, ListLayerStyle>, std::size_t> kept;
    for (const LayerList& k : lists_in_layer(lists, slice)) ++kept[{lists[k.index].kind, k.style}];
    EXPECT_EQ(kept, nbs_pass(sc.e, sc.grid, layer)) << "layer " << layer;
  }
  // Screen 3D: each cell's list once, in its own layer's view and ghosted in the one above's.
  const TraceLog screen = sc.trace("screen");
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
  const Camera camera = camera_over(-1.0, 5.0);
  for (const char* algorithm : {"nbs", "screen", "tree"}) {
    SCOPED_TRACE(algorithm);
    const TraceLog log = sc.trace(algorithm);
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
      const OverlayFlags f = lists_only();
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
  const TraceLog log = sc.trace("nbs");
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
      const OverlayFlags f = lists_only();
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
  const TraceLog log = sc.trace("nbs");
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
