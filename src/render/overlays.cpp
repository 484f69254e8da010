// Index: overlay table | picking helpers | bodies and elements | labels (one space: no label over
// another) | grid | lists | mask | pairs and checks | selection, trails, flashes | draw_scene.
#include "render/overlays.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <unordered_map>

namespace nbscope::render {

namespace {
constexpr Rgba kNone{0, 0, 0, 0};
// Circles smaller than this on screen get no ids: the text would cover its neighbours.
constexpr double kMinIdRadiusPx = 7.0;
// Details (spokes, bounding circles) of circles smaller than this on screen are left out.
constexpr double kMinDetailPx = 4.0;
// Most cells the occupancy shading counts; beyond it cells are too small to read anyway.
constexpr std::int64_t kMaxShadedCells = 400'000;

Vec2 v2(double x, double y) { return {static_cast<float>(x), static_cast<float>(y)}; }
Vec2 centre_of(const Elements& e, ElementId k) { return v2(e.x[k], e.y[k]); }

// True when a circle (world) touches the view rectangle.
bool in_view(const WorldRect& v, double x, double y, double r) {
  return x + r >= v.min.x() && x - r <= v.max.x() && y + r >= v.min.y() && y - r <= v.max.y();
}
bool segment_in_view(const WorldRect& v, Vec2 a, Vec2 b) {
  return std::max(a.x(), b.x()) >= v.min.x() && std::min(a.x(), b.x()) <= v.max.x() &&
         std::max(a.y(), b.y()) >= v.min.y() && std::min(a.y(), b.y()) <= v.max.y();
}
}  // namespace

// ---- overlay table ----------------------------------------------------------------------------

std::span<const OverlayInfo> overlay_infos() {
  static const OverlayInfo infos[] = {
      {"bodies", 'B', &OverlayFlags::bodies, "Box2D bodies"},
      {"elements", 'E', &OverlayFlags::elements, "bounding circles (the elements)"},
      {"grid", 'G', &OverlayFlags::grid, "cell grid, occupied cells shaded by count"},
      {"lists", 'L', &OverlayFlags::lists, "singly connected lists: head -> next -> ... -> end"},
      {"mask", 'M', &OverlayFlags::mask, "contact mask of the hovered cell"},
      {"pairs", 'C', &OverlayFlags::pairs, "detected contact pairs"},
      {"checks", 'K', &OverlayFlags::checks, "pairs confirmed by Box2D, violations in red"},
      {"broadphase", 'F', &OverlayFlags::broadphase, "Box2D-only broadphase pairs (fat AABBs)"},
      {"ids", 'I', &OverlayFlags::ids, "element ids (inside or beside the circle, never over another label)"},
      {"trails", 'T', &OverlayFlags::trails, "trails of the selected element"},
      {"flash", 'H', &OverlayFlags::flash, "flash elements that changed cell"},
  };
  return infos;
}

// ---- picking helpers --------------------------------------------------------------------------

std::optional<std::array<std::int32_t, 2>> cell_at(const Grid& grid, const Eigen::Vector2d& world) {
  const double fx = std::floor((world.x() - grid.origin[0]) * grid.inv_cell_size);
  const double fy = std::floor((world.y() - grid.origin[1]) * grid.inv_cell_size);
  if (!(fx >= 0 && fy >= 0 && fx < double(grid.n[0]) && fy < double(grid.n[1]))) return std::nullopt;
  return std::array<std::int32_t, 2>{static_cast<std::int32_t>(fx), static_cast<std::int32_t>(fy)};
}

ElementId element_at(const Elements& e, const Eigen::Vector2d& world) {
  ElementId best = -1;
  double best_r = 0;
  for (ElementId k = 0; k < static_cast<ElementId>(e.size()); ++k) {
    const double dx = e.x[k] - world.x(), dy = e.y[k] - world.y();
    if (dx * dx + dy * dy <= e.r[k] * e.r[k] && (best < 0 || e.r[k] < best_r)) {
      best = k;
      best_r = e.r[k];
    }
  }
  return best;
}

std::vector<std::array<std::int32_t, 2>> mask_cells(const Grid& grid, std::int32_t ix, std::int32_t iy) {
  static constexpr std::int32_t kHalfMask[4][2] = {{-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
  std::vector<std::array<std::int32_t, 2>> cells{{ix, iy}};
  for (const auto& o : kHalfMask) {
    const std::int32_t x = ix + o[0], y = iy + o[1];
    if (x >= 0 && y >= 0 && x < grid.n[0] && y < grid.n[1]) cells.push_back({x, y});
  }
  return cells;
}

namespace {

// ---- bodies and elements ----------------------------------------------------------------------

void draw_bodies(const OverlayScene& s, const WorldRect& view, double ppm, DrawSink& sink) {
  for (const ShapeDraw& b : s.shapes) {
    const Rgba fill = b.motion == Motion::Static      ? palette::kStaticFill
                      : b.motion == Motion::Kinematic ? palette::kKinematicFill
                                                      : palette::kDynamicFill;
    const Rgba outline = b.motion == Motion::Static      ? palette::kStaticOutline
                         : b.motion == Motion::Kinematic ? palette::kKinematicOutline
                                                         : palette::kDynamicOutline;
    if (b.is_circle) {
      if (!in_view(view, b.centre.x(), b.centre.y(), b.radius)) continue;
      sink.circle(Layer::Bodies, b.centre, b.radius, fill, outline, 1.0f);
      // A spoke shows the rotation, once it is long enough to see (a software rasterizer pays per primitive).
      if (b.radius * ppm < kMinDetailPx) continue;
      const Vec2 tip = b.centre + b.radius * Vec2(std::cos(b.angle), std::sin(b.angle));
      sink.line(Layer::Bodies, b.centre, tip, outline.with_alpha(150), 1.0f);
    } else if (b.count >= 3 && b.first + b.count <= s.shape_points.size()) {
      const auto pts = s.shape_points.subspan(b.first, b.count);
      Vec2 lo = pts[0], hi = pts[0];
      for (const Vec2& p : pts) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
      if (!segment_in_view(view, lo, hi)) continue;
      sink.polygon(Layer::Bodies, pts, fill, outline);
    }
  }
}

void draw_elements(const Elements& e, const WorldRect& view, double ppm, DrawSink& sink) {
  for (ElementId k = 0; k < static_cast<ElementId>(e.size()); ++k) {
    // A bounding circle under ~2 px would only repaint its body's pixels.
    if (e.r[k] * ppm < 0.5 * kMinDetailPx || !in_view(view, e.x[k], e.y[k], e.r[k])) continue;
    sink.circle(Layer::Overlay, centre_of(e, k), static_cast<float>(e.r[k]), kNone, palette::kBoundingCircle, 1.0f);
  }
}

// ---- labels -----------------------------------------------------------------------------------

// ImGui's default font, as the renderer draws labels: 7 px a character, 13 px a line.
constexpr double kCharPx = 7.0;
constexpr double kLinePx = 13.0;
double label_width(std::size_t chars) { return kCharPx * static_cast<double>(chars) + 2.0; }

// Screen rectangles of the labels placed so far, bucketed so that a new label is checked only
// against its neighbours. The grid's title and axis numbers are placed first, then the ids, so an
// id never covers them and overlapping bounding circles (a wall of boxes) never pile ids up.
class LabelSpace {
 public:
  LabelSpace(const WorldRect& view, double ppm) : view_(view), ppm_(ppm) {}
  // True (and the rectangle is taken) when a w x h px label centred on world point `at` overlaps none.
  bool take(Vec2 at, double w, double h) {
    const double cx = (at.x() - view_.min.x()) * ppm_, cy = (view_.max.y() - at.y()) * ppm_;
    const Box b{cx - 0.5 * w, cy - 0.5 * h, cx + 0.5 * w, cy + 0.5 * h};
    if (overlaps(b)) return false;
    insert(b);
    return true;
  }
  // Takes a rectangle in pixels (a panel's window) so that no label is placed under it.
  void reserve(const PixelRect& r) { insert({r.x0, r.y0, r.x1, r.y1}); }
  // take() for a text, drawn when it got its place.
  bool text(Vec2 at, const char* text, Rgba colour, DrawSink& sink) {
    if (!take(at, label_width(std::strlen(text)), kLinePx)) return false;
    sink.text(at, text, colour);
    return true;
  }

 private:
  struct Box {
    double x0, y0, x1, y1;
  };
  // Calls f(bucket key) for every bucket `b` touches.
  template <class F>
  static void for_buckets(const Box& b, F&& f) {
    for (auto by = bucket(b.y0); by <= bucket(b.y1); ++by)
      for (auto bx = bucket(b.x0); bx <= bucket(b.x1); ++bx) f(key(bx, by));
  }
  bool overlaps(const Box& b) const {
    bool hit = false;
    for_buckets(b, [&](std::uint64_t k) {
      const auto it = buckets_.find(k);
      if (hit || it == buckets_.end()) return;
      for (const std::size_t i : it->second)
        hit = hit || (boxes_[i].x0 < b.x1 && b.x0 < boxes_[i].x1 && boxes_[i].y0 < b.y1 && b.y0 < boxes_[i].y1);
    });
    return hit;
  }
  void insert(const Box& b) {
    for_buckets(b, [&](std::uint64_t k) { buckets_[k].push_back(boxes_.size()); });
    boxes_.push_back(b);
  }
  static constexpr double kBucketPx = 32.0;
  static std::int64_t bucket(double px) { return static_cast<std::int64_t>(std::floor(px / kBucketPx)); }
  static std::uint64_t key(std::int64_t bx, std::int64_t by) {
    return (static_cast<std::uint64_t>(bx) << 32) ^ static_cast<std::uint32_t>(by);
  }
  WorldRect view_;
  double ppm_;
  std::vector<Box> boxes_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> buckets_;
};

// True when a w x h px label centred on `at` lies inside `free` (the view less the panels).
bool label_inside(const WorldRect& free, Vec2 at, double w, double h, double ppm) {
  const double hw = 0.5 * w / ppm, hh = 0.5 * h / ppm;
  return at.x() - hw >= free.min.x() && at.x() + hw <= free.max.x() && at.y() - hh >= free.min.y() &&
         at.y() + hh <= free.max.y();
}

// Element ids: inside the circle when they fit, else just above it; only for circles at least
// kMinIdRadiusPx on screen, only where the view shows them (no panel over them: those are reserved
// in `space`), never over another label.
void draw_ids(const Elements& e, const WorldRect& view, double ppm, ElementId selected, bool book, LabelSpace& space,
              DrawSink& sink) {
  char buf[16];
  // The selected element's id first: it must never be the one left out.
  auto place = [&](ElementId k) {
    if (e.r[k] * ppm < kMinIdRadiusPx || !in_view(view, e.x[k], e.y[k], e.r[k])) return;
    const int digits = std::snprintf(buf, sizeof buf, "%d", book ? k + 1 : k);
    const double w = label_width(static_cast<std::size_t>(digits));
    const double r_px = e.r[k] * ppm;
    const Vec2 at = 2.0 * r_px >= w ? centre_of(e, k) : v2(e.x[k], e.y[k] + (r_px + 0.5 * kLinePx + 1.0) / ppm);
    if (!label_inside(view, at, w, kLinePx, ppm) || !space.take(at, w, kLinePx)) return;
    sink.text(at, buf, palette::kText);
  };
  if (selected >= 0 && selected < static_cast<ElementId>(e.size())) place(selected);
  for (ElementId k = 0; k < static_cast<ElementId>(e.size()); ++k)
    if (k != selected) place(k);
}

// ---- grid -------------------------------------------------------------------------------------

void draw_grid(const OverlayScene& s, const WorldRect& view, const WorldRect& free, double ppm, LabelSpace& labels,
               DrawSink& sink) {
  const Grid& g = *s.grid;
  const double d = g.cell_size;
  const double x0 = g.origin[0], y0 = g.origin[1];
  const double x1 = x0 + d * double(g.n[0]), y1 = y0 + d * double(g.n[1]);
  // The window of cells in view.
  const auto lo_x = static_cast<std::int64_t>(std::clamp(std::floor((view.min.x() - x0) / d), 0.0, double(g.n[0])));
  const auto hi_x = static_cast<std::int64_t>(std::clamp(std::ceil((view.max.x() - x0) / d), 0.0, double(g.n[0])));
  const auto lo_y = static_cast<std::int64_t>(std::clamp(std::floor((view.min.y() - y0) / d), 0.0, double(g.n[1])));
  const auto hi_y = static_cast<std::int64_t>(std::clamp(std::ceil((view.max.y() - y0) / d), 0.0, double(g.n[1])));
  const std::int64_t wx = hi_x - lo_x, wy = hi_y - lo_y;

  // Occupancy: elements per cell of the window, shaded from low to high.
  if (s.elements != nullptr && wx > 0 && wy > 0 && wx * wy <= kMaxShadedCells) {
    std::vector<std::int32_t> count(static_cast<std::size_t>(wx * wy), 0);
    const Elements& e = *s.elements;
    for (ElementId k = 0; k < static_cast<ElementId>(e.size()); ++k) {
      const std::int64_t cx = g.cell(e.x[k], 0) - lo_x, cy = g.cell(e.y[k], 1) - lo_y;
      if (cx >= 0 && cy >= 0 && cx < wx && cy < wy) ++count[static_cast<std::size_t>(cy * wx + cx)];
    }
    for (std::int64_t cy = 0; cy < wy; ++cy)
      for (std::int64_t cx = 0; cx < wx; ++cx) {
        const std::int32_t c = count[static_cast<std::size_t>(cy * wx + cx)];
        if (c == 0) continue;
        const float t = std::min(1.0f, float(c - 1) / float(palette::kCellShadeSaturation - 1));
        const double ax = x0 + d * double(lo_x + cx), ay = y0 + d * double(lo_y + cy);
        sink.rect(Layer::Cells, v2(ax, ay), v2(ax + d, ay + d), mix(palette::kCellShadeLow, palette::kCellShadeHigh, t));
      }
  }
  // Lines only while cells are at least 4 px wide; the border always.
  if (d * ppm >= 4.0) {
    for (std::int64_t ix = std::max<std::int64_t>(lo_x, 1); ix <= std::min(hi_x, g.n[0] - 1); ++ix) {
      const double x = x0 + d * double(ix);
      sink.line(Layer::Cells, v2(x, std::max(y0, view.min.y())), v2(x, std::min(y1, view.max.y())), palette::kGridLine);
    }
    for (std::int64_t iy = std::max<std::int64_t>(lo_y, 1); iy <= std::min(hi_y, g.n[1] - 1); ++iy) {
      const double y = y0 + d * double(iy);
      sink.line(Layer::Cells, v2(std::max(x0, view.min.x()), y), v2(std::min(x1, view.max.x()), y), palette::kGridLine);
    }
  }
  const Vec2 c00 = v2(x0, y0), c10 = v2(x1, y0), c11 = v2(x1, y1), c01 = v2(x0, y1);
  sink.line(Layer::Cells, c00, c10, palette::kGridBorder);
  sink.line(Layer::Cells, c10, c11, palette::kGridBorder);
  sink.line(Layer::Cells, c11, c01, palette::kGridBorder);
  sink.line(Layer::Cells, c01, c00, palette::kGridBorder);
  if (!(free.max.x() > free.min.x() && free.max.y() > free.min.y())) return;
  // A label wholly inside the free view and clear of those placed before it.
  const auto put = [&](Vec2 at, const char* text) {
    if (label_inside(free, at, label_width(std::strlen(text)), kLinePx, ppm)) labels.text(at, text, palette::kTextDim, sink);
  };
  // The dimensions above the top-left corner, kept inside the free part of the view (placed first:
  // nothing covers them).
  char buf[96];
  std::snprintf(buf, sizeof buf, "%lld x %lld cells, d = %.3g", static_cast<long long>(g.n[0]),
                static_cast<long long>(g.n[1]), d);
  const double title_w = label_width(std::strlen(buf));
  const double title_x = std::clamp(x0, free.min.x() + 4.0 / ppm, std::max(free.min.x(), free.max.x() - title_w / ppm));
  const double title_y = std::clamp(y1 + 12.0 / ppm, free.min.y() + 10.0 / ppm, free.max.y() - 10.0 / ppm);
  put(v2(title_x + 0.5 * title_w / ppm, title_y), buf);
  // Column and row numbers when cells are large enough: below and left of the grid, or along the
  // bottom and left edges of the free view when those edges are out of it (zoomed in).
  if (d * ppm < 18.0) return;
  const bool book = s.book_numbering;
  const double col_y = std::clamp(y0 - 9.0 / ppm, free.min.y() + 8.0 / ppm, free.max.y() - 8.0 / ppm);
  for (std::int64_t ix = lo_x; ix < hi_x; ++ix) {
    const double cx = x0 + d * (double(ix) + 0.5);
    if (cx < free.min.x() || cx > free.max.x()) continue;
    std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(book ? ix + 1 : ix));
    put(v2(cx, col_y), buf);
  }
  for (std::int64_t iy = lo_y; iy < hi_y; ++iy) {
    const double cy = y0 + d * (double(iy) + 0.5);
    // Rows reading as one number with the column numbers beside them are left out.
    if (cy < col_y + 15.0 / ppm || cy > free.max.y()) continue;
    std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(book ? iy + 1 : iy));
    const double half_w = 0.5 * label_width(std::strlen(buf)) / ppm;
    const double row_x = std::clamp(x0 - 3.0 / ppm - half_w, free.min.x() + 3.0 / ppm + half_w, free.max.x() - half_w);
    put(v2(row_x, cy), buf);
  }
}

// ---- lists ------------------------------------------------------------------------------------

Rgba list_colour(const TracedList& l) {
  if (l.secondary) return palette::kXListBelow;
  if (l.kind == "y-list" || l.kind == "z-list") return palette::kYList;
  return palette::kXList;
}

// Where a list's head is drawn: rows at the left edge of the grid, cells in a corner of the cell
// (top left for a row's own lists, bottom left for the copies of the row below); lists without a
// cell (tree leaves) just above-left of their first element.
Vec2 head_anchor(const TracedList& l, const Grid* grid, const Elements& e, const WorldRect& free, double ppm) {
  if (grid != nullptr) {
    const Grid& g = *grid;
    const double d = g.cell_size;
    // Row heads sit left of the grid, or at the left edge of the view when the grid's edge is out of it.
    if (l.cell[0] < 0 && l.cell[1] >= 0)
      return v2(std::max(g.origin[0] - 0.45 * d, free.min.x() + 22.0 / ppm), g.origin[1] + d * (l.cell[1] + 0.5));
    if (l.cell[0] >= 0 && l.cell[1] >= 0)
      return v2(g.origin[0] + d * (l.cell[0] + 0.12), g.origin[1] + d * (l.cell[1] + (l.secondary ? 0.12 : 0.88)));
  }
  const ElementId k = l.chain.front();
  const double off = (e.r[k] + 10.0 / ppm) * 0.7071;
  return v2(e.x[k] - off, e.y[k] + off);
}

void draw_lists(const OverlayScene& s, const WorldRect& view, const WorldRect& free, double ppm, DrawSink& sink) {
  const Elements& e = *s.elements;
  const auto n = static_cast<ElementId>(e.size());
  for (const TracedList& l : *s.lists) {
    if (l.chain.empty()) continue;
    if (l.secondary && (!s.focus_row || l.phase_index != *s.focus_row)) continue;
    const bool selected = s.selected >= 0 && std::find(l.chain.begin(), l.chain.end(), s.selected) != l.chain.end();
    // With a selection, the other lists step back so the selected element's lists read clearly.
    const Rgba colour = s.selected >= 0 && !selected ? list_colour(l).with_alpha(90) : list_colour(l);
    const float width = selected ? 3.0f : 1.5f;
    // Lists of different kinds between the same two elements run side by side, a few pixels apart.
    const float side = static_cast<float>((l.kind == "y-list" || l.kind == "z-list" ? 2.5 : -2.5) / ppm);
    auto link = [&](Vec2 a, float ra, Vec2 b, float rb) {
      const Vec2 ab = b - a;
      const float len = ab.norm();
      if (len <= 1e-9f) return;
      const Vec2 dir = ab / len, off = Vec2(-dir.y(), dir.x()) * side;
      const Vec2 from = a + dir * std::min(0.45f * ra, 0.3f * len) + off;
      const Vec2 to = b - dir * std::min(0.45f * rb, 0.3f * len) + off;
      if (segment_in_view(view, from, to)) sink.arrow(Layer::Overlay, from, to, colour, width);
    };
    if (std::any_of(l.chain.begin(), l.chain.end(), [n](ElementId k) { return k < 0 || k >= n; })) continue;
    // The head: a small square, then an arrow to the first element.
    Vec2 prev = head_anchor(l, s.grid, e, free, ppm);
    float prev_r = 0;
    sink.rect(Layer::Overlay, prev - Vec2::Constant(float(3.0 / ppm)), prev + Vec2::Constant(float(3.0 / ppm)), colour);
    for (const ElementId k : l.chain) {
      const Vec2 c = centre_of(e, k);
      const auto r = static_cast<float>(e.r[k]);
      link(prev, prev_r, c, r);
      prev = c;
      prev_r = r;
    }
    // The end of the list (-1): a short stub and a bar across it.
    const Vec2 stub_dir = Vec2(0.6f, -0.8f);
    const Vec2 stub_from = prev + stub_dir * (0.45f * prev_r);
    const Vec2 stub_to = prev + stub_dir * (0.45f * prev_r + float(9.0 / ppm));
    if (segment_in_view(view, stub_from, stub_to)) {
      const Vec2 bar = Vec2(-stub_dir.y(), stub_dir.x()) * float(3.5 / ppm);
      sink.line(Layer::Overlay, stub_from, stub_to, colour.with_alpha(200), width);
      sink.line(Layer::Overlay, stub_to - bar, stub_to + bar, colour.with_alpha(200), width);
    }
  }
}

// ---- mask -------------------------------------------------------------------------------------

void draw_mask(const Grid& g, std::array<std::int32_t, 2> cell, DrawSink& sink) {
  const double d = g.cell_size;
  bool own = true;
  for (const auto& c : mask_cells(g, cell[0], cell[1])) {
    const Vec2 a = v2(g.origin[0] + d * c[0], g.origin[1] + d * c[1]);
    sink.rect(Layer::Cells, a, a + Vec2::Constant(float(d)), own ? palette::kMaskCentre : palette::kMaskCell);
    own = false;
  }
}

// ---- pairs and checks -------------------------------------------------------------------------

// Segments between the centres of each pair. Zoomed far out a segment shrinks to a dot; those fade
// (down to a quarter) so that thousands of pairs tint the picture instead of hiding the bodies.
void draw_pair_list(const Elements& e, const PairList& pairs, const WorldRect& view, double ppm, Rgba colour,
                    float width, Layer layer, DrawSink& sink) {
  const auto n = static_cast<ElementId>(e.size());
  for (const Pair& p : pairs) {
    if (p.i < 0 || p.j < 0 || p.i >= n || p.j >= n) continue;
    const Vec2 a = centre_of(e, p.i), b = centre_of(e, p.j);
    if (!segment_in_view(view, a, b)) continue;
    const double length_px = (b - a).norm() * ppm;
    const Rgba c = length_px >= 4.0 ? colour
                                    : colour.with_alpha(static_cast<std::uint8_t>(colour.a * std::max(0.25, length_px / 4.0)));
    sink.line(layer, a, b, c, width);
  }
}

void draw_violations(const Elements& e, const PairList& violations, DrawSink& sink) {
  const auto n = static_cast<ElementId>(e.size());
  for (const Pair& p : violations) {
    if (p.i < 0 || p.j < 0 || p.i >= n || p.j >= n) continue;
    const Vec2 a = centre_of(e, p.i), b = centre_of(e, p.j);
    sink.line(Layer::Top, a, b, palette::kViolation, 2.5f);
    // A ring that never shrinks below 9 px, so a violation is found even zoomed far out.
    sink.circle(Layer::Top, 0.5f * (a + b), 0.5f * (b - a).norm() + static_cast<float>(std::max(e.r[p.i], e.r[p.j])),
                kNone, palette::kViolation, 2.0f, 9.0f);
  }
}

// ---- selection, trails, flashes ---------------------------------------------------------------

void draw_selection(const OverlayScene& s, const WorldRect& view, double ppm, DrawSink& sink) {
  const Elements& e = *s.elements;
  const ElementId k = s.selected;
  if (k < 0 || k >= static_cast<ElementId>(e.size())) return;
  if (s.grid != nullptr) {
    const Grid& g = *s.grid;
    const double d = g.cell_size;
    const Vec2 a = v2(g.origin[0] + d * g.cell(e.x[k], 0), g.origin[1] + d * g.cell(e.y[k], 1));
    sink.rect(Layer::Cells, a, a + Vec2::Constant(float(d)), palette::kSelectionCell);
  }
  if (s.pairs != nullptr) {
    PairList mine;
    for (const Pair& p : *s.pairs)
      if (p.i == k || p.j == k) mine.push_back(p);
    draw_pair_list(e, mine, view, ppm, palette::kSelection, 2.5f, Layer::Overlay, sink);
  }
  sink.circle(Layer::Top, centre_of(e, k), static_cast<float>(e.r[k]), kNone, palette::kSelection, 2.0f, 5.0f);
}

// The pair of a violation gone to: both cells outlined, both elements ringed (never smaller than
// 9 px, so the pair is found zoomed out), joined by a dashed-looking double segment.
void draw_focus_pair(const OverlayScene& s, DrawSink& sink) {
  const Elements& e = *s.elements;
  const Pair p = *s.focus_pair;
  const auto n = static_cast<ElementId>(e.size());
  if (p.i < 0 || p.j < 0 || p.i >= n || p.j >= n) return;
  if (s.grid != nullptr) {
    const Grid& g = *s.grid;
    const double d = g.cell_size;
    for (const ElementId k : {p.i, p.j}) {
      const Vec2 a = v2(g.origin[0] + d * g.cell(e.x[k], 0), g.origin[1] + d * g.cell(e.y[k], 1));
      sink.rect(Layer::Cells, a, a + Vec2::Constant(float(d)), palette::kSelectionCell);
    }
  }
  const Vec2 a = centre_of(e, p.i), b = centre_of(e, p.j);
  sink.line(Layer::Top, a, b, palette::kSelection, 3.5f);
  sink.line(Layer::Top, a, b, palette::kViolation, 1.5f);
  for (const ElementId k : {p.i, p.j})
    sink.circle(Layer::Top, centre_of(e, k), static_cast<float>(e.r[k]), kNone, palette::kSelection, 2.5f, 9.0f);
}

void draw_trails(std::span<const std::vector<Vec2>> trails, DrawSink& sink) {
  for (const auto& t : trails) {
    for (std::size_t i = 1; i < t.size(); ++i) {
      const auto alpha = static_cast<std::uint8_t>(60 + 180 * i / t.size());
      sink.line(Layer::Overlay, t[i - 1], t[i], palette::kTrail.with_alpha(alpha), 1.5f);
    }
  }
}

void draw_flashes(const Elements& e, std::span<const std::pair<ElementId, float>> flashes, const WorldRect& view,
                  DrawSink& sink) {
  for (const auto& [k, strength] : flashes) {
    if (k < 0 || k >= static_cast<ElementId>(e.size()) || !in_view(view, e.x[k], e.y[k], e.r[k])) continue;
    const auto alpha = static_cast<std::uint8_t>(std::clamp(strength, 0.0f, 1.0f) * 220.0f);
    sink.circle(Layer::Overlay, centre_of(e, k), static_cast<float>(e.r[k]), palette::kFlash.with_alpha(alpha / 3),
                palette::kFlash.with_alpha(alpha), 2.0f);
  }
}

}  // namespace

// ---- draw_scene -------------------------------------------------------------------------------

void draw_scene(const OverlayScene& s, const OverlayFlags& f, const Camera& camera, DrawSink& sink) {
  const WorldRect view = camera.view();
  const double ppm = camera.pixels_per_metre();
  WorldRect free = view;  // the part of the view no panel covers
  free.min.x() += s.insets.left / ppm;
  free.max.x() -= s.insets.right / ppm;
  free.max.y() -= s.insets.top / ppm;
  free.min.y() += s.insets.bottom / ppm;
  LabelSpace labels(view, ppm);
  for (const PixelRect& r : s.covered) labels.reserve(r);
  const bool have_elements = s.elements != nullptr;
  if (f.grid && s.grid != nullptr && s.grid->dim == 2) draw_grid(s, view, free, ppm, labels, sink);
  if (f.mask && s.grid != nullptr && s.hovered_cell) draw_mask(*s.grid, *s.hovered_cell, sink);
  if (f.bodies) draw_bodies(s, view, ppm, sink);
  if (!have_elements) return;
  const Elements& e = *s.elements;
  if (f.elements) draw_elements(e, view, ppm, sink);
  if (f.trails) draw_trails(s.trails, sink);
  if (f.flash) draw_flashes(e, s.flashes, view, sink);
  if (f.broadphase && s.checks != nullptr)
    draw_pair_list(e, s.checks->broadphase_only, view, ppm, palette::kBroadphaseOnly, 1.0f, Layer::Overlay, sink);
  const bool confirmed = f.checks && s.checks != nullptr && !s.checks->confirmed.empty();
  if (f.pairs && s.pairs != nullptr) {
    // A confirmed pair is drawn once, in the check's colour; the rest of A in the pairs' colour.
    if (confirmed) {
      PairList unconfirmed;
      std::set_difference(s.pairs->begin(), s.pairs->end(), s.checks->confirmed.begin(), s.checks->confirmed.end(),
                          std::back_inserter(unconfirmed));
      draw_pair_list(e, unconfirmed, view, ppm, palette::kPair, 1.5f, Layer::Overlay, sink);
    } else {
      draw_pair_list(e, *s.pairs, view, ppm, palette::kPair, 1.5f, Layer::Overlay, sink);
    }
  }
  if (confirmed) draw_pair_list(e, s.checks->confirmed, view, ppm, palette::kConfirmedPair, 1.5f, Layer::Overlay, sink);
  if (f.lists && s.lists != nullptr) draw_lists(s, view, free, ppm, sink);
  draw_selection(s, view, ppm, sink);
  if (f.checks && s.checks != nullptr) draw_violations(e, s.checks->violations, sink);
  if (s.focus_pair) draw_focus_pair(s, sink);
  if (f.ids || f.lists) draw_ids(e, view, ppm, s.selected, s.book_numbering, labels, sink);
  if (s.drag) sink.line(Layer::Top, (*s.drag)[0], (*s.drag)[1], palette::kDragLine, 1.5f);
}

}  // namespace nbscope::render
