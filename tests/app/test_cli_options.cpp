// The option table behind "gui: --report is not an option of gui (it is one of headless, replay)"
// agrees with --help: every option --help lists under a command is in that command's row, and
// every option of a row is in --help under that command.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/help.hpp"
#include "core/error.hpp"

namespace nbscope {
namespace {

// Every "--name" word of `line` (a letter after the dashes, then letters, digits and dashes). No
// std::regex: GCC 12's -O1 sanitizer build warns inside it (maybe-uninitialized), and CI builds -Werror.
std::vector<std::string> option_words(const std::string& line) {
  std::vector<std::string> out;
  const auto word_char = [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'; };
  for (std::size_t i = line.find("--"); i != std::string::npos; i = line.find("--", i)) {
    std::size_t end = i + 2;
    if (end < line.size() && line[end] >= 'a' && line[end] <= 'z') {
      while (end < line.size() && word_char(line[end])) ++end;
      out.push_back(line.substr(i, end - i));
    }
    i = end;
  }
  return out;
}

// The "--name" words of --help, by the command whose section they are in; the rendering flags'
// section counts for gui, headless and replay.
std::map<std::string, std::set<std::string>> options_in_help() {
  std::map<std::string, std::set<std::string>> out;
  std::istringstream in(kHelpText);
  std::string line, section;
  while (std::getline(in, line)) {
    if (line.rfind("  nbscope ", 0) == 0) {
      const std::string word = line.substr(10, line.find(' ', 10) - 10);
      section = word.rfind("[gui]", 0) == 0 ? "gui" : word;
    } else if (line.rfind("  rendering flags", 0) == 0) {
      section = "rendering";
    } else if (line.rfind("  ", 0) != 0) {
      section.clear();
    }
    if (section.empty() || section == "algorithms" || section == "--help") continue;
    for (const std::string& word : option_words(line)) {
      if (section == "rendering") {
        for (const char* c : {"gui", "headless", "replay"}) out[c].insert(word);
      } else {
        out[section].insert(word);
      }
    }
  }
  return out;
}

TEST(CliOptions, TheTableAgreesWithHelp) {
  const auto help = options_in_help();
  ASSERT_EQ(help.size(), command_options().size());
  for (const auto& [command, options] : command_options()) {
    ASSERT_TRUE(help.count(command)) << command;
    std::set<std::string> table(options.begin(), options.end());
    for (const std::string& o : help.at(command)) EXPECT_TRUE(table.count(o)) << command << " " << o << " in --help, not in the table";
    for (const std::string& o : table) EXPECT_TRUE(help.at(command).count(o)) << command << " " << o << " in the table, not in --help";
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
