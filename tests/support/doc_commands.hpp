// nbscope tests: the commands of the documentation pages, as tests/docs/test_docs_commands.cpp runs
// them: which fenced blocks are commands, what each command is, and the substitutions made before
// it runs. The rule, per fenced block:
// - tagged `sh`, `bash`, `shell`: every line is a command (`\` continues it, and so does an indented
//   line that starts with `[` or `-`, a synopsis's layout; `# ...` at its end is its comment; a line
//   that starts with `#` is prose);
// - tagged `console`: `$ ` lines are commands, the lines after one its output as the text shows it;
//   a `console` block without `$` is the output of the command just above it (the last of the
//   previous command block of the page, when no listing was given for it yet; else it is counted
//   as a listing without a command, and not checked);
// - any other tag (json, c, cmake, text, mermaid, none: LIGGGHTS input, output listings) is no
//   command; a line of such a block that starts with `nbscope COMMAND` or `nbscope --flag` fails the
//   test (tag it sh).
// docs/cli.md is generated help (a test of its own compares it), so it is not read.
//
// What each command is:
// - a synopsis: it has `[`, a ` ...` word or an upper-case placeholder (FILE, N, ELEMENTS.csv, ...):
//   not run; its command must exist and take every `--flag` it names (`nbscope COMMAND --help`);
// - covered elsewhere: `scripts/dev ...` (tests/scripts/test_dev_script.cpp), `cmake --install`,
//   `cpack`, `apt install` (tests/install; installing the .deb needs root), `ctest` (the suite itself),
//   `nbscope watch` and a simulation started in the background (`... &`: tests/dem/watch_lammps.sh);
// - a window (`gui` without --screenshot, `replay` without --headless or --screenshot): run on the
//   test's own Xvfb until its window shows, then SIGTERM: it must show and exit as below; then as written
//   without a display, where it runs headless, its output checked as any command's (in a build without
//   the window, NBSCOPE_GUI=OFF, these and the --screenshot commands are not run, and say so);
// - else run through bash in the page's directory, `nbscope` on PATH, no display.
#pragma once
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace nbscope::testdocs {

namespace fs = std::filesystem;

inline const fs::path kSource = NBSCOPE_SOURCE_DIR;

enum class Kind { run, window, synopsis, covered };

struct Command {
  std::string page;
  std::size_t line = 0;  // 1-based, of the command's first line
  std::string text;      // as written (continuations joined)
  std::string comment;   // its trailing `# ...`, without the `#`
  std::vector<std::string> output;  // the output the text lists for it
  bool elided = false;               // the listing has a `...` line
  std::string exit_prose;            // the text that may say its exit code
  Kind kind = Kind::run;
  std::string covered_by;
};

inline std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

inline std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

inline bool starts_with(const std::string& s, const std::string& p) { return s.rfind(p, 0) == 0; }

// The fence's language tag when `line` opens or closes a fenced block, else nullopt.
inline std::optional<std::string> fence(const std::string& line) {
  const std::string t = trim(line);
  if (!starts_with(t, "```") && !starts_with(t, "~~~")) return std::nullopt;
  return trim(t.substr(3));
}

// Splits a shell line into the command and its trailing comment (a `#` after white space, outside quotes).
inline std::pair<std::string, std::string> split_comment(const std::string& line) {
  char quote = 0;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '#' && k > 0 && (line[k - 1] == ' ' || line[k - 1] == '\t')) {
      return {trim(line.substr(0, k)), trim(line.substr(k + 1))};
    }
  }
  return {trim(line), ""};
}

// Lines [from, to) joined as prose.
inline std::string prose(const std::vector<std::string>& lines, std::size_t from, std::size_t to) {
  std::string out;
  for (std::size_t k = from; k < std::min(to, lines.size()); ++k) out += lines[k] + " ";
  return out;
}

inline const std::set<std::string> kShellTags = {"sh", "bash", "shell"};

