// The documentation a newcomer walks: every relative link and image in README.md and docs/**/*.md
// resolves (the file, and for `#anchor` a heading of it), README.md stays a first screen (at most
// 200 lines, a picture before line 40), and no table cell is a wall of text (docs/architecture.md).
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kReadmeMaxLines = 200;
constexpr std::size_t kPictureBeforeLine = 40;
constexpr std::size_t kTableCellMaxChars = 320;  // "about 300"

// The lines of a file, without their line ends.
std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

// True for a line that opens or closes a fenced code block (``` or ~~~, up to 3 spaces in).
bool is_fence(const std::string& line) {
  const std::size_t at = line.find_first_not_of(' ');
  return at != std::string::npos && at <= 3 && (line.compare(at, 3, "```") == 0 || line.compare(at, 3, "~~~") == 0);
}

// The lines outside fenced code blocks, each with its 1-based number.
std::vector<std::pair<std::size_t, std::string>> prose_lines(const std::vector<std::string>& lines) {
  std::vector<std::pair<std::size_t, std::string>> out;
  bool in_code = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (is_fence(lines[i])) {
      in_code = !in_code;
      continue;
    }
    if (!in_code) out.emplace_back(i + 1, lines[i]);
  }
  return out;
}

// A line with its inline code spans blanked, so that `[a](b)` written as code is no link.
std::string without_code_spans(const std::string& line) {
  std::string out = line;
  std::size_t at = 0;
  while ((at = out.find('`', at)) != std::string::npos) {
    std::size_t ticks = 1;
    while (at + ticks < out.size() && out[at + ticks] == '`') ++ticks;
    const std::size_t end = out.find(std::string(ticks, '`'), at + ticks);
    if (end == std::string::npos) break;
    for (std::size_t i = at; i < end + ticks; ++i) out[i] = ' ';
    at = end + ticks;
  }
  return out;
}

// GitHub's anchor of a heading: lower case, punctuation dropped, spaces as hyphens.
std::string slug_of(const std::string& heading) {
  std::string out;
  for (const char c : heading) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80 || std::isalnum(u) != 0 || c == '_' || c == '-') {
      out += static_cast<char>(u < 0x80 ? std::tolower(u) : u);
    } else if (c == ' ') {
      out += '-';
    }
  }
  return out;
}

// Every anchor a Markdown file's headings make, repeats numbered as GitHub numbers them.
std::set<std::string> anchors_of(const fs::path& file) {
  std::set<std::string> anchors;
  std::map<std::string, int> seen;
  for (const auto& [number, line] : prose_lines(lines_of(file))) {
    std::size_t level = 0;
    while (level < line.size() && line[level] == '#') ++level;
    if (level == 0 || level > 6 || level >= line.size() || line[level] != ' ') continue;
    std::string slug = slug_of(line.substr(level + 1));
    const int n = seen[slug]++;
    if (n > 0) slug += "-" + std::to_string(n);
    anchors.insert(slug);
  }
  return anchors;
}

// The targets of a line's inline links and images, `[text](target)` and `![alt](target "title")`.
std::vector<std::string> link_targets(const std::string& raw_line) {
  const std::string line = without_code_spans(raw_line);
  std::vector<std::string> targets;
  std::size_t at = 0;
  while ((at = line.find("](", at)) != std::string::npos) {
    const std::size_t start = at + 2;
    const std::size_t end = line.find(')', start);
    if (end == std::string::npos) break;
    std::string target = line.substr(start, end - start);
    if (const std::size_t space = target.find(' '); space != std::string::npos) target.resize(space);
    if (target.size() >= 2 && target.front() == '<' && target.back() == '>') target = target.substr(1, target.size() - 2);
    if (!target.empty()) targets.push_back(target);
    at = end;
  }
  return targets;
}

bool is_external(const std::string& target) {
  return target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0;
}

// Every link or image of `file` that does not resolve, one line each: "FILE:LINE: TARGET: why".
std::vector<std::string> broken_links_of(const fs::path& file, const fs::path& root) {
  std::vector<std::string> broken;
  const std::string name = fs::relative(file, root).generic_string();
  for (const auto& [number, line] : prose_lines(lines_of(file))) {
    for (const std::string& target : link_targets(line)) {
      if (is_external(target)) continue;
      const std::size_t hash = target.find('#');
      const std::string path = target.substr(0, hash);
      const fs::path resolved = path.empty() ? file : (file.parent_path() / path).lexically_normal();
      const std::string where = name + ":" + std::to_string(number) + ": " + target + ": ";
      if (!fs::exists(resolved)) {
        broken.push_back(where + "no such file");
        continue;
      }
      if (hash == std::string::npos || resolved.extension() != ".md") continue;
      if (anchors_of(resolved).count(target.substr(hash + 1)) == 0) broken.push_back(where + "no such heading");
    }
  }
  return broken;
}

