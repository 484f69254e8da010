// nbscope check: fault injection (`--inject-fault NAME`), so that tests can prove every invariant
// can fail. Faults never touch a detector's hot loop: stale-positions changes what the detector is
// given (the frame loop keeps last frame's elements), the others post-process what it returned —
// each one producing exactly the pairs a detector with that bug would return. They prove the checks;
// bugs in an algorithm's own code, with a trace to follow, are the plugins of examples/detectors/.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "check/report.hpp"
#include "core/cells.hpp"
#include "core/grid.hpp"
#include "core/pairs.hpp"

namespace nbscope {

enum class Fault : std::uint8_t {
  None,
  DropMaskCell,    // one neighbour cell, (ix-1, iy-1), left out of the contact mask
  OffByOneCell,    // integerisation shifted: ix one too large from the grid's middle column on
  StalePositions,  // detection on last frame's positions
  DropPair,        // one contact of A dropped each frame
  DropBox2dContact,  // Box2D's contact list loses one pair A needs (a broadphase that missed a pair)
};

// "none", "drop-mask-cell", "off-by-one-cell", "stale-positions", "drop-pair", "drop-box2d-contact".
const char* fault_name(Fault fault);
// One sentence saying what the fault does and how it is emulated.
const char* fault_description(Fault fault);
// The fault called `name`; throws Error listing the known names otherwise.
Fault parse_fault(std::string_view name);
// "drop-mask-cell, off-by-one-cell, ..." for help and messages.
std::string fault_names();

// Applies the output side of `fault` (stale-positions and drop-box2d-contact have none): `cells` are the detector's cells of
// each element and become the faulty ones (off-by-one-cell), `pairs` (sorted) lose what the faulty
// detector would miss. drop-mask-cell: pairs one cell apart diagonally, lower-left to upper-right;
// off-by-one-cell: pairs whose faulty cells are no longer neighbours; drop-pair: the middle pair.
void apply_output_fault(Fault fault, const Grid& grid, std::vector<CellIndex>& cells, PairList& pairs);

}  // namespace nbscope
