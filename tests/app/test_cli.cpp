// The command line: pairs, help, version, algorithms, and every bad input of the foundation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/paths.hpp"
#include "support/run_cli.hpp"

namespace nbscope {
namespace {

using testcli::read_text;
using testcli::run;
using testcli::scratch_dir;
using testcli::write_text;


TEST(Cli, HelpVersionAndAlgorithms) {
  auto help = run("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("\n  pairs "), std::string::npos);
  EXPECT_EQ(run("-h").out, help.out);
  EXPECT_EQ(run("help").out, help.out);
  auto version = run("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_EQ(version.out.rfind("nbscope ", 0), 0u);
  // The line scripts/dev run asks whether the window is built (its second line, whole).
#ifdef NBSCOPE_TEST_GUI
  EXPECT_NE(version.out.find("\nwindow: yes ("), std::string::npos) << version.out;
#else
  EXPECT_NE(version.out.find("\nwindow: no ("), std::string::npos) << version.out;
#endif
  const auto pairs = run("pairs --help");  // help after a command is its page, not an unknown flag
  EXPECT_EQ(pairs.exit_code, 0);
  EXPECT_NE(pairs.out.find("--repeat K"), std::string::npos);
  EXPECT_EQ(run("help pairs").out, pairs.out);
  EXPECT_EQ(run("headless -h").exit_code, 0);
  const auto extra = run("--version extra");
  EXPECT_EQ(extra.exit_code, 2);
  EXPECT_EQ(extra.err, "nbscope: error: extra: unexpected argument (see nbscope --help)\n");
  auto algos = run("algorithms");
  EXPECT_EQ(algos.exit_code, 0);
  EXPECT_NE(algos.out.find("brute"), std::string::npos);
  EXPECT_NE(algos.out.find("nbs"), std::string::npos);
}

TEST(Cli, PairsOfTheBundledExampleToStdoutAndFile) {
  const std::string dir = scratch_dir("pairs_example");
  auto r = run("pairs --input '" + testpaths::nine_csv() + "' --algorithm nbs");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("i,j\n", 0), 0u);
  EXPECT_NE(r.err.find("1 pair,"), std::string::npos);
  EXPECT_NE(r.err.find("detection"), std::string::npos);
  auto b = run("pairs --input '" + testpaths::nine_csv() + "' --algorithm brute --output '" + dir + "/p.csv'");
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(read_text(dir + "/p.csv"), r.out);
}

TEST(Cli, EmptyAndSingleElementSetsHaveNoPairs) {
  const std::string dir = scratch_dir("pairs_small");
  write_text(dir + "/zero.csv", "x,y,r\n");
  write_text(dir + "/one.csv", "1,2,0.5\n");
  for (const char* f : {"zero.csv", "one.csv"}) {
    auto r = run("pairs --input '" + dir + "/" + f + "'");
    EXPECT_EQ(r.exit_code, 0) << f << ": " << r.err;
    EXPECT_EQ(r.out, "i,j\n") << f;
  }
}

TEST(Cli, RepeatAgreesWithItself) {
  auto r = run("pairs --input '" + testpaths::nine_csv() + "' --repeat 5 --output /dev/null");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("all runs agree"), std::string::npos) << r.err;
}

TEST(Cli, ADeviceAsOutputIsWrittenInPlaceNotReplaced) {
  // A temporary renamed over /dev/null would turn the device into a plain file (as root).
  auto r = run("pairs --input '" + testpaths::nine_csv() + "' --output /dev/null");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
  if (std::filesystem::is_character_file("/dev/full")) {
    r = run("pairs --input '" + testpaths::nine_csv() + "' --output /dev/full");
    EXPECT_EQ(r.exit_code, 2);
    // The one error line only: the detection's summary line belongs to a run that wrote its output.
    EXPECT_EQ(r.err.rfind("nbscope: error: /dev/full: cannot write: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(std::filesystem::is_character_file("/dev/full"));
  }
}

struct BadInput {
  const char* name;
  const char* file_text;  // nullptr: the file does not exist
  const char* extra_args;
  const char* message;    // expected after "nbscope: error: "
};

// Short names in test listings instead of GoogleTest's byte dump.
void PrintTo(const BadInput& c, std::ostream* os) { *os << c.name; }

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, ExitsTwoWithOneLineAndNoOutputFile) {
  const BadInput& c = GetParam();
  const std::string dir = scratch_dir(std::string("bad_") + c.name);
  const std::string in = dir + "/in.csv", out = dir + "/out.csv";
  if (c.file_text) write_text(in, c.file_text);
  auto r = run("pairs --input '" + in + "' --output '" + out + "' " + c.extra_args);
  EXPECT_EQ(r.exit_code, 2);
  std::string expected = std::string("nbscope: error: ") + c.message + "\n";
  const std::string placeholder = "IN";
  if (const auto p = expected.find(placeholder); p != std::string::npos) expected.replace(p, placeholder.size(), in);
  if (const auto p = expected.find("ALGOS"); p != std::string::npos) {
    EXPECT_EQ(r.err.substr(0, p), expected.substr(0, p));  // the list grows with the registry
  } else {
    EXPECT_EQ(r.err, expected);
  }
  EXPECT_TRUE(r.out.empty());
  EXPECT_FALSE(std::filesystem::exists(out));
  std::size_t files = 0;  // no temporary left behind either
  for ([[maybe_unused]] const auto& f : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, c.file_text ? 1u : 0u);
}

const BadInput kBadInputs[] = {
    {"missing_file", nullptr, "", "IN: cannot open the elements file (no such file or not readable)"},
    {"empty_file", "", "", "IN:1: empty file (expected rows of x,y,r or x,y,z,r)"},
    {"two_columns", "x,y,r\n1,2,1\n3,4\n", "", "IN:3: 2 columns; expected 3 (x,y,r) or 4 (x,y,z,r)"},
    {"five_columns", "1,2,3,4,5\n", "", "IN:1: 5 columns; expected 3 (x,y,r) or 4 (x,y,z,r)"},
    {"not_a_number", "1,2,1\n1,two,1\n", "", "IN:2: y: 'two' is not a number"},
    {"nan", "nan,2,1\n", "", "IN:1: x: 'nan' is not a finite number"},
    {"inf", "1,2,inf\n", "", "IN:1: r: 'inf' is not a finite number"},
    {"zero_radius", "1,2,0\n", "", "IN:1: r: radius must be > 0, got 0"},
    {"negative_radius", "1,2,-0.5\n", "", "IN:1: r: radius must be > 0, got -0.5"},
    {"unknown_algorithm", "1,2,1\n", "--algorithm quick", "unknown algorithm 'quick' (known: ALGOS)"},
    {"unknown_flag", "1,2,1\n", "--fast", "pairs: --fast is not an option of pairs (see nbscope --help)"},
    {"option_of_another_command", "1,2,1\n", "--report=r.json", "pairs: --report is not an option of pairs (it is one of headless, replay, watch)"},
    {"bad_repeat", "1,2,1\n", "--repeat 0", "--repeat: '0' is not a whole number from 1 to 1000000"},
    {"missing_value", "1,2,1\n", "--algorithm", "--algorithm: missing value"},
    {"repeated_flag", "1,2,1\n", "--repeat 2 --repeat=3", "--repeat: given more than once"},
    {"pair_limit", "0,0,1\n0,0,1\n0,0,1\n0,0,1\n0,0,1\n", "--max-pairs 3",
     "IN: more than 3 contact pairs (the pair limit; too many elements overlap at one place)"},
};

INSTANTIATE_TEST_SUITE_P(Pairs, CliBadInput, ::testing::ValuesIn(kBadInputs), [](const auto& info) { return info.param.name; });

TEST(Cli, AnUnwritableOutputFailsBeforeDetection) {
  const std::string dir = scratch_dir("bad_output");
  write_text(dir + "/in.csv", "0,0,1\n1,0,1\n");
  auto r = run("pairs --input '" + dir + "/in.csv' --output '" + dir + "/no/out.csv'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "nbscope: error: " + dir + "/no/out.csv: cannot write: no directory " + dir + "/no\n");
  r = run("pairs --input '" + dir + "/in.csv' --output '" + dir + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "nbscope: error: " + dir + ": cannot write: it is a directory\n");
}

TEST(Cli, AnOutputThatIsTheInputIsRefusedAndTheInputKept) {
  const std::string dir = scratch_dir("output_is_input");
  write_text(dir + "/in.csv", "0,0,1\n1,0,1\n");
  // The same file by another spelling too.
  for (const std::string& out : {dir + "/in.csv", dir + "/./sub/../in.csv"}) {
    std::filesystem::create_directories(dir + "/sub");
    const auto r = run("pairs --input '" + dir + "/in.csv' --output '" + out + "'");
    EXPECT_EQ(r.exit_code, 2) << out;
    EXPECT_EQ(r.err, "nbscope: error: " + out + ": cannot write: it is also the --input\n");
    EXPECT_EQ(read_text(dir + "/in.csv"), "0,0,1\n1,0,1\n");
  }
}

TEST(Cli, ADirectoryAsInputIsRefusedByName) {
  const std::string dir = scratch_dir("dir_input");
  const auto r = run("pairs --input '" + dir + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "nbscope: error: " + dir + ": is a directory, not an elements file\n");
}

TEST(Cli, BytesFromABadFileAreEscapedSoTheErrorStaysOnePrintableLine) {
  const std::string dir = scratch_dir("unprintable") + "/d\xC3\xA9j\xC3\xA0";  // a UTF-8 name stays as it is
  std::filesystem::create_directories(dir);
  // (A NUL byte is refused before any field is read: tests/app/test_hostile_cli.cpp.)
  write_text(dir + "/in.csv", std::string("1,2\x01x\r\xFF,1\n", 10));
  const auto r = run("pairs --input '" + dir + "/in.csv'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "nbscope: error: " + dir + "/in.csv:1: y: '2\\x01x\\x0D\\xFF' is not a number\n");
}

// The window's keys (every one the host and the Stepper handle) in gui --help and in docs/window.md's key
// list, as in the Help menu (test_stepper_ui.cpp checks the menu).
TEST(Cli, HelpAndTheReadmeNameEveryKeyOfTheWindow) {
  const auto one_line = [](const std::string& text) {  // line breaks and indents as single spaces
    std::string out;
    for (const char c : text) {
      const bool space = std::isspace(static_cast<unsigned char>(c)) != 0;
      if (space && !out.empty() && out.back() == ' ') continue;
      out += space ? ' ' : c;
    }
    return out;
  };
  const std::string help = one_line(run("gui --help").out);
  const std::string readme = testcli::read_text(std::string(NBSCOPE_SOURCE_DIR) + "/docs/window.md");
  const std::size_t keys_at = readme.find("Keys: P play/pause");
  ASSERT_NE(keys_at, std::string::npos);
  const std::string keys = one_line(readme.substr(keys_at, readme.find("\n\n", keys_at) - keys_at));
  for (const char* key : {"P play", "O single step", "R restart", "Home", "1..N", "Esc", "J play backwards", "Shift+[", "->",
                          "<-", "Space", "PageUp", "PageDown", "Shift: one phase", "Shift: on the selected cell"}) {
    EXPECT_NE(help.find(key), std::string::npos) << key << " missing from gui --help";
    EXPECT_NE(keys.find(key), std::string::npos) << key << " missing from docs/window.md's key list";
  }
}

// An option a command does not take is named, not its value (gui --report x.json was refused
// as "x.json: unexpected argument").
TEST(Cli, AnOptionOfAnotherCommandIsNamed) {
#ifdef NBSCOPE_TEST_GUI
  for (const char* args : {"gui --report x.json", "--report x.json", "gui --scene s.json --report=x.json"}) {
    const auto r = run(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(r.err, "nbscope: error: gui: --report is not an option of gui (it is one of headless, replay, watch)\n") << args;
  }
#endif
  auto r = run("replay --rewind 5:2 in.nbsrec");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "nbscope: error: replay: --rewind is not an option of replay (it is one of headless)\n");
  r = run("dump --input in.csv --algorithm nbs --repeat 3");
  EXPECT_EQ(r.err, "nbscope: error: dump: --repeat is not an option of dump (it is one of pairs)\n");
}

TEST(Cli, AListsFilterNotKnownIsRefusedByName) {
#ifndef NBSCOPE_TEST_GUI
  GTEST_SKIP() << "rendering flags are refused as a whole without the GUI";
#endif
  const auto r = run("headless --scene " + std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/book-fig-3-15.json --frames 1 --lists rows --screenshot x.png");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "nbscope: error: --lists: 'rows' is not one of all, selected, row\n");
}

// The commands `nbscope --help` lists ("  NAME  summary" lines under "commands:").
std::vector<std::string> listed_commands(const std::string& summary) {
  std::vector<std::string> names;
  std::istringstream in(summary.substr(summary.find("commands:\n") + 10));
  std::string line;
  while (std::getline(in, line) && line.rfind("  ", 0) == 0)
    if (line[2] != ' ') names.push_back(line.substr(2, line.find(' ', 2) - 2));  // not a summary's second line
  return names;
}

// `nbscope --help` is one screen: every command with one line, the global options, where to read more.
TEST(Cli, TheSummaryFitsOneScreen) {
  const auto r = run("--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_LE(std::count(r.out.begin(), r.out.end(), '\n'), 30) << r.out;
  EXPECT_NE(r.out.find("nbscope COMMAND --help for its options; docs/cli.md for the reference"), std::string::npos);
  EXPECT_NE(r.out.find("--version"), std::string::npos);
  for (const char* c : {"gui", "headless", "replay", "pairs", "dump", "verify", "scaling", "algorithms"})
    EXPECT_NE(std::find(listed_commands(r.out).begin(), listed_commands(r.out).end(), c), listed_commands(r.out).end()) << c;
}

// Every command's page runs, exits 0, is the same by `help COMMAND`, and names each option it
// lists in usage (the table's test, test_cli_options.cpp, ties the options to the parsers).
TEST(Cli, EveryCommandHasItsPage) {
  const auto names = listed_commands(run("--help").out);
  ASSERT_GE(names.size(), 8u);
  for (const std::string& name : names) {
    const auto page = run(name + " --help");
    EXPECT_EQ(page.exit_code, 0) << name << ": " << page.err;
    EXPECT_EQ(page.out.rfind("nbscope " + name + " - ", 0), 0u) << name;
    EXPECT_NE(page.out.find("\nusage:\n"), std::string::npos) << name;
    EXPECT_NE(page.out.find("\nexit codes: "), std::string::npos) << name;
    EXPECT_EQ(run(name + " -h").out, page.out) << name;
    EXPECT_EQ(run("help " + name).out, page.out) << name;
    // Every "--option" word of the usage lines is on the page as an option of its own.
    const std::string usage = page.out.substr(0, page.out.find("\n\n", page.out.find("usage:")));
    for (std::size_t i = usage.find("[--"); i != std::string::npos; i = usage.find("[--", i + 1)) {
      const std::string option = usage.substr(i + 1, usage.find_first_of(" ]=", i + 1) - i - 1);
      EXPECT_NE(page.out.find("\n  " + option), std::string::npos) << name << " " << option;
    }
  }
}

TEST(Cli, HelpOfAnUnknownCommandIsOneErrorLine) {
  for (const char* args : {"help bogus", "--help bogus", "bogus --help"}) {
    const auto r = run(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(r.err, "nbscope: error: bogus: unknown command (see nbscope --help)\n") << args;
    EXPECT_EQ(r.out, "") << args;
  }
}

// docs/cli.md is `nbscope help --markdown`, so the reference cannot drift from the table.
TEST(Cli, TheReferencePageIsTheTablesMarkdown) {
  const auto r = run("help --markdown");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string page = read_text(std::string(NBSCOPE_SOURCE_DIR) + "/docs/cli.md");
  EXPECT_EQ(page, r.out) << "docs/cli.md is out of date: nbscope help --markdown > docs/cli.md";
  for (const std::string& name : listed_commands(run("--help").out))
    EXPECT_NE(page.find("\n## nbscope " + name + "\n"), std::string::npos) << name;
}

TEST(Cli, UnknownCommandExitsTwo) {
  auto r = run("frobnicate");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "nbscope: error: frobnicate: unknown command (see nbscope --help)\n");
}

}  // namespace
}  // namespace nbscope