// Every command of one page, in order; `problems` gets a command found in a block that is not tagged as one.
inline std::vector<Command> commands_of(const fs::path& file, const std::string& page, std::vector<std::string>& problems,
                                 int& blocks, int& listings_without_command) {
  const std::vector<std::string> lines = lines_of(file);
  std::vector<Command> out;
  std::size_t last_block_end = 0;       // the line after the previous closing fence
  std::size_t last_command_block = 0;   // index in `out` one past the previous command block's commands
  bool have_command_block = false;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const auto tag = fence(lines[k]);
    if (!tag) continue;
    std::size_t end = k + 1;
    while (end < lines.size() && !fence(lines[end])) ++end;
    ++blocks;
    const std::vector<std::string> body(lines.begin() + static_cast<long>(k) + 1, lines.begin() + static_cast<long>(std::min(end, lines.size())));
    const std::string before = prose(lines, last_block_end, k);
    const std::string after = end + 1 < lines.size() ? lines[end + 1] : "";
    if (kShellTags.count(*tag) != 0) {
      for (std::size_t b = 0; b < body.size(); ++b) {
        std::string joined = body[b];
        const std::size_t first = b;
        while (!joined.empty() && joined.back() == '\\' && b + 1 < body.size()) joined = joined.substr(0, joined.size() - 1) + " " + trim(body[++b]);
        if (trim(joined).empty() || starts_with(trim(joined), "#")) continue;
        auto [text, comment] = split_comment(joined);
        if (joined[0] == ' ' && (text[0] == '[' || text[0] == '-') && !out.empty() && out.back().line > k) {  // of this block
          out.back().text += " " + text;  // a synopsis laid out on several lines
          continue;
        }
        out.push_back({page, k + 2 + first, text, comment, {}, false, "", Kind::run, ""});
      }
      if (!out.empty()) out.back().exit_prose = after;
      last_command_block = out.size();
      have_command_block = true;
    } else if (*tag == "console") {
      const std::size_t start = out.size();
      for (std::size_t b = 0; b < body.size(); ++b) {
        if (starts_with(body[b], "$ ")) {
          auto [text, comment] = split_comment(body[b].substr(2));
          out.push_back({page, k + 2 + b, text, comment, {}, false, "", Kind::run, ""});
        } else if (out.size() > start) {
          if (trim(body[b]) == "...") {
            out.back().elided = true;
          } else {
            out.back().output.push_back(body[b]);
          }
        }
      }
      if (out.size() > start) {
        out.back().exit_prose = after;
        last_command_block = out.size();
        have_command_block = true;
      } else if (have_command_block && last_command_block > 0 && out[last_command_block - 1].output.empty()) {
        Command& c = out[last_command_block - 1];  // the output of the command just above
        for (const std::string& l : body) {
          if (trim(l) == "...") {
            c.elided = true;
          } else {
            c.output.push_back(l);
          }
        }
        c.exit_prose = before;
      } else {
        ++listings_without_command;
      }
    } else {
      static const std::regex command_line(R"(^(\$ )?nbscope (--|[a-z]).*)");  // not `nbscope 0.1.0`, --version's output
      for (const std::string& l : body)
        if (std::regex_match(trim(l), command_line))
          problems.push_back(page + ":" + std::to_string(k + 1) + ": a command in a block tagged '" + *tag + "' (tag it sh or console)");
    }
    last_block_end = end + 1;
    k = end;
  }
  return out;
}

// The documentation pages read: README.md and docs/*.md but cli.md (generated help).
inline std::vector<std::string> pages() {
  std::vector<std::string> out{"README.md"};
  std::vector<std::string> docs;
  for (const auto& entry : fs::directory_iterator(kSource / "docs"))
    if (entry.path().extension() == ".md" && entry.path().filename() != "cli.md") docs.push_back("docs/" + entry.path().filename().string());
  std::sort(docs.begin(), docs.end());
  out.insert(out.end(), docs.begin(), docs.end());
  return out;
}

inline std::vector<std::string> words_of(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> w;
  for (std::string x; in >> x;) w.push_back(x);
  return w;
}

// An upper-case placeholder word: FILE, N, ELEMENTS.csv, OUT.png, NX,NY, WxH.
inline bool placeholder(const std::string& word) {
  static const std::regex re(R"(^[A-Z][A-Z_]*(\.[a-z]+)?(,[A-Z]+)*$|^WxH$)");
  return std::regex_match(word, re);
}

// The substitutions of the header: the page directory `dir` for /tmp/, the tree's headers, a scene for FILE.
inline std::string substitute(std::string s, const std::string& dir) {
  const std::vector<std::pair<std::string, std::string>> kSubstitutions = {
      {"/tmp/", dir + "/tmp/"},
      {"-I<prefix>/include", "-I" + (kSource / "include").string()},
      {"-I/usr/local/include", "-I" + (kSource / "include").string()},
      {"--scene FILE", "--scene assets/scenes/default.json"},
  };
  for (const auto& [from, to] : kSubstitutions)
    for (std::size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size()) s.replace(at, from.size(), to);
  return s;
}

inline bool has_word(const std::vector<std::string>& w, const std::string& x) { return std::find(w.begin(), w.end(), x) != w.end(); }

inline void classify(Command& c) {
  const std::vector<std::string> w = words_of(substitute(c.text, "/tmp"));
  if (w.empty()) return;
  if (w[0] == "scripts/dev") {
    c.kind = Kind::covered;
    c.covered_by = "tests/scripts/test_dev_script.cpp (scripts/dev's every subcommand)";
  } else if ((w[0] == "cmake" && has_word(w, "--install")) || has_word(w, "cpack") || has_word(w, "apt")) {
    c.kind = Kind::covered;
    c.covered_by = "tests/install: cmake --install into a prefix, the .deb cpack makes (its files checked, extracted: installing it needs root)";
  } else if ((w[0] == "nbscope" && w.size() > 1 && w[1] == "watch") || w.back() == "&") {
    c.kind = Kind::covered;  // a simulation started in the background and watched: no doc command can wait for one
    c.covered_by = "tests/dem/watch_lammps.sh, mpi_lammps.sh (dem.watch, dem.mpi_np2/4): a real LAMMPS run watched while it writes";
  } else if (w[0] == "ctest") {
    c.kind = Kind::covered;
    c.covered_by = "the test suite itself";
  } else if (std::any_of(w.begin(), w.end(), [](const std::string& x) { return x == "..." || x.find('[') != std::string::npos || placeholder(x); })) {
    c.kind = Kind::synopsis;
  } else if (w[0] == "nbscope" && w.size() > 1 &&
             ((w[1] == "gui" && !has_word(w, "--screenshot")) || (w[1] == "replay" && !has_word(w, "--headless") && !has_word(w, "--screenshot")))) {
    c.kind = Kind::window;
  }
}

}  // namespace nbscope::testdocs
