// nbscope io: a `dump custom` frame's rows as read (file order) and their turn into a DumpFrame:
// ascending ids, repeated ids refused, periodic centres wrapped, the precision band.
#pragma once
#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "io/lammps_dump.hpp"
#include "io/lammps_dump_parse.hpp"

namespace nbscope::dump {

// The atoms of one frame in the columns the frame keeps. LAMMPS numbers atoms 1..N: while every id
// so far is one of 1..NUMBER OF ATOMS, seen once, row id-1 takes it as it is read, and the frame is
// in id order when the last row arrives (no sort, no second pass over memory). The first id outside
// that range packs the rows read so far and the rest are appended, for finish_frame to sort.
struct RawAtoms {
  RawAtoms(int dim, bool with_types) : dim(dim), with_types(with_types) {}
  int dim;
  bool with_types;
  Eigen::ArrayXd x, y, z, r;  // rows [0, size), or slots by id while `by_id`
  // DumpOptions::keep_columns: the ATOMS line's names, and the other columns kept (as x; set before
  // start()) with their names and whether every value was a number (a text column is dropped).
  bool keep_columns = false;
  std::vector<std::string> header, kept_names;
  std::vector<Eigen::ArrayXd> kept_values;
  std::vector<char> kept_numeric;
  std::vector<std::int64_t> ids;  // row -> id (while by_id: empty, slot k is id k + 1)
  std::vector<std::int32_t> types;
  // Each row's place in the file, for messages; while by_id: place + 1 per slot, 0 for a slot not yet filled.
  std::vector<std::uint32_t> file_row;
  Eigen::Index size = 0;
  bool by_id = false;
  std::uint32_t rows_read = 0;
  std::size_t first_line = 0;  // the file line of row 0 (rows are consecutive lines)
  Digits position_digits, radius_digits;

  // Room for `n` rows (NUMBER OF ATOMS), slots by id when `by_id_allowed` (else at most 2^24 ahead).
  void start(std::int64_t n, bool by_id_allowed);
  // One row.
  void push(std::int64_t id, std::int32_t type, const double (&pos)[3], double radius, const double* kept_row = nullptr) {
    Eigen::Index k = 0;
    if (by_id && id >= 1 && id <= x.size() && file_row[static_cast<std::size_t>(id - 1)] == 0) {
      k = static_cast<Eigen::Index>(id - 1);
      file_row[static_cast<std::size_t>(k)] = rows_read + 1;
    } else {
      if (by_id) leave_by_id();
      if (size == x.size()) grow(std::max<Eigen::Index>(1024, 2 * size));
      k = size++;
      ids.push_back(id);
      if (with_types) types.push_back(0);
      file_row.push_back(rows_read);
    }
    ++rows_read;
    if (with_types) types[static_cast<std::size_t>(k)] = type;
    x[k] = pos[0];
    y[k] = pos[1];
    if (dim == 3) z[k] = pos[2];
    r[k] = radius;
    for (std::size_t c = 0; c < kept_values.size(); ++c) kept_values[c][k] = kept_row[c];
  }
  // Columns of `n` rows (not fewer than size).
  void grow(Eigen::Index n);
  // Packs the rows placed by id so far; rows are appended from now on (a repeated id: found by the sort).
  void leave_by_id();
};

// "<path>:<line>: atom id 7 appears twice in the frame of timestep 500 (lines 12 and 40)" for rows a, b.
[[noreturn]] void repeated_id(const RawAtoms& raw, const DumpFrame& frame, std::uint32_t a, std::uint32_t b);

// `raw` (consumed) into `frame`'s elements, ids and types in ascending id order, wrapped into the
// periodic box, with its precision. `scaled`: positions are xs ys zs (fractions of the box);
// `box_half`: half a unit of the box bounds' last digit; `from_diameter`: radii are halved diameters.
// Error "<path>:<line>: atom id 7 appears twice (lines 12 and 40)".
void finish_frame(RawAtoms& raw, DumpFrame& frame, const DumpOptions& options, bool scaled, double box_half, bool from_diameter);

}  // namespace nbscope::dump
