// nbscope io: a LAMMPS data file (`write_data`) read as one frame, as a `dump custom` frame is (docs/formats.md).
//
//   LAMMPS data file via write_data, version 29 Sep 2021, timestep = 5000[, units = lj]   the title line
//   240 atoms                     header lines: counts, `xlo xhi`, `ylo yhi`, `zlo zhi` (`xy xz yz` refused)
//   0 20 xlo xhi
//   Atoms # sphere                id type diameter density x y z [ix iy iz]   (style `atomic`: id type x y z [ix iy iz])
//   Velocities, Masses, ...       any other section is skipped
//
// Radii are half the diameters (sphere), or --type-radius / --radius (atomic). The box has no
// boundary flags in a data file: an axis is periodic when an atom's image flag on it is not 0, or
// when --periodic names it.
#pragma once
#include <string>
#include <string_view>

#include "io/lammps_dump.hpp"

namespace nbscope {

// True when `head` (a file's first bytes) is a LAMMPS data file: write_data's title, or a header line
// `N atoms` among its first lines (a data file's title is free text).
bool looks_like_lammps_data(std::string_view head);

// The `units = X` of write_data's title, the first line of `head` ("" when it has none).
std::string lammps_data_units(std::string_view head);

// The frame of the data file `path` (text or gzip): ids and types kept, rows in ascending id order,
// `timestep` from the title's `timestep = N` (else 0). `units` (when not null) gets the title's
// `units = X`, or "" when it has none. Error "<path>:<line>: <what>" for: no `atoms` header line, no
// Atoms section, an Atoms line without `# style` or of a style other than sphere and atomic, a triclinic
// box, a row with another column count, a non-number, NaN/Inf, a diameter <= 0, an atomic file without
// --radius/--type-radius for a type, fewer or more rows than `N atoms`, a repeated id.
DumpFrame read_lammps_data(const std::string& path, const DumpOptions& options, std::string* units = nullptr);
// The same from memory; `where` names it in messages.
DumpFrame parse_lammps_data(const std::string& text, const std::string& where, const DumpOptions& options,
                            std::string* units = nullptr);

}  // namespace nbscope
