#include "support/run_cli.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace nbscope::testcli {

const std::string& binary() {
  static const std::string path = NBSCOPE_BIN;
  return path;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string scratch_dir(const std::string& test_name) {
  const auto dir = std::filesystem::path(NBSCOPE_TEST_OUT) / test_name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

Result run_shell(const std::string& command, const std::string& out, const std::string& err) {
  const std::string cmd = command + " </dev/null >'" + out + "' 2>'" + err + "'";
  const int status = std::system(cmd.c_str());
  Result r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

Result run(const std::string& args, const std::string& prefix) {
  static int counter = 0;
  const std::string base = scratch_dir("cli_capture_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  Result r = run_shell((prefix.empty() ? "" : prefix + " ") + "'" + binary() + "' " + args, base + "/out", base + "/err");
  std::filesystem::remove_all(base);
  return r;
}

}  // namespace nbscope::testcli
