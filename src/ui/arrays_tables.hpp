// nbscope ui, the Arrays panel's own: one traced array as a table, as the book's figures draw it — a
// next array as a row of integers over its indices (Figs 3.13, 3.20), a heads array of cells as a
// matrix C[ix][iy] (eq. 3.31), NBS's B[2][nx] as the current row over the row below — with -1 for
// an empty list or the end of one, "·" for an entry not written yet, the entry just written and the
// entries the current operation reads highlighted, long arrays windowed around them; and the room
// each table asks for, so that the panel can lay the tables out before it draws them.
//
// Index: Marks (what to highlight) | sizes | tables.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ui/stepper_session.hpp"

namespace nbscope::ui::arrays {

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

// Fills `marks` for the session's current operation: the last write, the walk, the lists of the
// cell, row and layer it works on, its element. Returns the line saying what was written last
// ("" when nothing was written yet).
std::string mark_arrays(const StepperSession& s, Marks& marks);

// ---- sizes (ImGui's current style: call between NewFrame and Render) ----
// The width array `array`'s table takes when every column fits (a row array or a matrix's columns
// up to 16), else with its window's first eight columns.
[[nodiscard]] float array_width(const StepperSession& s, const Marks& m, int array);
// The width of its table with the fewest columns a window shows (four).
[[nodiscard]] float narrowest_array_width(const StepperSession& s, const Marks& m, int array);
// The width of its table drawn in `room_x` pixels (a long array takes as many columns as fit, up to 16).
[[nodiscard]] float drawn_array_width(const StepperSession& s, const Marks& m, int array, float room_x);
// The height of its table with every row a matrix shows when room allows (at most ten), and the
// lines above and below it (a 3D slice's, "... N more rows").
[[nodiscard]] float array_height(const StepperSession& s, int array);

// ---- tables ----
// Draws array `array`: a row array, or a matrix whose rows are windowed to those that fit above
// `bottom` (screen y). Its columns are windowed to those that fit in `room_x` pixels beside its label.
void draw_array(const StepperSession& s, const Marks& m, int array, float bottom, float room_x);

}  // namespace nbscope::ui::arrays
