// Periodic frames (Elements::box, core/elements.hpp): the elements near a periodic edge drawn
// again, faded, at their images across it; a pair whose minimum image crosses the box drawn as two
// half-links that end at its edge (never one line across the whole box); the periodic edges dashed.
// None of it runs for an open space, so those pictures stay as they were.
#include <algorithm>
#include <cmath>

#include "render/overlay_parts.hpp"

namespace nbscope::render::detail {

namespace {

// Ghosts are the bodies' colours, faded: seen as copies, never taken for elements.
constexpr Rgba kGhostFill = palette::kDynamicFill.with_alpha(55);
constexpr Rgba kGhostOutline = palette::kDynamicOutline.with_alpha(110);
constexpr Rgba kBoxEdge{235, 150, 60, 210};
constexpr double kDashPx = 8.0, kGapPx = 5.0;
// Past this many dashes in view an edge is drawn solid (a software rasterizer pays per primitive).
constexpr double kMaxDashes = 600.0;

// The point where the segment from `from` along `d` leaves the box on a periodic axis (or its end).
Vec2 to_box_edge(const PeriodicBox& box, const Eigen::Vector2d& from, const Eigen::Vector2d& d) {
  double t = 1.0;
  for (int a = 0; a < 2; ++a) {
    if (!box.periodic[a] || d[a] == 0) continue;
    const double end = from[a] + d[a];
    if (end > box.hi[a]) t = std::min(t, (box.hi[a] - from[a]) / d[a]);
    if (end < box.lo[a]) t = std::min(t, (box.lo[a] - from[a]) / d[a]);
  }
  const Eigen::Vector2d p = from + std::clamp(t, 0.0, 1.0) * d;
  return v2(p.x(), p.y());
}

// The images' shifts of one coordinate: 0, and +-L when within `reach` of the low or high edge.
int image_shifts(const PeriodicBox& box, int a, double c, double reach, double out[3]) {
  int n = 0;
  out[n++] = 0;
  if (!box.periodic[a] || box.length(a) <= 0) return n;
  if (c - box.lo[a] < reach) out[n++] = box.length(a);
  if (box.hi[a] - c < reach) out[n++] = -box.length(a);
  return n;
}

// A dashed segment, only its part in view.
void dashed(const WorldRect& view, double ppm, Vec2 a, Vec2 b, DrawSink& sink) {
  const Vec2 lo = view.min.cast<float>(), hi = view.max.cast<float>();
  a = a.cwiseMax(lo).cwiseMin(hi);
  b = b.cwiseMax(lo).cwiseMin(hi);
  const double length_px = (b - a).norm() * ppm;
  if (length_px <= 0) return;
  if (length_px / (kDashPx + kGapPx) > kMaxDashes) {
    sink.line(Layer::Overlay, a, b, kBoxEdge, 1.5f);
    return;
  }
  const Vec2 step = (b - a) / static_cast<float>(length_px);  // one pixel along
  for (double at = 0; at < length_px; at += kDashPx + kGapPx)
    sink.line(Layer::Overlay, a + static_cast<float>(at) * step,
              a + static_cast<float>(std::min(at + kDashPx, length_px)) * step, kBoxEdge, 1.5f);
}

}  // namespace

Eigen::Vector2d min_image_delta(const Elements& e, ElementId i, ElementId j) {
  Eigen::Vector2d d(e.x[j] - e.x[i], e.y[j] - e.y[i]);
  for (int a = 0; a < 2; ++a) {
    const double l = e.box.length(a);
    if (e.box.periodic[a] && l > 0) d[a] -= l * std::round(d[a] / l);
  }
  return d;
}

int pair_segments(const Elements& e, ElementId i, ElementId j, std::array<std::array<Vec2, 2>, 2>& out) {
  out[0] = {centre_of(e, i), centre_of(e, j)};
  if (!e.box.any()) return 1;
  const Eigen::Vector2d d = min_image_delta(e, i, j);
  if (d.x() == e.x[j] - e.x[i] && d.y() == e.y[j] - e.y[i]) return 1;  // no image shifted: inside the box
  out[0] = {centre_of(e, i), to_box_edge(e.box, {e.x[i], e.y[i]}, d)};
  out[1] = {centre_of(e, j), to_box_edge(e.box, {e.x[j], e.y[j]}, -d)};
  return 2;
}

void draw_ghosts(const OverlayScene& s, const WorldRect& view, DrawSink& sink) {
  const Elements& e = *s.elements;
  if (!e.box.any() || e.size() == 0) return;
  // One cell: what a neighbour across the edge can reach (the grid's, else the largest diameter).
  const double reach = s.grid != nullptr && s.grid->cell_size > 0 ? s.grid->cell_size : 2.0 * e.max_radius();
  double sx[3], sy[3];
  for (ElementId k = 0; k < static_cast<ElementId>(e.size()); ++k) {
    if (s.layer != nullptr && s.layer->place(k) != LayerPlace::Here) continue;  // 3D: the layer shown's only
    const int nx = image_shifts(e.box, 0, e.x[k], reach, sx), ny = image_shifts(e.box, 1, e.y[k], reach, sy);
    if (nx == 1 && ny == 1) continue;
    for (int a = 0; a < nx; ++a)
      for (int b = 0; b < ny; ++b) {
        if (a == 0 && b == 0) continue;
        const double x = e.x[k] + sx[a], y = e.y[k] + sy[b];
        if (in_view(view, x, y, e.r[k])) sink.circle(Layer::Bodies, v2(x, y), static_cast<float>(e.r[k]), kGhostFill, kGhostOutline);
      }
  }
}

void draw_box_edges(const Elements& e, const WorldRect& view, double ppm, DrawSink& sink) {
  if (!e.box.any()) return;
  const Bounds b = e.centre_bounds();
  const double r = e.max_radius();
  // Along the other axis: the box's own extent when it has one, else the elements'.
  const auto extent = [&](int a) {
    return e.box.hi[a] > e.box.lo[a] ? std::array<double, 2>{e.box.lo[a], e.box.hi[a]}
                                     : std::array<double, 2>{b.min[a] - r, b.max[a] + r};
  };
  for (int a = 0; a < 2; ++a) {
    if (!e.box.periodic[a] || e.box.length(a) <= 0) continue;
    const auto along = extent(1 - a);
    for (const double at : {e.box.lo[a], e.box.hi[a]}) {
      const Vec2 p = a == 0 ? v2(at, along[0]) : v2(along[0], at);
      const Vec2 q = a == 0 ? v2(at, along[1]) : v2(along[1], at);
      if (segment_in_view(view, p, q)) dashed(view, ppm, p, q, sink);
    }
  }
}

}  // namespace nbscope::render::detail
