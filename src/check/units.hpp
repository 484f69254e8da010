// nbscope check: the units a run's lengths and times are in (LAMMPS's `units` command: lj, real,
// metal, si, cgs, micro, nano), and the one formatter every report and panel prints them with.
// A scene and a .nbsrec have none: nbscope's own metres and seconds.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace nbscope {

struct Units {
  std::string name;          // "lj", "real", ...; "" for nbscope's own (m, s)
  std::string length = "m";  // "sigma", "Angstrom", ...
  std::string time = "s";    // "tau", "fs", ...; "steps" for a run whose times are its timesteps (no dt known)

  // "1.5 sigma": `value` printed with `format` (a printf format of one double), then the length unit;
  // without `unit_when_own`, nbscope's own metres are left out ("1.5": where a scene never showed them).
  [[nodiscard]] std::string length_text(double value, const char* format = "%.3g", bool unit_when_own = true) const;
  // "5 tau": the same with the time unit.
  [[nodiscard]] std::string time_text(double value, const char* format = "%.3g") const;
  // "units lj (lengths in sigma, times in tau)"; "" for nbscope's own.
  [[nodiscard]] std::string description() const;
};

// The units LAMMPS calls `name`; none for another name.
std::optional<Units> units_named(std::string_view name);
// The names units_named knows, in the order the command line lists them.
const std::vector<std::string>& unit_names();

}  // namespace nbscope
