#include "core/cells.hpp"

#include <cassert>

namespace nbscope {

void integerise(const Elements& elements, const Grid& grid, int axis, std::span<std::int32_t> out) {
  assert(static_cast<std::int64_t>(out.size()) == elements.size() && "integerise: output size");
  const Eigen::ArrayXd& v = elements.axis(axis);
  const double last = static_cast<double>(grid.n[axis] - 1);
  Eigen::Map<Eigen::Array<std::int32_t, Eigen::Dynamic, 1>> cells(out.data(), v.size());
  const Eigen::ArrayXd c = ((v - grid.origin[axis]) * grid.inv_cell_size).floor();
  // As Grid::cell: below 0 (and NaN, for which c >= 0 is false) is cell 0, beyond the grid the last.
  cells = (c >= 0.0).select(c, 0.0).min(last).cast<std::int32_t>();
}

}  // namespace nbscope
