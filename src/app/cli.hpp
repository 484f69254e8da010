// nbscope app: a small command-line parser. Flags are taken by name; whatever is left over is an
// error, so every command refuses unknown flags the same way.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace nbscope {

// The most frames any command's --frames runs (headless, replay, gui, verify): one limit for all,
// since a run's memory no longer grows with its length (docs: README "Long runs").
inline constexpr long long kMaxFrames = 100'000'000;

class Args {
 public:
  // Wraps the arguments after the command name; `command` names the command in errors.
  explicit Args(std::vector<std::string> args, std::string command = {})
      : args_(std::move(args)), used_(args_.size(), false), command_(std::move(command)) {}

  // True (and consumed) when `--name` is present.
  bool flag(const std::string& name);
  // The value of `--name VALUE` or `--name=VALUE`; Error when the value is missing.
  std::optional<std::string> value(const std::string& name);
  // Every value of a repeatable `--name VALUE` (or `--name=VALUE`), in order; Error when one is missing.
  std::vector<std::string> values(const std::string& name);
  // True when `--name` or `--name=VALUE` is among the arguments not yet taken; takes nothing.
  [[nodiscard]] bool has(const std::string& name) const;
  // The value of `--name` among the arguments not yet taken (the first one), taking nothing.
  [[nodiscard]] std::optional<std::string> peek(const std::string& name) const;
  // Makes `value` the value of `--name`: the first one not yet taken replaced, else `--name value` added.
  void set(const std::string& name, const std::string& value);
  // Like value(), parsed as an integer in [min, max] ("1e6" is one too); Error names the flag otherwise.
  std::optional<long long> integer(const std::string& name, long long min, long long max);
  // Like value(), parsed as a finite double.
  std::optional<double> number(const std::string& name);
  // The next unconsumed argument not starting with "--", consumed. Taken after every option: an
  // option nobody took is refused first (by its name, so that its value is not blamed instead).
  std::optional<std::string> positional();
  // Error for an option nobody consumed, named as such ("gui: --report is not an option of gui (it
  // is one of headless, replay)"), else for the first argument nobody consumed.
  void finish() const;
  // Error for the first option (an argument starting with "-") nobody consumed.
  void refuse_unknown_options() const;

 private:
  // The index of the first argument from `from` on, not yet taken, that is `--name` or `--name=VALUE`; npos if none.
  [[nodiscard]] std::size_t untaken(const std::string& name, std::size_t from = 0) const;
  // Takes the option at `i` and returns its value (the next argument, or what follows "=").
  std::string take(const std::string& name, std::size_t i);
  void refuse_repeat(const std::string& name) const;

  std::vector<std::string> args_;
  std::vector<bool> used_;
  std::string command_;
};

// Loads the detector plugins of every --detector-lib (after --detector-timeout) when `command` takes
// them, before the command resolves an algorithm name (app/cli_plugins.cpp).
void load_detector_libs(Args& args, const std::string& command);

// The names of a comma-separated list ("nbs,sort"); Error naming `flag` for an empty or repeated name.
std::vector<std::string> split_names(const std::string& flag, const std::string& text);

// The options each command takes ("gui", "headless", "replay", "pairs", "dump", "scaling"), as --help lists
// them; the commands of the ones that take `option` (without any "=VALUE"), comma-separated.
const std::vector<std::pair<const char*, std::vector<const char*>>>& command_options();
std::string commands_taking(const std::string& option);

// "W" "x" "H" into width and height; Error names `flag` otherwise.
void parse_size(const std::string& flag, const std::string& text, int& out_width, int& out_height);
// "X,Y[,Z]" into up to three doubles; Error names `flag` otherwise. Returns the count (2 or 3).
int parse_point(const std::string& flag, const std::string& text, double out[3]);

}  // namespace nbscope
