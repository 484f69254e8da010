// The docs as tests (issue 36): every command in a fenced shell block of README.md and docs/*.md runs
// here as written, and what the text says next to it is held to what it does. A doc change that
// breaks a command, its exit code or a number it quotes fails this test.
// Which blocks are commands, what each command is and the substitutions: support/doc_commands.hpp.
//
// Each page runs in a fresh directory holding links to the tree's assets/, docs/ and examples/, its
// commands in the page's order (a command makes the files the next one reads, as for a reader).
// Inputs made as the docs say (make_inputs()): docs/dem.md's recipes (`<!-- run: CODE FILE -->`:
// its LAMMPS input run by lmp, its LIGGGHTS input by liggghts) run there, the LAMMPS one for
// README.md too, and a block marked `<!-- part-of: CODE -->` (README.md, formats.md) must be lines of
// that recipe; `myplugin.c` (README, install.md) and `brute_plugin.c` (plugins.md) are
// examples/minimal/brute_plugin.c, the plugin docs/plugins.md shows. Substitutions (substitute()):
// `/tmp/` is the page directory's tmp/ (parallel runs share no files), `-I<prefix>/include` and
// `-I/usr/local/include` the tree's include/ (the installed header), `--scene FILE` default.json.
//
// What is checked: the exit code the text implies, first found of: `exit N` in the command's comment;
// 1 when its listed output says WRONG (verify); 1 with --inject-fault (a planted fault is a failed
// check: headless.md, replay.md); `exit(s) N` in the line right after its block (its last command)
// or in the lines just before its output-only listing; else 0. Its listed output: every line is one
// of the command's output lines (stdout or stderr), timings masked (a number before ` ms`/` s`, the
// ns and repeats columns of `scaling`); without a `...` line, no other output line. A `"quoted"`
// text in its comment is in its output (up to a `...`), and so is every number its comment quotes
// (`# 1,000 spheres, 6 layers`: 1000 and 6 are numbers of its output; its exit code aside).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/doc_commands.hpp"
#include "support/run_cli.hpp"
#include "support/x_display.hpp"

namespace nbscope {
namespace {

using namespace testdocs;  // the pages' commands, fs and kSource (support/doc_commands.hpp)

// The exit code the text implies (the rule in the header).
int expected_exit(const Command& c) {
  static const std::regex exit_re(R"(\b[Ee]xits? (\d)\b)");
  std::smatch m;
  if (std::regex_search(c.comment, m, exit_re)) return std::stoi(m[1]);
  for (const std::string& l : c.output)
    if (l.size() >= 5 && l.compare(l.size() - 5, 5, "WRONG") == 0) return 1;
  if (c.text.find("--inject-fault") != std::string::npos) return 1;
  if (std::regex_search(c.exit_prose, m, exit_re)) return std::stoi(m[1]);
  return 0;
}

// A line with its timings masked: a number before ` ms` or ` s`; the ns/element and repeats of a `scaling` row
// (and runs of spaces as one).
std::string mask_timings(const std::string& line) {
  static const std::regex timing(R"(\d[\d.,]*( m?s\b))");
  std::string s = std::regex_replace(line, timing, "#$1");
  static const std::regex table(R"(^(\S+\s+\S+\s+\d+\s+)[\d.]+(\s+[\d.]+\s+\d+\s+)\d+(\s+\d+)$)");
  static const std::regex csv(R"(^([a-z0-9_ ]+,[a-z_]+,\d+,)[\d.]+(,[\d.]+,\d+,)\d+(,\d+)$)");
  s = std::regex_replace(s, table, "$1#$2#$3");
  s = std::regex_replace(s, csv, "$1#$2#$3");
  // A table's columns are padded to its numbers' widths, which change with the timings ("9.52", "10.24").
  static const std::regex padding(R"(  +)");
  return std::regex_replace(s, padding, " ");
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);)
    if (!trim(l).empty()) out.push_back(l);
  return out;
}

std::string quote(const std::string& s) { return "'" + s + "'"; }

// docs/dem.md's recipe input for `code` ("lammps", "liggghts"): the fenced block after its mark
// `<!-- run: CODE FILE -->`, as {FILE, text}; {"", ""} when the page has none.
std::pair<std::string, std::string> recipe_of(const std::string& code) {
  const std::vector<std::string> lines = lines_of(kSource / "docs/dem.md");
  const std::regex mark("<!-- run: " + code + " (\\S+) -->");
  for (std::size_t k = 0; k < lines.size(); ++k) {
    std::smatch m;
    if (!std::regex_match(lines[k], m, mark)) continue;
    std::size_t at = k + 1;
    while (at < lines.size() && trim(lines[at]).empty()) ++at;
    std::string text;
    for (++at; at < lines.size() && !fence(lines[at]); ++at) text += lines[at] + "\n";
    return {m[1], text};
  }
  return {"", ""};
}

