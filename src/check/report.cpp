#include "check/report.hpp"

#include <cstdio>
#include <type_traits>

namespace nbscope {

const char* invariant_name(Invariant invariant) {
  switch (invariant) {
    case Invariant::AEqualsR: return "A==R";
    case Invariant::AInF: return "A-in-F";
    case Invariant::TInA: return "T-in-A";
    case Invariant::AabbInCells: return "AABB-in-cells";
    case Invariant::Cells: return "cells";
    case Invariant::Contract: return "contract";
  }
  return "?";
}

const char* invariant_description(Invariant invariant) {
  switch (invariant) {
    case Invariant::AEqualsR: return "the algorithm's pairs A equal the reference's pairs R";
    case Invariant::AInF:
      return "every pair of A that Box2D would consider (its filters applied; with a polygon, the shapes' tight AABBs "
             "overlapping) "
             "is in Box2D's contact list F";
    case Invariant::TInA: return "every pair of shapes touching at the current transforms (T) is in A";
    case Invariant::AabbInCells:
      return "every pair whose tight AABBs overlap (b2TestOverlap, inclusive) lies in the same or neighbouring cells of the "
             "detector's integerisation";
    case Invariant::Cells:
      return "every element's cell as the detector integerised it (a plugin that reports its cells) equals the grid's "
             "(eq. 3.76), and every list the detector walks (a plugin that traces its lists) holds only elements of its "
             "cell; detectors that use the grid's own integerisation and lists hold it by construction";
    case Invariant::Contract:
      return "the detector's traced operations keep its algorithm's contracts (every element on its lists, every row "
             "processed, the mask relating every neighbour, each test exact and reported once) and a plugin keeps the API's "
             "rules (docs/diagnosis.md); checked on the frames whose detection was traced, and on every frame a plugin misbehaves";
  }
  return "?";
}

std::string boundary_text(const BoundaryPair& b, const Units* units) {
  if (b.tie) return "an exact tie (gap 0): a contact under --touching inclusive, not under strict";
  const auto length = [units](double v) {
    if (units != nullptr) return units->length_text(v);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return std::string(buf);
  };
  return "at the boundary, within the data's precision (gap " + length(b.gap) + ", resolution " + length(b.resolution) + ")";
}

std::string gap_text(double gap) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "distance - radii = %.6g (%s)", gap, gap <= 0 ? "in contact" : "apart");
  return buf;
}

std::string frame_label(FrameUnit unit, std::int64_t number) { return std::string(frame_unit_name(unit)) + " " + std::to_string(number); }

const char* frame_unit_name(FrameUnit unit) { return unit == FrameUnit::timestep ? "timestep" : "frame"; }

std::string periodic_text(const std::array<bool, 3>& periodic) {
  std::string s;
  for (std::size_t a = 0; a < 3; ++a)
    if (periodic[a]) s += std::string(s.empty() ? "" : ",") + static_cast<char>('x' + a);
  return s.empty() ? "none" : s;
}

std::string apart_pairs_hint(std::int64_t apart, std::int64_t listed, double gap_max) {
  if (apart < 10 || apart * 20 < listed) return "";
  char gap[32];
  std::snprintf(gap, sizeof gap, "%.3g", gap_max);
  return "hint: " + std::to_string(apart) + " of the " + std::to_string(listed) + " listed pairs do not touch (gaps up to " + gap +
         "): a neighbour list rather than contacts? LAMMPS lists contacts with `compute property/local patom1 patom2 cutoff "
         "radius`, LIGGGHTS with `compute pair/gran/local pos id`";
}

void name_atoms(FrameReport& report, const std::vector<std::int64_t>* ids, const std::vector<std::int32_t>* ranks) {
  const auto at = [](const auto* column, ElementId row) {
    using T = std::decay_t<decltype((*column)[0])>;
    return column != nullptr && row >= 0 && static_cast<std::size_t>(row) < column->size() ? (*column)[static_cast<std::size_t>(row)] : T{-1};
  };
  if (ids == nullptr && ranks == nullptr) return;
  for (Violation& v : report.violations) {
    v.atom_i = at(ids, v.pair.i);
    v.atom_j = at(ids, v.pair.j);
    v.rank_i = at(ranks, v.pair.i);
    v.rank_j = at(ranks, v.pair.j);
  }
}

std::string violation_pair_text(const Violation& v, int first) {
  const auto name = [&](std::int64_t atom, ElementId row) { return std::to_string(atom >= 0 ? atom : row >= 0 ? row + first : row); };
  std::string i = name(v.atom_i, v.pair.i), j = name(v.atom_j, v.pair.j);
  if (v.rank_i >= 0 && v.rank_j >= 0 && v.rank_i != v.rank_j) {
    i += " of rank " + std::to_string(v.rank_i);
    j += " of rank " + std::to_string(v.rank_j);
  }
  return i + ", " + j;
}

}  // namespace nbscope
