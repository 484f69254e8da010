// nbscope core: what every cell-based detector shares besides the Grid itself — the contact mask
// (which neighbour cells an element is checked against) and the integerisation of all elements.
//
// Index: CellOffset and the half masks kMask2d/kMask3d | in_half_mask | CellIndex, integerise_cells,
// cell_at | integerise.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/elements.hpp"
#include "core/grid.hpp"

namespace nbscope {

// A neighbour cell relative to the element's own cell.
struct CellOffset {
  std::int32_t dx = 0, dy = 0, dz = 0;
};

// The contact mask without the own cell: the neighbours "before" a cell in (z, y, x) order. Every
// two neighbouring cells meet exactly once when each element is checked against these cells and,
// in its own cell, against the elements after it in the list, so every pair is tested once.
// 2D: (ix-1,iy), (ix-1,iy-1), (ix,iy-1), (ix+1,iy-1), as the book's NBS contact mask.
inline constexpr std::array<CellOffset, 4> kMask2d = {{{-1, 0, 0}, {-1, -1, 0}, {0, -1, 0}, {1, -1, 0}}};
// 3D: the four of 2D in the own layer, then all nine cells of the layer below (iz-1).
inline constexpr std::array<CellOffset, 13> kMask3d = {{{-1, 0, 0},
                                                        {-1, -1, 0},
                                                        {0, -1, 0},
                                                        {1, -1, 0},
                                                        {-1, -1, -1},
                                                        {0, -1, -1},
                                                        {1, -1, -1},
                                                        {-1, 0, -1},
                                                        {0, 0, -1},
                                                        {1, 0, -1},
                                                        {-1, 1, -1},
                                                        {0, 1, -1},
                                                        {1, 1, -1}}};

// The half mask of `dim` (2 or 3).
[[nodiscard]] inline std::span<const CellOffset> contact_mask(int dim) {
  if (dim == 3) return kMask3d;
  return kMask2d;
}

// The half mask of compile-time dimension D (for loops the compiler unrolls).
template <int D>
[[nodiscard]] constexpr const auto& half_mask() {
  if constexpr (D == 3) {
    return kMask3d;
  } else {
    return kMask2d;
  }
}

// True when the offset (dx, dy, dz) between two cells is one of the half mask's: the lexicographic
// test the masks above enumerate (dz < 0, or dz == 0 and dy < 0, or dz == dy == 0 and dx < 0), for
// offsets within one cell on every axis.
[[nodiscard]] constexpr bool in_half_mask(std::int32_t dx, std::int32_t dy, std::int32_t dz) {
  if (dz != 0) return dz < 0;
  if (dy != 0) return dy < 0;
  return dx < 0;
}

// An element's cell as the detector integerised it (book numbering is 1-based; these are 0-based).
struct CellIndex {
  std::int32_t ix = 0;
  std::int32_t iy = 0;
  std::int32_t iz = 0;  // 3D frames only (0 in 2D)
  friend bool operator==(const CellIndex&, const CellIndex&) = default;
};

// The cell of every element under `grid` (eq. 3.76, clamped as Grid::cell), written into `cells`:
// the cells the cross-check compares a detector's against.
void integerise_cells(const Elements& elements, const Grid& grid, std::vector<CellIndex>& cells);

// The cell (ix, iy) of a world point, or nullopt outside the grid (picking: not clamped).
std::optional<std::array<std::int32_t, 2>> cell_at(const Grid& grid, const Eigen::Vector2d& world);

// Integerised coordinates of every element on axis `axis` (eq. 3.76, clamped as Grid::cell), as one
// vectorised array expression; `out` must hold elements.size() entries.
void integerise(const Elements& elements, const Grid& grid, int axis, std::span<std::int32_t> out);

}  // namespace nbscope
