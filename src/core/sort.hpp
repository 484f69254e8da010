// nbscope core: `sort`, direct mapping onto cells followed by sorting (book pp.87, 102).
//
// Each element is mapped onto one cell of size d by integerising its centre (Step 1, p.87): the
// integer arrays ix[N], iy[N] (3D also iz[N]). The permutation order[N] is then sorted by cell
// (ix major, then iy, then iz; ties by element id), so the elements of a cell form one run, and a
// sweep over the sorted array checks each element against the rest of its own run and against the
// runs of the cells of the contact mask; each mask cell keeps its own cursor into the sorted array,
// which only moves forward. Time ~ N log2 N (the sort), RAM 3N integers in 2D and 4N in 3D
// (eq. 3.54) whatever the spatial distribution.
#pragma once
#include <cstdint>
#include <vector>

#include "core/detector.hpp"

namespace nbscope {

class SortDetector final : public DimensionalDetector<SortDetector> {
 public:
  [[nodiscard]] std::string_view name() const override { return "sort"; }
  [[nodiscard]] bool supports_dim(int dim) const override { return dim == 2 || dim == 3; }
  // 3N integers in 2D (ix, iy, order), 4N in 3D (ix, iy, iz, order): the book's M = 3N / 4N.
  [[nodiscard]] std::size_t own_bytes() const override;
  [[nodiscard]] const Grid* last_grid() const override { return &grid_; }
  [[nodiscard]] const std::vector<const char*>& pseudocode(int dim) const override;

 private:
  friend DimensionalDetector<SortDetector>;
  template <int D, class Trace>
  void run(const Elements& elements, const DetectOptions& options, PairList& out_pairs, Trace& trace);

  Grid grid_;
  std::vector<std::int32_t> cell_[3];  // ix[N], iy[N], iz[N] (iz empty in 2D)
  std::vector<std::int32_t> order_;    // order[p]: the element at sorted position p
};

// Instantiated once, in sort.cpp, where run() is defined.
extern template class DimensionalDetector<SortDetector>;

}  // namespace nbscope
