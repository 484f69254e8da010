// nbscope app: the one option parser. A command's arguments are parsed against its command-table
// row (app/command_table.hpp: every option's kind, range, choices, repeat) before the command runs:
// an unknown option, a missing or bad value, a value out of range and a repeat are refused there.
// The command then reads typed values by name; a name not in its row is a programming error
// (std::logic_error at the read), so no option is read that the table does not list.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "app/option_spec.hpp"

namespace nbscope {

// The most frames any command's --frames runs (headless, replay, gui, verify): one limit for all,
// since a run's memory no longer grows with its length (docs: README "Long runs").
inline constexpr long long kMaxFrames = 100'000'000;

struct CommandSpec;

class Args {
 public:
  // Parses `args` (the words after the command's name) against `command`'s row, every group.
  Args(std::vector<std::string> args, const CommandSpec& command);
  // Against `options`, for what has no row (help, --version); `command` names it in errors.
  Args(std::vector<std::string> args, std::string command, std::vector<OptionSpec> options);

  // True when the flag `--name` was given.
  bool flag(const std::string& name);
  // The value of `--name VALUE` or `--name=VALUE` (a text or choice option).
  std::optional<std::string> value(const std::string& name);
  // Every value of a repeatable `--name VALUE`, in order.
  std::vector<std::string> values(const std::string& name);
  // The value of an integer option, within its row's range.
  std::optional<long long> integer(const std::string& name);
  // The value of a number option: finite, within its row's range.
  std::optional<double> number(const std::string& name);
  // True when `--name` was given; reads nothing (the option still has to be read, or it does not apply).
  [[nodiscard]] bool has(const std::string& name) const;
  // True when the command's row has `--name` (given or not).
  [[nodiscard]] bool offers(const std::string& name) const;
  // Makes `value` the one value of the text option `--name`, as if it had been given so.
  void set(const std::string& name, const std::string& value);
  // The next argument that is no option and no option's value. Read after every option: an option
  // given but not read is refused first (by its name, so that its value is not blamed instead).
  std::optional<std::string> positional();
  // Error for an option given but not read ("replay: --gl does not apply here (see nbscope --help)"),
  // else for the first argument nobody read.
  void finish() const;

 private:
  struct Given {
    std::vector<std::string> values;  // one "" per time a flag was given
    std::size_t first = 0;            // where in the arguments it was first given
    bool read = false;
  };
  void parse(const std::vector<std::string>& args);
  // The option `name` of the row, marked read; std::logic_error when the row has no such option or
  // it is not of `kind`.
  std::size_t index(const std::string& name) const;
  Given& read(const std::string& name, OptionKind kind);
  void refuse_unread() const;

  std::string command_;
  std::vector<OptionSpec> options_;
  std::vector<Given> given_;  // one per option of options_
  std::vector<std::string> positionals_;
  std::size_t next_positional_ = 0;
};

// Loads the detector plugins of every --detector-lib (after --detector-timeout) when the command's
// row offers them, before the command resolves an algorithm name (app/cli_plugins.cpp).
void load_detector_libs(Args& args, const std::string& command);

// The names of a comma-separated list ("nbs,sort"); Error naming `flag` for an empty or repeated name.
std::vector<std::string> split_names(const std::string& flag, const std::string& text);

// The commands whose rows list `option` (hidden rows aside), comma-separated in the table's order.
std::string commands_taking(const std::string& option);

// "W" "x" "H" into width and height; Error names `flag` otherwise.
void parse_size(const std::string& flag, const std::string& text, int& out_width, int& out_height);
// "X,Y[,Z]" into up to three doubles; Error names `flag` otherwise. Returns the count (2 or 3).
int parse_point(const std::string& flag, const std::string& text, double out[3]);

}  // namespace nbscope
