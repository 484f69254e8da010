// nbscope tests and benchmarks: element sets of the families every detector is checked on.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/elements.hpp"
#include "core/grid.hpp"
#include "core/pairs.hpp"

namespace nbscope::testdata {

// The layouts of the property tests and benchmarks.
enum class Layout {
  Loose,        // uniform, area (volume) fraction ~0.05
  Dense,        // uniform, area fraction ~0.6 (overlaps allowed)
  Clustered,    // a few tight Gaussian clusters in a large empty world
  OneCell,      // every centre inside one cell
  OnePoint,     // every centre at the same point
  OnLine,       // centres on one horizontal line
  Touching,     // integer lattice, r = 0.5: neighbours touch exactly
  FarAway,      // loose, shifted to about -1e6 (negative and large coordinates)
  UnequalRadii, // radii from 0.01 to 1 (cell size = the largest diameter)
  CellBorders,  // pairs as far apart as contact allows, to the last ulp, on cell borders, at
                // magnitudes 1 to 1e9: where rounding in Int((x - xmin)/d) could split a contact
};

// Every layout, for parameterised tests.
const std::vector<Layout>& all_layouts();
// Short name ("loose", "dense", ...), as used by benchmark names.
std::string layout_name(Layout layout);
// N elements of `layout` in `dim` (2 or 3) dimensions, reproducible from `seed`.
Elements make_layout(Layout layout, std::int64_t n, int dim, std::uint64_t seed);
// The book's Fig. 3.15: nine elements of radius 0.1 (assets/examples/nine.csv, 0-based here).
Elements book_nine();
// Its grid as the book pins it: 10 x 10 unit cells from (0, 0).
GridOptions book_grid();
// The reference every detector is checked against: brute force, sorted by (i, j).
PairList brute_pairs(const Elements& elements);

}  // namespace nbscope::testdata