// Every line of a block marked `<!-- part-of: CODE -->` in `page` is a line of CODE's recipe.
void check_recipe_parts(const std::string& page) {
  const std::vector<std::string> lines = lines_of(kSource / page);
  static const std::regex mark("<!-- part-of: (\\S+) -->");
  for (std::size_t k = 0; k < lines.size(); ++k) {
    std::smatch m;
    if (!std::regex_match(lines[k], m, mark)) continue;
    const std::string recipe = "\n" + recipe_of(m[1]).second;
    EXPECT_NE(recipe, "\n") << page << ":" << k + 1 << ": no recipe " << m[1] << " in docs/dem.md";
    std::size_t at = k + 1;
    while (at < lines.size() && trim(lines[at]).empty()) ++at;
    for (++at; at < lines.size() && !fence(lines[at]); ++at)
      EXPECT_NE(recipe.find("\n" + lines[at] + "\n"), std::string::npos)
          << page << ":" << at + 1 << ": '" << lines[at] << "' is not a line of the " << m[1] << " recipe (docs/dem.md)";
  }
}

// The inputs a page's commands read, made as the docs say (the header).
void make_inputs(const std::string& page, const fs::path& dir) {
  const std::string minimal = (kSource / "examples/minimal/brute_plugin.c").string();
  // docs/dem.md's recipe for `code` run as written, in `dir`, by `program` (lmp, liggghts).
  const auto recipe = [&](const std::string& code, const std::string& program) {
    if (std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) != 0) {
      const char* ci = std::getenv("CI");
      if (ci != nullptr && std::string(ci) == "true") FAIL() << page << ": " << program << " is not installed (CI=true: it must run)";
      GTEST_SKIP() << page << ": its " << code << " frames need " << program << " (apt-get install " << code << ")";
    }
    const auto [file, text] = recipe_of(code);
    ASSERT_FALSE(file.empty()) << "docs/dem.md has no `<!-- run: " << code << " FILE -->` recipe";
    std::ofstream(dir / file) << text;
    // -screen none would crash LIGGGHTS (fix insert/pack prints to the NULL screen).
    const std::string cmd = "cd " + quote(dir.string()) + " && " + program + " -in " + quote(file) + " -log log." + program +
                            " -echo none -screen /dev/null >" + program + ".out 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << page << ": " << program << " -in " << file << " failed (" << dir << "/log." << program << ")";
  };
  if (page == "README.md") {
    recipe("lammps", "lmp");
    fs::copy_file(minimal, dir / "myplugin.c");
  } else if (page == "docs/dem.md") {
    recipe("lammps", "lmp");
    if (!testing::Test::IsSkipped() && !testing::Test::HasFatalFailure()) recipe("liggghts", "liggghts");
  } else if (page == "docs/install.md") {
    fs::copy_file(minimal, dir / "myplugin.c");
  } else if (page == "docs/plugins.md") {
    fs::copy_file(minimal, dir / "brute_plugin.c");
  }
}

// The options `nbscope COMMAND --help` lists.
std::string help_of(const std::string& command) {
  static std::map<std::string, std::string> cache;
  if (!cache.count(command)) cache[command] = testcli::run(command + " --help").out;
  return cache[command];
}

// True when `help` names `option` as a whole word (--thread is not --threads).
bool names_option(const std::string& help, const std::string& option) {
  for (std::size_t at = help.find(option); at != std::string::npos; at = help.find(option, at + 1)) {
    const std::size_t end = at + option.size();
    if (end == help.size() || !(std::isalnum(static_cast<unsigned char>(help[end])) != 0 || help[end] == '-')) return true;
  }
  return false;
}

struct Inventory {
  std::vector<Command> commands;
  std::vector<std::string> problems;
  int blocks = 0, listings_without_command = 0;
};

Inventory inventory() {
  Inventory inv;
  for (const std::string& page : pages()) {
    std::vector<Command> cs = commands_of(kSource / page, page, inv.problems, inv.blocks, inv.listings_without_command);
    for (Command& c : cs) classify(c);
    inv.commands.insert(inv.commands.end(), cs.begin(), cs.end());
  }
  return inv;
}

std::string where(const Command& c) { return c.page + ":" + std::to_string(c.line) + ": " + c.text; }

