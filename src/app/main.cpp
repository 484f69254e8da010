// nbscope: entry point. Dispatches to one sub-command of the command table (app/command_table.hpp)
// and turns errors into exit codes.
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "app/command_table.hpp"
#include "app/commands.hpp"
#include "app/help.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/data_dir.hpp"
#include "physics/box2d_detector.hpp"
#include "physics/box2d_memory.hpp"

namespace {

bool is_help(const std::string& a) { return a == "--help" || a == "-h" || a == "help"; }

int dispatch(const std::string& command, const std::vector<std::string>& rest) {
  if (is_help(command)) {  // `nbscope help [COMMAND]`, `nbscope --help`
    nbscope::Args args(rest, "help", {nbscope::help_markdown_option()});
    return nbscope::run_help(args);
  }
  if (command == "--version") {
    nbscope::Args args(rest, command, {});
    args.finish();
    std::printf("nbscope %s\n%s\n", nbscope::kVersion, nbscope::window_build_line());
    std::fputs(nbscope::data_dirs_text().c_str(), stdout);  // which scenes and shaders it reads
    return 0;
  }
  const nbscope::CommandSpec* spec = nbscope::find_command(command);
  if (spec == nullptr) throw nbscope::Error(command + ": unknown command (see nbscope --help)");
  // `nbscope pairs --help` is a request for that command's page, not an unknown flag.
  if (!rest.empty() && (rest[0] == "--help" || rest[0] == "-h")) {
    std::fputs(nbscope::command_help(*spec).c_str(), stdout);
    return 0;
  }
  nbscope::Args args(rest, *spec);  // every option parsed from the command's row (app/cli.hpp)
  nbscope::load_detector_libs(args, command);  // before any algorithm name is resolved
  return spec->run(args);
}

}  // namespace

int main(int argc, char** argv) {
  // `nbscope` alone, or with flags only (`nbscope --scene F`), is `nbscope gui`.
  const bool implicit_gui = argc == 1 || (std::strncmp(argv[1], "--", 2) == 0 && std::strcmp(argv[1], "--help") != 0 &&
                                          std::strcmp(argv[1], "--version") != 0);
  const std::vector<std::string> rest(argv + (implicit_gui ? 1 : 2), argv + argc);
  const std::string command = implicit_gui ? "gui" : argv[1];
  try {
    nbscope::register_physics_detectors();  // "box2d" joins core's detectors
    nbscope::set_box2d_out_of_memory_cleanup(nbscope::remove_live_temporaries);
    return dispatch(command, rest);
  } catch (const nbscope::DetectorBug& e) {
    std::fprintf(stderr, "nbscope: error: %s\n", nbscope::printable_line(e.what()).c_str());
    return 1;  // the detector's own bug, as a violation ends a run
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
