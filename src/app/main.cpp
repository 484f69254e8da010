// nbscope: entry point. Dispatches to one sub-command and turns errors into exit codes.
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/help.hpp"
#include "core/detector.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "physics/box2d_detector.hpp"
#include "physics/box2d_memory.hpp"

namespace {

int print_algorithms() {
  for (const nbscope::DetectorInfo& d : nbscope::detector_infos()) {
    std::printf("%-7s %-6s %s\n", d.name.c_str(), d.dim3 ? (d.dim2 ? "2D,3D" : "3D") : "2D", d.summary.c_str());
  }
  return 0;
}

bool is_help(const std::string& a) { return a == "--help" || a == "-h" || a == "help"; }

int dispatch(const std::string& command, const std::vector<std::string>& rest, nbscope::Args& args) {
  // `nbscope pairs --help` is a request for help, not an unknown flag.
  if (is_help(command) || (command != "--version" && !rest.empty() && (rest[0] == "--help" || rest[0] == "-h"))) {
    std::fputs(nbscope::kHelpText, stdout);
    return 0;
  }
  if (command == "--version") {
    args.finish();
    std::printf("nbscope %s\n", nbscope::kVersion);
    return 0;
  }
  if (command == "algorithms") {
    args.finish();
    return print_algorithms();
  }
  if (command == "pairs") return nbscope::run_pairs(args);
  if (command == "dump") return nbscope::run_dump(args);
  if (command == "headless") return nbscope::run_headless(args);
  if (command == "gui") return nbscope::run_gui(args);
  if (command == "replay") return nbscope::run_replay(args);
  if (command == "verify") return nbscope::run_verify(args);
  if (command == "scaling") return nbscope::run_scaling_command(args);
  throw nbscope::Error(command + ": unknown command (see nbscope --help)");
}

}  // namespace

int main(int argc, char** argv) {
  // `nbscope` alone, or with flags only (`nbscope --scene F`), is `nbscope gui`.
  const bool implicit_gui = argc == 1 || (std::strncmp(argv[1], "--", 2) == 0 && std::strcmp(argv[1], "--help") != 0 &&
                                          std::strcmp(argv[1], "--version") != 0);
  std::vector<std::string> rest(argv + (implicit_gui ? 1 : 2), argv + argc);
  const std::string command = implicit_gui ? "gui" : argv[1];
  nbscope::Args args(rest, command);
  try {
    nbscope::register_physics_detectors();  // "box2d" joins core's detectors
    nbscope::set_box2d_out_of_memory_cleanup(nbscope::remove_live_temporaries);
    return dispatch(command, rest, args);
  } catch (const nbscope::Error& e) {
    std::fprintf(stderr, "nbscope: error: %s\n", nbscope::printable_line(e.what()).c_str());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "nbscope: error: out of memory (the input is too large for this machine)\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "nbscope: error: internal: %s\n", nbscope::printable_line(e.what()).c_str());
    return 2;
  }
}
