// The Arrays panel: every array of the recorded detection laid out as the book's figures draw them
// — a next array as a row of integers over its indices (Figs 3.13, 3.20), a heads array of cells as
// a matrix C[ix][iy] (eq. 3.31), NBS's B[2][nx] as the current row over the row below — with -1 for
// an empty list or the end of one, "·" for an entry not written yet (its contents mean nothing),
// the entry just written highlighted with its old value, large arrays windowed around the active
// entries (what the current operation reads or writes, the list of the cell and row it works on,
// the element k, and to the rows the panel's room holds), and an element filter that answers "where
// is k?". It sits in the bottom dock; a cell matrix (screen's C) keeps the other arrays at its right.
//
// Index: cell colours | column fitting | Marks and window focus | row and matrix arrays | element
// section | ArraysPanel.
#include <imgui.h>

#include <algorithm>
#include <functional>
#include <string>

#include "io/plural.hpp"
#include "ui/stepper_panels.hpp"

namespace nbscope::ui {

namespace {

constexpr std::int64_t kMaxColumns = 16;
constexpr std::int64_t kMaxRows = 10;
const ImVec4 kEmpty(0.50f, 0.52f, 0.56f, 1.0f);  // -1
const ImVec4 kValue(0.92f, 0.92f, 0.95f, 1.0f);
const ImVec4 kIndex(0.55f, 0.60f, 0.70f, 1.0f);
const ImU32 kWrittenBg = IM_COL32(230, 170, 40, 200);
const ImU32 kEarlierWrittenBg = IM_COL32(230, 170, 40, 90);
const ImU32 kActiveBg = IM_COL32(40, 170, 150, 170);
const ImU32 kFocusBg = IM_COL32(60, 110, 190, 170);

// The width kept for an array's value column: values are at most as wide as the largest index (in
// book numbering, `length`) or, in an array of element ids, the largest id (`elements`), and -1.
float column_width(std::int64_t length, std::int64_t elements) {
  const int digits = static_cast<int>(std::to_string(std::max<std::int64_t>({length, elements, 10})).size());
  return ImGui::CalcTextSize("0").x * static_cast<float>(digits) + 2 * ImGui::GetStyle().CellPadding.x + 2;
}
// The width kept for an array's label column: a row array's name, "index" or "of N" (`length`); a
// matrix's, the longest its rows are named by.
float label_width(const TracedArray& a, std::int64_t length) {
  const float text = a.shape.size() >= 2 ? ImGui::CalcTextSize("[1] row iy-1 ...").x
                                         : std::max({ImGui::CalcTextSize(a.name.c_str()).x, ImGui::CalcTextSize("index").x,
                                                     ImGui::CalcTextSize(("of " + std::to_string(length)).c_str()).x});
  return text + 2 * ImGui::GetStyle().CellPadding.x + 2;
}

// How many value columns of an array of `length` entries fit the panel beside its label (`label`
// pixels): at least 4, at most kMaxColumns.
std::int64_t fit_columns(std::int64_t length, std::int64_t elements, float label) {
  const float room = ImGui::GetContentRegionAvail().x - label;
  return std::clamp<std::int64_t>(static_cast<std::int64_t>(room / column_width(length, elements)), 4, kMaxColumns);
}

// What to highlight this frame.
struct Marks {
  const ArrayWrite* writes = nullptr;  // the last write event's writes
  int write_count = 0;
  bool write_is_current = true;  // false: the last write happened before the current event
  std::pair<int, std::int64_t> active[2] = {{-1, -1}, {-1, -1}};  // entries the current test reads
  std::int32_t focus = -1;  // the filtered element
  std::int64_t n = 0;       // element count (arrays of this length are indexed by element)
  // Where the current operation works: its lists (heads array, flat index) of the cell, the row
  // and the layer, and its element k.
  std::vector<std::pair<int, std::int64_t>> lists;
  std::int32_t k = -1;
};

bool written(const Marks& m, int array, std::int64_t index) {
  for (int w = 0; w < m.write_count; ++w)
    if (m.writes[w].array == array && m.writes[w].index == index) return true;
  return false;
}

// One entry as a table cell: the value, coloured; background for the written / filtered entry.
void value_cell(const StepperSession& s, const Marks& m, int array, std::int64_t flat, std::int32_t value,
                bool element_indexed_at_focus) {
  const bool is_written = written(m, array, flat);
  const bool is_active = (m.active[0].first == array && m.active[0].second == flat) ||
                         (m.active[1].first == array && m.active[1].second == flat);
  const bool is_focus = m.focus >= 0 && (element_indexed_at_focus || (s.holds_elements(array) && value == m.focus));
  if (is_active) ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, kActiveBg);
  else if (is_written) ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, m.write_is_current ? kWrittenBg : kEarlierWrittenBg);
  else if (is_focus) ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, kFocusBg);
  if (!s.is_set(array, flat)) {
    ImGui::TextColored(kEmpty, "\xC2\xB7");  // not written yet in this detection: no meaning
    return;
  }
  const std::int64_t v = shown_value(s, array, value);
  ImGui::TextColored(value == -1 && !is_written ? kEmpty : kValue, "%lld", static_cast<long long>(v));
}

