// nbscope app: the pieces the command table's two files share (app/command_table.cpp holds the
// window's commands, app/command_table_files.cpp the file commands).
#pragma once
#include <initializer_list>
#include <vector>

#include "app/command_table.hpp"

namespace nbscope {

// The rendering options gui, headless, replay and verify --screenshot share (app/view_options.cpp).
const std::vector<OptionSpec>& rendering_options();
// --cell-size, --origin, --cells: the grid pins of pairs, dump, verify and gui --arrays (app/grid_flags.cpp).
const std::vector<OptionSpec>& grid_options();
// --detector-lib, --detector-timeout: the detector plugins of gui, headless, replay, pairs, dump, scaling, algorithms.
const std::vector<OptionSpec>& plugin_options();
// Their heading on every page that lists them.
inline constexpr const char* kPluginOptionsTitle = "detector plugins (gui, headless, replay, pairs, dump, scaling, algorithms)";
// --gl: the off-screen GL of a screenshot (headless, replay, verify).
OptionSpec gl_option();
// The groups several commands' rows name (each row says which it takes; the table adds none):
// the rendering options, the detector plugins, the dump flags of pairs/dump/verify --input FILE.dump,
// replay's dump flags (--dump, --contacts, --dt and the same), gui --input's.
OptionGroup rendering_group();
OptionGroup plugin_group();
OptionGroup dump_input_group();
OptionGroup dump_replay_group();
OptionGroup gui_input_group();
// `parts` one after another: a group's own options, then shared ones (grid_options(), --threads, --touching).
std::vector<OptionSpec> joined(std::initializer_list<std::vector<OptionSpec>> parts);
// The rows of pairs, dump, verify, scaling and algorithms, in --help order.
std::vector<CommandSpec> file_commands();

}  // namespace nbscope
