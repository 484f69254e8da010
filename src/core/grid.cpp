#include "core/grid.hpp"

#include <charconv>
#include <cstdio>
#include <string>

#include "core/error.hpp"

namespace nbscope {

namespace {
// The shortest text that reads back as `v`: exact, yet "2e-300" rather than 17 digits of noise.
std::string fmt(double v) {
  char buf[64];
  const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
  return std::string(buf, end);
}
// A count too large to be exact anyway, in six digits.
std::string fmt_count(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}
}  // namespace

Grid make_grid(const Elements& elements, const GridOptions& options) {
  Grid g;
  g.dim = elements.dim;
  const double diameter = 2.0 * elements.max_radius();
  double d = options.cell_size.value_or(diameter);
  if (elements.size() == 0 && !options.cell_size) d = 1.0;
  if (!std::isfinite(d) || d <= 0) throw Error("cell size must be a positive finite number, got " + fmt(d));
  if (d < diameter) {
    throw Error("cell size " + fmt(d) + " is smaller than the largest diameter " + fmt(diameter) +
                " (contacts could span more than one cell)");
  }
  g.cell_size = d;
  g.inv_cell_size = 1.0 / d;
  const Bounds b = elements.centre_bounds();
  static const char* axis_name[3] = {"x", "y", "z"};
  for (int a = 0; a < g.dim; ++a) {
    g.origin[a] = options.origin ? (*options.origin)[a] : b.min[a];
    if (!std::isfinite(g.origin[a])) throw Error("grid origin must be finite");
    if (options.cells) {
      const std::int64_t pinned = (*options.cells)[a];
      if (pinned < 1 || pinned > kMaxCellsPerSide) {
        throw Error(std::string("the number of cells along ") + axis_name[a] + " must be in 1.." +
                    std::to_string(kMaxCellsPerSide) + ", got " + std::to_string(pinned));
      }
      g.n[a] = pinned;
      continue;
    }
    const double top = elements.size() == 0 ? g.origin[a] : b.max[a];
    const double span_cells = std::floor((top - g.origin[a]) / d) + 1.0;
    const double cells = span_cells < 1.0 ? 1.0 : span_cells;
    if (!(cells <= static_cast<double>(kMaxCellsPerSide))) {
      throw Error(std::string("the grid would need ") + fmt_count(cells) + " cells along " + axis_name[a] +
                  " (limit " + std::to_string(kMaxCellsPerSide) + "); the world is " + fmt(top - g.origin[a]) +
                  " wide for cells of " + fmt(d) + ": use a larger --cell-size");
    }
    g.n[a] = static_cast<std::int64_t>(cells);
  }
  return g;
}

}  // namespace nbscope
