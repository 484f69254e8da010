// nbscope core: the element layouts that the property tests, the benchmarks and the scaling runs
// share (loose, dense, clustered, ...): N bounding circles or spheres reproducible from a seed.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/elements.hpp"

namespace nbscope {

// The layouts. The enumerators' values seed the generator: never reorder them.
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

// Every layout, in enumerator order.
const std::vector<Layout>& all_layouts();
// Short name ("loose", "dense", ...), as benchmark names and `nbscope scaling --layout` use it.
std::string layout_name(Layout layout);
// The layout called `name` (as layout_name() gives it), or nullopt.
std::optional<Layout> parse_layout(std::string_view name);
// "loose, dense, ..." for messages.
std::string layout_names();
// N elements of `layout` in `dim` (2 or 3) dimensions, reproducible from `seed`.
Elements make_layout(Layout layout, std::int64_t n, int dim, std::uint64_t seed);

}  // namespace nbscope
