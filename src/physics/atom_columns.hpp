// nbscope physics: a dump frame's per-atom columns beyond its elements (type, vx, proc, ...), which
// travel with the frame (Frame::columns) to --color-by and --export-vtk (docs/export.md).
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace nbscope {

struct AtomColumns {
  // Every column the ATOMS line names, in its order (what an unknown --color-by name is told).
  std::vector<std::string> header;
  // The columns kept, by name: `type` first when the dump has one, then every other numeric column
  // but id, the positions and the radius (those are the elements'); values[c][row] in the frame's rows.
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;

  // The values of column `name`, or null when it is not kept.
  [[nodiscard]] const std::vector<double>* find(std::string_view name) const {
    for (std::size_t c = 0; c < names.size(); ++c)
      if (names[c] == name) return &values[c];
    return nullptr;
  }
  // True when the ATOMS line names `name`.
  [[nodiscard]] bool has(std::string_view name) const {
    for (const std::string& h : header)
      if (h == name) return true;
    return false;
  }
};

}  // namespace nbscope
