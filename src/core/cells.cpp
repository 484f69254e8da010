#include "core/cells.hpp"

#include <cassert>
#include <cmath>

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

void integerise_cells(const Elements& e, const Grid& grid, std::vector<CellIndex>& cells) {
  const auto n = static_cast<std::size_t>(e.size());
  cells.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    cells[k] = {grid.cell(e.x[i], 0), grid.cell(e.y[i], 1), grid.dim == 3 && e.dim == 3 ? grid.cell(e.z[i], 2) : 0};
  }
}

std::optional<std::array<std::int32_t, 2>> cell_at(const Grid& grid, const Eigen::Vector2d& world) {
  const double fx = std::floor((world.x() - grid.origin[0]) * grid.inv_cell_size);
  const double fy = std::floor((world.y() - grid.origin[1]) * grid.inv_cell_size);
  if (!(fx >= 0 && fy >= 0 && fx < double(grid.n[0]) && fy < double(grid.n[1]))) return std::nullopt;
  return std::array<std::int32_t, 2>{static_cast<std::int32_t>(fx), static_cast<std::int32_t>(fy)};
}

}  // namespace nbscope