// Where an array's window should be centred: the entry the current operation reads or writes, the
// list of the cell, row or layer it works on, the entry of its element k (an array indexed by
// element), the filtered element; else the start.
std::int64_t focus_index(const StepperSession& s, const Marks& m, int array, const TracedArray& a) {
  for (const auto& [act_array, act_index] : m.active)
    if (act_array == array) return act_index;
  for (int w = 0; w < m.write_count; ++w)
    if (m.writes[w].array == array) return m.writes[w].index;
  for (const auto& [heads, index] : m.lists)
    if (heads == array) return index;
  const bool by_element = a.shape.size() == 1 && a.shape[0] == m.n && s.stepper().next_array_of(array) < 0;
  if (by_element && m.k >= 0) return m.k;
  if (by_element && m.focus >= 0) return m.focus;
  return 0;
}

// A 1D array: values over indices, as the book prints E (Fig. 3.20).
void draw_row_array(const StepperSession& s, const Marks& m, int array) {
  const TracedArray& a = s.stepper().trace().arrays()[array];
  const std::vector<std::int32_t>& values = s.stepper().state()[array];
  const auto length = static_cast<std::int64_t>(values.size());
  const auto [begin, end] =
      window_range(length, focus_index(s, m, array, a), fit_columns(length, s.holds_elements(array) ? m.n : 0, label_width(a, length)));
  const bool by_element = length == m.n && s.stepper().next_array_of(array) < 0;
  const int columns = static_cast<int>(end - begin) + 1;
  if (columns > 63 || !ImGui::BeginTable(a.name.c_str(), columns, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerV))
    return;
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextUnformatted(a.name.c_str());
  for (std::int64_t i = begin; i < end; ++i) {
    ImGui::TableSetColumnIndex(static_cast<int>(i - begin) + 1);
    value_cell(s, m, array, i, values[static_cast<std::size_t>(i)], by_element && i == m.focus);
  }
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  if (end - begin < length) {
    // A window: say which part of the array it is.
    ImGui::TextColored(kIndex, "of %lld", static_cast<long long>(length));
  } else {
    ImGui::TextColored(kIndex, "index");
  }
  for (std::int64_t i = begin; i < end; ++i) {
    ImGui::TableSetColumnIndex(static_cast<int>(i - begin) + 1);
    ImGui::TextColored(kIndex, "%lld", static_cast<long long>(shown(i, s.book_numbering)));
  }
  ImGui::EndTable();
}

