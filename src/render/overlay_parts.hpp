// nbscope render (private to the overlay files): small geometry helpers and the parts of
// draw_scene that live in files of their own — the grid with its heat map and legend
// (overlay_grid.cpp), the singly connected lists (overlay_lists.cpp) and a verify run's red marks
// (overlay_verify.cpp), and the layer view's 3D parts (overlay_layers.cpp).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "render/label_space.hpp"
#include "render/overlay_layers.hpp"
#include "render/overlays.hpp"

namespace nbscope::render::detail {

inline constexpr Rgba kNone{0, 0, 0, 0};

inline Vec2 v2(double x, double y) { return {static_cast<float>(x), static_cast<float>(y)}; }
inline Vec2 centre_of(const Elements& e, ElementId k) { return v2(e.x[k], e.y[k]); }

// True when a circle (world) touches the view rectangle.
inline bool in_view(const WorldRect& v, double x, double y, double r) {
  return x + r >= v.min.x() && x - r <= v.max.x() && y + r >= v.min.y() && y - r <= v.max.y();
}
inline bool segment_in_view(const WorldRect& v, Vec2 a, Vec2 b) {
  return std::max(a.x(), b.x()) >= v.min.x() && std::min(a.x(), b.x()) <= v.max.x() &&
         std::max(a.y(), b.y()) >= v.min.y() && std::min(a.y(), b.y()) <= v.max.y();
}

// The camera's view, the part of it no panel covers, and the scale; world points from pixels.
struct ViewFrame {
  WorldRect view, free;
  double ppm = 1;
  // The world point at pixel (px, py) of the viewport (origin top left, y down).
  [[nodiscard]] Vec2 at_px(double px, double py) const { return v2(view.min.x() + px / ppm, view.max.y() - py / ppm); }
};

// What the grid found that the legend reports: the fullest cell and row in view.
struct GridStats {
  bool heat_map = false;    // cells below kHeatMapBelowPx: the overview was drawn
  std::int32_t max_cell = 0;
  std::int32_t max_row = 0;
};

// The window of cells in view (wx x wy from (lo_x, lo_y)), its elements per cell (row-major; empty
// without elements or when too many to count) and per row, with their maxima.
struct GridCounts {
  GridStats stats;
  std::int64_t lo_x = 0, lo_y = 0, wx = 0, wy = 0;
  std::vector<std::int32_t> cells, rows;
};
GridCounts count_cells(const OverlayScene& s, const ViewFrame& v);

// The grid: occupancy shading (a heat map over the bodies when cells are a few pixels wide), lines
// (fading to major lines), the title and the axis numbers, whose bands are reserved in `labels`.
void draw_grid(const OverlayScene& s, const ViewFrame& v, const GridCounts& counts, LabelSpace& labels, DrawSink& sink);
// The lists the filter keeps — y-lists as arcs within their row's band, long ones as a rail of slots
// in list order along it (numbered when there is room, in `labels`) — the stepper's list and pair
// highlighted.
// A verify run's wrong links that lie along a drawn chain are drawn there, in red; `marked_links`
// (when given) gets true for each such problem.
void draw_lists(const OverlayScene& s, const OverlayFlags& f, const ViewFrame& v, LabelSpace& labels, DrawSink& sink,
                std::vector<bool>* marked_links = nullptr);
// A verify run's marks (s.verify): the wrong links the lists did not draw (straight red arrows,
// from the list's head when the link leaves it), every problem's elements ringed in red, and the
// selected problem's elements, cells and link highlighted like a selection.
void draw_verify(const OverlayScene& s, const ViewFrame& v, const std::vector<bool>& marked_links, DrawSink& sink);
// The heads' names of the lists drawn (TracedList::head_label: a verify run's "C[5][7]"), beside their
// squares and clear of every label placed before (call after the ids: those matter more).
void draw_head_labels(const OverlayScene& s, const ViewFrame& v, LabelSpace& labels, DrawSink& sink);
// Where a list's head is drawn (its square; the lists overlay's arrows start there).
// `below`: a list of the layer below in a 3D frame's layer view (anchored as the row below's copies).
Vec2 head_anchor(const TracedList& l, const Grid* grid, const Elements& e, const WorldRect& free, double ppm, bool below = false);
// The legend in the free view's lower right corner: the cell shading or heat map, the list kinds
// drawn and the lists caption; its box is reserved in `labels`.
void draw_legend(const OverlayScene& s, const OverlayFlags& f, const GridStats& stats, const ViewFrame& v,
                 LabelSpace& labels, DrawSink& sink);

// Periodic frames (overlay_periodic.cpp). c_j - c_i by the minimum image on the periodic axes of
// e.box (x and y; the overlays are 2D).
Eigen::Vector2d min_image_delta(const Elements& e, ElementId i, ElementId j);
// The segments that draw pair (i, j): one, centre to centre; or, when its minimum image crosses the
// box, two half-links from each centre towards the other's nearest image, ending at the box's edge.
int pair_segments(const Elements& e, ElementId i, ElementId j, std::array<std::array<Vec2, 2>, 2>& out);
// The elements within one cell of a periodic edge again at their images across it (corners: both
// axes), faded; picking never sees them.
void draw_ghosts(const OverlayScene& s, const WorldRect& view, DrawSink& sink);
// The box's periodic edges, dashed, along the box (or the elements) on the other axis.
void draw_box_edges(const Elements& e, const WorldRect& view, double ppm, DrawSink& sink);

// The layer view of a 3D frame (overlay_layers.cpp). Purple means "the layer below" throughout:
// its elements' dashed ghosts, its lists (as NBS's row-below lists in 2D) and its mask cells.
inline constexpr Rgba kBelowFill{86, 120, 160, 40};
inline constexpr Rgba kBelowOutline{190, 150, 255, 190};
inline constexpr Rgba kBelowBoundingCircle{190, 150, 255, 110};
inline constexpr Rgba kMaskBelow{190, 150, 255, 85};
inline constexpr std::uint8_t kBelowListAlpha = 160;  // a list of the layer below, ghosted
inline constexpr std::uint8_t kBelowTextAlpha = 120;  // a ghost's id
// A circle's outline as dashes (a ghost of the layer below); a plain thin circle when too small
// on screen for dashes to read.
void dashed_circle(Layer layer, Vec2 centre, float radius, Rgba colour, double ppm, DrawSink& sink);
// The pairs of `pairs` drawn in the layer view: those with at least one element in the layer shown.
PairList pairs_in_layer(const PairList& pairs, const LayerSlice& slice);
// At the end of each pair of `pairs` whose element is not in the layer shown: a chevron pointing to
// its layer ("v" below, "^" above) and its layer beside it ("iz-1", "iz+1"), in `colour`, on `layer`.
void draw_layer_marks(const Elements& e, const PairList& pairs, const LayerSlice& slice, Rgba colour, Layer layer,
                      const ViewFrame& v, LabelSpace& labels, DrawSink& sink);
// The 3D mask of cell (ix, iy) of the layer shown: this layer's cells as in 2D (the own cell
// stronger), the layer below's as smaller purple squares inside their cells.
void draw_mask_3d(const Grid& g, std::array<std::int32_t, 2> cell, std::int32_t layer, DrawSink& sink);
// Per traced list: -1 when the layer view leaves it out, else its ListLayerStyle (lists_in_layer).
std::vector<std::int8_t> list_layer_styles(const OverlayScene& s);

// Each rank's subdomain (s.subdomains) outlined in its colour and labelled "rank r" (overlay_subdomains.cpp).
void draw_subdomains(const OverlayScene& s, const ViewFrame& v, LabelSpace& labels, DrawSink& sink);

}  // namespace nbscope::render::detail
