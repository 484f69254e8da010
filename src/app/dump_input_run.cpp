// What a dump run is, found in its files before it is read: a data file among them, its units (the
// data file's header, or LAMMPS's log), and whether it is a `dimension 2` run (app/dump_input.hpp).
#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/dump_input.hpp"
#include "core/error.hpp"
#include "io/excerpt.hpp"
#include "io/input_source.hpp"
#include "io/lammps_data.hpp"

namespace nbscope {

namespace {

// Every file `inputs` names (globs expanded; a name that matches nothing is left to the reader's error).
std::vector<std::string> files_of(const std::vector<std::string>& inputs) {
  std::vector<std::string> out;
  for (const std::string& spec : inputs) {
    try {
      for (std::string& p : expand_dump_spec("--dump", spec)) out.push_back(std::move(p));
    } catch (const Error&) {
      out.push_back(spec);
    }
  }
  return out;
}

bool regular_file(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

// The `units`, `timestep` and `boundary` commands of a LAMMPS log (the last of each before the first `run`).
struct LogFacts {
  std::string units;
  std::optional<double> timestep;
  std::optional<std::array<bool, 3>> periodic;  // `boundary p f p`: the axes whose first word is p
};

LogFacts read_log(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("--log: " + path + ": cannot be read");
  LogFacts facts;
  std::string line;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    std::istringstream words(line.substr(0, line.find('#')));
    std::string command, value;
    if (!(words >> command >> value)) continue;
    if (command == "units") {
      if (!units_named(value))
        throw Error(path + ":" + std::to_string(n) + ": units '" + excerpt(value) + "': nbscope knows lj, real, metal, si, cgs, electron, micro and nano");
      facts.units = value;
    } else if (command == "timestep") {
      try {
        const double dt = std::stod(value);
        if (dt > 0) facts.timestep = dt;
      } catch (const std::logic_error&) {
        // `timestep ${dt}`: a variable; --dt gives it
      }
    } else if (command == "boundary") {
      std::array<bool, 3> axes{value == "p", false, false};
      std::string y, z;
      words >> y >> z;
      axes[1] = y == "p";
      axes[2] = z == "p";
      facts.periodic = axes;
    } else if (command == "run") {
      break;  // the frames' settings are those of the first run
    }
  }
  return facts;
}

}  // namespace

bool is_data_file(const std::string& path) {
  std::string head;
  try {
    head = peek_input(path, 4096, "input file");  // a pipe keeps these bytes for the reader
  } catch (const Error&) {
    return false;
  }
  return head.rfind("ITEM:", 0) != 0 && looks_like_lammps_data(head);
}

Units settle_units_and_log(DumpFlags& flags, const std::vector<std::string>& inputs) {
  std::optional<LogFacts> log;
  if (flags.log) {
    log = read_log(*flags.log);
    if (!flags.dt && log->timestep) flags.dt = log->timestep;
  }
  const std::vector<std::string> files = files_of(inputs);
  if (log && log->periodic && !flags.options.periodic && std::any_of(files.begin(), files.end(), is_data_file))
    flags.options.periodic = log->periodic;
  // The dumps' heads: ITEM: UNITS (in the run's first frame only, whichever file holds it by name) and
  // whether the frames carry ITEM: TIME.
  const auto dump = [](const std::string& p) { return regular_file(p) && is_dump_file(p); };
  const DumpHead head = !files.empty() && dump(files.front()) ? read_dump_head(files.front()) : DumpHead{};
  std::string units_in = files.empty() ? "" : files.front();
  DumpHead units_head = head;
  if (!flags.units)
    for (std::size_t k = 1; k < files.size() && units_head.units.empty(); ++k)
      if (dump(files[k])) {
        units_head = read_dump_head(files[k]);
        units_in = files[k];
      }
  std::string name = flags.units.value_or("");
  const auto known = [](const std::string& units, const std::string& where) {
    if (!units_named(units))
      throw Error(where + ": units '" + excerpt(units) + "': nbscope knows lj, real, metal, si, cgs, electron, micro and nano (--units names them)");
    return units;
  };
  if (name.empty() && !units_head.units.empty()) name = known(units_head.units, units_in);
  if (name.empty())
    for (const std::string& p : files) {
      if (!is_data_file(p)) continue;
      const std::string units = lammps_data_units(peek_input(p, 4096, "input file"));
      if (!units.empty()) {
        name = known(units, p + ":1");
        break;
      }
    }
  if (name.empty() && log) name = log->units;
  if (name.empty()) return Units{};
  Units units = *units_named(name);
  // Without a dt (--dt, the log's) or ITEM: TIME, a dump's or data file's time is its timestep: say so, not tau.
  const bool timesteps = std::any_of(files.begin(), files.end(), [](const std::string& p) { return is_dump_file(p) || is_data_file(p); });
  if (!flags.dt && timesteps && !head.has_time) units.time = "steps";
  return units;
}

std::string planar_note(const std::string& path) {
  return "note: " + path + ": every z is 0 in a thin z box (a `dimension 2` run): read as 2D, as --2d does";
}

std::string settle_planar(DumpFlags& flags, const std::vector<std::string>& inputs) {
  if (flags.options.force_2d) return "";
  const std::vector<std::string> files = files_of(inputs);
  if (files.empty() || !regular_file(files.front())) return "";
  const std::string& path = files.front();
  if (!is_dump_file(path) && !is_data_file(path)) return "";  // ELEMENTS.csv: its dimension is its columns'
  const std::optional<DumpFrame> probe =
      is_data_file(path) ? read_lammps_data(path, flags.options) : first_z_periodic_frame(path, flags.options);
  if (!probe || !is_planar(*probe)) return "";
  flags.options.force_2d = true;
  return planar_note(path);
}

}  // namespace nbscope
