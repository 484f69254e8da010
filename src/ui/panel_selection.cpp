// The Selection panel: the clicked element's position, cell, lists (with the next-array entry
// after it, as the book writes them) and contact pairs.
#include <imgui.h>

#include <algorithm>
#include <string>

#include "ui/panels.hpp"

namespace nbscope::ui {

namespace {

// "y-list y_heads[3]: 9 -> [7] -> 2 -> ... -> -1", windowed around the element.
std::string describe_chain(const render::TracedList& l, ElementId k) {
  const auto at = std::find(l.chain.begin(), l.chain.end(), k);
  const auto pos = static_cast<std::size_t>(at - l.chain.begin());
  std::string text = l.heads_name + "[" + std::to_string(l.slot) + "]: ";
  const std::size_t from = pos > 3 ? pos - 3 : 0;
  const std::size_t to = std::min(l.chain.size(), pos + 4);
  if (from > 0) text += "... -> ";
  for (std::size_t i = from; i < to; ++i) {
    const std::string id = std::to_string(l.chain[i]);
    text += i == pos ? "[" + id + "]" : id;
    text += " -> ";
  }
  text += to < l.chain.size() ? "..." : "-1";
  return text;
}

class SelectionPanel final : public Panel {
 public:
  [[nodiscard]] const char* title() const override { return "Selection"; }
  [[nodiscard]] PanelPlace place() const override { return PanelPlace::Right; }
  [[nodiscard]] float width() const override { return 290.0f; }
  [[nodiscard]] bool visible(const UiContext& c) const override {
    return c.sim.elements != nullptr && c.state.selected >= 0 && c.state.selected < c.sim.elements->size();
  }

  void draw(UiContext& c) override {
    const SimView& s = c.sim;
    const ElementId k = c.state.selected;
    const Elements& e = *s.elements;
    ImGui::Text("element %d", k);
    ImGui::Text("centre (%.3f, %.3f)  r = %.3f", e.x[k], e.y[k], e.r[k]);
    if (s.grid != nullptr) ImGui::Text("cell ix = %d, iy = %d", s.grid->cell(e.x[k], 0), s.grid->cell(e.y[k], 1));

    if (s.lists == nullptr) {
      ImGui::TextDisabled("lists: turn on the list overlay (L)");
    } else {
      for (const render::TracedList& l : *s.lists) {
        const auto at = std::find(l.chain.begin(), l.chain.end(), k);
        if (at == l.chain.end()) continue;
        const ElementId next = at + 1 == l.chain.end() ? -1 : *(at + 1);
        if (l.secondary)
          ImGui::TextDisabled("%s (copy for row %d)", l.kind.c_str(), l.phase_index);
        else
          ImGui::Text("%s", l.kind.c_str());
        ImGui::SameLine();
        ImGui::Text("%s[%d] = %d", l.next_name.c_str(), k, next);
        ImGui::TextWrapped("  %s", describe_chain(l, k).c_str());
      }
    }

    if (s.pairs != nullptr) {
      std::string others;
      std::size_t count = 0;
      for (const Pair& p : *s.pairs) {
        if (p.i != k && p.j != k) continue;
        if (++count <= 16) others += (others.empty() ? "" : ", ") + std::to_string(p.i == k ? p.j : p.i);
      }
      if (count > 16) others += ", ...";
      ImGui::TextWrapped("contacts (%zu): %s", count, count == 0 ? "none" : others.c_str());
    }
    ImGui::TextDisabled("Esc clears the selection");
  }
};

}  // namespace

std::unique_ptr<Panel> make_selection_panel() { return std::make_unique<SelectionPanel>(); }

}  // namespace nbscope::ui
