// nbscope io (internal): a `dump custom` ATOMS line's columns: which is the id, the type, the
// position (x, xu, xs, xsu), the radius or diameter, and which others are kept (lammps_dump.cpp).
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "io/lammps_dump.hpp"

namespace nbscope::dump {

enum class Column : std::uint8_t { kOther, kId, kType, kX, kY, kZ, kRadius, kDiameter };
inline const char* const kColumnName[] = {"", "id", "type", "x", "y", "z", "radius", "diameter"};

// The ATOMS line's columns: which one is what, and which position columns (x, xu, xs, xsu).
struct Layout {
  std::vector<Column> roles;
  std::vector<std::string> names;
  bool scaled = false;
  bool has_z = false, has_type = false;
  Column radius = Column::kOther;  // kRadius, kDiameter, or kOther: from the options
  std::vector<int> kept;            // DumpOptions::keep_columns: each kOther column's place among the kept, else -1
  std::vector<std::string> kept_names;
};

// The columns of the ATOMS line `names_line` (after "ITEM: ATOMS"); Error at `at` for no `id`, no
// positions, or no radius where the options give none.
Layout layout_of(std::string_view names_line, const std::string& at, const DumpOptions& options);

}  // namespace nbscope::dump