// README.md and every Markdown file under docs/.
std::vector<fs::path> documentation_of(const fs::path& root) {
  std::vector<fs::path> files{root / "README.md"};
  if (fs::is_directory(root / "docs")) {
    for (const auto& entry : fs::recursive_directory_iterator(root / "docs")) {
      if (entry.is_regular_file() && entry.path().extension() == ".md") files.push_back(entry.path());
    }
  }
  return files;
}

std::vector<std::string> broken_links_under(const fs::path& root) {
  std::vector<std::string> broken;
  for (const fs::path& file : documentation_of(root)) {
    for (std::string& line : broken_links_of(file, root)) broken.push_back(std::move(line));
  }
  return broken;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) out += line + "\n";
  return out;
}

void write_file(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

const fs::path kSource = NBSCOPE_SOURCE_DIR;

TEST(DocsLinks, EveryRelativeLinkAndImageResolves) {
  const auto files = documentation_of(kSource);
  EXPECT_GT(files.size(), 10u) << "README.md and the pages of docs/";
  const auto broken = broken_links_under(kSource);
  EXPECT_TRUE(broken.empty()) << joined(broken);
}

TEST(DocsLinks, TheReadmeIsOneScreenWithAPictureFirst) {
  const auto lines = lines_of(kSource / "README.md");
  EXPECT_LE(lines.size(), kReadmeMaxLines);
  std::size_t first_picture = 0;
  for (const auto& [number, line] : prose_lines(lines)) {
    if (line.find("![") != std::string::npos) {
      first_picture = number;
      break;
    }
  }
  EXPECT_NE(first_picture, 0u) << "README.md shows no picture";
  EXPECT_LT(first_picture, kPictureBeforeLine) << "README.md's first picture is on line " << first_picture;
}

TEST(DocsLinks, NoTableCellIsAWallOfText) {
  std::vector<std::string> walls;
  for (const fs::path& file : documentation_of(kSource)) {
    for (const auto& [number, line] : prose_lines(lines_of(file))) {
      if (line.rfind("|", 0) != 0) continue;
      std::size_t cell_start = 1;
      for (std::size_t i = 1; i <= line.size(); ++i) {
        if (i < line.size() && !(line[i] == '|' && line[i - 1] != '\\')) continue;
        if (i - cell_start > kTableCellMaxChars) {
          walls.push_back(fs::relative(file, kSource).generic_string() + ":" + std::to_string(number) + ": a cell of " +
                          std::to_string(i - cell_start) + " characters");
        }
        cell_start = i + 1;
      }
    }
  }
  EXPECT_TRUE(walls.empty()) << joined(walls);
}

// The checker itself: a tree with a missing page, a missing heading and a missing image is caught,
// while links in code, external links and good anchors (repeated headings too) are not flagged.
TEST(DocsLinks, ABrokenLinkOrImageIsCaught) {
  const fs::path root = fs::temp_directory_path() / ("nbscope-docs-links-" + std::to_string(::getpid()));
  fs::remove_all(root);
  write_file(root / "README.md",
             "# Top\n![shot](docs/shot.png)\nSee [a](docs/a.md#the-frames-path) and [gone](docs/gone.md).\n"
             "`[in code](nowhere.md)` and [web](https://example.org/x.md)\n```\n[fenced](nowhere.md)\n```\n");
  write_file(root / "docs/a.md",
             "# A page\n## The frame's path\n## Notes\n## Notes\n[up](../README.md#top) [twice](#notes-1) "
             "[bad](#no-such) ![pic](missing.png)\n");
  write_file(root / "docs/shot.png", "png");
  const auto broken = broken_links_under(root);
  fs::remove_all(root);
  EXPECT_EQ(broken.size(), 3u) << joined(broken);
  EXPECT_NE(joined(broken).find("README.md:3: docs/gone.md: no such file"), std::string::npos) << joined(broken);
  EXPECT_NE(joined(broken).find("docs/a.md:5: #no-such: no such heading"), std::string::npos) << joined(broken);
  EXPECT_NE(joined(broken).find("docs/a.md:5: missing.png: no such file"), std::string::npos) << joined(broken);
}

}  // namespace
