// The layer view's 3D parts: which lists a layer's view keeps, the 3D contact mask, picking within
// the layer, and the marks that tell a pair's partner in the layer below or above. The other
// overlays call these when OverlayScene::layer is set (a 3D frame).
//
// Index: lists_in_layer | mask_cells_3d | element_at | dashed ghosts | pairs across layers | mask.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>

#include "core/cells.hpp"
#include "render/overlay_parts.hpp"

namespace nbscope::render {

std::vector<LayerList> lists_in_layer(const std::vector<TracedList>& lists, const LayerSlice& slice) {
  std::vector<LayerList> kept;
  for (std::size_t i = 0; i < lists.size(); ++i) {
    const TracedList& l = lists[i];
    if (l.kind == "z-list") continue;
    // NBS 3D builds lists of layer iz-1 again in layer iz's pass (B[1], the x-lists of the rows
    // below): the view shows that pass's, not the ones built for the layers on either side.
    if (l.phase_layer >= 0 && l.phase_layer != slice.layer) continue;
    const LayerPlace place = list_layer_place(l, slice);
    if (place == LayerPlace::Here) kept.push_back({i, ListLayerStyle::Here});
    else if (place == LayerPlace::Below) kept.push_back({i, ListLayerStyle::Below});
  }
  return kept;
}

std::vector<std::array<std::int32_t, 3>> mask_cells_3d(const Grid& grid, std::int32_t ix, std::int32_t iy, std::int32_t iz) {
  std::vector<std::array<std::int32_t, 3>> cells{{ix, iy, iz}};
  for (const CellOffset& o : kMask3d) {
    const std::int32_t x = grid.neighbour(ix, o.dx, 0), y = grid.neighbour(iy, o.dy, 1), z = grid.neighbour(iz, o.dz, 2);
    if (x >= 0 && y >= 0 && z >= 0) cells.push_back({x, y, z});
  }
  return cells;
}

ElementId element_at(const Elements& e, const Eigen::Vector2d& world, const LayerSlice* layer) {
  ElementId best = -1;
  double best_r = 0;
  const bool sliced = layer != nullptr && layer->element_layer.size() == static_cast<std::size_t>(e.size());
  for (ElementId k = 0; k < static_cast<ElementId>(e.size()); ++k) {
    if (sliced && layer->place(k) != LayerPlace::Here) continue;
    const double dx = e.x[k] - world.x(), dy = e.y[k] - world.y();
    if (dx * dx + dy * dy <= e.r[k] * e.r[k] && (best < 0 || e.r[k] < best_r)) {
      best = k;
      best_r = e.r[k];
    }
  }
  return best;
}

}  // namespace nbscope::render

