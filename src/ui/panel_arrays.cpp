// The Arrays panel: every array of the recorded detection laid out as the book's figures draw them
// (the tables: ui/arrays_tables.hpp), the line saying what was written last, and an element filter
// that answers "where is k?". It sits in the bottom dock. A cell matrix (screen's C) keeps the other
// arrays at its right; the others flow, each beside the one before where it fits, or, when that
// would run past the panel's room, stand as the book's list families side by side: each heads array
// over the next array its lists link through (NBS 3D: C over Z, B over Y, A over X), the long next
// arrays windowed to their family's width around the current operation's entries.
//
// In a row's phase every array is the phase's (NBS tests against the x-lists A, X of the row, walked
// from the row's y-list in B, Y, of the layer's z-list in C, Z: the lists the tables mark), so the
// layout keeps them all whole in view rather than the current one alone.
//
// Index: layouts (flow, families) | element section | ArraysPanel.
#include <imgui.h>

#include <algorithm>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

#include "ui/arrays_tables.hpp"
#include "ui/stepper_panels.hpp"

namespace nbscope::ui {

namespace {

using arrays::Marks;

const ImVec4 kIndex(0.55f, 0.60f, 0.70f, 1.0f);

float array_gap() { return 2 * ImGui::GetStyle().ItemSpacing.x; }

// ---- layouts ----

// The height arrays [first, end) take flowed into `width` pixels as draw_flow lays them: each beside
// the one before when its array_width fits there, drawn as wide as the rest of the line lets it (a
// long array takes up to 16 columns). The widths are estimates the drawn tables never exceed.
float flow_height(const StepperSession& s, const Marks& m, std::size_t first, float width) {
  const std::size_t end = s.stepper().trace().arrays().size();
  float x = 0, line = 0, total = 0;
  for (std::size_t a = first; a < end; ++a) {
    const int id = static_cast<int>(a);
    const float h = arrays::array_height(s, id);
    if (a > first && x + array_gap() + arrays::array_width(s, m, id) <= width) {
      x += array_gap();
      x += arrays::drawn_array_width(s, m, id, width - x);
      line = std::max(line, h);
      continue;
    }
    if (a > first) total += line + ImGui::GetStyle().ItemSpacing.y;
    x = arrays::drawn_array_width(s, m, id, width);
    line = h;
  }
  return total + line;
}

// Arrays [first, end) one after another, each beside the one before when all its columns fit there;
// matrix rows are windowed to what fits above `bottom`.
void draw_flow(const StepperSession& s, const Marks& m, std::size_t first, float bottom) {
  const std::size_t end = s.stepper().trace().arrays().size();
  const float right_edge = ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;  // the window's or a table cell's
  for (std::size_t a = first; a < end; ++a) {
    const int id = static_cast<int>(a);
    if (a > first && ImGui::GetItemRectMax().x + array_gap() + arrays::array_width(s, m, id) <= right_edge)
      ImGui::SameLine(0, array_gap());
    ImGui::BeginGroup();
    ImGui::PushID(id);
    arrays::draw_array(s, m, id, bottom, right_edge - ImGui::GetCursorScreenPos().x);
    ImGui::PopID();
    ImGui::EndGroup();
  }
}

// The book's list families among arrays [first, end): a heads array with the next array its lists
// link through when that follows it (y_heads and Y, B and X; C and Z, ...), else an array alone.
std::vector<std::vector<int>> list_families(const StepperSession& s, std::size_t first) {
  const std::size_t end = s.stepper().trace().arrays().size();
  std::vector<std::vector<int>> families;
  for (std::size_t a = first; a < end; ++a) {
    const int id = static_cast<int>(a);
    if (a + 1 < end && s.stepper().next_array_of(id) == id + 1) {
      families.push_back({id, id + 1});
      ++a;
    } else {
      families.push_back({id});
    }
  }
  return families;
}

// The families side by side in `width` pixels: each family's width (its first array whole where the
// room allows, the rest windowed to it, the room left shared out), empty when they do not fit even
// with their narrowest windows.
std::vector<float> family_widths(const StepperSession& s, const Marks& m, const std::vector<std::vector<int>>& families,
                                 float width) {
  std::vector<float> want, least;
  for (const auto& family : families) {
    float narrowest = 0;
    for (const int a : family) narrowest = std::max(narrowest, arrays::narrowest_array_width(s, m, a));
    least.push_back(narrowest);
    want.push_back(std::max(narrowest, arrays::array_width(s, m, family.front())));
  }
  const float room = width - array_gap() * static_cast<float>(families.size() - 1);
  const float wanted = std::accumulate(want.begin(), want.end(), 0.0f), needed = std::accumulate(least.begin(), least.end(), 0.0f);
  if (needed > room) return {};
  std::vector<float> widths(families.size());
  for (std::size_t f = 0; f < families.size(); ++f) {
    // All they want and the room left shared alike; else each as far above its least as the room allows.
    widths[f] = wanted <= room ? want[f] + (room - wanted) / static_cast<float>(families.size())
                               : least[f] + (want[f] - least[f]) * (room - needed) / std::max(wanted - needed, 1.0f);
  }
  return widths;
}

// The height of a family: its tables one over another.
float family_height(const StepperSession& s, const std::vector<int>& family) {
  float h = 0;
  for (const int a : family) h += arrays::array_height(s, a);
  return h + ImGui::GetStyle().ItemSpacing.y * static_cast<float>(family.size() - 1);
}

// The families side by side, each a column `widths[f]` wide, its tables one over another; a
// matrix's rows are windowed to leave room above `bottom` for the tables under it.
void draw_families(const StepperSession& s, const Marks& m, const std::vector<std::vector<int>>& families,
                   const std::vector<float>& widths, float bottom) {
  for (std::size_t f = 0; f < families.size(); ++f) {
    if (f > 0) ImGui::SameLine(0, array_gap());
    ImGui::BeginGroup();
    float below = family_height(s, families[f]);
    for (const int a : families[f]) {
      below -= arrays::array_height(s, a);
      ImGui::PushID(a);
      arrays::draw_array(s, m, a, bottom - below, widths[f]);
      ImGui::PopID();
      below -= ImGui::GetStyle().ItemSpacing.y;
    }
    ImGui::EndGroup();
  }
}

// Arrays [first, end) under the cursor, above `bottom`: flowed when that fits, else as list families
// side by side when they fit the width and take less height.
void lay_out_arrays(const StepperSession& s, const Marks& m, std::size_t first, float bottom) {
  const float width = ImGui::GetContentRegionAvail().x, room = bottom - ImGui::GetCursorScreenPos().y;
  const float flowed = flow_height(s, m, first, width);
  if (flowed > room) {
    const auto families = list_families(s, first);
    const bool paired = std::any_of(families.begin(), families.end(), [](const auto& f) { return f.size() > 1; });
    const std::vector<float> widths = paired && families.size() > 1 ? family_widths(s, m, families, width) : std::vector<float>{};
    float tallest = 0;
    for (const auto& family : families) tallest = std::max(tallest, family_height(s, family));
    if (!widths.empty() && tallest < flowed) {
      draw_families(s, m, families, widths, bottom);
      return;
    }
  }
  draw_flow(s, m, first, bottom);
}

// The controls, the line saying what was written last (and in 3D the arrays' shapes, beside the
// controls where they fit), then every array. A cell matrix (screen's C) first keeps the rest at its
// right when the panel is that wide, so C and E are in view together; matrix rows are windowed to
// what fits above `bottom` (screen y: the end of the panel's room).
void draw_arrays(const StepperSession& s, const std::function<void()>& controls, float bottom) {
  const auto& traced = s.stepper().trace().arrays();
  if (traced.empty()) {
    controls();
    ImGui::TextWrapped("%s keeps no arrays: it tests every pair i < j. Pick an element to see its tests.",
                       s.algorithm().c_str());
    return;
  }
  Marks marks;
  const std::string written_text = arrays::mark_arrays(s, marks);
  constexpr float kBesideMinWidth = 360.0f;  // the controls, the written line and E's nine entries
  ImGui::PushStyleVar(ImGuiStyleVar_CellPadding, ImVec2(ImGui::GetStyle().CellPadding.x, 1.0f));  // more rows in view
  std::size_t first = 0;
  if (is_cell_matrix(traced.front(), s.grid()) && ImGui::GetContentRegionAvail().x >= arrays::array_width(s, marks, 0) + kBesideMinWidth) {
    ImGui::BeginGroup();
    ImGui::PushID(0);
    arrays::draw_array(s, marks, 0, bottom, ImGui::GetContentRegionAvail().x);
    ImGui::PopID();
    ImGui::EndGroup();
    ImGui::SameLine(0, array_gap());
    first = 1;
  }
  ImGui::BeginGroup();
  const float right_edge = ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;  // the window's or a table cell's
  controls();
  if (s.elements().dim == 3) {
    const std::string shapes = array_shapes_text(s);
    if (ImGui::GetItemRectMax().x + array_gap() + ImGui::CalcTextSize(shapes.c_str()).x <= right_edge) ImGui::SameLine(0, array_gap());
    ImGui::TextColored(kIndex, "%s", shapes.c_str());
  }
  if (!written_text.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, marks.write_is_current ? ImVec4(0.95f, 0.75f, 0.3f, 1.0f) : ImVec4(0.7f, 0.6f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", written_text.c_str());
    ImGui::PopStyleColor();
  }
  lay_out_arrays(s, marks, first, bottom);
  ImGui::EndGroup();
  ImGui::PopStyleVar();
}

// Where the filtered element is: its cell, the lists holding it now, the next entries after it and
// every pair it is tested in (click one to go there).
void draw_element(StepperSession& s, std::int32_t k) {
  const bool book = s.book_numbering;
  const Elements& e = s.elements();
  Stepper& st = s.stepper();
  const auto& arrays = st.trace().arrays();
  ImGui::Text("element %lld", static_cast<long long>(shown(k, book)));
  std::int32_t cell[3] = {-1, -1, -1};
  if (const Grid* g = s.grid()) {
    cell[0] = g->cell(e.x[k], 0);
    cell[1] = g->cell(e.y[k], 1);
    if (e.dim == 3) cell[2] = g->cell(e.z[k], 2);
    ImGui::SameLine();
    ImGui::Text(e.dim == 3 ? "in cell (%lld, %lld, %lld)" : "in cell (%lld, %lld)", static_cast<long long>(shown(cell[0], book)),
                static_cast<long long>(shown(cell[1], book)), static_cast<long long>(shown(cell[2], book)));
  }
  const ElementEntries entries = element_entries(s, k);
  if (!entries.next.empty()) ImGui::TextWrapped("next: %s", entries.next.c_str());
  if (!entries.own.empty()) ImGui::TextWrapped("its entries: %s", entries.own.c_str());
  if (!entries.position.empty()) ImGui::TextWrapped("position: %s", entries.position.c_str());
  // The lists of its row, layer and cell as they stand now.
  const std::int32_t keys[4][3] = {{cell[0], cell[1], cell[2]}, {-1, cell[1], cell[2]}, {-1, -1, cell[2]}, {-1, cell[1], -1}};
  std::vector<std::pair<int, std::int64_t>> shown_lists;
  for (const auto& key : keys) {
    if (key[0] == -1 && key[1] == -1 && key[2] == -1) continue;
    const auto list = s.list_of_cell(key);
    if (!list) continue;
    const std::pair<int, std::int64_t> id{list->heads, list->list};
    if (std::find(shown_lists.begin(), shown_lists.end(), id) != shown_lists.end()) continue;
    shown_lists.push_back(id);
    const std::vector<std::int32_t> members = st.list_members(list->heads, list->list);
    if (std::find(members.begin(), members.end(), k) == members.end()) continue;
    std::string chain = std::string(list->kind) + " " + entry_name(arrays[list->heads], list->list, book) + ": ";
    for (std::size_t i = 0; i < members.size() && i < 12; ++i) {
      const std::string id = std::to_string(shown(members[i], book));
      chain += (members[i] == k ? "[" + id + "]" : id) + " -> ";
    }
    chain += members.size() > 12 ? "..." : "-1";
    ImGui::TextWrapped("%s", chain.c_str());
  }
  const auto& tests = s.tests_of(k);
  ImGui::Text("tested against (%zu):", tests.size());
  for (std::size_t i = 0; i < tests.size() && i < 24; ++i) {
    const auto& t = tests[i];
    const bool done = t.event < st.position();
    const std::string label = std::to_string(shown(t.other, book)) + (t.contact ? " contact" : " no") + "##t" + std::to_string(i);
    ImGui::SameLine();
    if (ImGui::GetContentRegionAvail().x < 90) ImGui::NewLine();
    ImGui::PushStyleColor(ImGuiCol_Button, t.contact ? ImVec4(0.2f, 0.55f, 0.3f, done ? 1.0f : 0.4f)
                                                     : ImVec4(0.35f, 0.35f, 0.4f, done ? 1.0f : 0.4f));
    if (ImGui::SmallButton(label.c_str())) {
      st.pause();
      st.seek(t.event + 1);
    }
    ImGui::PopStyleColor();
  }
  if (tests.size() > 24) ImGui::TextDisabled("... %zu more", tests.size() - 24);
}

class ArraysPanel final : public Panel {
 public:
  explicit ArraysPanel(std::shared_ptr<StepperSession> session) : session_(std::move(session)) {}
  [[nodiscard]] const char* title() const override { return kArraysTitle; }
  [[nodiscard]] PanelPlace place() const override { return PanelPlace::Bottom; }
  [[nodiscard]] bool open_by_default() const override { return false; }
  [[nodiscard]] float width() const override { return 560.0f; }
  [[nodiscard]] bool part_of_stepping_layout() const override { return true; }

  void draw(UiContext& c) override {
    StepperSession& s = *session_;
    s.book_numbering = c.state.book_numbering;
    s.update(c.sim, ImGui::GetIO().DeltaTime, ImGui::GetFrameCount());
    if (!s.has_capture()) {
      ImGui::TextDisabled("%s", idle_message(s).c_str());
      return;
    }
    const auto controls = [&] {
      if (ImGui::Checkbox("book numbering (from 1)", &c.state.book_numbering)) s.book_numbering = c.state.book_numbering;
      ImGui::SameLine();
      int shown_focus = static_cast<int>(shown(s.focus_element, s.book_numbering));
      ImGui::SetNextItemWidth(90);
      if (ImGui::InputInt("element", &shown_focus)) {
        const int k = s.book_numbering ? shown_focus - 1 : shown_focus;
        s.focus_element = std::clamp<std::int32_t>(k, -1, static_cast<std::int32_t>(s.elements().size()) - 1);
      }
    };
    // The end of the room the host gives the window's contents: matrices window their rows to it.
    const ImGuiStyle& style = ImGui::GetStyle();
    const float bottom = ImGui::GetCursorScreenPos().y + c.room.height - ImGui::GetFrameHeight() - 2 * style.WindowPadding.y;
    const bool element = s.focus_element >= 0 && s.focus_element < s.elements().size();
    // A wide dock (a large display) puts the element beside the arrays, so the scene keeps its height.
    if (element && ImGui::GetContentRegionAvail().x >= 880.0f &&
        ImGui::BeginTable("##layout", 2, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_BordersInnerV)) {
      ImGui::TableSetupColumn("arrays", ImGuiTableColumnFlags_WidthStretch, 0.62f);
      ImGui::TableSetupColumn("element", ImGuiTableColumnFlags_WidthStretch, 0.38f);
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      draw_arrays(s, controls, bottom);
      ImGui::TableSetColumnIndex(1);
      draw_element(s, s.focus_element);
      ImGui::EndTable();
      return;
    }
    draw_arrays(s, controls, bottom);
    if (element) {
      ImGui::Separator();
      draw_element(s, s.focus_element);
    }
  }

 private:
  std::shared_ptr<StepperSession> session_;
};

}  // namespace

std::unique_ptr<Panel> make_arrays_panel(std::shared_ptr<StepperSession> session) {
  return std::make_unique<ArraysPanel>(std::move(session));
}

}  // namespace nbscope::ui
