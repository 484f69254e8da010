#include "app/grid_flags.hpp"

#include <cmath>

#include "core/error.hpp"

namespace nbscope {

GridFlags take_grid_flags(Args& args) {
  GridFlags f;
  f.cell_size = args.number("--cell-size");
  f.origin = args.value("--origin");
  f.cells = args.value("--cells");
  if (f.origin) f.origin_dim = parse_point("--origin", *f.origin, f.origin_values);
  if (f.cells) {
    f.cells_dim = parse_point("--cells", *f.cells, f.cell_counts);
    for (int a = 0; a < f.cells_dim; ++a) {
      const double c = f.cell_counts[a];
      if (c < 1 || c != std::floor(c) || c > 1e15)
        throw Error("--cells: '" + *f.cells + "' is not NX,NY or NX,NY,NZ of whole numbers >= 1");
    }
  }
  return f;
}

GridOptions grid_options_for(const GridFlags& f, int dim) {
  if (f.origin && f.origin_dim != dim)
    throw Error("--origin: '" + *f.origin + "' has " + std::to_string(f.origin_dim) + " coordinates, the elements are " +
                std::to_string(dim) + "D");
  if (f.cells && f.cells_dim != dim)
    throw Error("--cells: '" + *f.cells + "' has " + std::to_string(f.cells_dim) + " counts, the elements are " +
                std::to_string(dim) + "D");
  GridOptions g;
  g.cell_size = f.cell_size;
  if (f.origin) g.origin = std::array<double, 3>{f.origin_values[0], f.origin_values[1], f.origin_values[2]};
  if (f.cells) {
    g.cells = std::array<std::int64_t, 3>{static_cast<std::int64_t>(f.cell_counts[0]),
                                          static_cast<std::int64_t>(f.cell_counts[1]),
                                          static_cast<std::int64_t>(f.cell_counts[2])};
  }
  return g;
}

}  // namespace nbscope
