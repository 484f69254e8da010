// nbscope app: the command table. One row per command: its name, run function, one-line summary,
// options (declared data, app/option_spec.hpp: name, argument, default, help line, and the value's
// kind, range, choices and repeat) and long help. main dispatches from it, the one option parser
// (Args, app/cli.hpp) parses each command's arguments from its row, and every help text is printed
// from it (app/help.hpp; docs/cli.md is its Markdown). Options several commands share are groups
// (app/command_table_parts.hpp) that each command's row names.
#pragma once
#include <string>
#include <vector>

#include "app/cli.hpp"

namespace nbscope {

// One command: what main runs and what its help page says.
struct CommandSpec {
  const char* name;                     // "pairs"
  int (*run)(Args& args);               // the exit code: 0 all well, 1 a check failed (2: Error thrown)
  const char* summary;                  // one line for `nbscope --help`
  std::vector<const char*> usage;       // synopsis lines, each "nbscope ..." (continuations indented)
  std::vector<const char*> paragraphs;  // the long help; a paragraph starting with two spaces is preformatted
  std::vector<OptionGroup> groups;      // every option the command takes, under headings (shared groups too)
  std::vector<const char*> examples;    // command lines
  const char* exit_codes;               // what 0, 1 and 2 mean for this command
};

// Every command, in the order `nbscope --help` lists them (and "it is one of ..." names them).
const std::vector<CommandSpec>& command_table();
// The row of `name`; nullptr when no command has that name.
const CommandSpec* find_command(const std::string& name);
// Every option name of `command` across its groups, in page order (hidden ones aside).
std::vector<std::string> option_names(const CommandSpec& command);

// `nbscope algorithms`: lists the detectors (name, dimensions, summary).
int run_algorithms(Args& args);

}  // namespace nbscope
