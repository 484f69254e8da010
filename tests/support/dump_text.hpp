// nbscope tests: LAMMPS dump text for the dump readers' tests: a frame's text, a temporary folder,
// a file written whole, and the message an Error carries.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"

namespace nbscope::testdump {

// A fresh empty folder under the system's temporary one, named for the test and the process.
inline std::string temp_dir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("nbscope-dump-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

inline void write_file(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// A `dump custom` frame's header, then `rows` (one atom a line).
inline std::string frame(long timestep, int atoms, const std::string& columns, const std::string& rows,
                         const std::string& bounds = "pp pp pp", const std::string& box = "0 1\n0 1\n0 1\n") {
  return "ITEM: TIMESTEP\n" + std::to_string(timestep) + "\nITEM: NUMBER OF ATOMS\n" + std::to_string(atoms) + "\nITEM: BOX BOUNDS " +
         bounds + "\n" + box + "ITEM: ATOMS " + columns + "\n" + rows;
}

inline const std::string kColumns = "id type x y z radius";

// The message of the Error `f` throws ("" when it throws none).
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace nbscope::testdump
