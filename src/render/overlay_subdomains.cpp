// The subdomains overlay (D): each MPI rank's part of the box, as the run split it (per-rank dumps,
// core/subdomain_grid.hpp), outlined in the rank's colour (the colour --color-by rank gives its atoms
// when every rank has some) over a dark band, and labelled with its rank on a dark backdrop. A 3D
// frame's layer view shows the subdomains the layer's mid-plane cuts.
#include <algorithm>
#include <cstdio>
#include <cstring>

#include "render/overlay_parts.hpp"

namespace nbscope::render::detail {

void draw_subdomains(const OverlayScene& s, const ViewFrame& v, LabelSpace& labels, DrawSink& sink) {
  const Subdomains& split = *s.subdomains;
  // The z the layer view cuts at: the mid-plane of the layer of cells shown.
  const bool cut = s.layer != nullptr && s.grid != nullptr && s.grid->dim == 3;
  const double z = cut ? s.grid->origin[2] + s.grid->cell_size * (s.layer->layer + 0.5) : 0;
  char text[32];
  for (int rank = 0; rank < split.rank_count(); ++rank) {
    const Bounds b = split.bounds_of(rank);
    if (cut && split.grid[2] > 1 && !(z >= b.min[2] && z < b.max[2])) continue;
    const Vec2 lo = v2(b.min[0], b.min[1]), hi = v2(b.max[0], b.max[1]);
    if (!segment_in_view(v.view, lo, hi)) continue;
    const Rgba colour = category_colour(static_cast<std::size_t>(rank));
    const Vec2 corners[4] = {lo, v2(b.max[0], b.min[1]), hi, v2(b.min[0], b.max[1])};
    // Over the atoms, which may wear the same colour (--color-by rank): a dark band under the line.
    for (int k = 0; k < 4; ++k) sink.line(Layer::Top, corners[k], corners[(k + 1) % 4], palette::kBackground, 5.0f);
    for (int k = 0; k < 4; ++k) sink.line(Layer::Top, corners[k], corners[(k + 1) % 4], colour, 2.0f);
    // The label just inside the subdomain's upper left corner, where the free view shows it.
    std::snprintf(text, sizeof text, "rank %d", rank);
    const double w = label_width(std::strlen(text));
    const double x = std::max<double>(b.min[0], v.free.min.x()), y = std::min<double>(b.max[1], v.free.max.y());
    const Vec2 at = v2(x + (0.5 * w + 4.0) / v.ppm, y - (0.5 * kLinePx + 4.0) / v.ppm);
    if (!(at.x() < b.max[0] && at.y() > b.min[1] && label_inside(v.free, at, w, kLinePx, v.ppm)) || !labels.take(at, w, kLinePx)) continue;
    const Vec2 half = v2(0.5 * w / v.ppm, 0.5 * kLinePx / v.ppm);  // on a dark backdrop, legible over the atoms
    sink.rect(Layer::Top, at - half, at + half, palette::kBackground.with_alpha(220));
    sink.text(at, text, palette::kText);
  }
}

}  // namespace nbscope::render::detail
