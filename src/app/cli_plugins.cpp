// --detector-lib and --detector-timeout (cli.hpp): the plugins load before any algorithm name is
// resolved, so --algorithm, --compare lanes, the Algorithm panel and `nbscope algorithms` see them
// as they see the built-ins.
#include "app/cli.hpp"
#include "core/error.hpp"
#include "io/plugin_library.hpp"

namespace nbscope {

void load_detector_libs(Args& args, const std::string& command) {
  if ((", " + commands_taking("--detector-lib") + ", ").find(", " + command + ", ") == std::string::npos) return;
  if (const auto seconds = args.number("--detector-timeout")) {
    if (*seconds < 0 || *seconds > 1e6) throw Error("--detector-timeout: the seconds must be from 0 (no limit) to 1e6");
    set_detector_timeout(*seconds);
  }
  for (const std::string& path : args.values("--detector-lib")) load_detector_plugin(path);
}

}  // namespace nbscope
