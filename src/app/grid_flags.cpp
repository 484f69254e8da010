#include "app/grid_flags.hpp"

#include <cmath>

#include "core/error.hpp"

namespace nbscope {

GridFlags take_grid_flags(Args& args) {
  GridFlags f;
  f.grid.cell_size = args.number("--cell-size");
  const auto origin = args.value("--origin");
  const auto cells = args.value("--cells");
  if (origin) {
    f.origin_text = *origin;
    double values[3] = {0, 0, 0};
    f.origin_dim = parse_point("--origin", *origin, values);
    f.grid.origin = std::array<double, 3>{values[0], values[1], values[2]};
  }
  if (cells) {
    f.cells_text = *cells;
    double counts[3] = {1, 1, 1};
    f.cells_dim = parse_point("--cells", *cells, counts);
    for (int a = 0; a < f.cells_dim; ++a) {
      const double c = counts[a];
      if (c < 1 || c != std::floor(c) || c > 1e15)
        throw Error("--cells: '" + *cells + "' is not NX,NY or NX,NY,NZ of whole numbers >= 1");
    }
    f.grid.cells = std::array<std::int64_t, 3>{static_cast<std::int64_t>(counts[0]), static_cast<std::int64_t>(counts[1]),
                                               static_cast<std::int64_t>(counts[2])};
  }
  return f;
}

GridOptions grid_options_for(const GridFlags& f, int dim) {
  if (f.grid.origin && f.origin_dim != dim)
    throw Error("--origin: '" + f.origin_text + "' has " + std::to_string(f.origin_dim) + " coordinates, the elements are " +
                std::to_string(dim) + "D");
  if (f.grid.cells && f.cells_dim != dim)
    throw Error("--cells: '" + f.cells_text + "' has " + std::to_string(f.cells_dim) + " counts, the elements are " +
                std::to_string(dim) + "D");
  return f.grid;
}

}  // namespace nbscope
