// The grid overlay: occupancy shading (at scale: a heat map over the bodies and row bars), lines that
// fade to major lines, the title and axis numbers (their bands reserved so no id sits among them),
// and the legend that says what the shading and the lists mean.
//
// Index: heat colours | draw_grid | draw_legend.
#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include "render/overlay_parts.hpp"

namespace nbscope::render::detail {

namespace {
// Most cells the occupancy shading counts; beyond it cells are too small to read anyway.
constexpr std::int64_t kMaxShadedCells = 400'000;
// Minor lines fade out between these cell widths (px); below the first only major lines remain.
constexpr double kMinorLinesFrom = 4.0, kMinorLinesFull = 12.0;
// Major lines at least this far apart (px).
constexpr double kMajorSpacingPx = 48.0;
// Row bars (overview): the fullest row's bar is this long (px).
constexpr double kRowBarPx = 40.0;
// Gap between the grid's left edge and the row numbers: the y-lists' heads sit in it.
constexpr double kHeadGapPx = 16.0;

// The heat map's colour for t in [0, 1] (1 element .. the fullest cell in view).
Rgba heat(float t) {
  constexpr int kStops = static_cast<int>(std::size(palette::kHeat));
  const float x = std::clamp(t, 0.0f, 1.0f) * float(kStops - 1);
  const int i = std::min(kStops - 2, static_cast<int>(x));
  return mix(palette::kHeat[i], palette::kHeat[i + 1], x - float(i));
}
Rgba shade(std::int32_t count) {
  const float t = std::min(1.0f, float(count - 1) / float(palette::kCellShadeSaturation - 1));
  return mix(palette::kCellShadeLow, palette::kCellShadeHigh, t);
}
// Cells between major lines: 5, 10, 20, 50, 100, ... so that they are kMajorSpacingPx apart.
std::int64_t major_step(double cell_px) {
  for (std::int64_t p = 1; p < (std::int64_t{1} << 40); p *= 10)
    for (const std::int64_t f : {1, 2, 5})
      if (f * p >= 5 && double(f * p) * cell_px >= kMajorSpacingPx) return f * p;
  return std::int64_t{1} << 40;
}

// One line of the legend: a colour ramp, then texts each behind an optional arrow of its colour.
struct Key {
  std::string text;
  Rgba colour = palette::kTextDim;
  bool arrow = false;
  bool swatch = false;  // a square of `colour` before the text (which is then drawn in kText)
};
struct Line {
  std::vector<Key> keys;
  int swatches = 0;  // a colour ramp of this many steps before the text
  bool heat = false;
  bool colour_map = false;  // the ramp is --color-by's map (colour_map.hpp)
};

// --color-by's key: the title and each category's swatch, or the colour bar with its low and high.
void colour_legend(const ColourKey& key, std::vector<Line>& lines) {
  char buf[96];
  if (key.continuous) {
    std::snprintf(buf, sizeof buf, "%.4g .. %.4g", key.low, key.high);
    lines.push_back({{{key.title + " " + buf, palette::kText}}, 8, false, true});
    return;
  }
  Line l{{{key.title, palette::kText}}};
  for (const auto& [label, colour] : key.categories) {
    if (l.keys.size() == 7) {  // a long list wraps
      lines.push_back(std::move(l));
      l = Line{};
    }
    l.keys.push_back({label, colour, false, true});
  }
  if (key.more > 0) l.keys.push_back({"+" + std::to_string(key.more) + " more", palette::kTextDim});
  lines.push_back(std::move(l));
}

// What the layer view of a 3D frame adds to the legend: the ghosts, the cross-layer marks, the mask.
void layer_legend(const OverlayScene& s, const OverlayFlags& f, std::vector<Line>& lines) {
  if (s.layer->below >= 0) lines.push_back({{{"dashed: layer iz-1 (the mask reaches it); layers above hidden", kBelowOutline}}});
  else lines.push_back({{{"no layer below; layers above hidden"}}});
  if (f.pairs || f.checks || f.broadphase) lines.push_back({{{"v iz-1 / ^ iz+1: a pair's partner in the layer below / above"}}});
  if (f.mask && (s.hovered_cell || s.selected >= 0) && s.layer->below >= 0)
    lines.push_back({{{"mask: inner squares = its 9 cells in layer iz-1", kBelowOutline}}});
}

}  // namespace

GridCounts count_cells(const OverlayScene& s, const ViewFrame& v) {
  GridCounts out;
  if (s.grid == nullptr) return out;
  const Grid& g = *s.grid;
  const double d = g.cell_size;
  const double x0 = g.origin[0], y0 = g.origin[1];
  out.lo_x = static_cast<std::int64_t>(std::clamp(std::floor((v.view.min.x() - x0) / d), 0.0, double(g.n[0])));
  const auto hi_x = static_cast<std::int64_t>(std::clamp(std::ceil((v.view.max.x() - x0) / d), 0.0, double(g.n[0])));
  out.lo_y = static_cast<std::int64_t>(std::clamp(std::floor((v.view.min.y() - y0) / d), 0.0, double(g.n[1])));
  const auto hi_y = static_cast<std::int64_t>(std::clamp(std::ceil((v.view.max.y() - y0) / d), 0.0, double(g.n[1])));
  out.wx = hi_x - out.lo_x;
  out.wy = hi_y - out.lo_y;
  out.stats.heat_map = d * v.ppm < kHeatMapBelowPx;
  if (s.elements == nullptr || out.wx <= 0 || out.wy <= 0 || out.wx * out.wy > kMaxShadedCells) return out;
  out.cells.assign(static_cast<std::size_t>(out.wx * out.wy), 0);
  out.rows.assign(static_cast<std::size_t>(out.wy), 0);
  const Elements& e = *s.elements;
  for (ElementId k = 0; k < static_cast<ElementId>(e.size()); ++k) {
    if (s.layer != nullptr && s.layer->place(k) != LayerPlace::Here) continue;  // 3D: the layer shown's cells
    const std::int64_t cx = g.cell(e.x[k], 0) - out.lo_x, cy = g.cell(e.y[k], 1) - out.lo_y;
    if (cy < 0 || cy >= out.wy) continue;
    ++out.rows[static_cast<std::size_t>(cy)];
    if (cx >= 0 && cx < out.wx) ++out.cells[static_cast<std::size_t>(cy * out.wx + cx)];
  }
  out.stats.max_cell = *std::max_element(out.cells.begin(), out.cells.end());
  out.stats.max_row = *std::max_element(out.rows.begin(), out.rows.end());
  return out;
}

void draw_grid(const OverlayScene& s, const ViewFrame& v, const GridCounts& counts, LabelSpace& labels, DrawSink& sink) {
  const GridStats& stats = counts.stats;
  const Grid& g = *s.grid;
  const WorldRect& view = v.view;
  const WorldRect& free = v.free;
  const double ppm = v.ppm;
  const double d = g.cell_size;
  const double cell_px = d * ppm;
  const double x0 = g.origin[0], y0 = g.origin[1];
  const double x1 = x0 + d * double(g.n[0]), y1 = y0 + d * double(g.n[1]);
  // The window of cells in view, as counted.
  const std::int64_t lo_x = counts.lo_x, lo_y = counts.lo_y, wx = counts.wx, wy = counts.wy;
  const std::int64_t hi_x = lo_x + wx, hi_y = lo_y + wy;

  // Occupancy: elements per cell of the window (a cell's x-list or cell list has that length), and
  // per row (its y-list's length), shaded; at scale a heat map over the bodies instead.
  if (!counts.cells.empty()) {
    const std::vector<std::int32_t>& count = counts.cells;
    const std::vector<std::int32_t>& row = counts.rows;
    for (std::int64_t cy = 0; cy < wy; ++cy)
      for (std::int64_t cx = 0; cx < wx; ++cx) {
        const std::int32_t c = count[static_cast<std::size_t>(cy * wx + cx)];
        if (c == 0) continue;
        const double ax = x0 + d * double(lo_x + cx), ay = y0 + d * double(lo_y + cy);
        if (stats.heat_map)
          sink.rect(Layer::Overlay, v2(ax, ay), v2(ax + d, ay + d),
                    heat(stats.max_cell > 1 ? float(c - 1) / float(stats.max_cell - 1) : 0.0f));
        else
          sink.rect(Layer::Cells, v2(ax, ay), v2(ax + d, ay + d), shade(c));
      }
    if (stats.heat_map && stats.max_row > 0) {
      // Row bars right of the grid: elements per row, the fullest row kRowBarPx long.
      for (std::int64_t cy = 0; cy < wy; ++cy) {
        const std::int32_t c = row[static_cast<std::size_t>(cy)];
        if (c == 0) continue;
        const double ay = y0 + d * double(lo_y + cy);
        const double len = kRowBarPx * double(c) / double(stats.max_row) / ppm;
        sink.rect(Layer::Overlay, v2(x1 + 3.0 / ppm, ay), v2(x1 + 3.0 / ppm + len, ay + d), palette::kRowBar);
      }
    }
  }
  // Lines: minor lines fade out as cells shrink; major lines take over.
  const double minor = std::clamp((cell_px - kMinorLinesFrom) / (kMinorLinesFull - kMinorLinesFrom), 0.0, 1.0);
  const std::int64_t step = minor >= 1.0 ? 1 : major_step(cell_px);
  const auto lines = [&](std::int64_t every, Rgba colour) {
    for (std::int64_t ix = std::max<std::int64_t>(lo_x, 1); ix <= std::min(hi_x, g.n[0] - 1); ++ix) {
      if (ix % every != 0 || (every == 1 && step > 1 && ix % step == 0)) continue;
      const double x = x0 + d * double(ix);
      sink.line(Layer::Cells, v2(x, std::max(y0, view.min.y())), v2(x, std::min(y1, view.max.y())), colour);
    }
    for (std::int64_t iy = std::max<std::int64_t>(lo_y, 1); iy <= std::min(hi_y, g.n[1] - 1); ++iy) {
      if (iy % every != 0 || (every == 1 && step > 1 && iy % step == 0)) continue;
      const double y = y0 + d * double(iy);
      sink.line(Layer::Cells, v2(std::max(x0, view.min.x()), y), v2(std::min(x1, view.max.x()), y), colour);
    }
  };
  if (minor > 0) lines(1, palette::kGridLine.with_alpha(static_cast<std::uint8_t>(palette::kGridLine.a * minor)));
  if (step > 1) lines(step, palette::kGridMajor);
  const Vec2 c00 = v2(x0, y0), c10 = v2(x1, y0), c11 = v2(x1, y1), c01 = v2(x0, y1);
  sink.line(Layer::Cells, c00, c10, palette::kGridBorder);
  sink.line(Layer::Cells, c10, c11, palette::kGridBorder);
  sink.line(Layer::Cells, c11, c01, palette::kGridBorder);
  sink.line(Layer::Cells, c01, c00, palette::kGridBorder);
  if (!(free.max.x() > free.min.x() && free.max.y() > free.min.y())) return;
  // A label wholly inside the free view and clear of those placed before it.
  const auto put = [&](Vec2 at, const char* text) {
    return label_inside(free, at, label_width(std::strlen(text)), kLinePx, ppm) && labels.text(at, text, palette::kTextDim, sink);
  };
  // The dimensions above the top-left corner, kept inside the free part of the view (placed first:
  // nothing covers them), on a backdrop so that bodies above the grid never hide them.
  char buf[160];
  int used = std::snprintf(buf, sizeof buf, "%lld x %lld cells, d = %.3g%s%s%s", static_cast<long long>(g.n[0]),
                           static_cast<long long>(g.n[1]), d, s.length_unit.empty() ? "" : " ", s.length_unit.c_str(),
                           step > 1 ? (", lines every " + std::to_string(step)).c_str() : "");
  if (s.layer != nullptr && used > 0 && static_cast<std::size_t>(used) < sizeof buf) {
    // The layer shown and its band of z (the book's layer iz: iz*d <= z - z_min < (iz+1)*d).
    const int iz = s.layer->layer, shown = s.book_numbering ? iz + 1 : iz;
    std::snprintf(buf + used, sizeof buf - static_cast<std::size_t>(used), "; layer iz = %d of %d, z - z_min in [%.3g, %.3g)",
                  shown, s.layer->count, d * iz, d * (iz + 1));
  }
  const double title_w = label_width(std::strlen(buf));
  // (std::clamp needs lo <= hi: a free view narrower than the title keeps its left edge.)
  const double title_x = std::clamp(x0, free.min.x() + 4.0 / ppm, std::max(free.min.x() + 4.0 / ppm, free.max.x() - title_w / ppm));
  const double title_y = std::clamp(y1 + 12.0 / ppm, free.min.y() + 10.0 / ppm, std::max(free.min.y() + 10.0 / ppm, free.max.y() - 10.0 / ppm));
  const Vec2 title_at = v2(title_x + 0.5 * title_w / ppm, title_y);
  if (put(title_at, buf)) {
    const Vec2 half = v2(0.5 * title_w / ppm + 2.0 / ppm, 0.5 * kLinePx / ppm + 1.0 / ppm);
    sink.rect(Layer::Top, title_at - half, title_at + half, palette::kLabelBack);
  }
  // Column and row numbers: every cell's when cells are large enough, else (the overview) at the
  // major lines. Below and left of the grid (rows leave a gap for the y-lists' heads), or along the
  // bottom and left edges of the free view when those edges are out of it (zoomed in). Their bands
  // are then reserved along the whole line, so no id sits among them or beside their ends.
  const std::int64_t every = cell_px >= 18.0 ? 1 : major_step(cell_px);
  if (double(every) * cell_px < 18.0) return;
  // Cell centres, or the major lines themselves (the overview's numbers name the line).
  const double at_of = every == 1 ? 0.5 : 0.0;
  const bool book = s.book_numbering;
  const double col_y = std::clamp(y0 - 9.0 / ppm, free.min.y() + 8.0 / ppm, std::max(free.min.y() + 8.0 / ppm, free.max.y() - 8.0 / ppm));
  const auto first = [every](std::int64_t lo) { return (lo + every - 1) / every * every; };
  const std::int64_t last_x = every == 1 ? hi_x - 1 : std::min(hi_x, g.n[0]);
  for (std::int64_t ix = first(lo_x); ix <= last_x; ix += every) {
    const double cx = x0 + d * (double(ix) + at_of);
    if (cx < free.min.x() || cx > free.max.x()) continue;
    std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(book ? ix + 1 : ix));
    put(v2(cx, col_y), buf);
  }
  // The column numbers' line and a line's height above and below it: a row number or an id there
  // reads as one more column number ("41 0 1 2 3" zoomed in on mixed-sizes.json), so none goes there.
  const double band = 0.5 * kLinePx / ppm + 1.0 / ppm, beside = (kLinePx + 2.0) / ppm;
  labels.reserve_world(v2(free.min.x(), col_y - band - beside), v2(free.max.x(), col_y + band + beside));
  double row_lo = x0, row_hi = std::min(x0, free.max.x()), row_bottom = HUGE_VAL, row_top = -HUGE_VAL;
  const std::int64_t last_y = every == 1 ? hi_y - 1 : std::min(hi_y, g.n[1]);
  for (std::int64_t iy = first(lo_y); iy <= last_y; iy += every) {
    const double cy = y0 + d * (double(iy) + at_of);
    // Rows reading as one number with the column numbers beside them are left out.
    if (cy < col_y + 15.0 / ppm || cy > free.max.y()) continue;
    std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(book ? iy + 1 : iy));
    const double half_w = 0.5 * label_width(std::strlen(buf)) / ppm;
    const double row_lo_x = free.min.x() + 3.0 / ppm + half_w;
    const double row_x = std::clamp(x0 - kHeadGapPx / ppm - half_w, row_lo_x, std::max(row_lo_x, free.max.x() - half_w));
    if (!put(v2(row_x, cy), buf)) continue;
    row_lo = std::min(row_lo, row_x - half_w);
    row_hi = std::max(row_hi, row_x + half_w);
    row_bottom = std::min(row_bottom, cy);
    row_top = std::max(row_top, cy);
  }
  // The row numbers' column, a line past its ends too (an id there reads as one more row number).
  if (row_bottom <= row_top) {
    const double past = (1.5 * kLinePx + 2.0) / ppm;
    labels.reserve_world(v2(row_lo, std::max(col_y + band + beside, row_bottom - past)), v2(row_hi, std::min(free.max.y(), row_top + past)));
  }
}

