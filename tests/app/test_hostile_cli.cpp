// Hostile files through the binary: /dev/zero as every kind of input, 80 KB and 1 MB of nested
// brackets as a scene, 20 MB and 2 MB numeric fields, a .nbsrec header given twice — each exits 2 with one
// short line naming the file. Time and memory are not measured here (see docs/limits.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "support/run_cli.hpp"

namespace nbscope {
namespace {

using testcli::run;
using testcli::scratch_dir;
using testcli::write_text;

// Exit 2 and exactly one line on stderr, "nbscope: error: " + `message`, nothing on stdout.
void expect_refused(const testcli::Result& r, const std::string& message, const std::string& args) {
  EXPECT_EQ(r.exit_code, 2) << args;
  EXPECT_EQ(r.err, "nbscope: error: " + message + "\n") << args << "\n" << r.err.substr(0, 400);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args;
  EXPECT_EQ(r.out, "") << args;
}

const char* const kNul = ": a NUL byte (byte 0): ";
const char* const kBinary = " is text, this is binary data (or UTF-16 text: save it as UTF-8)";

TEST(HostileCli, DevZeroIsRefusedAsEveryKindOfInput) {
  const std::string dir = scratch_dir("hostile_dev_zero");
  const std::string csv = dir + "/e.csv";
  write_text(csv, "0,0,1\n1,0,1\n");
  const struct {
    std::string args;
    std::string kind;
  } cases[] = {
      {"pairs --input /dev/zero", "an elements file"},
      {"headless --scene /dev/zero --frames 1", "a scene file"},
      {"replay /dev/zero --headless", "a recording"},
      {"verify --input " + csv + " --arrays /dev/zero", "an arrays file"},
      {"verify --input " + csv + " --pairs /dev/zero", "a pairs file"},
      {"verify --input /dev/zero --pairs " + csv, "an elements file"},
  };
  for (const auto& c : cases) expect_refused(run(c.args), "/dev/zero:1" + std::string(kNul) + c.kind + kBinary, c.args);
}

// --frames has one upper limit for every command, and 1e8 is the same number as 100000000.
TEST(HostileCli, EveryCommandLimitsFramesAlike) {
  const std::string dir = scratch_dir("hostile_frames");
  const std::string csv = dir + "/e.csv";
  write_text(csv, "0,0,1\n1,0,1\n");
  write_text(dir + "/r.nbsrec", "nbsrec 1\nframe 0 0\n0,0,1\n");
  struct Case {
    std::string args;
    long long min;  // 0 where --frames 0 means "the first picture only"
  };
  const std::string scene = std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/default.json";
  std::vector<Case> cases = {{"headless --scene " + scene, 1}, {"replay " + dir + "/r.nbsrec --headless", 1}};
#ifdef NBSCOPE_TEST_GUI  // the window's commands exist in the GUI build only
  cases.push_back({"gui --scene " + scene + " --screenshot " + dir + "/x.png", 0});
  cases.push_back({"gui --input " + csv + " --arrays " + dir + "/a.json --screenshot " + dir + "/y.png", 0});
#endif
  for (const auto& c : cases) {
    for (const char* frames : {"100000001", "1e12", "1000000000000"}) {
      const std::string args = c.args + " --frames " + frames;
      expect_refused(run(args), "--frames: '" + std::string(frames) + "' is not a whole number from " + std::to_string(c.min) +
                                    " to 100000000", args);
    }
  }
}

TEST(HostileCli, NestedBracketsAreRefusedAtTheDepthLimit) {
  const std::string dir = scratch_dir("hostile_nesting");
  for (const std::size_t depth : {std::size_t{40'000}, std::size_t{500'000}}) {  // 80 KB and 1 MB
    const std::string path = dir + "/nested-" + std::to_string(depth) + ".json";
    write_text(path, std::string(depth, '[') + std::string(depth, ']'));
    const std::string args = "headless --scene " + path + " --frames 1";
    expect_refused(run(args), path + ":1: arrays and objects nested deeper than 64 levels, the limit for scene files", args);
  }
}

TEST(HostileCli, HugeNumericFieldsAreQuotedShort) {
  const std::string dir = scratch_dir("hostile_big_field");
  const std::string csv = dir + "/big.csv";
  write_text(csv, "x,y,r\n" + std::string(20'000'000, '1') + ",0,1\n");
  expect_refused(run("pairs --input " + csv),
                 csv + ":2: a line longer than 64 KiB, the limit for an elements file (its lines are short rows; is this the right file?)",
                 "pairs big.csv");
  const std::string scene = dir + "/big.json";
  write_text(scene, "{\"gravity\": [0, " + std::string(2'000'000, '1') + "]}");  // 2 MB: the JSON lexer reads it all
  expect_refused(run("headless --scene " + scene + " --frames 1"),
                 scene + ":1: gravity: JSON syntax error: number out of range '" + std::string(37, '1') + "...' (not a finite double)",
                 "headless big.json");
}

TEST(HostileCli, ARecordingHeaderGivenTwiceIsRefused) {
  const std::string dir = scratch_dir("hostile_nbsrec_twice");
  const std::string rec = dir + "/r.nbsrec";
  write_text(rec, "nbsrec 1\ncell_size 1\norigin 0,0\ncell_size 2\nframe 0 0\n0,0,0.1\n");
  expect_refused(run("replay " + rec + " --headless"), rec + ":4: cell_size given twice (first on line 2)", "replay r.nbsrec");
  // Once, it replays.
  write_text(rec, "nbsrec 1\ncell_size 1\norigin 0,0\nframe 0 0\n0,0,0.1\n");
  EXPECT_EQ(run("replay " + rec + " --headless").exit_code, 0);
}

// Help for a command that is not one, its name unprintable too: one escaped line, exit 2, no page.
TEST(HostileCli, HelpOfAnUnknownCommandIsOneLine) {
  expect_refused(run("help bogus"), "bogus: unknown command (see nbscope --help)", "help bogus");
  expect_refused(run("help \"$(printf 'bo\\001gus')\""), "bo\\x01gus: unknown command (see nbscope --help)", "help bo^Agus");
  expect_refused(run("help pairs --markdown"), "--markdown: prints every command; give no command", "help pairs --markdown");
}

}  // namespace
}  // namespace nbscope
