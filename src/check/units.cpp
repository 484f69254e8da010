#include "check/units.hpp"

#include <cstdio>

namespace nbscope {

namespace {

std::string with_unit(double value, const char* format, const std::string& unit) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, value);
  return unit.empty() ? std::string(buf) : std::string(buf) + " " + unit;
}

// LAMMPS's `units` styles (its manual's table): the length and time unit of each.
const Units kUnits[] = {
    {"lj", "sigma", "tau"},        {"real", "Angstrom", "fs"},         {"metal", "Angstrom", "ps"}, {"si", "m", "s"},
    {"cgs", "cm", "s"},            {"electron", "Bohr", "fs"},         {"micro", "micrometre", "microsecond"},
    {"nano", "nm", "ns"},
};

}  // namespace

std::string Units::length_text(double value, const char* format, bool unit_when_own) const {
  return with_unit(value, format, name.empty() && !unit_when_own ? "" : length);
}

std::string Units::time_text(double value, const char* format) const { return with_unit(value, format, time); }

std::string Units::description() const {
  if (name.empty()) return "";
  const std::optional<Units> own = units_named(name);
  if (own && own->time != time)  // the frames' times are timesteps
    return "units " + name + " (lengths in " + length + "; times in " + time + ": --dt or --log gives them in " + own->time + ")";
  return "units " + name + " (lengths in " + length + ", times in " + time + ")";
}

std::optional<Units> units_named(std::string_view name) {
  for (const Units& u : kUnits)
    if (u.name == name) return u;
  return std::nullopt;
}

const std::vector<std::string>& unit_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const Units& u : kUnits) v.push_back(u.name);
    return v;
  }();
  return names;
}

}  // namespace nbscope
