// nbscope app: the help texts, all printed from the command table (app/command_table.hpp), and the
// version. `nbscope --help` is one screen; `nbscope COMMAND --help` one command's page; the hidden
// `nbscope help --markdown` is docs/cli.md.
#pragma once
#include <string>

#include "app/cli.hpp"
#include "app/command_table.hpp"

namespace nbscope {

inline constexpr const char* kVersion = "0.1.0";

// `nbscope --help`: every command with its summary, the global options, where to read more.
std::string help_summary();
// `nbscope COMMAND --help`: usage, what it does, every option (argument, default, help), examples, exit codes.
std::string command_help(const CommandSpec& command);
// docs/cli.md: the summary and every command's page as Markdown.
std::string cli_markdown();
// `nbscope help [COMMAND] [--markdown]`: prints one of the three; Error for an unknown command.
int run_help(Args& args);
// help's one option, --markdown (hidden: it writes docs/cli.md), for the parser.
OptionSpec help_markdown_option();

}  // namespace nbscope
