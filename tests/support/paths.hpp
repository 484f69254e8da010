// nbscope tests: paths into the source tree (NBSCOPE_SOURCE_DIR is baked in by CMake).
#pragma once
#include <string>

namespace nbscope::testpaths {

// assets/scenes/NAME.json of the source tree.
inline std::string scene(const std::string& name) { return std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/" + name + ".json"; }

// assets/examples/nine.csv: the nine elements of the book's Fig. 3.15.
inline std::string nine_csv() { return std::string(NBSCOPE_SOURCE_DIR) + "/assets/examples/nine.csv"; }

}  // namespace nbscope::testpaths
