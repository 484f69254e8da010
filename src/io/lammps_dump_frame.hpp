// nbscope io: a `dump custom` frame's rows as read (file order) and their turn into a DumpFrame:
// ascending ids, repeated ids refused, periodic centres wrapped, the precision band.
#pragma once
#include <cstdint>
#include <vector>

#include "io/lammps_dump.hpp"
#include "io/lammps_dump_parse.hpp"

namespace nbscope::dump {

// The atoms of one frame in file order.
struct RawAtoms {
  RawAtoms(int dim, bool with_types) : dim(dim), with_types(with_types) {}
  int dim;
  bool with_types;
  std::vector<double> x, y, z, r;
  std::vector<std::int64_t> ids;
  std::vector<std::int32_t> types;
  std::size_t first_line = 0;  // the file line of row 0 (rows are consecutive lines)
  Digits position_digits, radius_digits;

  // Room for `n` rows (at most 2^24 ahead: the count is the file's word).
  void reserve(std::int64_t n);
  // One row.
  void push(std::int64_t id, std::int32_t type, const double (&pos)[3], double radius) {
    ids.push_back(id);
    if (with_types) types.push_back(type);
    x.push_back(pos[0]);
    y.push_back(pos[1]);
    if (dim == 3) z.push_back(pos[2]);
    r.push_back(radius);
  }
};

// `raw` (consumed) into `frame`'s elements, ids and types in ascending id order, wrapped into the
// periodic box, with its precision. `scaled`: positions are xs ys zs (fractions of the box);
// `box_half`: half a unit of the box bounds' last digit; `from_diameter`: radii are halved diameters.
// Error "<path>:<line>: atom id 7 appears twice (lines 12 and 40)".
void finish_frame(RawAtoms& raw, DumpFrame& frame, const DumpOptions& options, bool scaled, double box_half, bool from_diameter);

}  // namespace nbscope::dump
