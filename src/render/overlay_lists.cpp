// The lists overlay: each singly connected list as head -> first -> ... -> end (-1). A row's y-list
// runs as arcs inside the row's band (rightward links above its middle, leftward below, taller the
// farther they reach), so each can be followed; cell lists are short arrows inside their cell. The
// filter keeps all lists, the selected element's, or one row's; the stepper's list and pair stand out.
#include <cmath>

#include "render/overlay_parts.hpp"

namespace nbscope::render::detail {

namespace {

Rgba list_colour(const TracedList& l) {
  if (l.secondary) return palette::kXListBelow;
  if (l.kind == "y-list" || l.kind == "z-list") return palette::kYList;
  return palette::kXList;
}

// A row's list (NBS y-list): its pushes fix the row only.
bool row_list(const TracedList& l) { return l.cell[0] < 0 && l.cell[1] >= 0 && l.cell[2] < 0; }

// The row a list belongs to: its cell's, the row it was built for (B[1] copies), else its head
// element's (tree leaves, which carry no cell).
std::int64_t row_of(const TracedList& l, const Grid* g, const Elements& e) {
  if (l.secondary) return l.phase_index;
  if (l.cell[1] >= 0) return l.cell[1];
  return g != nullptr ? g->cell(e.y[l.chain.front()], 1) : -1;
}

// Where a list's head is drawn: a row's left of the grid, in the gap before the row numbers (right
// of the row numbers at the view's left edge when the grid's is out of it); a cell's in a corner of the cell (top left for a
// row's own lists, bottom left for the copies of the row below); lists without a cell (tree leaves)
// just above-left of their first element.
Vec2 head_anchor(const TracedList& l, const Grid* grid, const Elements& e, const WorldRect& free, double ppm) {
  if (grid != nullptr) {
    const Grid& g = *grid;
    const double d = g.cell_size;
    if (row_list(l)) return v2(std::max(g.origin[0] - 8.0 / ppm, free.min.x() + 30.0 / ppm), g.origin[1] + d * (l.cell[1] + 0.5));
    if (l.cell[0] >= 0 && l.cell[1] >= 0)
      return v2(g.origin[0] + d * (l.cell[0] + 0.12), g.origin[1] + d * (l.cell[1] + (l.secondary ? 0.12 : 0.88)));
  }
  const ElementId k = l.chain.front();
  const double off = (e.r[k] + 10.0 / ppm) * 0.7071;
  return v2(e.x[k] - off, e.y[k] + off);
}

bool kept_by_filter(const OverlayScene& s, const TracedList& l) {
  switch (s.list_filter) {
    case ListFilter::All: return true;
    case ListFilter::Selected:
      return s.selected >= 0 && std::find(l.chain.begin(), l.chain.end(), s.selected) != l.chain.end();
    case ListFilter::Row: return s.focus_row && row_of(l, s.grid, *s.elements) == *s.focus_row;
  }
  return true;
}

}  // namespace

void draw_lists(const OverlayScene& s, const OverlayFlags& /*f*/, const ViewFrame& v, DrawSink& sink) {
  const Elements& e = *s.elements;
  const double ppm = v.ppm;
  const auto n = static_cast<ElementId>(e.size());
  const std::vector<TracedList>& lists = *s.lists;
  // The list the stepper is writing: the latest build of its head (NBS rebuilds x-lists per row).
  std::ptrdiff_t active = -1;
  if (s.active_list)
    for (std::size_t i = 0; i < lists.size(); ++i)
      if (lists[i].heads_array == s.active_list->first && lists[i].slot == s.active_list->second) active = static_cast<std::ptrdiff_t>(i);
  for (std::size_t i = 0; i < lists.size(); ++i) {
    const TracedList& l = lists[i];
    const bool is_active = static_cast<std::ptrdiff_t>(i) == active;
    if (l.chain.empty()) continue;
    if (std::any_of(l.chain.begin(), l.chain.end(), [n](ElementId k) { return k < 0 || k >= n; })) continue;
    if (!is_active && l.secondary && (!s.focus_row || l.phase_index != *s.focus_row)) continue;
    if (!is_active && !kept_by_filter(s, l)) continue;
    const bool selected = s.selected >= 0 && std::find(l.chain.begin(), l.chain.end(), s.selected) != l.chain.end();
    // With a selection (or a list being written), the other lists step back.
    const bool step_back = (s.selected >= 0 && !selected) || (active >= 0 && !is_active);
    const Rgba colour = step_back ? list_colour(l).with_alpha(90) : list_colour(l);
    const float width = is_active ? 3.0f : selected ? 2.5f : 1.5f;
    const bool arcs = s.grid != nullptr && row_list(l);
    const double d = s.grid != nullptr ? s.grid->cell_size : 0.0;
    const double band_lo = arcs ? s.grid->origin[1] + d * l.cell[1] : 0.0, band_hi = band_lo + d;
    const double grid_width = s.grid != nullptr ? d * double(s.grid->n[0]) : 1.0;
    // Lists of different kinds between the same two elements run side by side, a few pixels apart.
    const float side = static_cast<float>(-2.5 / ppm);
    const auto segment = [&](Vec2 a, Vec2 b, bool head) {
      if (!segment_in_view(v.view, a, b)) return;
      if (is_active) sink.line(Layer::Overlay, a, b, palette::kActiveList, 7.0f);
      if (head) sink.arrow(Layer::Overlay, a, b, colour, width);
      else sink.line(Layer::Overlay, a, b, colour, width);
    };
    const auto link = [&](Vec2 a, float ra, Vec2 b, float rb) {
      const Vec2 ab = b - a;
      const float len = ab.norm();
      if (len <= 1e-9f) return;
      const float t0 = std::min(0.45f * ra / len, 0.3f), t1 = 1.0f - std::min(0.45f * rb / len, 0.3f);
      if (!arcs) {
        const Vec2 dir = ab / len, off = Vec2(-dir.y(), dir.x()) * side;
        segment(a + ab * t0 + off, a + ab * t1 + off, true);
        return;
      }
      // An arc diagram along the row's middle line: each element hangs on it by a stem, and each
      // link is an arc over the line for a step to the right, under it for one to the left, its
      // height in proportion to its reach across the grid, so that arcs of different reach nest
      // instead of running together; it never leaves the row's band.
      const double mid = 0.5 * (band_lo + band_hi);
      const double dx = std::abs(double(ab.x()));
      const double up = ab.x() >= 0 ? 1.0 : -1.0;
      const double h = 0.45 * d * std::min(1.0, 0.06 + dx / grid_width);
      const Vec2 from = v2(a.x(), mid), to = v2(b.x(), mid);
      const auto at = [&](double t) { return Vec2(from + (to - from) * float(t) + Vec2(0.0f, float(up * h * 4.0 * t * (1.0 - t)))); };
      constexpr int kSteps = 14;
      Vec2 prev = at(0.0);
      for (int k = 1; k < kSteps; ++k) {
        const Vec2 next = at(double(k) / kSteps);
        segment(prev, next, false);
        prev = next;
      }
      segment(prev, to, true);
      if (rb > 0) segment(to, b, false);  // the stem of the element reached
    };
    // The head: a small square, then an arrow to the first element.
    Vec2 prev = head_anchor(l, s.grid, e, v.free, ppm);
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
    if (segment_in_view(v.view, stub_from, stub_to)) {
      const Vec2 bar = Vec2(-stub_dir.y(), stub_dir.x()) * float(3.5 / ppm);
      sink.line(Layer::Overlay, stub_from, stub_to, colour.with_alpha(200), width);
      sink.line(Layer::Overlay, stub_to - bar, stub_to + bar, colour.with_alpha(200), width);
    }
  }
  // The pair the stepper is testing, coloured by the test's result.
  if (s.tested_pair) {
    const Pair p = *s.tested_pair;
    if (p.i >= 0 && p.j >= 0 && p.i < n && p.j < n)
      sink.line(Layer::Top, centre_of(e, p.i), centre_of(e, p.j), s.tested_contact ? palette::kConfirmedPair : palette::kTextDim,
                s.tested_contact ? 4.0f : 2.5f);
  }
}

}  // namespace nbscope::render::detail