// What each row of NBS's selector arrays holds (B, and A in 3D), or null for any other array.
const char* const* nbs_row_names(const StepperSession& s, const TracedArray& a) {
  static constexpr const char* kB2d[2] = {"row iy", "row iy-1"};
  static constexpr const char* kB3d[2] = {"layer iz", "layer iz-1"};
  static constexpr const char* kA3d[5] = {"row (iy,iz)", "(iy-1,iz)", "(iy-1,iz-1)", "(iy,iz-1)", "(iy+1,iz-1)"};
  if (s.algorithm() != "nbs" || a.shape.size() != 2) return nullptr;
  const bool three = s.elements().dim == 3;
  if (a.name == "B" && a.shape[0] == 2) return three ? kB3d : kB2d;
  if (three && a.name == "A" && a.shape[0] == 5) return kA3d;
  return nullptr;
}

// How many of a matrix's `rows` fit between the cursor and `bottom` (screen y) under its header
// row: all of them, else those that leave a line for "... N more rows"; at least 3.
std::int64_t rows_that_fit(std::int64_t rows, float bottom) {
  const float row = ImGui::GetTextLineHeight() + 2 * ImGui::GetStyle().CellPadding.y;
  const float room = bottom - ImGui::GetCursorScreenPos().y;
  if (static_cast<float>(rows + 1) * row <= room) return rows;
  return std::max<std::int64_t>(static_cast<std::int64_t>((room - ImGui::GetTextLineHeightWithSpacing()) / row) - 1, 3);
}

