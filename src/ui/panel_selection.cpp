// The Selection panel: the clicked element's position, cell, lists (with the next-array entry
// after it, as the book writes them, and the list from its head named as the Arrays panel names
// it) and contact pairs, all in the chosen numbering; a dump's atoms by their ids (the lists, being
// the arrays' contents, stay rows).
//
// Index: SelectionPanel | describe_chain.
#include <imgui.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "core/traced_lists.hpp"
#include "ui/panels.hpp"
#include "ui/stepper_session.hpp"

namespace nbscope::ui {

namespace {

class SelectionPanel final : public Panel {
 public:
  [[nodiscard]] const char* title() const override { return "Selection"; }
  [[nodiscard]] PanelPlace place() const override { return PanelPlace::Right; }
  [[nodiscard]] float width() const override { return 290.0f; }
  [[nodiscard]] int priority() const override { return 10; }
  [[nodiscard]] bool takes_room_left() const override { return true; }
  [[nodiscard]] bool visible(const UiContext& c) const override {
    return c.sim.elements != nullptr && c.state.selected >= 0 && c.state.selected < c.sim.elements->size();
  }

  void draw(UiContext& c) override {
    const SimView& s = c.sim;
    const ElementId k = c.state.selected;
    const Elements& e = *s.elements;
    const bool book = c.state.book_numbering;
    const auto num = [book](std::int64_t v) { return static_cast<long long>(shown(v, book)); };
    // A dump's atom by its id (the row shifts as atoms are lost or inserted), else the row.
    const std::vector<std::int64_t>* ids = s.ids();
    if (ids != nullptr && static_cast<std::size_t>(k) < ids->size())
      ImGui::Text("atom %lld  (row %lld)", static_cast<long long>(element_number(k, book, ids)), num(k));
    else
      ImGui::Text("element %lld", num(k));
    if (e.dim == 3) {
      ImGui::TextWrapped("centre (%.4g, %.4g, %.4g)  r = %s", e.x[k], e.y[k], e.z[k], s.units.length_text(e.r[k], "%.4g", false).c_str());
      for (const std::string& line : selection_layer_lines(s, k, book)) ImGui::TextUnformatted(line.c_str());
    } else {
      ImGui::Text("centre (%.3f, %.3f)  r = %s", e.x[k], e.y[k], s.units.length_text(e.r[k], "%.3f", false).c_str());
      if (const Grid* grid = s.grid()) ImGui::Text("cell ix = %lld, iy = %lld", num(grid->cell(e.x[k], 0)), num(grid->cell(e.y[k], 1)));
    }

    // The lists overlay's lists, else (3D: the place in the z-, y- and x-lists is what a layer view
    // asks) the finished lists of the frame's trace when one was made (paused, the stepper).
    const std::vector<TracedList>* lists = s.lists != nullptr ? s.lists : e.dim == 3 ? trace_lists(s) : nullptr;
    if (lists == nullptr) {
      ImGui::TextDisabled("lists: turn on the list overlay (L)");
    } else {
      if (s.lists == nullptr) ImGui::TextDisabled("lists of the frame's trace, finished:");
      for (const TracedList& l : *lists) {
        const auto at = std::find(l.chain.begin(), l.chain.end(), k);
        if (at == l.chain.end()) continue;
        const ElementId next = at + 1 == l.chain.end() ? -1 : *(at + 1);
        // The list, k's place in it and k's next entry: wrapped, never cut at the panel's edge.
        std::string head = l.kind + (l.secondary ? " (copy for row " + std::to_string(num(l.phase_index)) + ")" : "") + " " +
                           list_place_text(l, static_cast<std::size_t>(at - l.chain.begin()), book);
        if (!l.next_name.empty()) head += ", " + l.next_name + "[" + std::to_string(num(k)) + "] = " + std::to_string(num(next));
        if (l.secondary) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("%s", head.c_str());
        if (l.secondary) ImGui::PopStyleColor();
        ImGui::TextWrapped("  %s", describe_chain(l, k, book).c_str());
      }
    }

    if (s.pairs() != nullptr) {
      std::string others;
      std::size_t count = 0;
      for (const Pair& p : *s.pairs()) {
        if (p.i != k && p.j != k) continue;
        if (++count <= 16) others += (others.empty() ? "" : ", ") + std::to_string(element_number(p.i == k ? p.j : p.i, book, ids));
      }
      if (count > 16) others += ", ...";
      ImGui::TextWrapped("contacts (%zu%s): %s", count, ids != nullptr ? ", atom ids" : "", count == 0 ? "none" : others.c_str());
    }
    ImGui::TextDisabled("Esc clears the selection");
  }