namespace nbscope::render::detail {

namespace {
// Dashes around a ghost's outline, and the smallest radius (px) they are drawn at.
constexpr int kDashes = 10;
constexpr double kMinDashedPx = 6.0;
// Half the width of a cross-layer pair's chevron (px).
constexpr double kChevronPx = 5.0;
// Marks in view beyond which the chevrons go without their "iz-1" labels (a settled pack has a
// mark at most contacts: the labels would bury it; the legend says what the chevrons mean).
constexpr int kMaxLabelledMarks = 40;
// A mask cell of the layer below is this much smaller than its cell on each side (fraction of d).
constexpr double kBelowCellInset = 0.2;
}  // namespace

void dashed_circle(Layer layer, Vec2 centre, float radius, Rgba colour, double ppm, DrawSink& sink) {
  if (radius * ppm < kMinDashedPx) {
    sink.circle(layer, centre, radius, kNone, colour, 1.0f);
    return;
  }
  // Every other of 2 * kDashes arcs, each as one segment.
  constexpr double kStep = std::numbers::pi / kDashes;
  for (int k = 0; k < kDashes; ++k) {
    const double a0 = 2.0 * k * kStep, a1 = a0 + kStep;
    sink.line(layer, centre + radius * v2(std::cos(a0), std::sin(a0)), centre + radius * v2(std::cos(a1), std::sin(a1)),
              colour, 1.5f);
  }
}

PairList pairs_in_layer(const PairList& pairs, const LayerSlice& slice) {
  PairList kept;
  const auto n = static_cast<ElementId>(slice.element_layer.size());
  for (const Pair& p : pairs) {
    if (p.i < 0 || p.j < 0 || p.i >= n || p.j >= n) continue;
    if (slice.place(p.i) == LayerPlace::Here || slice.place(p.j) == LayerPlace::Here) kept.push_back(p);
  }
  return kept;
}

void draw_layer_marks(const Elements& e, const PairList& pairs, const LayerSlice& slice, Rgba colour, Layer layer,
                      const ViewFrame& v, LabelSpace& labels, DrawSink& sink) {
  const auto n = static_cast<ElementId>(std::min<std::size_t>(slice.element_layer.size(), static_cast<std::size_t>(e.size())));
  const float s = static_cast<float>(kChevronPx / v.ppm);
  char text[24];
  // The marks in view, each partner's end once per pair.
  const auto marked = [&](ElementId k, ElementId other) {
    return slice.place(k) != LayerPlace::Here && slice.place(other) == LayerPlace::Here && in_view(v.view, e.x[k], e.y[k], s);
  };
  int in_view_count = 0;
  for (const Pair& p : pairs)
    if (p.i >= 0 && p.j >= 0 && p.i < n && p.j < n) in_view_count += (marked(p.i, p.j) ? 1 : 0) + (marked(p.j, p.i) ? 1 : 0);
  const bool labelled = in_view_count <= kMaxLabelledMarks;
  for (const Pair& p : pairs) {
    if (p.i < 0 || p.j < 0 || p.i >= n || p.j >= n) continue;
    for (const auto& [k, other] : {std::pair{p.i, p.j}, std::pair{p.j, p.i}}) {
      if (!marked(k, other)) continue;
      const LayerPlace place = slice.place(k);
      const Vec2 c = centre_of(e, k);
      // The chevron points to the partner's layer: "v" down to the layer below, "^" up.
      const std::int32_t iz = slice.element_layer[static_cast<std::size_t>(k)];
      const bool down = place == LayerPlace::Below || (place == LayerPlace::Other && iz < slice.layer);
      const float tip = down ? -0.6f * s : 0.6f * s;
      sink.line(layer, c + Vec2(-s, -tip), c + Vec2(0.0f, tip), colour, 2.0f);
      sink.line(layer, c + Vec2(0.0f, tip), c + Vec2(s, -tip), colour, 2.0f);
      if (!labelled) continue;
      // Beside it, the layer as the loop names it (a periodic z's wrap is still "iz-1").
      const int offset = place == LayerPlace::Below ? -1 : place == LayerPlace::Above ? 1 : iz - slice.layer;
      std::snprintf(text, sizeof text, "iz%+d", offset);
      const double w = label_width(std::strlen(text));
      const Vec2 at = c + v2((kChevronPx + 2.0 + 0.5 * w) / v.ppm, 0.0);
      if (label_inside(v.free, at, w, kLinePx, v.ppm)) labels.text(at, text, colour, sink);
    }
  }
}

void draw_mask_3d(const Grid& g, std::array<std::int32_t, 2> cell, std::int32_t layer, DrawSink& sink) {
  const double d = g.cell_size;
  bool own = true;
  for (const auto& c : mask_cells_3d(g, cell[0], cell[1], layer)) {
    const Vec2 a = v2(g.origin[0] + d * c[0], g.origin[1] + d * c[1]);
    if (c[2] == layer) {
      sink.rect(Layer::Cells, a, a + Vec2::Constant(float(d)), own ? palette::kMaskCentre : palette::kMaskCell);
    } else {
      const Vec2 inset = Vec2::Constant(float(kBelowCellInset * d));
      sink.rect(Layer::Cells, a + inset, a + Vec2::Constant(float(d)) - inset, kMaskBelow);
    }
    own = false;
  }
}

std::vector<std::int8_t> list_layer_styles(const OverlayScene& s) {
  std::vector<std::int8_t> styles;
  if (s.layer == nullptr || s.lists == nullptr) return styles;
  styles.assign(s.lists->size(), -1);
  for (const LayerList& l : lists_in_layer(*s.lists, *s.layer)) styles[l.index] = static_cast<std::int8_t>(l.style);
  return styles;
}

}  // namespace nbscope::render::detail