void draw_legend(const OverlayScene& s, const OverlayFlags& f, const GridStats& stats, const ViewFrame& v,
                 LabelSpace& labels, DrawSink& sink) {
  // The lines, each a text and an optional swatch row; laid out bottom-up from the free corner.
  std::vector<Line> lines;
  if (s.colour_key != nullptr) colour_legend(*s.colour_key, lines);
  const bool grid = f.grid && s.grid != nullptr && (s.grid->dim == 2 || s.layer != nullptr);
  if (grid && stats.heat_map && stats.max_cell > 0) {
    lines.push_back({{{"elements per cell 1 .. " + std::to_string(std::max(1, stats.max_cell)) + " (its list's length)"}}, 5, true});
    lines.push_back({{{"bars: elements per row (its y-list), up to " + std::to_string(stats.max_row)}}});
    if (f.pairs || f.checks || f.broadphase) lines.push_back({{{"pairs not drawn over the heat map: zoom in"}}});
  } else if (grid && !stats.heat_map) {
    lines.push_back({{{"elements per cell 1 .. " + std::to_string(palette::kCellShadeSaturation) + "+"}}, palette::kCellShadeSaturation});
  }
  if (f.lists && s.lists != nullptr && !s.lists->empty()) {
    std::set<std::string> kinds;
    bool below = false;
    const std::vector<std::int8_t> styles = list_layer_styles(s);  // 3D: the layer view's lists only
    for (std::size_t i = 0; i < s.lists->size(); ++i) {
      const TracedList& l = (*s.lists)[i];
      if (!styles.empty() && styles[i] < 0) continue;
      if (l.secondary && styles.empty()) below = true;
      else if (styles.empty() || styles[i] == static_cast<std::int8_t>(ListLayerStyle::Here)) kinds.insert(l.kind);
      else below = true;
    }
    Line keys;
    for (const std::string& k : kinds)
      keys.keys.push_back({k, k == "y-list" || k == "z-list" ? palette::kYList : palette::kXList, true});
    if (below && s.layer == nullptr) keys.keys.push_back({"row below (B[1])", palette::kXListBelow, true});
    if (below && s.layer != nullptr) keys.keys.push_back({"layer below (iz-1)", kBelowOutline, true});
    lines.push_back(std::move(keys));
  }
  if (s.layer != nullptr) layer_legend(s, f, lines);
  for (const std::string& c : s.lists_caption) lines.push_back({{{c, palette::kText}}});
  if (s.verify != nullptr) {
    // Someone's arrays checked: what the red means, then the selected problem's text (or the all-clear).
    if (!s.verify->ok) lines.push_back({{{"wrong link", palette::kViolation, true}, {"red rings: elements at fault", palette::kViolationText}}});
    for (const std::string& c : s.verify->caption)
      lines.push_back({{{c, s.verify->ok ? palette::kConfirmedPair : palette::kViolationText}}});
  }
  if (lines.empty()) return;

  constexpr double kPad = 6.0, kSwatchPx = 12.0, kArrowPx = 18.0, kGapPx = 10.0;
  const auto key_px = [&](const Key& k) {
    return (k.arrow ? kArrowPx + 4.0 : 0.0) + (k.swatch ? kSwatchPx + 2.0 : 0.0) + label_width(k.text.size());
  };
  double width_px = 0;
  for (const Line& l : lines) {
    double w = l.swatches > 0 ? kSwatchPx * l.swatches + 4.0 : 0.0;
    for (const Key& k : l.keys) w += key_px(k) + (&k == &l.keys.front() ? 0.0 : kGapPx);
    width_px = std::max(width_px, w);
  }
  const double line_px = kLinePx + 2.0;  // lines never touch
  const double height_px = line_px * double(lines.size()) + 2 * kPad;
  width_px += 2 * kPad;
  // The free view's lower right corner, in pixels of the viewport.
  const double right = (v.free.max.x() - v.view.min.x()) * v.ppm - 6.0;
  // Above the column numbers when they run along the free view's bottom edge (zoomed in).
  const bool columns_at_edge = grid && s.grid->cell_size * v.ppm >= 18.0 && s.grid->origin[1] - 9.0 / v.ppm <= v.free.min.y() + 8.0 / v.ppm;
  const double bottom = (v.view.max.y() - v.free.min.y()) * v.ppm - 6.0 - (columns_at_edge ? kLinePx + 4.0 : 0.0);
  const double left = right - width_px, top = bottom - height_px;
  if (left < (v.free.min.x() - v.view.min.x()) * v.ppm || top < (v.view.max.y() - v.free.max.y()) * v.ppm) return;
  const Vec2 lo = v.at_px(left, bottom), hi = v.at_px(right, top);
  sink.rect(Layer::Top, lo, hi, palette::kLabelBack);
  labels.reserve_world(lo, hi);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const Line& l = lines[i];
    const double cy = top + kPad + line_px * (double(i) + 0.5);
    double x = left + kPad;
    for (int k = 0; k < l.swatches; ++k) {
      const float t = float(k) / float(l.swatches - 1);
      const Rgba c = l.colour_map ? colour_map(t) : l.heat ? heat(t) : shade(k + 1);
      sink.rect(Layer::Top, v.at_px(x + 1, cy + 5), v.at_px(x + kSwatchPx - 1, cy - 5), c.with_alpha(255));
      x += kSwatchPx;
    }
    if (l.swatches > 0) x += 4.0;
    for (const Key& k : l.keys) {
      if (k.arrow) {
        // Drawn as lines (arrows are the lists' own).
        sink.line(Layer::Top, v.at_px(x, cy), v.at_px(x + kArrowPx, cy), k.colour, 2.0f);
        sink.line(Layer::Top, v.at_px(x + kArrowPx - 5, cy - 4), v.at_px(x + kArrowPx, cy), k.colour, 2.0f);
        sink.line(Layer::Top, v.at_px(x + kArrowPx - 5, cy + 4), v.at_px(x + kArrowPx, cy), k.colour, 2.0f);
        x += kArrowPx + 4.0;
      }
      if (k.swatch) {
        sink.rect(Layer::Top, v.at_px(x + 1, cy + 5), v.at_px(x + kSwatchPx - 1, cy - 5), k.colour.with_alpha(255));
        x += kSwatchPx + 2.0;
      }
      const Rgba text_colour = k.swatch ? palette::kText : k.colour;
      // The reserved box holds the text: it is drawn directly, not placed.
      sink.text(v.at_px(x + 0.5 * label_width(k.text.size()), cy), k.text, text_colour);
      x += label_width(k.text.size()) + kGapPx;
    }
  }
}

}  // namespace nbscope::render::detail