TEST(DocsCommands, EveryCommandBlockIsTaggedAndEverySynopsisNamesRealOptions) {
  const Inventory inv = inventory();
  for (const std::string& p : inv.problems) ADD_FAILURE() << p;
  for (const std::string& page : pages()) check_recipe_parts(page);
  std::map<Kind, int> count;
  for (const Command& c : inv.commands) {
    ++count[c.kind];
    if (c.kind != Kind::synopsis) continue;
    const std::vector<std::string> w = words_of(c.text);
    if (w[0] != "nbscope") continue;  // a compiler line with a placeholder: its flags are the compiler's
    ASSERT_GE(w.size(), 2u) << where(c);
    const std::string help = help_of(w[1]);
    EXPECT_FALSE(help.empty()) << where(c) << ": no command '" << w[1] << "'";
    static const std::regex flag(R"(--[a-z][a-z0-9-]*)");
    for (auto it = std::sregex_iterator(c.text.begin(), c.text.end(), flag); it != std::sregex_iterator(); ++it)
      EXPECT_TRUE(names_option(help, it->str())) << where(c) << ": `nbscope " << w[1] << "` has no option " << it->str();
  }
  std::printf("docs: %d fenced blocks, %zu commands: %d run, %d in a window, %d synopses (flags checked), %d covered "
              "elsewhere; %d output listings without a command\n",
              inv.blocks, inv.commands.size(), count[Kind::run], count[Kind::window], count[Kind::synopsis], count[Kind::covered],
              inv.listings_without_command);
  for (const Command& c : inv.commands)
    if (c.kind == Kind::covered) {
      std::printf("  covered elsewhere: %s (%s)\n", where(c).c_str(), c.covered_by.c_str());
    } else if (c.kind == Kind::synopsis) {
      std::printf("  synopsis: %s\n", where(c).c_str());
    }
}

class PageCommands : public testing::TestWithParam<std::string> {};

// Runs `c` in `dir` through bash, `nbscope` on PATH, no display: exit code, stdout, stderr.
testcli::Result run_in(const std::string& dir, const std::string& command) {
  const std::string cmd = "cd " + quote(dir) + " && env -u DISPLAY -u WAYLAND_DISPLAY PATH=" + quote(dir + "/bin") +
                          ":\"$PATH\" XDG_CONFIG_HOME=" + quote(dir + "/config") + " XDG_DATA_HOME=" + quote(dir + "/data") +
                          " bash -c " + quote(std::regex_replace(command, std::regex("'"), "'\\''"));
  return testcli::run_shell(cmd, dir + "/.out", dir + "/.err");
}

// Without thousands separators: "1,000" -> "1000".
std::string plain_numbers(const std::string& s) { return std::regex_replace(s, std::regex(R"((\d),(\d{3}))"), "$1$2"); }

// Every number the command's comment quotes (but its exit code) is a number of its output.
void check_comment_numbers(const Command& c, const std::string& output) {
  static const std::regex number(R"((^|[^\w.,])(\d[\d,]*(\.\d+)?)(?![\w]))");
  const std::string comment = std::regex_replace(c.comment, std::regex(R"([Ee]xits? \d)"), "");
  const std::string printed = " " + plain_numbers(output) + " ";
  for (auto it = std::sregex_iterator(comment.begin(), comment.end(), number); it != std::sregex_iterator(); ++it) {
    const std::string n = plain_numbers((*it)[2]);
    const std::regex whole("(^|[^\\d.])" + n + "([^\\d]|$)");
    EXPECT_TRUE(std::regex_search(printed, whole)) << where(c) << "\n  the comment quotes " << n << "; the command printed:\n" << output;
  }
}

