// The lists overlay: each singly connected list as head -> first -> ... -> end (-1). A row's y-list
// runs as arcs inside the row's band (rightward links above its middle, leftward below, taller the
// farther they reach), so each can be followed; cell lists are short arrows inside their cell. The
// filter keeps all lists, the selected element's, or one row's; the stepper's list and pair stand out.
#include <cmath>
#include <cstdio>
#include <string>

#include "render/overlay_parts.hpp"

namespace nbscope::render::detail {

namespace {
// A row's list (NBS y-list): its pushes fix the row only (and, in 3D, the row's layer).
bool row_list(const TracedList& l) { return l.cell[0] < 0 && l.cell[1] >= 0; }
}  // namespace

// Where a list's head is drawn: a row's left of the grid, in the gap before the row numbers (right
// of the row numbers at the view's left edge when the grid's is out of it); a cell's in a corner of the cell (top left for a
// row's own lists, bottom left for the copies of the row below); lists without a cell (tree leaves)
// just above-left of their first element. A 3D layer view's lists of the layer below (`below`)
// sit as the row below's copies do: a cell's bottom left, a row's lower in its band.
Vec2 head_anchor(const TracedList& l, const Grid* grid, const Elements& e, const WorldRect& free, double ppm, bool below) {
  if (grid != nullptr) {
    const Grid& g = *grid;
    const double d = g.cell_size;
    if (row_list(l))
      return v2(std::max(g.origin[0] - 8.0 / ppm, free.min.x() + 30.0 / ppm), g.origin[1] + d * (l.cell[1] + (below ? 0.25 : 0.5)));
    if (l.cell[0] >= 0 && l.cell[1] >= 0)
      return v2(g.origin[0] + d * (l.cell[0] + 0.12), g.origin[1] + d * (l.cell[1] + (l.secondary || below ? 0.12 : 0.88)));
  }
  const ElementId k = l.chain.front();
  const double off = (e.r[k] + 10.0 / ppm) * 0.7071;
  return v2(e.x[k] - off, e.y[k] + off);
}

namespace {

// The row a list belongs to: its cell's, the row it was built for (B[1] copies; 2D: in 3D NBS's
// B[1] holds the layer below's y-lists, built per layer), else its head element's (tree leaves,
// which carry no cell).
std::int64_t row_of(const TracedList& l, const Grid* g, const Elements& e, bool layered) {
  if (l.secondary && !layered) return l.phase_index;
  if (l.cell[1] >= 0) return l.cell[1];
  return g != nullptr ? g->cell(e.y[l.chain.front()], 1) : -1;
}

// A verify problem's wrong link along a chain: red, over a white band when it is the selected problem
// (a layer below: within a layer lines come after the arrows' heads and would cover them).
void draw_wrong_link(const OverlayScene& s, int problem, Vec2 a, Vec2 b, bool head, DrawSink& sink) {
  if (s.verify != nullptr && problem == s.verify->selected) sink.line(Layer::Bodies, a, b, palette::kSelection, 8.0f);
  if (head) sink.arrow(Layer::Overlay, a, b, palette::kViolation, 3.0f);
  else sink.line(Layer::Overlay, a, b, palette::kViolation, 3.0f);
}

// A list's end from `from` to `to`: a bar across it (-1), or, where the walk was cut (a cycle, an
// index out of range, an element seen before), the stub in red with a cross: the list never ends.
void draw_end(Vec2 from, Vec2 to, bool cut, Rgba colour, float width, double ppm, DrawSink& sink) {
  const Vec2 dir = (to - from).normalized();
  if (cut) {
    const float c = float(4.0 / ppm);
    sink.line(Layer::Overlay, from, to, palette::kViolation, 2.5f);
    sink.line(Layer::Top, to - Vec2(c, c), to + Vec2(c, c), palette::kViolation, 2.5f);
    sink.line(Layer::Top, to - Vec2(c, -c), to + Vec2(c, -c), palette::kViolation, 2.5f);
    return;
  }
  const Vec2 bar = Vec2(-dir.y(), dir.x()) * float(3.5 / ppm);
  sink.line(Layer::Overlay, from, to, colour, width);
  sink.line(Layer::Overlay, to - bar, to + bar, colour, width);
}

// A y-list longer than this is drawn as a rail: its arcs would run together.
constexpr std::size_t kMaxArcLinks = 12;

// A rail's slot is at least this wide (px): room for its number, never a solid band of slots.
constexpr double kMinSlotPx = 10.0;

// A long y-list as the book writes it, along its row's band: head -> slot -> slot -> ... -> end,
// evenly spaced left to right in list order, each slot joined to its element by a thin leader
// (bold for the selected element). The order reads off the rail; the leaders say where each is.
// A list with more slots than fit shows its two ends, numbered, and "... 790 more ..." between.
// `wrong(from, to)` names the problem whose wrong link that is (-1: none; from -1: the head).
template <class WrongLink>
void draw_rail(const OverlayScene& s, const TracedList& l, bool below, const ViewFrame& v, Rgba colour, float width,
               bool active, const WrongLink& wrong, LabelSpace& labels, DrawSink& sink) {
  const Elements& e = *s.elements;
  const Grid& g = *s.grid;
  const double d = g.cell_size, ppm = v.ppm;
  const double x0 = g.origin[0], x1 = g.origin[0] + d * double(g.n[0]);
  const double y = g.origin[1] + d * (l.cell[1] + (below ? 0.32 : 0.14));  // the layer below's rail above the row's own
  const Vec2 head = head_anchor(l, s.grid, e, v.free, ppm, below);
  const Vec2 start = v2(head.x(), y);
  sink.rect(Layer::Overlay, start - Vec2::Constant(float(3.0 / ppm)), start + Vec2::Constant(float(3.0 / ppm)), colour);
  // The slots shown: all when they fit, else the first and last `ends` each, with the gap between.
  const std::size_t count = l.chain.size();
  char id[16];
  const int widest = std::snprintf(id, sizeof id, "%d", static_cast<int>(e.size()) + (s.book_numbering ? 1 : 0));
  const double slot_px = std::max(kMinSlotPx, label_width(static_cast<std::size_t>(widest)) + 2.0);
  const double rail_px = (x1 - x0) * ppm;
  std::size_t ends = count;  // slots at each end when cut; count: not cut
  std::string gap_text;
  if (double(count) * slot_px > rail_px) {
    gap_text = "... " + std::to_string(count) + " more ...";  // the widest it can be
    const double gap_px = label_width(gap_text.size()) + 8.0;
    ends = static_cast<std::size_t>(std::max(1.0, std::floor((rail_px - gap_px) / slot_px / 2.0)));
    ends = std::min(ends, (count - 1) / 2);
    gap_text = "... " + std::to_string(count - 2 * ends) + " more ...";
  }
  const bool cut_middle = ends < count;
  const double gap = cut_middle ? std::max(0.0, rail_px - 2.0 * double(ends) * slot_px) / ppm : 0.0;
  const double step = cut_middle ? slot_px / ppm : (x1 - x0) / double(count);
  // Where chain position i sits along the rail (cut: the first `ends` from the left, the last from the right).
  const auto slot_at = [&](std::size_t i) {
    if (!cut_middle) return v2(x0 + step * (double(i) + 0.5), y);
    if (i < ends) return v2(x0 + step * (double(i) + 0.5), y);
    return v2(x1 - step * (double(count - i) - 0.5), y);
  };
  Vec2 prev = start;
  for (std::size_t i = 0; i < count; ++i) {
    if (cut_middle && i == ends) {
      // The hidden middle: a thin line under "... N more ...", then on to the tail's first slot.
      i = count - ends;
      const Vec2 next = slot_at(i);
      const Vec2 mid = v2(0.5 * (double(prev.x()) + double(next.x())), y);
      if (segment_in_view(v.view, prev, next)) sink.line(Layer::Overlay, prev, next, colour.with_alpha(static_cast<std::uint8_t>(colour.a / 2)), 1.0f);
      const Vec2 text_at = mid + Vec2(0.0f, float((0.5 * kLinePx + 3.0) / ppm));
      if (gap * ppm >= label_width(gap_text.size()) && label_inside(v.free, text_at, label_width(gap_text.size()), kLinePx, ppm))
        labels.text(text_at, gap_text.c_str(), colour, sink);
      prev = next - Vec2(float(step), 0.0f);
    }
    const ElementId k = l.chain[i];
    const Vec2 slot = slot_at(i);
    const bool bold = k == s.selected;
    const Vec2 gap_px = Vec2(float(std::min(3.0 / ppm, 0.3 * step)), 0.0f);
    if (segment_in_view(v.view, prev, slot)) {
      const int bad = wrong(i == 0 ? ElementId{-1} : l.chain[i - 1], k);
      if (active) sink.line(Layer::Overlay, prev + gap_px, slot - gap_px, palette::kActiveList, 7.0f);
      if (bad >= 0) draw_wrong_link(s, bad, prev + gap_px, slot - gap_px, true, sink);
      else sink.arrow(Layer::Overlay, prev + gap_px, slot - gap_px, colour, width);
    }
    const Vec2 c = centre_of(e, k);
    if (segment_in_view(v.view, slot, c))
      sink.line(Layer::Overlay, slot, c, bold ? palette::kSelection : colour.with_alpha(static_cast<std::uint8_t>(colour.a / 3)),
                bold ? 2.5f : 1.0f);
    sink.circle(Layer::Overlay, slot, float(0.5 / ppm), colour, colour, 1.0f, bold ? 3.5f : 2.0f);
    // The element's number under its slot when the slots are wide enough: the list reads as the
    // book writes it (y_heads[iy] -> 69 -> 14 -> ... -> -1).
    const int digits = std::snprintf(id, sizeof id, "%d", s.book_numbering ? k + 1 : k);
    if (step * ppm >= label_width(static_cast<std::size_t>(digits)) + 2.0) {
      const Vec2 at = slot - Vec2(0.0f, float((0.5 * kLinePx + 3.0) / ppm));
      if (label_inside(v.free, at, label_width(static_cast<std::size_t>(digits)), kLinePx, ppm))
        labels.text(at, id, bold ? palette::kSelection : colour, sink);
    }
    prev = slot;
  }
  // The end (-1): a bar after the last slot (a red cross where the walk was cut).
  const Vec2 end = prev + Vec2(float(std::min(8.0 / ppm, 0.5 * step)), 0.0f);
  draw_end(prev, end, l.cut, colour, width, ppm, sink);
}

// The elements a scene's lists are drawn over: a 3D frame's layer and the layer below, else all.
std::int64_t elements_shown(const OverlayScene& s) {
  if (s.layer == nullptr) return s.elements->size();
  const auto count = [&](std::int32_t iz) { return iz >= 0 && iz < s.layer->count ? s.layer->per_layer[static_cast<std::size_t>(iz)] : 0; };
  return count(s.layer->layer) + count(s.layer->below);
}

bool kept_by_filter(const OverlayScene& s, const TracedList& l) {
  switch (s.list_filter) {
    case ListFilter::All: return true;
    case ListFilter::Selected:
      return s.selected >= 0 && std::find(l.chain.begin(), l.chain.end(), s.selected) != l.chain.end();
    case ListFilter::Row:  // no row yet: all of a scene small enough to draw them all
      if (!s.focus_row) return elements_shown(s) <= kAllListsUpTo;
      // NBS 3D's x-lists of a row's pass (its own row's, the row below's and the layer below's three):
      // those it built for the row.
      if (s.layer != nullptr && l.phase_layer >= 0 && l.cell[0] >= 0) return l.phase_index == *s.focus_row;
      return row_of(l, s.grid, *s.elements, s.layer != nullptr) == *s.focus_row;
  }
  return true;
}

// True when the overlay draws list `l` (`active`: the one the stepper is writing); `style` is the
// layer view's (list_layer_styles: -1 left out; ignored for a 2D frame).
bool drawn(const OverlayScene& s, const TracedList& l, bool active, std::int8_t style) {
  const auto n = static_cast<ElementId>(s.elements->size());
  if (l.chain.empty()) return false;
  if (std::any_of(l.chain.begin(), l.chain.end(), [n](ElementId k) { return k < 0 || k >= n; })) return false;
  if (s.layer != nullptr) return style >= 0 && (active || kept_by_filter(s, l));
  if (!active && l.secondary && (!s.focus_row || l.phase_index != *s.focus_row)) return false;
  return active || kept_by_filter(s, l);
}

// The layer view's style of list i (-1: left out), for a 2D frame Here.
std::int8_t style_of(const std::vector<std::int8_t>& styles, std::size_t i) { return styles.empty() ? std::int8_t{0} : styles[i]; }
constexpr std::int8_t kBelowStyle = static_cast<std::int8_t>(ListLayerStyle::Below);

}  // namespace

void draw_lists(const OverlayScene& s, const OverlayFlags& /*f*/, const ViewFrame& v, LabelSpace& labels, DrawSink& sink,
                std::vector<bool>* marked_links) {
  const Elements& e = *s.elements;
  const double ppm = v.ppm;
  const auto n = static_cast<ElementId>(e.size());
  const std::vector<TracedList>& lists = *s.lists;
  // The list the stepper is writing: the latest build of its head (NBS rebuilds x-lists per row).
  // A 3D frame's layer view keeps its layer's pass only; NBS 3D rebuilds a head A[r][ix] for each
  // row of a pass, not in row order: there, the build of the stepper's row (the focus row).
  const std::vector<std::int8_t> styles = list_layer_styles(s);
  std::ptrdiff_t active = -1;
  if (s.active_list)
    for (std::size_t i = 0; i < lists.size(); ++i) {
      if (lists[i].heads_array != s.active_list->first || lists[i].slot != s.active_list->second) continue;
      if (s.layer != nullptr && style_of(styles, i) < 0) continue;
      const auto of_row = [&](std::ptrdiff_t k) { return s.focus_row && lists[static_cast<std::size_t>(k)].phase_index == *s.focus_row; };
      if (s.layer != nullptr && active >= 0 && of_row(active) && !of_row(static_cast<std::ptrdiff_t>(i))) continue;
      active = static_cast<std::ptrdiff_t>(i);
    }
  // A verify run's wrong links, by the list they leave: drawn in red where the chain takes them.
  std::vector<std::vector<int>> marks_of(s.verify != nullptr ? lists.size() : 0);
  if (s.verify != nullptr) {
    for (std::size_t p = 0; p < s.verify->problems.size(); ++p) {
      const ProblemMark& m = s.verify->problems[p];
      if (m.link && m.list >= 0 && static_cast<std::size_t>(m.list) < lists.size())
        marks_of[static_cast<std::size_t>(m.list)].push_back(static_cast<int>(p));
    }
    if (marked_links != nullptr) marked_links->assign(s.verify->problems.size(), false);
  }
  for (std::size_t i = 0; i < lists.size(); ++i) {
    const TracedList& l = lists[i];
    const bool is_active = static_cast<std::ptrdiff_t>(i) == active;
    const std::int8_t style = style_of(styles, i);
    if (!drawn(s, l, is_active, style)) continue;
    const bool below = s.layer != nullptr && style == kBelowStyle;  // a list of the layer below: ghosted
    const bool selected = s.selected >= 0 && std::find(l.chain.begin(), l.chain.end(), s.selected) != l.chain.end();
    // With a selection (or a list being written), the other lists step back.
    const bool step_back = (s.selected >= 0 && !selected) || (active >= 0 && !is_active);
    const Rgba own = s.layer == nullptr ? list_colour(l.kind, l.secondary)
                     : below            ? list_colour(l.kind, true).with_alpha(kBelowListAlpha)
                                        : list_colour(l.kind, false);
    const Rgba colour = step_back ? own.with_alpha(std::min<std::uint8_t>(own.a, 90)) : own;
    const float width = is_active ? 3.0f : selected ? 2.5f : 1.5f;
    const bool arcs = s.grid != nullptr && row_list(l);
    // The problem whose wrong link is from -> to on this list (from -1: its head), or -1.
    const auto wrong = [&](ElementId from, ElementId to) {
      if (marks_of.empty()) return -1;
      for (const int p : marks_of[i]) {
        const auto& link = *s.verify->problems[static_cast<std::size_t>(p)].link;
        if (link.first != from || link.second != to) continue;
        if (marked_links != nullptr) (*marked_links)[static_cast<std::size_t>(p)] = true;
        return p;
      }
      return -1;
    };
    int wrong_here = -1;  // the problem whose wrong link is being drawn
    const double d = s.grid != nullptr ? s.grid->cell_size : 0.0;
    const double band_lo = arcs ? s.grid->origin[1] + d * l.cell[1] : 0.0, band_hi = band_lo + d;
    // The list's widest step: arc heights spread over the band by reach relative to it.
    double widest = 1e-9;
    for (std::size_t m = 1; m < l.chain.size(); ++m)
      widest = std::max(widest, std::abs(e.x[l.chain[m]] - e.x[l.chain[m - 1]]));
    // Straight links run a few pixels beside the centre line, clear of the pair segments.
    const float side = static_cast<float>(-2.5 / ppm);
    bool bold_link = false;  // the link being drawn touches the selected element
    const auto segment = [&](Vec2 a, Vec2 b, bool head) {
      if (!segment_in_view(v.view, a, b)) return;
      if (wrong_here >= 0) {
        draw_wrong_link(s, wrong_here, a, b, head, sink);
        return;
      }
      if (is_active || bold_link) sink.line(Layer::Overlay, a, b, palette::kActiveList, bold_link ? 5.0f : 7.0f);
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
      // An arc inside the row's band: over the chord for a step to the right, under it for one to
      // the left, taller the farther it reaches (relative to the list's widest step) so that arcs
      // of different reach part; it never leaves the band.
      const double dx = std::abs(double(ab.x()));
      const double up = ab.x() >= 0 ? 1.0 : -1.0;
      const double mid = 0.5 * (double(a.y()) + double(b.y()));
      const double room = up > 0 ? band_hi - 0.04 * d - mid : mid - band_lo - 0.04 * d;
      const double h = std::clamp(0.45 * d * std::sqrt(dx / widest), 0.0, std::max(0.0, room));
      const auto at = [&](float t) { return Vec2(a + ab * t + Vec2(0.0f, float(up * h * 4.0 * t * (1.0 - t)))); };
      constexpr int kSteps = 14;
      const float tq = t1 - 0.15f * (t1 - t0);
      Vec2 prev = at(t0);
      for (int k = 1; k <= kSteps; ++k) {
        const Vec2 next = at(t0 + (tq - t0) * float(k) / kSteps);
        segment(prev, next, false);
        prev = next;
      }
      segment(prev, at(t1), true);
    };
    if (arcs && l.chain.size() > kMaxArcLinks) {
      draw_rail(s, l, below, v, colour, width, is_active, wrong, labels, sink);
      continue;
    }
    // The head: a small square, then an arrow to the first element.
    Vec2 prev = head_anchor(l, s.grid, e, v.free, ppm, below);
    float prev_r = 0;
    sink.rect(Layer::Overlay, prev - Vec2::Constant(float(3.0 / ppm)), prev + Vec2::Constant(float(3.0 / ppm)), colour);
    ElementId prev_k = -1;
    for (const ElementId k : l.chain) {
      const Vec2 c = centre_of(e, k);
      const auto r = static_cast<float>(e.r[k]);
      bold_link = s.selected >= 0 && (k == s.selected || prev_k == s.selected);
      wrong_here = wrong(prev_k, k);
      link(prev, prev_r, c, r);
      prev_k = k;
      prev = c;
      prev_r = r;
    }
    // The end of the list (-1): a short stub and a bar across it.
    const Vec2 stub_dir = Vec2(0.6f, -0.8f);
    const Vec2 stub_from = prev + stub_dir * (0.45f * prev_r);
    const Vec2 stub_to = prev + stub_dir * (0.45f * prev_r + float(9.0 / ppm));
    if (segment_in_view(v.view, stub_from, stub_to)) draw_end(stub_from, stub_to, l.cut, colour.with_alpha(200), width, ppm, sink);
  }
  // The pair the stepper is testing, coloured by the test's result.
  if (s.tested_pair) {
    const Pair p = *s.tested_pair;
    if (p.i >= 0 && p.j >= 0 && p.i < n && p.j < n)
      sink.line(Layer::Top, centre_of(e, p.i), centre_of(e, p.j), s.tested_contact ? palette::kConfirmedPair : palette::kTextDim,
                s.tested_contact ? 4.0f : 2.5f);
  }
}

void draw_head_labels(const OverlayScene& s, const ViewFrame& v, LabelSpace& labels, DrawSink& sink) {
  const double ppm = v.ppm;
  constexpr double kGapPx = 5.0;
  // Left of the row numbers, which sit kHeadGapPx (16 px) left of the grid, two digits wide or so.
  constexpr double kRowNumbersPx = 36.0;
  const std::vector<std::int8_t> styles = list_layer_styles(s);
  for (std::size_t i = 0; i < s.lists->size(); ++i) {
    const TracedList& l = (*s.lists)[i];
    const std::int8_t style = style_of(styles, i);
    if (l.head_label.empty() || !drawn(s, l, false, style)) continue;
    const Vec2 anchor = head_anchor(l, s.grid, *s.elements, v.free, ppm, s.layer != nullptr && style == kBelowStyle);
    const double w = label_width(l.head_label.size()), h = kLinePx;
    // Only where there is room: a row's band at least a line high, a cell as wide as its name, a
    // list without a cell (a tree leaf) where its first element is large enough for its id.
    const bool row = s.grid != nullptr && row_list(l), cell = s.grid != nullptr && l.cell[0] >= 0 && l.cell[1] >= 0;
    const double cell_px = s.grid != nullptr ? s.grid->cell_size * ppm : 0.0;
    if (row ? cell_px < h + 1.0 : cell ? cell_px < w + 6.0 : s.elements->r[l.chain.front()] * ppm < 7.0) continue;
    const auto at = [&](double dx_px, double dy_px) { return Vec2(anchor + v2(dx_px / ppm, dy_px / ppm)); };
    std::vector<Vec2> tries;
    if (row) {
      // Left of the row numbers; else under the square (a row's arcs to the right run above its middle).
      tries = {at(-(kRowNumbersPx + 0.5 * w), 0.0), at(0.5 * w - 3.0, -(0.5 * h + kGapPx)), at(0.5 * w - 3.0, 0.5 * h + kGapPx)};
    } else if (cell) {
      // Above the square, along the cell's top edge (its arrow runs down into the cell), else beside it.
      tries = {at(0.5 * w - 3.0, 0.5 * h + 4.0), at(kGapPx + 0.5 * w, 0.0), at(-(kGapPx + 0.5 * w), 0.0)};
    } else {
      tries = {at(-(kGapPx + 0.5 * w), 0.0), at(0.0, 0.5 * h + kGapPx), at(kGapPx + 0.5 * w, 0.0)};
    }
    for (const Vec2& t : tries)
      if (label_inside(v.free, t, w, h, ppm) && labels.text(t, l.head_label.c_str(), list_colour(l.kind, l.secondary), sink)) break;
  }
}

}  // namespace nbscope::render::detail

namespace nbscope::render {

Rgba list_colour(std::string_view kind, bool row_below) {
  if (row_below) return palette::kXListBelow;
  if (kind == "y-list" || kind == "z-list") return palette::kYList;
  return palette::kXList;
}

}  // namespace nbscope::render