 private:
  // The finished lists of the frame's trace, rebuilt once per trace; null without a usable one.
  const std::vector<TracedList>* trace_lists(const SimView& s) {
    if (!s.trace || !s.trace->refusal.empty() || s.trace->elements.size() != s.elements->size()) return nullptr;
    if (!lists_serial_ || s.trace->serial != *lists_serial_) {
      trace_lists_ = traced_lists(s.trace->log, static_cast<std::size_t>(s.trace->elements.size()));
      lists_serial_ = s.trace->serial;
    }
    return &trace_lists_;
  }

  std::vector<TracedList> trace_lists_;
  std::optional<std::uint64_t> lists_serial_;  // the trace they were rebuilt from
};

}  // namespace

std::vector<std::string> selection_layer_lines(const SimView& sim, ElementId k, bool book) {
  std::vector<std::string> lines;
  const Elements* e = sim.elements;
  const Grid* grid = sim.grid();
  if (e == nullptr || e->dim != 3 || k < 0 || k >= e->size()) return lines;
  const auto num = [book](std::int64_t v) { return std::to_string(shown(v, book)); };
  std::int32_t iz = -1;
  if (grid != nullptr && grid->dim == 3) {
    const std::int32_t ix = grid->cell(e->x[k], 0), iy = grid->cell(e->y[k], 1);
    iz = grid->cell(e->z[k], 2);
    lines.push_back("cell (ix, iy, iz) = (" + num(ix) + ", " + num(iy) + ", " + num(iz) + ")");
    lines.push_back("row (iy, iz) = (" + num(iy) + ", " + num(iz) + ")");
  }
  if (sim.layer != nullptr && static_cast<std::size_t>(k) < sim.layer->element_layer.size()) {
    iz = sim.layer->element_layer[static_cast<std::size_t>(k)];
    lines.push_back("in layer " + num(iz) + (iz == sim.layer->layer ? " (shown)" : " (layer shown: " + num(sim.layer->layer) + ")"));
  } else if (iz >= 0) {
    lines.push_back("in layer " + num(iz));
  }
  return lines;
}

std::string list_place_text(const TracedList& l, std::size_t position, bool book) {
  const TracedArray heads{l.heads_name, l.heads_shape.empty() ? std::vector<std::int64_t>{l.slot + 1} : l.heads_shape, {}};
  std::string text = entry_name(heads, l.slot, book) + ": position " + std::to_string(position + 1) + " of " + std::to_string(l.chain.size());
  if (l.phase_layer >= 0) text += " (pass of layer " + std::to_string(shown(l.phase_layer, book)) + ")";
  return text;
}

// Windowed around the element: three before it, three after.
std::string describe_chain(const TracedList& l, ElementId k, bool book) {
  const auto at = std::find(l.chain.begin(), l.chain.end(), k);
  const auto pos = static_cast<std::size_t>(at - l.chain.begin());
  const TracedArray heads{l.heads_name, l.heads_shape.empty() ? std::vector<std::int64_t>{l.slot + 1} : l.heads_shape, {}};
  std::string text = entry_name(heads, l.slot, book) + ": ";
  const std::size_t from = pos > 3 ? pos - 3 : 0;
  const std::size_t to = std::min(l.chain.size(), pos + 4);
  if (from > 0) text += "... -> ";
  for (std::size_t i = from; i < to; ++i) {
    const std::string id = std::to_string(shown(l.chain[i], book));
    text += i == pos ? "[" + id + "]" : id;
    text += " -> ";
  }
  text += to < l.chain.size() ? "..." : "-1";
  return text;
}

std::unique_ptr<Panel> make_selection_panel() { return std::make_unique<SelectionPanel>(); }

}  // namespace nbscope::ui
