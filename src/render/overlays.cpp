// Index: overlay table | picking helpers | bodies and elements | labels (ids, a dump's atom ids; one space: no label
// over another) | mask | pairs and checks | selection, trails, flashes | draw_scene. The grid and the
// legend are in overlay_grid.cpp, the lists in overlay_lists.cpp, periodic ghosts, half-links and box
// edges in overlay_periodic.cpp.
#include "render/overlays.hpp"

#include "core/cells.hpp"
#include "render/overlay_parts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <unordered_map>

namespace nbscope::render {

namespace {
using namespace detail;
// Circles smaller than this on screen get no ids: the text would cover its neighbours.
constexpr double kMinIdRadiusPx = 7.0;
// Details (spokes, bounding circles) of circles smaller than this on screen are left out.
constexpr double kMinDetailPx = 4.0;
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
      {"subdomains", 'D', &OverlayFlags::subdomains, "each MPI rank's subdomain, labelled with its rank (per-rank dumps)"},
  };
  return infos;
}

void set_overlay(OverlayFlags& flags, bool OverlayFlags::*flag, bool on) {
  if (on && flag == &OverlayFlags::lists && !flags.lists) flags.ids = true;
  flags.*flag = on;
}

// ---- picking helpers --------------------------------------------------------------------------

ElementId element_at(const Elements& e, const Eigen::Vector2d& world) { return element_at(e, world, nullptr); }

std::vector<std::array<std::int32_t, 2>> mask_cells(const Grid& grid, std::int32_t ix, std::int32_t iy) {
  std::vector<std::array<std::int32_t, 2>> cells{{ix, iy}};
  for (const CellOffset& o : kMask2d) {
    const std::int32_t x = ix + o.dx, y = iy + o.dy;
    if (x >= 0 && y >= 0 && x < grid.n[0] && y < grid.n[1]) cells.push_back({x, y});
  }
  return cells;
}

