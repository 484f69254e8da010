// The command table behind "gui: --report is not an option of gui (it is one of headless, replay)"
// and every help page: it names every option the parsers take (read from src/app), each with a help
// line, and nothing they do not take.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/command_table.hpp"
#include "app/help.hpp"
#include "core/error.hpp"

namespace nbscope {
namespace {

// The source files that take options from Args, and the commands whose parser runs each; a file
// that takes options and is not here fails the test (map it). view_options.cpp's --gl is taken only
// off-screen: gui has no --gl.
struct ParserFile {
  const char* file;
  std::vector<std::string> commands;
  std::set<std::string> not_for_gui;
};

const std::vector<ParserFile>& parser_files() {
  static const std::vector<ParserFile> files = {
      {"cmd_pairs.cpp", {"pairs"}, {}},
      {"cmd_dump.cpp", {"dump"}, {}},
      {"cmd_headless.cpp", {"headless"}, {}},
      {"cmd_replay.cpp", {"replay"}, {}},
      {"cmd_scaling.cpp", {"scaling"}, {}},
      {"cmd_verify.cpp", {"verify"}, {}},
      {"verify_run.cpp", {"verify", "gui"}, {}},
      {"cmd_gui.cpp", {"gui"}, {}},
      {"verify_window.cpp", {"gui"}, {}},
      {"grid_flags.cpp", {"pairs", "dump", "verify", "gui"}, {}},
      {"dump_input.cpp", {"replay", "pairs", "dump", "verify", "gui"}, {"--contact-ids"}},
      {"input_window.cpp", {"gui"}, {}},
      {"touching_flag.cpp", {"gui", "headless", "replay", "pairs", "dump", "verify", "scaling"}, {}},
      {"threads_flag.cpp", {"gui", "headless", "replay", "pairs", "verify", "scaling"}, {}},
      {"view_options.cpp", {"headless", "replay", "verify", "gui"}, {"--gl"}},
      {"scaling_flags.cpp", {"scaling", "headless"}, {}},
      {"cli_plugins.cpp", {"gui", "headless", "replay", "pairs", "dump", "scaling", "algorithms"}, {}},  // from main
      {"help.cpp", {}, {}},  // `help --markdown`, hidden: not a command's option
  };
  return files;
}

// The option names `source` hands to Args: the "--name" literal of every args.value/values/flag/
// integer/number/has call. No std::regex: GCC 12's -O1 sanitizer build warns inside it (maybe-uninitialized),
// and CI builds -Werror.
std::set<std::string> options_taken(const std::string& source) {
  std::set<std::string> out;
  const auto word_char = [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'; };
  for (const char* call : {".value(\"--", ".values(\"--", ".flag(\"--", ".integer(\"--", ".number(\"--", ".has(\"--"}) {
    const std::string needle = call;
    for (std::size_t i = source.find(needle); i != std::string::npos; i = source.find(needle, i + 1)) {
      std::size_t begin = i + needle.size() - 2, end = begin + 2;
      while (end < source.size() && word_char(source[end])) ++end;
      out.insert(source.substr(begin, end - begin));
    }
  }
  return out;
}

std::string read_source(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every option a parser takes is in the table, with a help line, under each command that runs the
// parser; every option of the table is taken by one of the command's parsers. An option added to a
// parser without a line in the table fails here (and would be refused at run time as unknown).
TEST(CliOptions, TheTableNamesEveryOptionTheParsersTake) {
  const std::string dir = std::string(NBSCOPE_SOURCE_DIR) + "/src/app";
  std::map<std::string, std::set<std::string>> taken;  // by command
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".cpp") continue;
    const std::string file = entry.path().filename().string();
    const std::set<std::string> names = options_taken(read_source(entry.path().string()));
    if (names.empty()) continue;
    const auto row = std::find_if(parser_files().begin(), parser_files().end(), [&](const ParserFile& p) { return file == p.file; });
    ASSERT_NE(row, parser_files().end()) << file << " takes options: add it to parser_files() with the commands that run it";
    for (const std::string& command : row->commands) {
      const CommandSpec* spec = find_command(command);
      ASSERT_NE(spec, nullptr) << command;
      const std::vector<std::string> table = option_names(*spec);
      for (const std::string& name : names) {
        if (command == "gui" && row->not_for_gui.count(name)) continue;
        taken[command].insert(name);
        EXPECT_NE(std::find(table.begin(), table.end(), name), table.end())
            << file << " takes " << name << " for " << command << ": give it a line in the command table";
      }
    }
  }
  for (const CommandSpec& c : command_table()) {
    for (const OptionGroup& g : c.groups) {
      for (const OptionSpec& o : g.options) {
        EXPECT_TRUE(taken[c.name].count(o.name)) << c.name << " " << o.name << " is in the table, but no parser of " << c.name << " takes it";
        EXPECT_GT(std::string(o.help).size(), 10u) << c.name << " " << o.name << ": no help line";
      }
    }
  }
}

// Each command's page names every option of its row, and the summary every command.
TEST(CliOptions, EveryPageNamesItsOptionsAndTheSummaryEveryCommand) {
  const std::string summary = help_summary();
  for (const CommandSpec& c : command_table()) {
    EXPECT_NE(summary.find("\n  " + std::string(c.name) + " "), std::string::npos) << c.name;
    const std::string page = command_help(c);
    for (const std::string& o : option_names(c)) EXPECT_NE(page.find("\n  " + o), std::string::npos) << c.name << " " << o;
    // An option given twice in one row would be listed twice and taken once.
    std::vector<std::string> names = option_names(c);
    std::sort(names.begin(), names.end());
    EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end()) << c.name;
  }
}

std::string error_of(std::vector<std::string> args, const std::string& command, bool positional) {
  Args a(std::move(args), command);
  a.value("--scene");
  try {
    if (positional) a.positional();
    a.finish();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// An option is named by its name, not blamed through its value (left over as a positional).
TEST(CliOptions, AnOptionNotTakenIsNamed) {
  EXPECT_EQ(error_of({"--report", "x.json"}, "gui", true), "gui: --report is not an option of gui (it is one of headless, replay)");
  EXPECT_EQ(error_of({"--scene", "s.json", "--report=x.json"}, "gui", false),
            "gui: --report is not an option of gui (it is one of headless, replay)");
  EXPECT_EQ(error_of({"--fast", "yes"}, "pairs", false), "pairs: --fast is not an option of pairs (see nbscope --help)");
  EXPECT_EQ(error_of({"--gl", "osmesa", "r.nbsrec"}, "replay", true), "replay: --gl does not apply here (see nbscope --help)");
  EXPECT_EQ(error_of({"extra"}, "gui", false), "extra: unexpected argument (see nbscope --help)");
}

// The error Args::integer gives for `value` in [min, max], or "" when it takes it (then `*out` is set).
std::string integer_error(const std::string& value, long long min, long long max, long long* out = nullptr) {
  Args args({"--n", value}, "test");
  try {
    const auto n = args.integer("--n", min, max);
    if (out != nullptr) *out = n.value_or(-1);
    return "";
  } catch (const Error& e) {
    return e.what();
  }
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
