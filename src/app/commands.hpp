// nbscope app: one function per sub-command (one file each), returning the process exit code:
// 0 all well, 1 a check failed, 2 bad input (thrown as Error and reported by main). Their options,
// usage and help are rows of the command table (app/command_table.hpp; docs/cli.md).
#pragma once
#include "app/cli.hpp"

namespace nbscope {

// `nbscope pairs`: contact pairs of an elements file (app/cmd_pairs.cpp).
int run_pairs(Args& args);

// `nbscope dump`: an algorithm's integer arrays as JSON (app/cmd_dump.cpp).
int run_dump(Args& args);

// `nbscope headless`: a scene's frames with no window, every frame checked (app/cmd_headless.cpp, app/headless.hpp).
int run_headless(Args& args);

// `nbscope replay`: recorded frames detected and checked again (app/cmd_replay.cpp, app/replay.hpp).
int run_replay(Args& args);

// `nbscope watch`: the dumps of a run still being written, each frame checked as it lands (app/cmd_watch.cpp).
int run_watch(Args& args);

// `nbscope scaling`: ns and bytes per element against N (app/cmd_scaling.cpp).
int run_scaling_command(Args& args);

// `nbscope verify`: someone else's pairs or arrays checked (app/cmd_verify.cpp).
int run_verify(Args& args);

// `nbscope [gui]`: the window (app/cmd_gui.cpp); headless with a screenshot when there is no display.
int run_gui(Args& args);

// `nbscope --version`'s line on the window, for scripts that ask whether it was built ("window: yes
// (...)" or "window: no (...)"): cmd_gui.cpp where the window is built, gui_stub.cpp where not.
const char* window_build_line();

}  // namespace nbscope
