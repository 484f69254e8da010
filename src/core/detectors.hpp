// nbscope core: the built-in detectors (one file each) and their registry entries.
#pragma once
#include <vector>

#include "core/detector.hpp"

namespace nbscope {

// The registry entries of core's own detectors, in the order `nbscope algorithms` lists them.
std::vector<DetectorInfo> builtin_detectors();

}  // namespace nbscope
