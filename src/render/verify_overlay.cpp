// A verify run's lists and problems turned into what the overlays draw: TracedLists with their
// heads named (the lists overlay draws them as it draws nbscope's own) and one ProblemMark per
// problem (drawn in red by overlay_verify.cpp), with the caption the legend shows.
#include "render/verify_overlay.hpp"

#include <map>

#include "io/plural.hpp"

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

}  // namespace nbscope::render
