// nbscope core: `screen`, the screening contact detection algorithm (book p.91).
//
// Every element is pushed onto the list of its cell: the screen array C[nx][ny] (3D: C[nx][ny][nz])
// holds one list head per cell and the next array E[N] links the elements of a list (eq. 3.21). Then
// each element is checked against the elements after it in its own list and against the lists of
// the cells of the contact mask, and the heads that were set are reset to -1. Fast, but the screen
// array grows with the grid's area (volume), not with N: a sparse world needs too much memory, so
// the detector refuses grids of more than kScreenMaxCells cells before allocating anything.
#pragma once
#include <cstdint>
#include <vector>

#include "core/detector.hpp"

namespace nbscope {

// Most cells the screen array may have: 2^25 = 33,554,432 heads = 128 MiB of int32. Beyond it,
// `nbs` (memory linear in N and in the grid's side) is the algorithm to use.
inline constexpr std::int64_t kScreenMaxCells = std::int64_t{1} << 25;

// Throws Error when the screen array of `grid` would exceed kScreenMaxCells, naming the memory it
// would need and suggesting `nbs` (with what nbs would need for `n_elements`) or a larger cell.
void check_screen_array_size(const Grid& grid, std::int64_t n_elements);

class ScreenDetector final : public DimensionalDetector<ScreenDetector> {
 public:
  [[nodiscard]] std::string_view name() const override { return "screen"; }
  [[nodiscard]] bool supports_dim(int dim) const override { return dim == 2 || dim == 3; }
  // nx*ny(*nz) + N integers: the screen array C and the next array E.
  [[nodiscard]] std::size_t own_bytes() const override;
  [[nodiscard]] const Grid* last_grid() const override { return &grid_; }
  [[nodiscard]] const std::vector<const char*>& pseudocode(int dim) const override;

 private:
  friend DimensionalDetector<ScreenDetector>;
  template <int D, class Trace>
  void run(const Elements& elements, const DetectOptions& options, PairList& out_pairs, Trace& trace);

  Grid grid_;
  std::vector<std::int32_t> heads_;  // C, flat: C[ix][iy][iz] = heads_[grid_.flat(ix, iy, iz)]
  std::vector<std::int32_t> next_;   // E[N]
};

// Instantiated once, in screen.cpp, where run() is defined.
extern template class DimensionalDetector<ScreenDetector>;

}  // namespace nbscope