namespace {

// ---- bodies and elements ----------------------------------------------------------------------

// Where body `b` lies in a 3D frame's layer view (Here for a 2D frame or a body of no element).
LayerPlace body_place(const OverlayScene& s, const ShapeDraw& b) {
  if (s.layer == nullptr || b.element < 0 || static_cast<std::size_t>(b.element) >= s.layer->element_layer.size())
    return LayerPlace::Here;
  return s.layer->place(b.element);
}

void draw_bodies(const OverlayScene& s, const WorldRect& view, double ppm, DrawSink& sink) {
  for (const ShapeDraw& b : s.shapes) {
    const LayerPlace place = body_place(s, b);
    if (place == LayerPlace::Above || place == LayerPlace::Other) continue;
    if (place == LayerPlace::Below) {
      // A ghost of the layer below: a faint fill under a dashed purple outline, no spoke; under the
      // layer's bodies (drawn with the cells: within a draw layer lines come after every circle).
      if (!b.is_circle || !in_view(view, b.centre.x(), b.centre.y(), b.radius)) continue;
      sink.circle(Layer::Cells, b.centre, b.radius, kBelowFill, kNone, 0.0f);
      dashed_circle(Layer::Cells, b.centre, b.radius, kBelowOutline, ppm, sink);
      continue;
    }
    Rgba fill = b.motion == Motion::Static      ? palette::kStaticFill
                : b.motion == Motion::Kinematic ? palette::kKinematicFill
                                                : palette::kDynamicFill;
    Rgba outline = b.motion == Motion::Static      ? palette::kStaticOutline
                   : b.motion == Motion::Kinematic ? palette::kKinematicOutline
                                                   : palette::kDynamicOutline;
    // --color-by: the moving bodies (a scene's walls keep their colour; a dump's atoms are all dynamic).
    if (b.motion == Motion::Dynamic && b.element >= 0 && static_cast<std::size_t>(b.element) < s.element_fills.size()) {
      fill = s.element_fills[static_cast<std::size_t>(b.element)];
      outline = mix(fill, palette::kText, 0.45f);
    }
    if (b.is_circle) {
      if (!in_view(view, b.centre.x(), b.centre.y(), b.radius)) continue;
      sink.circle(Layer::Bodies, b.centre, b.radius, fill, outline, 1.0f);
      // A spoke shows the rotation, once it is long enough to see (a software rasterizer pays per primitive).
      if (!b.spoke || b.radius * ppm < kMinDetailPx) continue;
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

void draw_elements(const Elements& e, const LayerSlice* layer, const WorldRect& view, double ppm, DrawSink& sink) {
  for (ElementId k = 0; k < static_cast<ElementId>(e.size()); ++k) {
    // A bounding circle under ~2 px would only repaint its body's pixels.
    if (e.r[k] * ppm < 0.5 * kMinDetailPx || !in_view(view, e.x[k], e.y[k], e.r[k])) continue;
    const LayerPlace place = layer != nullptr ? layer->place(k) : LayerPlace::Here;
    if (place == LayerPlace::Below) dashed_circle(Layer::Cells, centre_of(e, k), static_cast<float>(e.r[k]), kBelowBoundingCircle, ppm, sink);
    if (place != LayerPlace::Here) continue;
    sink.circle(Layer::Overlay, centre_of(e, k), static_cast<float>(e.r[k]), kNone, palette::kBoundingCircle, 1.0f);
  }
}

// ---- labels -----------------------------------------------------------------------------------

// Element ids: inside the circle when they fit, else just above it; only for circles at least
// kMinIdRadiusPx on screen, only where the view shows them (no panel over them: those are reserved
// in `space`), never over another label.
void draw_ids(const Elements& e, const LayerSlice* layer, const WorldRect& view, double ppm, ElementId selected, bool book,
              const std::vector<std::int64_t>* ids, LabelSpace& space, DrawSink& sink) {
  char buf[24];
  if (ids != nullptr && ids->size() != static_cast<std::size_t>(e.size())) ids = nullptr;  // not this frame's
  // The selected element's id first: it must never be the one left out.
  auto place = [&](ElementId k) {
    if (e.r[k] * ppm < kMinIdRadiusPx || !in_view(view, e.x[k], e.y[k], e.r[k])) return;
    // A 3D frame's layer view: the layer's ids, the ghosts' faded, none of the hidden layers.
    const LayerPlace place = layer != nullptr ? layer->place(k) : LayerPlace::Here;
    if (place != LayerPlace::Here && place != LayerPlace::Below) return;
    // A dump's atoms by their ids (as every panel names them), else the row.
    const int digits = ids != nullptr ? std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>((*ids)[static_cast<std::size_t>(k)]))
                                      : std::snprintf(buf, sizeof buf, "%d", book ? k + 1 : k);
    const double w = label_width(static_cast<std::size_t>(digits));
    const double r_px = e.r[k] * ppm;
    const Vec2 at = 2.0 * r_px >= w ? centre_of(e, k) : v2(e.x[k], e.y[k] + (r_px + 0.5 * kLinePx + 1.0) / ppm);
    if (!label_inside(view, at, w, kLinePx, ppm) || !space.take(at, w, kLinePx)) return;
    sink.text(at, buf, place == LayerPlace::Here ? palette::kText : palette::kText.with_alpha(kBelowTextAlpha));
  };
  if (selected >= 0 && selected < static_cast<ElementId>(e.size())) place(selected);
  // The layer's own ids before its ghosts': a ghost's never takes an element's place.
  const auto ghost = [layer](ElementId k) { return layer != nullptr && layer->place(k) != LayerPlace::Here; };
  for (const bool ghosts : {false, true})
    for (ElementId k = 0; k < static_cast<ElementId>(e.size()); ++k)
      if (k != selected && ghost(k) == ghosts) place(k);
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
  std::array<std::array<Vec2, 2>, 2> segments;
  for (const Pair& p : pairs) {
    if (p.i < 0 || p.j < 0 || p.i >= n || p.j >= n) continue;
    // Across a periodic edge: two half-links (overlay_periodic.cpp).
    const int count = pair_segments(e, p.i, p.j, segments);
    for (int s = 0; s < count; ++s) {
      const auto [a, b] = segments[static_cast<std::size_t>(s)];
      if (!segment_in_view(view, a, b)) continue;
      const double length_px = (b - a).norm() * ppm;
      const Rgba c = length_px >= 4.0 ? colour
                                      : colour.with_alpha(static_cast<std::uint8_t>(colour.a * std::max(0.25, length_px / 4.0)));
      sink.line(layer, a, b, c, width);
    }
  }
}

void draw_violations(const Elements& e, const PairList& violations, DrawSink& sink) {
  const auto n = static_cast<ElementId>(e.size());
  std::array<std::array<Vec2, 2>, 2> segments;
  for (const Pair& p : violations) {
    if (p.i < 0 || p.j < 0 || p.i >= n || p.j >= n) continue;
    const float r = static_cast<float>(std::max(e.r[p.i], e.r[p.j]));
    // Across a periodic edge each half-link gets its ring, around the pair as seen from that side.
    const int count = pair_segments(e, p.i, p.j, segments);
    const Vec2 d = count == 1 ? Vec2::Zero() : Vec2(min_image_delta(e, p.i, p.j).cast<float>());
    for (int s = 0; s < count; ++s) {
      const auto [a, b] = segments[static_cast<std::size_t>(s)];
      const Vec2 other = count == 1 ? b : s == 0 ? Vec2(a + d) : Vec2(a - d);  // the other's (nearest image's) centre
      sink.line(Layer::Top, a, b, palette::kViolation, 2.5f);
      // A ring that never shrinks below 9 px, so a violation is found even zoomed far out.
      sink.circle(Layer::Top, 0.5f * (a + other), 0.5f * (other - a).norm() + r, kNone, palette::kViolation, 2.0f, 9.0f);
    }
  }
}

// ---- selection, trails, flashes ---------------------------------------------------------------

void draw_selection(const OverlayScene& s, const ViewFrame& v, LabelSpace& labels, DrawSink& sink) {
  const Elements& e = *s.elements;
  const ElementId k = s.selected;
  if (k < 0 || k >= static_cast<ElementId>(e.size())) return;
  if (s.layer != nullptr && !s.layer->visible(k)) return;  // in a hidden layer: its own view shows it
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
    if (s.layer != nullptr) mine = pairs_in_layer(mine, *s.layer);
    draw_pair_list(e, mine, v.view, v.ppm, palette::kSelection, 2.5f, Layer::Overlay, sink);
    if (s.layer != nullptr) draw_layer_marks(e, mine, *s.layer, palette::kSelection, Layer::Overlay, v, labels, sink);
  }
  sink.circle(Layer::Top, centre_of(e, k), static_cast<float>(e.r[k]), kNone, palette::kSelection, 2.0f, 5.0f);
}

// The pair of a violation gone to: both cells outlined, both elements ringed (never smaller than
// 9 px, so the pair is found zoomed out), joined by a dashed-looking double segment; in a 3D
// frame's layer view, a partner in another layer is marked with its layer.
void draw_focus_pair(const OverlayScene& s, const ViewFrame& v, LabelSpace& labels, DrawSink& sink) {
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
  // As the check measures the pair: each element joined to the other's nearest image, ringed there
  // too; across a periodic edge from both sides (the camera frames i's side, focus_violation).
  std::array<std::array<Vec2, 2>, 2> segments;
  const bool crosses = pair_segments(e, p.i, p.j, segments) == 2;
  const Vec2 d = min_image_delta(e, p.i, p.j).cast<float>();
  const std::array<std::pair<ElementId, ElementId>, 2> sides{{{p.i, p.j}, {p.j, p.i}}};
  for (int side = 0; side < (crosses ? 2 : 1); ++side) {
    const auto [from, to] = sides[static_cast<std::size_t>(side)];
    const Vec2 a = centre_of(e, from), b = a + (side == 0 ? d : Vec2(-d));
    sink.line(Layer::Top, a, b, palette::kSelection, 3.5f);
    sink.line(Layer::Top, a, b, palette::kViolation, 1.5f);
    sink.circle(Layer::Top, a, static_cast<float>(e.r[from]), kNone, palette::kSelection, 2.5f, 9.0f);
    sink.circle(Layer::Top, b, static_cast<float>(e.r[to]), kNone, palette::kSelection, 2.5f, 9.0f);
  }
  if (s.layer != nullptr) draw_layer_marks(e, PairList{p}, *s.layer, palette::kSelection, Layer::Top, v, labels, sink);
}

void draw_trails(std::span<const std::vector<Vec2>> trails, const PeriodicBox& box, DrawSink& sink) {
  // A step wrapped across a periodic box is a jump of more than half its length: no segment there.
  const auto wrapped = [&box](Vec2 a, Vec2 b) {
    for (int k = 0; k < 2; ++k)
      if (box.periodic[k] && std::abs(double(b[k]) - double(a[k])) > 0.5 * box.length(k)) return true;
    return false;
  };
  for (const auto& t : trails) {
    for (std::size_t i = 1; i < t.size(); ++i) {
      if (wrapped(t[i - 1], t[i])) continue;
      const auto alpha = static_cast<std::uint8_t>(60 + 180 * i / t.size());
      sink.line(Layer::Overlay, t[i - 1], t[i], palette::kTrail.with_alpha(alpha), 1.5f);
    }
  }
}

void draw_flashes(const Elements& e, const LayerSlice* layer, std::span<const std::pair<ElementId, float>> flashes,
                  const WorldRect& view, DrawSink& sink) {
  for (const auto& [k, strength] : flashes) {
    if (k < 0 || k >= static_cast<ElementId>(e.size()) || !in_view(view, e.x[k], e.y[k], e.r[k])) continue;
    if (layer != nullptr && !layer->visible(k)) continue;
    const auto alpha = static_cast<std::uint8_t>(std::clamp(strength, 0.0f, 1.0f) * 220.0f);
    sink.circle(Layer::Overlay, centre_of(e, k), static_cast<float>(e.r[k]), palette::kFlash.with_alpha(alpha / 3),
                palette::kFlash.with_alpha(alpha), 2.0f);
  }
}

// Broadphase-only, detected and confirmed pairs. A 3D frame's layer view keeps the pairs with an
// element in the layer, and marks the partner's end of those that reach the layer below or above.
void draw_pairs(const OverlayScene& s, const OverlayFlags& f, const ViewFrame& v, LabelSpace& labels, DrawSink& sink) {
  const Elements& e = *s.elements;
  const auto draw = [&](const PairList& all, Rgba colour, float width) {
    if (s.layer == nullptr) {
      draw_pair_list(e, all, v.view, v.ppm, colour, width, Layer::Overlay, sink);
      return;
    }
    const PairList here = pairs_in_layer(all, *s.layer);
    draw_pair_list(e, here, v.view, v.ppm, colour, width, Layer::Overlay, sink);
    draw_layer_marks(e, here, *s.layer, colour, Layer::Overlay, v, labels, sink);
  };
  if (f.broadphase && s.checks != nullptr) draw(s.checks->broadphase_only, palette::kBroadphaseOnly, 1.0f);
  const bool confirmed = f.checks && s.checks != nullptr && !s.checks->confirmed.empty();
  if (f.pairs && s.pairs != nullptr) {
    // A confirmed pair is drawn once, in the check's colour; the rest of A in the pairs' colour.
    if (confirmed) {
      PairList unconfirmed;
      std::set_difference(s.pairs->begin(), s.pairs->end(), s.checks->confirmed.begin(), s.checks->confirmed.end(),
                          std::back_inserter(unconfirmed));
      draw(unconfirmed, palette::kPair, 1.5f);
    } else {
      draw(*s.pairs, palette::kPair, 1.5f);
    }
  }
  if (confirmed) draw(s.checks->confirmed, palette::kConfirmedPair, 1.5f);
}

}  // namespace

std::optional<std::int32_t> list_focus_row(std::optional<std::int32_t> stepper_row,
                                           std::optional<std::array<std::int32_t, 2>> hovered_cell,
                                           std::optional<std::int32_t> selected_row) {
  if (stepper_row) return stepper_row;
  if (hovered_cell) return (*hovered_cell)[1];
  return selected_row;
}

// ---- draw_scene -------------------------------------------------------------------------------

void draw_scene(const OverlayScene& scene, const OverlayFlags& f, const Camera& camera, DrawSink& sink) {
  // A layer slice of other elements than these (a stale one) is not used: the frame is drawn whole.
  OverlayScene checked;
  const bool stale = scene.layer != nullptr && (scene.elements == nullptr ||
                                                scene.layer->element_layer.size() != static_cast<std::size_t>(scene.elements->size()));
  if (stale) {
    checked = scene;
    checked.layer = nullptr;
  }
  const OverlayScene& s = stale ? checked : scene;
  ViewFrame v;
  v.view = camera.view();
  v.ppm = camera.pixels_per_metre();
  const WorldRect& view = v.view;
  const double ppm = v.ppm;
  v.free = view;  // the part of the view no panel covers
  v.free.min.x() += s.insets.left / ppm;
  v.free.max.x() -= s.insets.right / ppm;
  v.free.max.y() -= s.insets.top / ppm;
  v.free.min.y() += s.insets.bottom / ppm;
  LabelSpace labels(view, ppm);
  for (const PixelRect& r : s.covered) labels.reserve(r);
  const bool have_elements = s.elements != nullptr;
  // The legend's box first (its corner is fixed), then the grid's labels around it.
  // A 3D grid is drawn as its layer shown (x-y cells), never without one.
  const bool flat = s.grid != nullptr && (s.grid->dim == 2 || (s.layer != nullptr && s.layer->layer < s.grid->n[2]));
  const bool grid = f.grid && flat;
  const GridCounts counts = grid ? count_cells(s, v) : GridCounts{};
  draw_legend(s, f, counts.stats, v, labels, sink);
  if (grid) draw_grid(s, v, counts, labels, sink);
  if (f.mask && flat) {
    // The hovered cell's mask, else the selected element's (headless: --select shows it; in the
    // layer view only an element of the layer).
    std::optional<std::array<std::int32_t, 2>> cell = s.hovered_cell;
    const ElementId k = s.selected;
    if (!cell && have_elements && k >= 0 && k < static_cast<ElementId>(s.elements->size()) &&
        (s.layer == nullptr || s.layer->place(k) == LayerPlace::Here))
      cell = {s.grid->cell(s.elements->x[k], 0), s.grid->cell(s.elements->y[k], 1)};
    if (cell && s.layer != nullptr) draw_mask_3d(*s.grid, *cell, s.layer->layer, sink);
    else if (cell) draw_mask(*s.grid, *cell, sink);
  }
  if (f.bodies) draw_bodies(s, view, ppm, sink);
  if (!have_elements) return;
  const Elements& e = *s.elements;
  if (f.bodies || f.elements) draw_ghosts(s, view, sink);  // periodic frames only
  draw_box_edges(e, view, ppm, sink);
  if (f.subdomains && s.subdomains != nullptr) draw_subdomains(s, v, labels, sink);
  if (f.elements) draw_elements(e, s.layer, view, ppm, sink);
  // Trails are the selected element's: not while it is in a hidden layer.
  if (f.trails && (s.layer == nullptr || s.selected < 0 || s.selected >= static_cast<ElementId>(e.size()) || s.layer->visible(s.selected)))
    draw_trails(s.trails, e.box, sink);
  if (f.flash) draw_flashes(e, s.layer, s.flashes, view, sink);
  // The overview's heat map is the picture at that scale: pair segments a few pixels long would
  // bury it (large.json settled: 40,000 of them); violations are still drawn, and zooming in shows pairs.
  // A violation's marks first (on top, and their labels placed before those of the pairs under them).
  const bool violations = f.checks && s.checks != nullptr;
  PairList violations_here;
  if (violations && s.layer != nullptr) {
    violations_here = pairs_in_layer(s.checks->violations, *s.layer);
    draw_layer_marks(e, violations_here, *s.layer, palette::kViolation, Layer::Top, v, labels, sink);
  }
  if (!counts.stats.heat_map) draw_pairs(s, f, v, labels, sink);
  std::vector<bool> marked_links;  // the problems whose wrong link the lists drew (in red, along their chain)
  if (f.lists && s.lists != nullptr) draw_lists(s, f, v, labels, sink, &marked_links);
  if (s.verify != nullptr) draw_verify(s, v, marked_links, sink);
  draw_selection(s, v, labels, sink);
  // A violation keeps its red in the layer view (its partner in another layer marked above).
  if (violations) draw_violations(e, s.layer != nullptr ? violations_here : s.checks->violations, sink);
  if (s.focus_pair) draw_focus_pair(s, v, labels, sink);
  if (f.ids) draw_ids(e, s.layer, view, ppm, s.selected, s.book_numbering, s.ids, labels, sink);
  if (f.lists && s.lists != nullptr) draw_head_labels(s, v, labels, sink);
  if (s.drag) sink.line(Layer::Top, (*s.drag)[0], (*s.drag)[1], palette::kDragLine, 1.5f);
}

}  // namespace nbscope::render
