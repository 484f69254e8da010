// nbscope tests: a real LAMMPS run (`lmp`, Debian's `lammps`) in a directory of the test's own, for
// the tests that read what LAMMPS writes. Missing lmp: the caller skips, unless CI=true (CI must run it).
#pragma once
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace nbscope::testlammps {

// True when `lmp` is on PATH.
inline bool have_lmp() { return std::system("command -v lmp >/dev/null 2>&1") == 0; }

// True when CI=true: a test that needs lmp fails there instead of skipping.
inline bool ci() {
  const char* c = std::getenv("CI");
  return c != nullptr && std::string(c) == "true";
}

// A fresh directory for one test's run (emptied first).
inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("nbscope-lmp-" + name + "-" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Writes `input` to DIR/in.lmp and runs lmp there (its log echoing the commands, as by default, into
// DIR/log.lammps); true when lmp exited 0.
inline bool run_lmp(const std::filesystem::path& dir, const std::string& input) {
  std::ofstream(dir / "in.lmp") << input;
  const std::string cmd = "cd '" + dir.string() + "' && lmp -in in.lmp -log log.lammps -screen /dev/null >lmp.out 2>&1";
  return std::system(cmd.c_str()) == 0;
}

}  // namespace nbscope::testlammps

// Skips the test when lmp is missing (fails under CI=true).
#define NBSCOPE_NEED_LMP()                                                                  \
  do {                                                                                      \
    if (!nbscope::testlammps::have_lmp()) {                                                 \
      if (nbscope::testlammps::ci()) FAIL() << "lmp is not installed (CI=true: this test must run)"; \
      GTEST_SKIP() << "lmp is not installed (apt-get install lammps)";                      \
    }                                                                                       \
  } while (false)
