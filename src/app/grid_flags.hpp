// nbscope app: the grid-pinning flags shared by `pairs` and `dump` (--cell-size, --origin, --cells).
#pragma once
#include <optional>
#include <string>

#include "app/cli.hpp"
#include "core/grid.hpp"

namespace nbscope {

// The flags as given; checked against the elements' dimension once those are read.
struct GridFlags {
  std::optional<double> cell_size;
  std::optional<std::string> origin;
  std::optional<std::string> cells;
  double origin_values[3] = {0, 0, 0};
  double cell_counts[3] = {1, 1, 1};
  int origin_dim = 0;
  int cells_dim = 0;
};

// Takes --cell-size D, --origin X,Y[,Z] and --cells NX,NY[,NZ] from `args`; Error on malformed values.
GridFlags take_grid_flags(Args& args);
// The grid options for elements of `dim` dimensions; Error when --origin/--cells have another dimension.
GridOptions grid_options_for(const GridFlags& flags, int dim);

}  // namespace nbscope
