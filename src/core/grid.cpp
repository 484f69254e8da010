#include "core/grid.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <cstdio>
#include <string>

#include "core/error.hpp"
#include "core/pairs.hpp"

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
// The factor of Int((v - origin) * factor). Exactly 1/d when d exceeds the largest diameter D by
// more than rounding can blur; otherwise 1/(D + guard). Why: v - origin is rounded to within
// u*|v - origin| (u = 2^-53) and the product once more, so two centres D apart could land two
// cells apart when d == D, and a contact would be missed. With the guard, computed positions of
// centres at most D apart differ by at most 1 cell, so their cells are neighbours.
double integerisation_scale(const Grid& g, const Bounds& b, double diameter) {
  double reach = g.cell_size;  // largest |v - origin| over the data, per axis
  for (int a = 0; a < g.dim; ++a)
    reach = std::max({reach, std::abs(b.max[a] - g.origin[a]), std::abs(b.min[a] - g.origin[a]),
                      g.periodic[a] ? std::abs(g.period[a]) : 0.0});
  const double guard = 8.0 * std::numeric_limits<double>::epsilon() * reach;
  return 1.0 / std::max(g.cell_size, diameter + guard);
}

// A periodic axis a: origin lo and n = floor(L * scale) cells, where 1/scale (>= d) is the width
// integerisation really uses, so every cell but the last is that wide and the last absorbs the
// remainder (width in [1/scale, 2/scale)). Why no contact is lost: two centres in contact across the
// boundary lie within d of lo and of hi, so the one near lo is in cell 0 and the one near hi, at
// least L - 1/scale >= (n - 1)/scale from lo, in cell n - 1 (clamped there), which the wrapped mask
// makes cell 0's neighbour; within the box the wider last cell only joins centres, so neighbours
// stay neighbours. Fewer than 3 cells: refused (a cell's two neighbours would be one cell).
void fit_periodic_axis(Grid& g, const Elements& e, const GridOptions& options, int a, const char* axis) {
  const double lo = e.box.lo[a], period = e.box.length(a);
  if (options.origin && (*options.origin)[a] != lo) {
    throw Error(std::string(axis) + " is periodic from " + fmt(lo) + ": a pinned grid origin of " +
                fmt((*options.origin)[a]) + " disagrees with the box");
  }
  g.origin[a] = lo;
  g.periodic[a] = true;
  g.period[a] = period;
  const double cells = std::floor(period * g.inv_cell_size);
  // The cells are a few ulps wider than d when d is the largest diameter (integerisation_scale).
  const char* widened = "; cells are a few ulps wider than a cell size equal to the largest diameter: give a larger --cell-size";
  if (!(cells >= 3)) {
    throw Error(std::string(axis) + " is periodic over L = " + fmt(period) + " with cell size " + fmt(g.cell_size) +
                ": " + fmt_count(cells) + " cells; the wrap needs at least 3 (a cell's left and right neighbour " +
                "would be the same cell)" + (std::floor(period / g.cell_size) >= 3 ? widened : "") +
                // LIGGGHTS's `dimension 2` writes z = 0 in a thin periodic z slab.
                (a == 2 ? "; a 2D simulation's frames (z = 0) are read as 2D with --2d" : ""));
  }
  if (!(cells <= static_cast<double>(kMaxCellsPerSide))) {
    throw Error(std::string("the grid would need ") + fmt_count(cells) + " cells along periodic " + axis +
                " (limit " + std::to_string(kMaxCellsPerSide) + "): use a larger --cell-size");
  }
  if (options.cells && (*options.cells)[a] != static_cast<std::int64_t>(cells)) {
    throw Error(std::string(axis) + " is periodic over L = " + fmt(period) + ", which holds " + fmt_count(cells) +
                " cells of size " + fmt(g.cell_size) + ", not the pinned " + std::to_string((*options.cells)[a]));
  }
  g.n[a] = static_cast<std::int64_t>(cells);
}

}  // namespace

Grid make_grid(const Elements& elements, const GridOptions& options) {
  Grid g;
  g.dim = elements.dim;
  const double diameter = 2.0 * elements.max_radius();
  double d = options.cell_size.value_or(diameter);
  if (elements.size() == 0 && !options.cell_size) {
    d = 1.0;
    // No elements, nothing to find: cells that fit at least 3 to every period (a dump's first frame
    // before any atom is inserted), not cells of 1 a small box cannot hold (a quarter: rounding of
    // the periodic grid's width must not leave fewer than 3).
    for (int a = 0; a < elements.dim; ++a)
      if (elements.box.periodic[a] && elements.box.length(a) > 0) d = std::min(d, elements.box.length(a) / 4);
  }
  if (!std::isfinite(d) || d <= 0) throw Error("cell size must be a positive finite number, got " + fmt(d));
  if (d < diameter) {
    throw Error("cell size " + fmt(d) + " is smaller than the largest diameter " + fmt(diameter) +
                " (contacts could span more than one cell)");
  }
  g.cell_size = d;
  if (elements.box.any()) check_periodic_box(elements, "grid");
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
  for (int a = 0; a < g.dim; ++a) {
    g.periodic[a] = elements.box.periodic[a];
    g.period[a] = elements.box.length(a);
  }
  g.inv_cell_size = integerisation_scale(g, b, elements.size() == 0 ? 0.0 : diameter);
  for (int a = 0; a < g.dim; ++a)
    if (g.periodic[a]) fit_periodic_axis(g, elements, options, a, axis_name[a]);
  return g;
}

}  // namespace nbscope
