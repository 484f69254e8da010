// nbscope app: the grid-pinning flags shared by `pairs` and `dump` (--cell-size, --origin, --cells).
#pragma once
#include <string>

#include "app/cli.hpp"
#include "core/grid.hpp"

namespace nbscope {

// The flags parsed into the grid they pin, with what is needed to check them against the elements'
// dimension once those are read.
struct GridFlags {
  GridOptions grid;         // 2 values given: origin z 0, cells nz 1
  std::string origin_text;  // --origin as given, for messages
  std::string cells_text;   // --cells as given, for messages
  int origin_dim = 0;       // how many values --origin gave (0: not given)
  int cells_dim = 0;        // how many values --cells gave (0: not given)
};

// Takes --cell-size D, --origin X,Y[,Z] and --cells NX,NY[,NZ] from `args`; Error on malformed values.
GridFlags take_grid_flags(Args& args);
// The grid options for elements of `dim` dimensions; Error when --origin/--cells have another dimension.
GridOptions grid_options_for(const GridFlags& flags, int dim);

}  // namespace nbscope