void check_output(const Command& c, const std::string& dir, const testcli::Result& r) {
  const std::string all = r.err + (r.err.empty() || r.err.back() == '\n' ? "" : "\n") + r.out;
  std::vector<std::string> actual = split_lines(all);
  for (std::string& l : actual) l = mask_timings(l);
  std::multiset<std::string> unmatched(actual.begin(), actual.end());
  for (const std::string& listed : c.output) {
    if (trim(listed).empty()) continue;
    const std::string want = mask_timings(substitute(listed, dir));
    const auto it = unmatched.find(want);
    EXPECT_NE(it, unmatched.end()) << where(c) << "\n  the text lists: " << listed << "\n  the command printed:\n" << all;
    if (it != unmatched.end()) unmatched.erase(it);
  }
  if (!c.output.empty() && !c.elided) {
    EXPECT_TRUE(unmatched.empty()) << where(c) << "\n  printed lines the text does not list (add `...` if it leaves some out):\n"
                                   << all;
  }
  check_comment_numbers(c, all);
  static const std::regex quoted(R"re("([^"]+)")re");
  for (auto it = std::sregex_iterator(c.comment.begin(), c.comment.end(), quoted); it != std::sregex_iterator(); ++it) {
    std::string said = (*it)[1];
    if (const auto dots = said.find("..."); dots != std::string::npos) said = said.substr(0, dots);
    EXPECT_NE(all.find(said), std::string::npos) << where(c) << "\n  the comment says \"" << said << "\"; the command printed:\n" << all;
  }
}

TEST_P(PageCommands, RunAsWritten) {
  const std::string page = GetParam();
  std::vector<std::string> problems;
  int blocks = 0, loose = 0;
  std::vector<Command> commands = commands_of(kSource / page, page, problems, blocks, loose);
  for (Command& c : commands) classify(c);
  std::string name = page;
  std::replace(name.begin(), name.end(), '/', '_');
  const fs::path dir = fs::absolute(testcli::scratch_dir("docs_commands/" + name));
  for (const char* tree : {"assets", "docs", "examples"}) fs::create_directory_symlink(kSource / tree, dir / tree);
  fs::create_directories(dir / "bin");
  fs::create_directories(dir / "tmp");
  fs::create_symlink(testcli::binary(), dir / "bin/nbscope");
  make_inputs(page, dir);
  if (testing::Test::IsSkipped() || testing::Test::HasFatalFailure()) return;
  for (const Command& c : commands) {
    const std::string text = substitute(c.text, dir.string());
    if (c.kind == Kind::window) {
#ifdef NBSCOPE_TEST_GUI
      if (!testcli::have_xvfb()) {
        std::printf("not run (no Xvfb): %s\n", where(c).c_str());
        continue;
      }
      const std::string command = "env -C " + quote(dir.string()) + " XDG_CONFIG_HOME=" + quote(dir.string() + "/config") + " " +
                                  quote(testcli::binary()) + text.substr(std::string("nbscope").size());
      const testcli::WindowRun w = testcli::run_until_window_then_term(command);
      std::printf("ran in a window %s:%zu (exit %d on SIGTERM)\n", c.page.c_str(), c.line, w.exit_code);
      EXPECT_TRUE(w.window_shown) << where(c) << ": no window showed\n" << w.out << w.err;
      EXPECT_EQ(w.exit_code, expected_exit(c)) << where(c) << ": closed by SIGTERM\n" << w.out << w.err;
      // And as written where there is no display: the same frames, headless (replay.md, window.md).
      const testcli::Result r = run_in(dir.string(), text);
      EXPECT_EQ(r.exit_code, expected_exit(c)) << where(c) << " (no display)\n--- stdout:\n" << r.out << "--- stderr:\n" << r.err;
      check_output(c, dir.string(), r);
#else
      std::printf("not run (a build without the window): %s\n", where(c).c_str());
#endif
      continue;
    }
    if (c.kind != Kind::run) continue;
#ifndef NBSCOPE_TEST_GUI
    if (text.find("--screenshot") != std::string::npos) {  // off-screen drawing is the window's code
      std::printf("not run (a build without the window): %s\n", where(c).c_str());
      continue;
    }
#endif
    const testcli::Result r = run_in(dir.string(), text);
    std::printf("ran %s:%zu (exit %d)\n", c.page.c_str(), c.line, r.exit_code);
    EXPECT_EQ(r.exit_code, expected_exit(c)) << where(c) << "\n--- stdout:\n" << r.out << "--- stderr:\n" << r.err;
    check_output(c, dir.string(), r);
  }
}

// The pages with a command to run (architecture.md, say, has none: its blocks are diagrams and code).
std::vector<std::string> pages_with_commands() {
  std::vector<std::string> out;
  for (const std::string& page : pages()) {
    std::vector<std::string> problems;
    int blocks = 0, loose = 0;
    std::vector<Command> commands = commands_of(kSource / page, page, problems, blocks, loose);
    for (Command& c : commands) classify(c);
    if (std::any_of(commands.begin(), commands.end(), [](const Command& c) { return c.kind == Kind::run || c.kind == Kind::window; }))
      out.push_back(page);
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Pages, PageCommands, testing::ValuesIn(pages_with_commands()), [](const testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& ch : name)
    if (std::isalnum(static_cast<unsigned char>(ch)) == 0) ch = '_';
  return name;
});

}  // namespace
}  // namespace nbscope
