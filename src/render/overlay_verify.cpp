// A verify run's red marks over the user's lists: each problem's elements ringed, the wrong links
// the lists did not draw along a chain as straight red arrows (from the list's head when the link
// leaves it), and the selected problem highlighted like a selection (its cells shaded, its elements
// ringed in white, its link on a white band).
#include <set>

#include "render/overlay_parts.hpp"

namespace nbscope::render::detail {

namespace {
// Rings stay at least this large on screen (px), so a problem is found zoomed out.
constexpr float kMinRingPx = 9.0f;
}  // namespace

void draw_verify(const OverlayScene& s, const ViewFrame& v, const std::vector<bool>& marked_links, DrawSink& sink) {
  const VerifyMarks& m = *s.verify;
  const Elements& e = *s.elements;
  const double ppm = v.ppm;
  const auto n = static_cast<ElementId>(e.size());
  const auto valid = [n](ElementId k) { return k >= 0 && k < n; };
  // A wrong link's ends: the first element (or its list's head) and the second, clear of their circles.
  const auto link_ends = [&](const ProblemMark& p) -> std::optional<std::array<Vec2, 2>> {
    if (!p.link || !valid(p.link->second)) return std::nullopt;
    const ElementId a = p.link->first, b = p.link->second;
    Vec2 from;
    float from_r = 0;
    if (valid(a)) {
      from = centre_of(e, a);
      from_r = static_cast<float>(e.r[a]);
    } else if (a == -1 && s.lists != nullptr && p.list >= 0 && static_cast<std::size_t>(p.list) < s.lists->size() &&
               !(*s.lists)[static_cast<std::size_t>(p.list)].chain.empty() &&
               valid((*s.lists)[static_cast<std::size_t>(p.list)].chain.front())) {
      from = head_anchor((*s.lists)[static_cast<std::size_t>(p.list)], s.grid, e, v.free, ppm);
    } else {
      return std::nullopt;
    }
    const Vec2 to = centre_of(e, b);
    const Vec2 ab = to - from;
    const float len = ab.norm();
    if (len <= 1e-9f) return std::nullopt;
    const Vec2 dir = ab / len;
    const float t0 = std::min(0.45f * from_r, 0.3f * len), t1 = std::min(0.45f * static_cast<float>(e.r[b]), 0.3f * len);
    return std::array<Vec2, 2>{from + dir * t0, to - dir * t1};
  };
  const auto drawn_along_chain = [&](std::size_t p) { return p < marked_links.size() && marked_links[p]; };

  // The selected problem, under the red: its cells shaded, its elements (and its link's) ringed in white.
  if (m.selected >= 0 && static_cast<std::size_t>(m.selected) < m.problems.size()) {
    const ProblemMark& p = m.problems[static_cast<std::size_t>(m.selected)];
    std::vector<ElementId> ks = p.elements;
    if (p.link) {
      ks.push_back(p.link->first);
      ks.push_back(p.link->second);
    }
    std::set<std::pair<std::int64_t, std::int64_t>> cells;
    std::set<ElementId> ringed;
    for (const ElementId k : ks) {
      if (!valid(k) || !ringed.insert(k).second) continue;
      if (s.grid != nullptr && s.grid->dim == 2) {
        const Grid& g = *s.grid;
        const std::int64_t cx = g.cell(e.x[k], 0), cy = g.cell(e.y[k], 1);
        if (cells.insert({cx, cy}).second) {
          const Vec2 lo = v2(g.origin[0] + g.cell_size * double(cx), g.origin[1] + g.cell_size * double(cy));
          sink.rect(Layer::Cells, lo, lo + Vec2::Constant(float(g.cell_size)), palette::kSelectionCell);
        }
      }
      sink.circle(Layer::Top, centre_of(e, k), static_cast<float>(e.r[k] + 8.0 / ppm), kNone, palette::kSelection, 2.0f,
                  kMinRingPx + 5.0f);
    }
    if (!drawn_along_chain(static_cast<std::size_t>(m.selected)))
      if (const auto ends = link_ends(p)) sink.line(Layer::Overlay, (*ends)[0], (*ends)[1], palette::kSelection, 8.0f);
  }
  // Every problem: its wrong link (unless the lists drew it along the chain) and its elements in red.
  for (std::size_t i = 0; i < m.problems.size(); ++i) {
    const ProblemMark& p = m.problems[i];
    if (!drawn_along_chain(i))
      if (const auto ends = link_ends(p); ends && segment_in_view(v.view, (*ends)[0], (*ends)[1]))
        sink.arrow(Layer::Top, (*ends)[0], (*ends)[1], palette::kViolation, 3.0f);
    for (const ElementId k : p.elements) {
      if (!valid(k) || !in_view(v.view, e.x[k], e.y[k], e.r[k] + 12.0 / ppm)) continue;
      sink.circle(Layer::Top, centre_of(e, k), static_cast<float>(e.r[k] + 3.5 / ppm), kNone, palette::kViolation, 2.5f,
                  kMinRingPx);
    }
  }
}

}  // namespace nbscope::render::detail
