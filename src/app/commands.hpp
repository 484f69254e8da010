// nbscope app: one function per sub-command (one file each), returning the process exit code:
// 0 all well, 1 a check failed, 2 bad input (thrown as Error and reported by main).
#pragma once
#include "app/cli.hpp"

namespace nbscope {

// `nbscope pairs --input F [--algorithm A] [--output F] [--repeat K]`
int run_pairs(Args& args);

// `nbscope dump --input F --algorithm A [--cell-size D] [--origin X,Y[,Z]] [--cells NX,NY[,NZ]] [--format json]`
int run_dump(Args& args);

// `nbscope headless --scene F [--frames N] [--algorithm A] [--report F] [--inject-fault NAME]` (app/headless.hpp)
int run_headless(Args& args);

// `nbscope replay FILE.nbsrec [--headless] [--frames N] [--algorithm A|a,b|all] [--report F] ...`:
// recorded frames detected and checked again (app/cmd_replay.cpp, app/replay.hpp).
int run_replay(Args& args);

// `nbscope scaling [--algorithm A,B|all] [--layout L,M] [--n MIN..MAX] [--points-per-decade K]
// [--output OUT.csv] [--quiet]`: ns and bytes per element against N (app/cmd_scaling.cpp).
int run_scaling_command(Args& args);

// `nbscope verify --input F (--pairs F | --arrays F [--algorithm A] [--exact]) [--base 1] [grid flags]
// [--screenshot OUT.png]`: someone else's pairs or arrays checked (app/cmd_verify.cpp).
int run_verify(Args& args);

// `nbscope [gui] [--scene F] [--algorithm A] [--frames N --screenshot OUT.png] [--size WxH] ...`:
// the window (app/cmd_gui.cpp); headless with a screenshot when there is no display.
int run_gui(Args& args);

}  // namespace nbscope
