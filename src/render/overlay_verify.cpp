// A verify run's overlay: its lists and problems turned into what the overlays draw (TracedLists
// with their heads named, drawn as the lists overlay draws nbscope's own, and one ProblemMark per
// problem with the caption the legend shows), and the red marks drawn from them: each problem's
// elements ringed, the wrong links the lists did not draw along a chain as straight red arrows
// (from the list's head when the link leaves it), and the selected problem highlighted like a
// selection (its cells shaded, its elements ringed in white, its link on a white band).
//
// Index: family_kind, user_lists, wrap_words, problem_caption, verify_marks (the model) |
// detail::draw_verify (the marks drawn).
#include "render/overlay_verify.hpp"

#include <map>
#include <set>

#include "io/plural.hpp"
#include "render/overlay_parts.hpp"

namespace nbscope::render {


std::string family_kind(const verify::ListFamily& family) {
  const std::string& h = family.heads_name;
  if (h == "y_heads") return "y-list";
  if (h == "z_heads") return "z-list";
  if (h == "x_heads") return "x-list";
  if (h == "C") return "cell list";
  if (h == "HEAD") return "leaf list";
  return h + " list";
}

std::vector<TracedList> user_lists(const verify::UserArrays& user, const verify::ArraysVerdict& verdict, int base) {
  std::vector<TracedList> out;
  out.reserve(verdict.lists.size());
  for (const verify::WalkedList& w : verdict.lists) {
    TracedList l;
    l.chain = w.chain;
    l.cut = w.cut;
    if (w.family >= 0 && static_cast<std::size_t>(w.family) < user.families.size()) {
      const verify::ListFamily& f = user.families[static_cast<std::size_t>(w.family)];
      l.kind = family_kind(f);
      l.heads_name = f.heads_name;
      l.next_name = f.next_name;
      l.heads_shape = f.heads_shape;
      l.phase_index = f.scope[1];
      if (w.list >= 0 && static_cast<std::size_t>(w.list) < f.lists.size()) {
        const verify::UserList& u = f.lists[static_cast<std::size_t>(w.list)];
        l.slot = u.slot;
        for (int a = 0; a < 3; ++a) l.cell[a] = u.cell[static_cast<std::size_t>(a)];
        l.head_label = verify::slot_name(f, u.slot, base);
      }
    }
    out.push_back(std::move(l));
  }
  return out;
}

std::vector<std::string> wrap_words(const std::string& text, std::size_t width) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t space = text.find(' ', start);
    if (space == std::string::npos) space = text.size();
    const std::string word = text.substr(start, space - start);
    const std::size_t indent = lines.empty() ? 0 : 2;
    if (!line.empty() && indent + line.size() + 1 + word.size() > width) {
      lines.push_back(std::string(indent, ' ') + line);
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    start = space + 1;
  }
  if (!line.empty() || lines.empty()) lines.push_back(std::string(lines.empty() ? 0 : 2, ' ') + line);
  return lines;
}

std::vector<std::string> problem_caption(const verify::ArraysVerdict& verdict, int selected, std::size_t wrap) {
  if (verdict.problems.empty() && verdict.problem_count == 0) {
    std::vector<std::string> out = wrap_words(
        "no problems: " + plural(static_cast<long long>(verdict.lists.size()), "list") +
            ", every element on exactly one, the list of its own cell", wrap);
    if (verdict.other_order_lists > 0) {
      for (const std::string& l :
           wrap_words(plural(verdict.other_order_lists, "list") + " right but not in the book's order (--exact holds them to it)", wrap))
        out.push_back(l);
    }
    return out;
  }
  const auto count = static_cast<long long>(verdict.problem_count);
  if (selected < 0 || static_cast<std::size_t>(selected) >= verdict.problems.size())
    return wrap_words(plural(count, "problem") + ": pick one in the Problems panel", wrap);
  const verify::Problem& p = verdict.problems[static_cast<std::size_t>(selected)];
  return wrap_words(std::to_string(selected + 1) + " of " + plural(count, "problem") + ": " + p.text, wrap);
}

VerifyMarks verify_marks(const verify::ArraysVerdict& verdict, int selected, std::size_t wrap) {
  VerifyMarks m;
  m.ok = verdict.problem_count == 0;
  m.selected = selected >= 0 && static_cast<std::size_t>(selected) < verdict.problems.size() ? selected : -1;
  m.caption = problem_caption(verdict, m.selected, wrap);
  // The drawn lists are verdict.lists, in order: a problem's (family, list) is found among them.
  std::map<std::pair<int, int>, int> drawn;
  for (std::size_t i = 0; i < verdict.lists.size(); ++i)
    drawn.emplace(std::make_pair(verdict.lists[i].family, verdict.lists[i].list), static_cast<int>(i));
  m.problems.reserve(verdict.problems.size());
  for (const verify::Problem& p : verdict.problems) {
    ProblemMark mark;
    mark.elements = p.elements;
    mark.link = p.link;
    if (const auto it = drawn.find({p.family, p.list}); it != drawn.end()) mark.list = it->second;
    m.problems.push_back(std::move(mark));
  }
  return m;
}

namespace detail {

namespace {
// Rings stay at least this large on screen (px), so a problem is found zoomed out.
constexpr float kMinRingPx = 9.0f;
}  // namespace

void draw_verify(const OverlayScene& s, const ViewFrame& v, const std::vector<bool>& marked_links, DrawSink& sink) {
  const VerifyMarks& m = *s.verify;
  const Elements& e = *s.elements;
  const double ppm = v.ppm;
  const auto n = static_cast<ElementId>(e.size());
  // A 3D run's layer view: the marks of the elements drawn (the layer's and, ghosted, the one below's).
  const auto valid = [n, &s](ElementId k) { return k >= 0 && k < n && (s.layer == nullptr || s.layer->visible(k)); };
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


}  // namespace detail

}  // namespace nbscope::render
