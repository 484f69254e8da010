#include "io/data_dir.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

// src/io/CMakeLists.txt defines both; the fuzz build compiles io's files from fuzz/ without them.
#ifndef NBSCOPE_BUILD_DATA_DIR
#define NBSCOPE_BUILD_DATA_DIR "."
#endif
#ifndef NBSCOPE_INSTALL_DATA_RELATIVE
#define NBSCOPE_INSTALL_DATA_RELATIVE "../share/nbscope"
#endif

namespace nbscope {

namespace {

namespace fs = std::filesystem;

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr && *v != '\0' ? std::string(v) : std::string();
}

// BINDIR/<relative data dir> of the running binary, or "" when the binary was not installed with
// its data (a build tree has no share/nbscope beside it).
std::string installed_data_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec || exe.empty()) return "";
  const fs::path dir = (exe.parent_path() / NBSCOPE_INSTALL_DATA_RELATIVE).lexically_normal();
  return fs::is_directory(dir, ec) ? dir.string() : "";
}

bool is_file(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

}  // namespace

DataDir data_dir() {
  if (std::string dir = env("NBSCOPE_DATA_DIR"); !dir.empty()) return {dir, "$NBSCOPE_DATA_DIR"};
  if (std::string dir = installed_data_dir(); !dir.empty()) return {dir, "installed"};
  return {NBSCOPE_BUILD_DATA_DIR, "build tree"};
}

DataDir default_shader_dir() {
  if (std::string dir = env("NBSCOPE_SHADER_DIR"); !dir.empty()) return {dir, "$NBSCOPE_SHADER_DIR"};
  DataDir data = data_dir();
  return {data.path + "/shaders", data.origin};
}

std::string data_dirs_text() {
  const DataDir data = data_dir();
  const DataDir shaders = default_shader_dir();
  return "data: " + data.path + " (" + data.origin + ")\nshaders: " + shaders.path + " (" + shaders.origin + ")\n";
}

std::string resolve_scene_path(const std::string& path) {
  const fs::path given(path);
  if (path.empty() || given.is_absolute() || is_file(given)) return path;
  const fs::path data(data_dir().path);
  for (const fs::path& bundled : {data / given, data / "assets" / "scenes" / given})
    if (is_file(bundled)) return bundled.string();
  return path;  // the error names what the user wrote
}

}  // namespace nbscope
