// nbscope app: --threads N, on every command that detects (docs/cli.md): one parser and one option
// row shared by all of them, as --touching is.
#pragma once
#include "app/cli.hpp"
#include "app/command_table.hpp"

namespace nbscope {

// --threads N (default machine_threads()): N a whole number from 1 to kMaxThreads; Error naming the
// flag for anything else ("0", "-1", "two", "65", "").
int take_threads(Args& args);
// --threads' row in the command table.
OptionSpec threads_option();

}  // namespace nbscope
