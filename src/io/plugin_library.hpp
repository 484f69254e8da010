// nbscope io: detector plugins (include/nbscope/detector.h) loaded from shared libraries with
// --detector-lib PATH.so: dlopen, the symbols, the checks, registration as a detector like the
// built-ins; and the guard around every call into one, dlopen's constructors included (a crash or a
// hang is one error line naming the library and the call, exit 2).
// docs/plugins.md is the guide; docs/limits.md "Detector plugins" says what is refused and what it costs.
#pragma once
#include <string>
#include <vector>

#include "io/plugin_host.hpp"

namespace nbscope {

// Default of --detector-timeout: the seconds one call into a plugin may take.
inline constexpr double kDefaultDetectorTimeout = 60;

// Opens the library at `path` (RTLD_NOW | RTLD_LOCAL; never closed: its release may run at exit), checks its
// version symbol, its required symbols and its description, and registers its detector; returns the
// detector's name. The same file loaded again is not loaded twice: its name is returned. Throws Error
// "PATH: what" for anything amiss (docs/limits.md "Detector plugins").
std::string load_detector_plugin(const std::string& path);

// The absolute paths of the libraries loaded so far, in load order (the window's settings keep them).
std::vector<std::string> loaded_detector_libraries();

// The seconds one call into a plugin (its load, describe, detect, release, own_bytes) may run before
// the process ends with an error line and exit 2 (0: no limit); for plugins loaded from now on.
void set_detector_timeout(double seconds);

// Where the detectors of libraries loaded from now on run their calls (--detector-isolation; the
// default: PluginIsolation::process, each instance in a host process of its own).
void set_plugin_isolation(PluginIsolation isolation);

}  // namespace nbscope
