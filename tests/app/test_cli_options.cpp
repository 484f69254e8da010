// The one option parser (app/cli.hpp) and the command table it parses from: every kind of bad
// value refused with its one line, an option read that its row does not list caught at once, the
// shared groups on exactly the commands that name them, and each command's reads all in its row.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/command_table.hpp"
#include "app/command_table_parts.hpp"
#include "app/dump_input.hpp"
#include "app/help.hpp"
#include "app/threads_flag.hpp"
#include "core/error.hpp"

namespace nbscope {
namespace {

// The Error (or "") of parsing `args` against `options` and running `reads` on the result.
std::string error_of(const std::vector<std::string>& args, const std::vector<OptionSpec>& options,
                     const std::function<void(Args&)>& reads = [](Args& a) { a.finish(); }) {
  try {
    Args a(args, "test", options);
    reads(a);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

const std::vector<OptionSpec>& test_row() {
  static const std::vector<OptionSpec> row = {
      {"--quiet", "", "", "a flag", flag_value()},
      {"--name", "TEXT", "", "a text"},
      {"--n", "N", "", "an integer", integer_value(1, 10)},
      {"--x", "X", "", "a number", number_value()},
      {"--gap", "G", "", "a number with a range", number_value(0, 2)},
      {"--dt", "S", "", "a number with its own refusal", number_value(0.5, 1, "must be from 0.5 to 1 ({} is not)")},
      {"--mode", "a|b", "", "a choice", choice_value({"a", "b", "c"})},
      {"--how", "a|b", "", "a choice with its own refusal", choice_value({"on", "off"}, "{} is not on or off")},
      {"--file", "F", "", "repeatable", repeated_value()},
  };
  return row;
}

// Every value kind parsed and read; what was not given reads as absent.
TEST(CliOptions, EachKindIsParsedFromItsRow) {
  Args a({"--quiet", "--name", "x y", "--n=7", "--x", "-2.5", "--mode", "c", "--file", "a", "--file=b", "pos"}, "test", test_row());
  EXPECT_TRUE(a.flag("--quiet"));
  EXPECT_EQ(a.value("--name"), "x y");
  EXPECT_EQ(a.integer("--n"), 7);
  EXPECT_EQ(a.number("--x"), -2.5);
  EXPECT_EQ(a.value("--mode"), "c");
  EXPECT_EQ(a.values("--file"), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(a.number("--gap"), std::nullopt);
  EXPECT_EQ(a.value("--how"), std::nullopt);
  EXPECT_EQ(a.number("--dt"), std::nullopt);
  EXPECT_TRUE(a.has("--name"));
  EXPECT_FALSE(a.has("--how"));
  EXPECT_EQ(a.positional(), "pos");
  EXPECT_EQ(a.positional(), std::nullopt);
  EXPECT_NO_THROW(a.finish());
}

// Each bad value, missing value and repeat is refused when parsed, before the command reads anything.
TEST(CliOptions, EachKindsErrorsAreOneLine) {
  const auto parsed = [](const std::vector<std::string>& args) { return error_of(args, test_row(), [](Args&) {}); };
  EXPECT_EQ(parsed({"--name"}), "--name: missing value");
  EXPECT_EQ(parsed({"--quiet=yes"}), "--quiet: takes no value");
  EXPECT_EQ(parsed({"--quiet", "--quiet"}), "--quiet: given more than once");
  EXPECT_EQ(parsed({"--name", "a", "--name=b"}), "--name: given more than once");
  EXPECT_EQ(parsed({"--n", "11"}), "--n: '11' is not a whole number from 1 to 10");
  EXPECT_EQ(parsed({"--n", "two"}), "--n: 'two' is not a whole number from 1 to 10");
  EXPECT_EQ(parsed({"--x", "nan"}), "--x: 'nan' is not a finite number");
  EXPECT_EQ(parsed({"--x", "1e999"}), "--x: '1e999' is not a finite number");
  EXPECT_EQ(parsed({"--gap", "3"}), "--gap: '3' is not a number from 0 to 2");
  EXPECT_EQ(parsed({"--dt", "0.25"}), "--dt: must be from 0.5 to 1 ('0.25' is not)");
  EXPECT_EQ(parsed({"--mode", "d"}), "--mode: 'd' is not one of a, b, c");
  EXPECT_EQ(parsed({"--how", "maybe"}), "--how: 'maybe' is not on or off");
  // The first problem in the arguments' order; a bad value before an unknown option.
  EXPECT_EQ(parsed({"--n", "0", "--mode", "d"}), "--n: '0' is not a whole number from 1 to 10");
  EXPECT_EQ(parsed({"--bogus", "--n", "0"}), "--n: '0' is not a whole number from 1 to 10");
  EXPECT_EQ(parsed({"--bogus", "1"}), "test: --bogus is not an option of test (see nbscope --help)");
  EXPECT_EQ(parsed({"--name", "--n", "3"}), "") << "a value may look like an option";
}

// An option the command's row does not list cannot be read: the read is a programming error, at once,
// whether or not it was given; so is reading an option as another kind than its row says.
TEST(CliOptions, ReadingAnOptionMissingFromTheRowThrows) {
  Args a({"--name", "x"}, "test", test_row());
  EXPECT_THROW(a.value("--scene"), std::logic_error);
  EXPECT_THROW(a.flag("--verbose"), std::logic_error);
  EXPECT_THROW(static_cast<void>(a.has("--scene")), std::logic_error);
  EXPECT_THROW(a.integer("--name"), std::logic_error);
  EXPECT_THROW(a.value("--n"), std::logic_error);
  EXPECT_THROW(a.value("--file"), std::logic_error) << "a repeatable option is read with values()";
  EXPECT_THROW(a.values("--name"), std::logic_error);
  EXPECT_THROW(a.flag("--name"), std::logic_error);
  EXPECT_FALSE(a.offers("--scene"));
  EXPECT_TRUE(a.offers("--name"));
}

// What a command's run reads, given `args`: "" when it stopped at an Error of its own after reading
// (the arguments below are chosen so that each stops before doing any work), the logic_error's text
// when it read an option its row does not list.
std::string run_reads(const CommandSpec& spec, const std::vector<std::string>& args) {
  try {
    Args a(args, spec);
    load_detector_libs(a, spec.name);
    spec.run(a);
  } catch (const std::logic_error& e) {
    return e.what();
  } catch (const Error&) {
  }
  return "";
}

struct StoppingRun {
  const char* command;
  std::vector<std::string> args;  // each run stops with an Error after its options are read
};

const std::vector<StoppingRun>& stopping_runs() {
  static const std::vector<StoppingRun> runs = {
      {"gui", {"--back", "2"}},                                               // --back: needs --frames N
      {"gui", {"--input", "x.csv", "--screenshot", "x.png"}},                 // gui --input: needs --frames
      {"gui", {"--input", "x.csv", "--arrays", "a.json", "--screenshot", "x.png"}},  // gui --arrays: needs --frames
      {"headless", {}},                                                       // --scene is required
      {"headless", {"--scaling", "run"}},                                     // the scaling flags read too
      {"replay", {"--headless"}},                                             // a file is required
      {"pairs", {}},                                                          // --input is required
      {"dump", {}},                                                           // --input is required
      {"verify", {}},                                                         // --input is required
      {"scaling", {"--output", "/nonexistent-dir/x.csv"}},                    // the output's directory is checked
  };
  return runs;
}

// Every read of every command is of an option its row lists: each command's option reading runs
// against its row (a read of an option removed from the table throws, and fails here).
TEST(CliOptions, EveryCommandReadsOnlyOptionsOfItsRow) {
  for (const StoppingRun& r : stopping_runs()) {
    const CommandSpec* spec = find_command(r.command);
    ASSERT_NE(spec, nullptr) << r.command;
    EXPECT_EQ(run_reads(*spec, r.args), "") << r.command;
  }
}

// The row without one option it reads: the command's run fails at that read, naming it.
TEST(CliOptions, AnOptionMissingFromTheTableFailsTheRead) {
  for (const char* removed : {"--repeat", "--threads", "--touching", "--cell-size", "--radius", "--detector-timeout"}) {
    CommandSpec pairs = *find_command("pairs");
    for (OptionGroup& g : pairs.groups)
      g.options.erase(std::remove_if(g.options.begin(), g.options.end(), [&](const OptionSpec& o) { return o.name == std::string(removed); }),
                      g.options.end());
    const std::string error = run_reads(pairs, {});
    EXPECT_NE(error.find(std::string("reads ") + removed + ", which its command-table row does not list"), std::string::npos)
        << removed << ": " << error;
  }
}

// The shared groups are on exactly the commands whose rows name them, each with all its options.
TEST(CliOptions, SharedGroupsAreOnTheCommandsThatNameThem) {
  const auto every_option_on = [](const std::vector<OptionSpec>& group, const std::string& commands) {
    for (const OptionSpec& o : group)
      if (!o.hidden) {
        EXPECT_EQ(commands_taking(o.name), commands) << o.name;
      }
  };
  every_option_on(rendering_options(), "gui, headless, replay, watch, verify");
  every_option_on(plugin_options(), "gui, headless, replay, watch, pairs, dump, scaling, algorithms");
  every_option_on(grid_options(), "gui, pairs, dump, verify");
  every_option_on({gl_option()}, "headless, replay, watch, verify");
  every_option_on({threads_option()}, "gui, headless, replay, watch, pairs, verify, scaling");
  every_option_on({touching_option()}, "gui, headless, replay, watch, pairs, dump, verify, scaling");
  every_option_on({dump_input_options()[0]}, "pairs, dump, verify");  // --timestep: one frame of a dump
  for (const OptionSpec& o : dump_input_options())
    if (std::string(o.name) != "--timestep" && std::string(o.name) != "--contact-ids") {
      EXPECT_EQ(commands_taking(o.name), "gui, replay, watch, pairs, dump, verify") << o.name;
    }
  EXPECT_EQ(commands_taking("--contact-ids"), "replay, watch, pairs, dump, verify") << "hidden on gui: refused with its reason";
  EXPECT_EQ(commands_taking("--dump"), "replay");
}

// Every row says what the parser needs: a flag has no argument and an argument makes a value;
// ranges are ranges; and no option is listed twice in one command.
TEST(CliOptions, EveryRowIsWellFormed) {
  for (const CommandSpec& c : command_table()) {
    std::vector<std::string> names;
    for (const OptionGroup& g : c.groups) {
      for (const OptionSpec& o : g.options) {
        names.emplace_back(o.name);
        EXPECT_EQ(o.value.kind == OptionKind::flag, o.argument[0] == '\0') << c.name << " " << o.name;
        if (o.value.kind == OptionKind::integer) {
          EXPECT_LE(o.value.min, o.value.max) << c.name << " " << o.name;
        }
        if (o.value.kind == OptionKind::number) {
          EXPECT_LE(o.value.low, o.value.high) << c.name << " " << o.name;
        }
        if (o.value.kind == OptionKind::choice) {
          EXPECT_GE(o.value.choices.size(), 2u) << c.name << " " << o.name;
        }
        EXPECT_GT(std::string(o.help).size(), 10u) << c.name << " " << o.name << ": no help line";
      }
    }
    std::sort(names.begin(), names.end());
    EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end()) << c.name;
  }
}

// Each command's page names every option of its row (hidden ones aside), and the summary every command.
TEST(CliOptions, EveryPageNamesItsOptionsAndTheSummaryEveryCommand) {
  const std::string summary = help_summary();
  for (const CommandSpec& c : command_table()) {
    EXPECT_NE(summary.find("\n  " + std::string(c.name) + " "), std::string::npos) << c.name;
    const std::string page = command_help(c);
    for (const std::string& o : option_names(c)) EXPECT_NE(page.find("\n  " + o), std::string::npos) << c.name << " " << o;
  }
  EXPECT_EQ(command_help(*find_command("gui")).find("--contact-ids"), std::string::npos);
}

// The error of parsing `args` against `command`'s row, or "".
std::string parse_error(const std::vector<std::string>& args, const std::string& command) {
  try {
    Args a(args, *find_command(command));
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// The choices and ranges the commands checked by hand are their rows' now, in the same words.
TEST(CliOptions, TheRowsChoicesAndRangesKeepTheirWords) {
  EXPECT_EQ(parse_error({"--touching", "loose"}, "pairs"),
            "--touching: 'loose' is not inclusive (|c_i - c_j| <= r_i + r_j, the default) or strict (<, as LAMMPS and LIGGGHTS)");
  EXPECT_EQ(parse_error({"--detector-isolation", "thread"}, "scaling"), "--detector-isolation: 'thread' is not process or none");
  EXPECT_EQ(parse_error({"--detector-timeout", "-1"}, "pairs"), "--detector-timeout: the seconds must be from 0 (no limit) to 1e6");
  EXPECT_EQ(parse_error({"--gl", "vulkan"}, "headless"), "--gl: 'vulkan' is not one of osmesa, egl, auto");
  EXPECT_EQ(parse_error({"--lists", "rows"}, "verify"), "--lists: 'rows' is not one of all, selected, row");
  EXPECT_EQ(parse_error({"--radius", "0"}, "pairs"), "--radius: must be positive and finite");
  EXPECT_EQ(parse_error({"--tolerance", "-1e-9"}, "verify"), "--tolerance: must be 0 or more (a length)");
  EXPECT_EQ(parse_error({"--dt", "0"}, "replay"), "--dt: must be positive (seconds per timestep)");
  EXPECT_EQ(parse_error({"--threads", "65"}, "scaling"), "--threads: '65' is not a whole number from 1 to 64");
  EXPECT_EQ(parse_error({"--dt", "1e-300", "--touching", "strict", "--gl", "egl"}, "replay"), "");
}

std::string command_error(const std::vector<std::string>& args, const std::string& command, bool positional) {
  try {
    Args a(args, *find_command(command));
    if (a.offers("--scene")) a.value("--scene");
    if (positional) a.positional();
    a.finish();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// An option is named by its name, not blamed through its value (left over as a positional).
TEST(CliOptions, AnOptionNotTakenIsNamed) {
  EXPECT_EQ(command_error({"--report", "x.json"}, "gui", true), "gui: --report is not an option of gui (it is one of headless, replay, watch)");
  EXPECT_EQ(command_error({"--scene", "s.json", "--report=x.json"}, "gui", false),
            "gui: --report is not an option of gui (it is one of headless, replay, watch)");
  EXPECT_EQ(command_error({"--fast", "yes"}, "pairs", false), "pairs: --fast is not an option of pairs (see nbscope --help)");
  EXPECT_EQ(command_error({"--gl", "osmesa", "r.nbsrec"}, "replay", true), "replay: --gl does not apply here (see nbscope --help)");
  EXPECT_EQ(command_error({"extra"}, "gui", false), "extra: unexpected argument (see nbscope --help)");
  EXPECT_EQ(command_error({"--contact-ids", "1,2"}, "gui", false),
            "gui: --contact-ids is not an option of gui (it is one of replay, watch, pairs, dump, verify)")
      << "a hidden option not read is not offered";
}

// The error an integer option in [min, max] gives for `value`, or "" when it takes it (then `*out` is set).
std::string integer_error(const std::string& value, long long min, long long max, long long* out = nullptr) {
  return error_of({"--n", value}, {{"--n", "N", "", "an integer", integer_value(min, max)}}, [out](Args& a) {
    const auto n = a.integer("--n");
    if (out != nullptr) *out = n.value_or(-1);
  });
}

// A whole number is one however it is written: 1e6 and 1000000 are taken alike, and refused alike
// past the limit (the probe found 1e12 refused as "not a whole number" where 1000000000000 passed).
TEST(CliOptions, WholeNumbersWithAnExponentAreTakenAndLimitedAlike) {
  long long n = 0;
  EXPECT_EQ(integer_error("1e6", 1, kMaxFrames, &n), "");
  EXPECT_EQ(n, 1'000'000);
  EXPECT_EQ(integer_error("2.5e3", 1, kMaxFrames, &n), "");
  EXPECT_EQ(n, 2'500);
  EXPECT_EQ(integer_error("1e8", 1, kMaxFrames, &n), "");
  EXPECT_EQ(n, kMaxFrames);
  const std::string past = "--n: '1e12' is not a whole number from 1 to 100000000";
  EXPECT_EQ(integer_error("1e12", 1, kMaxFrames), past);
  EXPECT_EQ(integer_error("1000000000000", 1, kMaxFrames), "--n: '1000000000000' is not a whole number from 1 to 100000000");
  for (const char* bad : {"1.5", "1e-3", "nan", "inf", "1e400", "", "12abc", "0x10", "1e19"})
    EXPECT_NE(integer_error(bad, 0, kMaxFrames), "") << bad;
  const std::string huge(100'000, '9');
  EXPECT_LT(integer_error(huge, 0, kMaxFrames).size(), 120u) << "a huge value is quoted as an excerpt";
}

}  // namespace
}  // namespace nbscope
