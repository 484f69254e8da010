// nbscope core: the cell grid of the book (identical square cells of size d) and its integerisation.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include "core/elements.hpp"

namespace nbscope {

// Most cells along one side. Keeps every cell index in int32 and a heads array of one side
// (nbs: 2*nx + ny integers) within ~130 MB; a sparser world needs a larger --cell-size.
inline constexpr std::int64_t kMaxCellsPerSide = std::int64_t{1} << 24;

// How the grid is pinned. Unset fields are derived from the data each frame (docs/architecture.md "Cells").
// The one description of a pinned grid: detection options, scene files (Scene::grid), recordings
// (Recording::grid) and the --cell-size/--origin/--cells flags all hold one. 2D grids read the
// first two entries of `origin` and `cells`; by convention the third is 0 and 1 there.
struct GridOptions {
  std::optional<double> cell_size;              // default: the largest diameter (the book's d)
  std::optional<std::array<double, 3>> origin;  // default: minimum corner of the centres' bounding box
  // Cells per axis (nx, ny, nz), pinning the grid's extent as the book's figures draw it (Fig. 3.15:
  // 10x10). Default: just enough cells to cover every centre. Centres beyond the pinned grid are
  // clamped into its border cells, which keeps every contact (see Grid::cell).
  std::optional<std::array<std::int64_t, 3>> cells;
};

// A grid fitted to one element set: nx*ny(*nz) cells of size d from `origin`.
struct Grid {
  int dim = 2;
  double cell_size = 1;      // d, as the book and the user see it
  double inv_cell_size = 1;  // 1/d, or a hair less where rounding could split a contact (make_grid)
  double origin[3] = {0, 0, 0};
  std::int64_t n[3] = {1, 1, 1};  // cells per axis; n[2] == 1 in 2D
  // Periodic axes (the frame's box): origin = lo, cells n-1 and 0 are neighbours, n >= 3.
  bool periodic[3] = {false, false, false};
  double period[3] = {0, 0, 0};  // L = hi - lo on a periodic axis

  // Integerised coordinate Int((v - origin)/d) on axis a (eq. 3.76), clamped into [0, n[a]).
  // Clamping keeps neighbours neighbours (the map is monotone), so an origin pinned inside the
  // data still finds every contact.
  // On [0, n) Int() is truncation, which needs no floor() (a library call on baseline x86-64).
  // (AxisCells below holds the one implementation.)
  [[nodiscard]] std::int32_t cell(double v, int a) const;
  // The cell `offset` (-1, 0 or 1) from cell c along axis a: wrapped on a periodic axis, -1 past an open edge.
  [[nodiscard]] std::int32_t neighbour(std::int32_t c, std::int32_t offset, int a) const {
    const std::int32_t m = c + offset;
    const auto last = static_cast<std::int32_t>(n[a] - 1);
    if (m >= 0 && m <= last) return m;
    if (!periodic[a]) return -1;
    return m < 0 ? last : 0;
  }
  // Total number of cells nx*ny(*nz), as the screen array would need them.
  [[nodiscard]] std::int64_t cell_count() const { return n[0] * n[1] * n[2]; }
  // Flat index of cell (ix, iy, iz) in an array indexed [ix][iy] (2D) or [ix][iy][iz] (3D), the
  // book's C[nx][ny]; needs cell_count() to fit in int64 (the screen detector checks it first).
  [[nodiscard]] std::int64_t flat(std::int32_t ix, std::int32_t iy, std::int32_t iz) const {
    return (std::int64_t{ix} * n[1] + iy) * n[2] + iz;
  }
};

// Grid::cell on one axis, copied out of the grid: a loop that also stores through pointers keeps
// these in registers, where it would reload the grid's fields after every store it cannot rule out.
struct AxisCells {
  double origin = 0, inv_cell_size = 1, cells = 1;
  std::int32_t last = 0;
  AxisCells(const Grid& g, int a)
      : origin(g.origin[a]), inv_cell_size(g.inv_cell_size), cells(static_cast<double>(g.n[a])),
        last(static_cast<std::int32_t>(g.n[a] - 1)) {}
  // Grid::cell(v, a): Int((v - origin)/d), clamped into [0, n).
  [[nodiscard]] std::int32_t operator()(double v) const {
    const double c = (v - origin) * inv_cell_size;
    if (!(c >= 0)) return 0;  // also catches NaN
    if (c >= cells) return last;
    return static_cast<std::int32_t>(c);
  }
};

inline std::int32_t Grid::cell(double v, int a) const { return AxisCells(*this, a)(v); }

// Fits a grid to `elements`: d = options.cell_size or the largest diameter; origin = options.origin
// or the minimum corner; n = options.cells or enough to cover every centre. When d is within
// rounding of the largest diameter, integerisation divides by a d a few ulps of the coordinates
// larger, so that rounding never puts a contact two cells apart. Throws Error when d is not
// positive and finite, is smaller than the largest diameter (contacts could then skip a cell), or a
// side would exceed kMaxCellsPerSide (or be below 1). On the frame's periodic axes the grid spans
// the box: origin lo, floor(L/d) cells, the last one wider; Error when that is fewer than 3, or a
// pinned origin or cell count disagrees with the box.
Grid make_grid(const Elements& elements, const GridOptions& options);

}  // namespace nbscope
