#include "check/faults.hpp"

#include <algorithm>
#include <cstdlib>

#include "core/error.hpp"

namespace nbscope {

namespace {
constexpr Fault kAllFaults[] = {Fault::DropMaskCell, Fault::OffByOneCell, Fault::StalePositions, Fault::DropPair,
                                Fault::DropBox2dContact};
}

const char* fault_name(Fault fault) {
  switch (fault) {
    case Fault::None: return "none";
    case Fault::DropMaskCell: return "drop-mask-cell";
    case Fault::OffByOneCell: return "off-by-one-cell";
    case Fault::StalePositions: return "stale-positions";
    case Fault::DropPair: return "drop-pair";
    case Fault::DropBox2dContact: return "drop-box2d-contact";
  }
  return "?";
}

const char* fault_description(Fault fault) {
  switch (fault) {
    case Fault::None: return "";
    case Fault::DropMaskCell:
      return "the contact mask leaves out the neighbour cell (ix-1, iy-1) (in 3D (ix-1, iy-1, iz), of the same layer): the pairs "
             "whose cells are diagonal neighbours that way are removed from A, exactly what nbs returns without that mask cell";
    case Fault::OffByOneCell:
      return "the integerisation is shifted by one cell (ix + 1) for every element from the grid's middle column "
             "on: the detector's cells are shifted so, and the pairs whose shifted cells are no longer neighbours "
             "are removed from A";
    case Fault::StalePositions: return "the detector is given last frame's element positions instead of this frame's";
    case Fault::DropPair: return "the middle pair of A (sorted) is dropped every frame";
    case Fault::DropBox2dContact:
      return "Box2D's contact list F loses the middle pair of A's in-scope pairs before the comparison, as a "
             "broadphase that missed a pair would (the detector is untouched)";
  }
  return "?";
}

std::string fault_names() {
  std::string s;
  for (const Fault f : kAllFaults) s += (s.empty() ? "" : ", ") + std::string(fault_name(f));
  return s;
}

Fault parse_fault(std::string_view name) {
  if (name == "none") return Fault::None;
  for (const Fault f : kAllFaults)
    if (name == fault_name(f)) return f;
  throw Error("--inject-fault: unknown fault '" + std::string(name) + "' (known: " + fault_names() + ")");
}

void apply_output_fault(Fault fault, const Grid& grid, std::vector<CellIndex>& cells, PairList& pairs) {
  const auto cell_of = [&](ElementId k) { return cells[static_cast<std::size_t>(k)]; };
  switch (fault) {
    case Fault::None:
    case Fault::StalePositions:
    case Fault::DropBox2dContact:
      return;
    case Fault::DropMaskCell: {
      // The mask cell (ix-1, iy-1) of the element in the upper-right cell of the two.
      std::erase_if(pairs, [&](const Pair& p) {
        const CellIndex a = cell_of(p.i), b = cell_of(p.j);
        const int dx = b.ix - a.ix, dy = b.iy - a.iy;
        return ((dx == -1 && dy == -1) || (dx == 1 && dy == 1)) && a.iz == b.iz;  // iz: 0 in 2D
      });
      return;
    }
    case Fault::OffByOneCell: {
      const auto middle = static_cast<std::int32_t>(grid.n[0] / 2);
      for (CellIndex& c : cells)
        if (c.ix >= middle) ++c.ix;
      std::erase_if(pairs, [&](const Pair& p) {
        const CellIndex a = cell_of(p.i), b = cell_of(p.j);
        return std::abs(a.ix - b.ix) > 1 || std::abs(a.iy - b.iy) > 1;
      });
      return;
    }
    case Fault::DropPair:
      if (!pairs.empty()) pairs.erase(pairs.begin() + static_cast<std::ptrdiff_t>(pairs.size() / 2));
      return;
  }
}

}  // namespace nbscope
