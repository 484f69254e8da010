// nbscope io: where the bundled data (assets/, shaders/) is found at run time: an installed tree
// next to the binary, else the source tree baked in at build time (docs/install.md).
#pragma once
#include <string>

namespace nbscope {

// The data directory (it holds assets/ and shaders/) and what chose it.
struct DataDir {
  std::string path;
  std::string origin;  // "$NBSCOPE_DATA_DIR", "installed" or "build tree"
};

// $NBSCOPE_DATA_DIR when set; else BINDIR/../share/nbscope of the running binary (/proc/self/exe)
// when that directory exists; else the source tree the binary was built from.
DataDir data_dir();

// The shader directory and what chose it: $NBSCOPE_SHADER_DIR when set, else data_dir()'s shaders/.
DataDir default_shader_dir();

// `nbscope --version`'s lines after the first: "data: PATH (ORIGIN)" and "shaders: PATH (ORIGIN)",
// so a user (and the install test) sees which copy of the scenes and shaders the binary reads.
std::string data_dirs_text();

// A scene named on the command line: `path` itself when it names a file (or is absolute, or names
// nothing bundled either); else the bundled one, data_dir()/PATH (`assets/scenes/pile.json`) or
// data_dir()/assets/scenes/PATH (`pile.json`), so `--scene default.json` works from any directory.
std::string resolve_scene_path(const std::string& path);

}  // namespace nbscope
