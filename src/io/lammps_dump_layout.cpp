// nbscope io: a `dump custom` ATOMS line's columns (lammps_dump_layout.hpp).
#include "io/lammps_dump_layout.hpp"

#include "core/error.hpp"
#include "io/lammps_dump_parse.hpp"

namespace nbscope::dump {

Layout layout_of(std::string_view names_line, const std::string& at, const DumpOptions& options) {
  Layout lay;
  for (std::string_view w : dump::words_of(names_line)) lay.names.emplace_back(w);
  lay.roles.assign(lay.names.size(), Column::kOther);
  const auto find = [&](const std::string& name) {
    for (std::size_t c = 0; c < lay.names.size(); ++c)
      if (lay.names[c] == name) return static_cast<int>(c);
    return -1;
  };
  const int id = find("id");
  if (id < 0) throw Error(at + "ITEM: ATOMS has no `id` column (nbscope names elements by their atom ids)");
  lay.roles[static_cast<std::size_t>(id)] = Column::kId;
  if (const int t = find("type"); t >= 0) {
    lay.roles[static_cast<std::size_t>(t)] = Column::kType;
    lay.has_type = true;
  }
  bool found = false;
  for (const char* suffix : {"", "u", "s", "su"}) {
    const int x = find(std::string("x") + suffix), y = find(std::string("y") + suffix), z = find(std::string("z") + suffix);
    if (x < 0 || y < 0) continue;
    lay.roles[static_cast<std::size_t>(x)] = Column::kX;
    lay.roles[static_cast<std::size_t>(y)] = Column::kY;
    lay.has_z = z >= 0 && !options.force_2d;
    if (lay.has_z) lay.roles[static_cast<std::size_t>(z)] = Column::kZ;
    lay.scaled = std::string_view(suffix).find('s') != std::string_view::npos;
    found = true;
    break;
  }
  if (!found) throw Error(at + "ITEM: ATOMS has no position columns (x y [z], xu yu [zu], xs ys [zs] or xsu ysu [zsu])");
  for (Column c : {Column::kRadius, Column::kDiameter}) {
    const int k = find(kColumnName[static_cast<int>(c)]);
    if (k < 0) continue;
    lay.roles[static_cast<std::size_t>(k)] = c;
    lay.radius = c;
    break;
  }
  if (lay.radius == Column::kOther && !options.radius && (options.type_radius.empty() || !lay.has_type))
    throw Error(at + "no radius: ITEM: ATOMS has no radius or diameter column; give --radius R" +
                (lay.has_type ? " or --type-radius TYPE:R,..." : ""));
  lay.kept.assign(lay.names.size(), -1);
  if (options.keep_columns)
    for (std::size_t c = 0; c < lay.names.size(); ++c) {
      const bool position = lay.names[c].size() <= 3 && (lay.names[c][0] == 'x' || lay.names[c][0] == 'y' || lay.names[c][0] == 'z') &&
                            lay.names[c].find_first_not_of("xyzsu") == std::string::npos;
      if (lay.roles[c] != Column::kOther || position) continue;  // xu beside x: a position all the same
      lay.kept[c] = static_cast<int>(lay.kept_names.size());
      lay.kept_names.push_back(lay.names[c]);
    }
  return lay;
}

}  // namespace nbscope::dump