// A 2D array (or the slice of a 3D one at the focus's last index) as a matrix: rows are the first
// index, columns the second, except that a cell matrix (screen's C[ix][iy], eq. 3.31) is drawn as the
// scene shows its cells, ix across and iy upwards, and an array whose second index only picks one of a
// few parallel arrays (the tree's child[m][0/1]) one row per choice, so it reads like a next array.
// Its rows are windowed to those that fit above `bottom` (screen y), at most kMaxRows.
void draw_matrix_array(const StepperSession& s, const Marks& m, int array, float bottom) {
  const TracedArray& a = s.stepper().trace().arrays()[array];
  const std::vector<std::int32_t>& values = s.stepper().state()[array];
  const std::int64_t depth = a.shape.size() == 3 ? a.shape[2] : 1;
  const std::int64_t focus = focus_index(s, m, array, a);
  const std::int64_t fz = focus % depth;
  const std::int64_t f[2] = {focus / depth / a.shape[1], (focus / depth) % a.shape[1]};
  const bool cells = is_cell_matrix(a, s.grid());
  const int row_dim = cells || index_is_selector(a, 1) ? 1 : 0, col_dim = 1 - row_dim;
  const auto [r0, r1] = window_range(a.shape[row_dim], f[row_dim], std::min(kMaxRows, rows_that_fit(a.shape[row_dim], bottom)));
  const auto [c0, c1] =
      window_range(a.shape[col_dim], f[col_dim],
                   fit_columns(a.shape[col_dim], s.holds_elements(array) ? m.n : 0, label_width(a, a.shape[col_dim])));
  const bool book = s.book_numbering;
  if (depth > 1) ImGui::TextColored(kIndex, "slice [..][..][%lld]", static_cast<long long>(shown(fz, book)));
  const int columns = static_cast<int>(c1 - c0) + 1;
  if (!ImGui::BeginTable(a.name.c_str(), columns, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerV))
    return;
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextColored(kIndex, "%s%s%s", a.name.c_str(), cells ? " iy\\ix" : row_dim == 1 ? "[..][r]" : "", c0 > 0 ? " ..." : "");
  for (std::int64_t c = c0; c < c1; ++c) {
    ImGui::TableSetColumnIndex(static_cast<int>(c - c0) + 1);
    ImGui::TextColored(kIndex, "%lld", static_cast<long long>(shown(c, book && !index_is_selector(a, col_dim))));
  }
  // NBS's x heads: the current row's lists over the row below's (book p.102); in 3D the y heads of
  // the layer and the layer below, and the x heads of the five rows the mask reaches (p.123).
  const char* const* row_names = nbs_row_names(s, a);
  // A cell matrix's rows run downwards from the highest iy shown, as the scene's rows do.
  const std::int64_t rows_before = cells ? a.shape[row_dim] - r1 : r0, rows_after = cells ? r0 : a.shape[row_dim] - r1;
  for (std::int64_t i = 0; i < r1 - r0; ++i) {
    const std::int64_t r = cells ? r1 - 1 - i : r0 + i;
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    if (row_names != nullptr) {
      ImGui::TextColored(kIndex, "[%lld] %s", static_cast<long long>(r), row_names[r]);
    } else {
      ImGui::TextColored(kIndex, "[%lld]%s", static_cast<long long>(shown(r, book && !index_is_selector(a, row_dim))),
                         i == 0 && rows_before > 0 ? " ..." : "");
    }
    for (std::int64_t c = c0; c < c1; ++c) {
      ImGui::TableSetColumnIndex(static_cast<int>(c - c0) + 1);
      std::int64_t at[2];
      at[row_dim] = r;
      at[col_dim] = c;
      const std::int64_t flat = (at[0] * a.shape[1] + at[1]) * depth + fz;
      value_cell(s, m, array, flat, values[static_cast<std::size_t>(flat)], false);
    }
  }
  ImGui::EndTable();
  if (rows_after > 0) ImGui::TextColored(kIndex, "... %s more", plural(static_cast<long long>(rows_after), "row").c_str());
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

// During a mask visit or a pair test: the head of the visited cell's list and, for a test, the
// next entry of the element tested (the link the walk follows), so the walk can be read in the arrays.
void mark_walk(const StepperSession& s, Marks& m) {
  const TraceEvent* e = s.stepper().current();
  if (e == nullptr || (e->op != TraceOp::VisitCell && e->op != TraceOp::TestPair)) return;
  const LoopVars v = s.stepper().loop_vars();
  const std::int32_t cell[3] = {v.ix, v.iy, v.iz};
  const auto list = s.list_of_cell(cell);
  if (!list) return;
  m.active[0] = {list->heads, list->list};
  const int next = s.stepper().next_array_of(list->heads);
  if (e->op == TraceOp::TestPair && next >= 0) m.active[1] = {next, e->other};
}

// What to highlight: the last write and its line above the arrays (returned, "" when nothing was
// written yet), the walk, the lists of the cell, row and layer the current operation works on, its element.
std::string mark_arrays(const StepperSession& s, Marks& marks) {
  const Stepper& st = s.stepper();
  const auto& arrays = st.trace().arrays();
  marks.focus = s.focus_element;
  marks.n = s.elements().size();
  std::string text;
  if (const auto w = st.last_write_event()) {
    const TraceEvent& e = st.events()[*w];
    marks.writes = e.writes;
    marks.write_count = std::min<int>(e.write_count, 2);
    marks.write_is_current = *w + 1 == st.position();
    text = marks.write_is_current ? "just written: " : "last written (operation " + std::to_string(*w + 1) + "): ";
    for (int i = 0; i < marks.write_count; ++i) {
      const ArrayWrite& a = e.writes[i];
      text += (i > 0 ? ",  " : "") + entry_name(arrays[a.array], a.index, s.book_numbering) + " = " +
              std::to_string(shown_value(s, a.array, a.new_value)) + " (was " +
              (s.is_set_after(a.array, a.index, *w) ? std::to_string(shown_value(s, a.array, a.old_value))
                                                     : std::string("unset")) +
              ")";
    }
  }
  mark_walk(s, marks);
  const LoopVars v = st.loop_vars();
  marks.k = v.k;
  const std::int32_t keys[3][3] = {{v.ix, v.iy, v.iz}, {-1, v.iy, v.iz}, {-1, -1, v.iz}};
  for (const auto& key : keys) {
    if (key[0] < 0 && key[1] < 0 && key[2] < 0) continue;
    if (const auto l = s.list_of_cell(key)) marks.lists.emplace_back(l->heads, l->list);
  }
  return text;
}

// The width array `array` asks for beside another, as fit_columns counts columns: all of them, or
// for an array windowed anyway (longer than kMaxColumns) the window's first eight.
float array_width(const StepperSession& s, const Marks& m, int array) {
  const TracedArray& a = s.stepper().trace().arrays()[static_cast<std::size_t>(array)];
  const std::size_t col_dim = a.shape.size() < 2 ? 0 : is_cell_matrix(a, s.grid()) || index_is_selector(a, 1) ? 0 : 1;
  const std::int64_t length = a.shape.size() < 2 ? static_cast<std::int64_t>(s.stepper().state()[static_cast<std::size_t>(array)].size())
                                                 : a.shape[col_dim];
  const std::int64_t columns = length <= kMaxColumns ? length : 8;
  return label_width(a, length) + static_cast<float>(columns) * column_width(length, s.holds_elements(array) ? m.n : 0);
}

// The controls, the line saying what was written last, then every array. A cell matrix (screen's
// C) first keeps the rest at its right when the panel is that wide, so C and E are in view together;
// the others flow, each beside the one before when all its columns fit there; matrix rows are
// windowed to what fits above `bottom` (screen y: the end of the panel's room).
void draw_arrays(const StepperSession& s, const std::function<void()>& controls, float bottom) {
  const auto& arrays = s.stepper().trace().arrays();
  if (arrays.empty()) {
    controls();
    ImGui::TextWrapped("%s keeps no arrays: it tests every pair i < j. Pick an element to see its tests.",
                       s.algorithm().c_str());
    return;
  }
  Marks marks;
  const std::string written_text = mark_arrays(s, marks);
  const auto written_line = [&] {
    if (written_text.empty()) return;
    ImGui::PushStyleColor(ImGuiCol_Text, marks.write_is_current ? ImVec4(0.95f, 0.75f, 0.3f, 1.0f) : ImVec4(0.7f, 0.6f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", written_text.c_str());
    ImGui::PopStyleColor();
    if (s.elements().dim == 3) ImGui::TextColored(kIndex, "%s", array_shapes_text(s).c_str());
  };
  constexpr float kBesideMinWidth = 360.0f;  // the controls, the written line and E's nine entries
  ImGui::PushStyleVar(ImGuiStyleVar_CellPadding, ImVec2(ImGui::GetStyle().CellPadding.x, 1.0f));  // more rows in view
  std::size_t first = 0;
  if (is_cell_matrix(arrays.front(), s.grid()) && ImGui::GetContentRegionAvail().x >= array_width(s, marks, 0) + kBesideMinWidth) {
    ImGui::BeginGroup();
    ImGui::PushID(0);
    draw_matrix_array(s, marks, 0, bottom);
    ImGui::PopID();
    ImGui::EndGroup();
    ImGui::SameLine(0, 2 * ImGui::GetStyle().ItemSpacing.x);
    first = 1;
  }
  ImGui::BeginGroup();
  controls();
  written_line();
  const float gap = 2 * ImGui::GetStyle().ItemSpacing.x;
  const float right_edge = ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;  // the window's or a table cell's
  for (std::size_t a = first; a < arrays.size(); ++a) {
    if (a > first && ImGui::GetItemRectMax().x + gap + array_width(s, marks, static_cast<int>(a)) <= right_edge) ImGui::SameLine(0, gap);
    ImGui::BeginGroup();
    ImGui::PushID(static_cast<int>(a));
    if (arrays[a].shape.size() >= 2) {
      draw_matrix_array(s, marks, static_cast<int>(a), bottom);
    } else {
      draw_row_array(s, marks, static_cast<int>(a));
    }
    ImGui::PopID();
    ImGui::EndGroup();
  }
  ImGui::EndGroup();
  ImGui::PopStyleVar();
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
