// nbscope tests: run the nbscope binary and capture its exit code, stdout and stderr.
#pragma once
#include <string>

namespace nbscope::testcli {

struct Result {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Path of the nbscope binary under test (baked in by CMake).
const std::string& binary();
// Runs `nbscope <args>` through the shell (args are shell words) with stdin from /dev/null, after
// `prefix` when given (an environment assignment such as x_display.hpp's on_display(), or a wrapper).
Result run(const std::string& args, const std::string& prefix = "");
// Runs the shell line `command` (stdin from /dev/null; it must not redirect stdout or stderr itself),
// its stdout and stderr captured through the files `out` and `err`, which are left in place.
Result run_shell(const std::string& command, const std::string& out, const std::string& err);
// A fresh empty directory for one test's files.
std::string scratch_dir(const std::string& test_name);
// Writes `text` to `path`.
void write_text(const std::string& path, const std::string& text);
// Reads a whole file ("" if missing).
std::string read_text(const std::string& path);

}  // namespace nbscope::testcli
