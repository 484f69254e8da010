// The Arrays panel's tables (ui/arrays_tables.hpp): a row array, a matrix, their highlights and sizes.
//
// Index: cell colours | column fitting and sizes | Marks and window focus | row and matrix arrays.
#include "ui/arrays_tables.hpp"

#include <imgui.h>

#include <algorithm>
#include <string>

#include "io/plural.hpp"

namespace nbscope::ui::arrays {

namespace {

constexpr std::int64_t kMaxColumns = 16;
constexpr std::int64_t kMinColumns = 4;
constexpr std::int64_t kMaxRows = 10;
const ImVec4 kEmpty(0.50f, 0.52f, 0.56f, 1.0f);  // -1
const ImVec4 kValue(0.92f, 0.92f, 0.95f, 1.0f);
const ImVec4 kIndex(0.55f, 0.60f, 0.70f, 1.0f);
const ImU32 kWrittenBg = IM_COL32(230, 170, 40, 200);
const ImU32 kEarlierWrittenBg = IM_COL32(230, 170, 40, 90);
const ImU32 kActiveBg = IM_COL32(40, 170, 150, 170);
const ImU32 kFocusBg = IM_COL32(60, 110, 190, 170);

// ---- column fitting and sizes ----

// A table's column as ImGui sizes it (a fixed-fit table with inner borders): its text, the cell
// padding on both sides and the border after it. The table is the sum of its columns less one
// padding on each side and one border (table_width).
float column_around(float text) { return text + 2 * ImGui::GetStyle().CellPadding.x + 1; }
float table_width(float columns) { return columns - column_around(0); }

// The width kept for an array's value column: its widest text is the largest index or, in an array
// of element ids, the largest id (`elements`) in the chosen numbering, or -1.
float column_width(std::int64_t length, std::int64_t elements, bool book) {
  const std::int64_t widest = std::max<std::int64_t>({length - (book ? 0 : 1), elements - (book ? 0 : 1), 10});
  const int digits = static_cast<int>(std::to_string(widest).size());
  return column_around(ImGui::CalcTextSize("0").x * static_cast<float>(digits));
}
float text_column_width(const std::string& text) { return column_around(ImGui::CalcTextSize(text.c_str()).x); }

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

// How a matrix is laid out: a cell matrix (screen's C[ix][iy], eq. 3.31) as the scene shows its cells,
// ix across and iy upwards; an array whose second index only picks one of a few parallel arrays (the
// tree's child[m][0/1]) one row per choice; any other with rows the first index.
struct MatrixAxes {
  bool cells = false;
  int row_dim = 0, col_dim = 1;
};
MatrixAxes matrix_axes(const StepperSession& s, const TracedArray& a) {
  MatrixAxes x;
  x.cells = is_cell_matrix(a, s.grid());
  x.row_dim = x.cells || index_is_selector(a, 1) ? 1 : 0;
  x.col_dim = 1 - x.row_dim;
  return x;
}

// The header of a matrix's label column ("B", "C iy\ix", "child[..][r]"), " ..." when its columns are windowed.
std::string matrix_header(const TracedArray& a, const MatrixAxes& x, bool windowed) {
  return a.name + (x.cells ? " iy\\ix" : x.row_dim == 1 ? "[..][r]" : "") + (windowed ? " ..." : "");
}

// The width kept for an array's label column: a row array's name, "index" or "of N" (`length`); a
// matrix's header and the longest name of its rows.
float label_width(const StepperSession& s, const TracedArray& a, std::int64_t length) {
  if (a.shape.size() < 2)
    return std::max({text_column_width(a.name), text_column_width("index"), text_column_width("of " + std::to_string(length))});
  const MatrixAxes x = matrix_axes(s, a);
  float w = text_column_width(matrix_header(a, x, length > kMinColumns));
  const std::int64_t rows = a.shape[static_cast<std::size_t>(x.row_dim)];
  if (const char* const* names = nbs_row_names(s, a)) {
    for (std::int64_t r = 0; r < rows; ++r) w = std::max(w, text_column_width("[" + std::to_string(r) + "] " + names[r]));
  } else {
    w = std::max(w, text_column_width("[" + std::to_string(rows) + "] ..."));
  }
  return w;
}

// An array's length across (a row array's entries, a matrix's columns) and its value column's width.
std::pair<std::int64_t, float> columns_of(const StepperSession& s, const Marks& m, int array) {
  const TracedArray& a = s.stepper().trace().arrays()[static_cast<std::size_t>(array)];
  const std::int64_t length = a.shape.size() < 2 ? static_cast<std::int64_t>(s.stepper().state()[static_cast<std::size_t>(array)].size())
                                                 : a.shape[static_cast<std::size_t>(matrix_axes(s, a).col_dim)];
  return {length, column_width(length, s.holds_elements(array) ? m.n : 0, s.book_numbering)};
}

// How many value columns of `array` fit `room_x` pixels with its label: at least 4, at most kMaxColumns.
std::int64_t fit_columns(const StepperSession& s, const Marks& m, int array, float room_x) {
  const TracedArray& a = s.stepper().trace().arrays()[static_cast<std::size_t>(array)];
  const auto [length, column] = columns_of(s, m, array);
  const float room = room_x + column_around(0) - label_width(s, a, length);
  return std::clamp<std::int64_t>(static_cast<std::int64_t>(room / column), kMinColumns, kMaxColumns);
}

float row_height() { return ImGui::GetTextLineHeight() + 2 * ImGui::GetStyle().CellPadding.y; }

// How many of a matrix's `rows` fit between the cursor and `bottom` (screen y) under its header
// row: all of them, else those that leave a line for "... N more rows"; at least 3.
std::int64_t rows_that_fit(std::int64_t rows, float bottom) {
  const float row = row_height();
  const float room = bottom - ImGui::GetCursorScreenPos().y;
  if (static_cast<float>(rows + 1) * row <= room) return rows;
  return std::max<std::int64_t>(static_cast<std::int64_t>((room - ImGui::GetTextLineHeightWithSpacing()) / row) - 1, 3);
}

// ---- Marks and window focus ----

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

// ---- row and matrix arrays ----

// A 1D array: values over indices, as the book prints E (Fig. 3.20).
void draw_row_array(const StepperSession& s, const Marks& m, int array, float room_x) {
  const TracedArray& a = s.stepper().trace().arrays()[array];
  const std::vector<std::int32_t>& values = s.stepper().state()[array];
  const auto length = static_cast<std::int64_t>(values.size());
  const auto [begin, end] = window_range(length, focus_index(s, m, array, a), fit_columns(s, m, array, room_x));
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

// A 2D array (or the slice of a 3D one at the focus's last index) as a matrix laid out by
// matrix_axes. Its rows are windowed to those that fit above `bottom` (screen y), at most kMaxRows,
// its columns to those that fit `room_x` pixels.
void draw_matrix_array(const StepperSession& s, const Marks& m, int array, float bottom, float room_x) {
  const TracedArray& a = s.stepper().trace().arrays()[array];
  const std::vector<std::int32_t>& values = s.stepper().state()[array];
  const std::int64_t depth = a.shape.size() == 3 ? a.shape[2] : 1;
  const std::int64_t focus = focus_index(s, m, array, a);
  const std::int64_t fz = focus % depth;
  const std::int64_t f[2] = {focus / depth / a.shape[1], (focus / depth) % a.shape[1]};
  const auto [cells, row_dim, col_dim] = matrix_axes(s, a);
  const bool book = s.book_numbering;
  if (depth > 1) ImGui::TextColored(kIndex, "slice [..][..][%lld]", static_cast<long long>(shown(fz, book)));
  const auto [r0, r1] = window_range(a.shape[row_dim], f[row_dim], std::min(kMaxRows, rows_that_fit(a.shape[row_dim], bottom)));
  const auto [c0, c1] = window_range(a.shape[col_dim], f[col_dim], fit_columns(s, m, array, room_x));
  const int columns = static_cast<int>(c1 - c0) + 1;
  if (!ImGui::BeginTable(a.name.c_str(), columns, ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerV))
    return;
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextColored(kIndex, "%s", matrix_header(a, MatrixAxes{cells, row_dim, col_dim}, c0 > 0).c_str());
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

}  // namespace

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

float array_width(const StepperSession& s, const Marks& m, int array) {
  const TracedArray& a = s.stepper().trace().arrays()[static_cast<std::size_t>(array)];
  const auto [length, column] = columns_of(s, m, array);
  return table_width(label_width(s, a, length) + static_cast<float>(length <= kMaxColumns ? length : 8) * column);
}

float narrowest_array_width(const StepperSession& s, const Marks& m, int array) {
  const TracedArray& a = s.stepper().trace().arrays()[static_cast<std::size_t>(array)];
  const auto [length, column] = columns_of(s, m, array);
  return table_width(label_width(s, a, length) + static_cast<float>(std::min(length, kMinColumns)) * column);
}

float drawn_array_width(const StepperSession& s, const Marks& m, int array, float room_x) {
  const TracedArray& a = s.stepper().trace().arrays()[static_cast<std::size_t>(array)];
  const auto [length, column] = columns_of(s, m, array);
  return table_width(label_width(s, a, length) + static_cast<float>(std::min(length, fit_columns(s, m, array, room_x))) * column);
}

float array_height(const StepperSession& s, int array) {
  const TracedArray& a = s.stepper().trace().arrays()[static_cast<std::size_t>(array)];
  if (a.shape.size() < 2) return 2 * row_height();
  const std::int64_t rows = a.shape[static_cast<std::size_t>(matrix_axes(s, a).row_dim)];
  const float line = ImGui::GetTextLineHeightWithSpacing();
  return static_cast<float>(1 + std::min(rows, kMaxRows)) * row_height() + (a.shape.size() == 3 ? line : 0.0f) +
         (rows > kMaxRows ? line : 0.0f);
}

void draw_array(const StepperSession& s, const Marks& m, int array, float bottom, float room_x) {
  if (s.stepper().trace().arrays()[static_cast<std::size_t>(array)].shape.size() >= 2) {
    draw_matrix_array(s, m, array, bottom, room_x);
  } else {
    draw_row_array(s, m, array, room_x);
  }
}

}  // namespace nbscope::ui::arrays
