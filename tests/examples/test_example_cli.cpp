// The example plugins through the nbscope binary, as a user runs them: headless --detector-lib on the
// scene that shows the bug stops at the first violation with exit 1, and the report names the
// invariant (and for the cells check, the element and both cells); the reference passes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <vector>
#include <nlohmann/json.hpp>
#include <map>
#include <string>

#include "support/paths.hpp"
#include "support/run_cli.hpp"
#include "support/x_display.hpp"

namespace nbscope {
namespace {

using nlohmann::json;
using testcli::run;
using testpaths::scene;

std::string lib(const std::string& name) { return std::string(NBSCOPE_EXAMPLES_DIR) + "/" + name + ".so"; }

// headless --stop-at-violation with the plugin's library (and `algorithm`, when not empty); the first
// violation of the report. `summary` receives the run's line on stdout.
json first_violation(const std::string& plugin, const std::string& algorithm, const std::string& on, int& exit_code,
                     std::string* summary = nullptr) {
  // One folder per test and plugin: ctest runs tests side by side, and two of them run nbs_bug_trunc.
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::string dir = testcli::scratch_dir("example_cli_" + test + "_" + plugin);
  const auto r = run("headless --scene '" + scene(on) + "' --frames 120 --detector-lib '" + lib(plugin) + "'" +
                     (algorithm.empty() ? "" : " --algorithm " + algorithm) + " --stop-at-violation --report '" + dir + "/r.json'");
  exit_code = r.exit_code;
  if (summary != nullptr) *summary = r.out;
  EXPECT_EQ(r.err, "") << r.err;
  const json rep = json::parse(testcli::read_text(dir + "/r.json"));
  for (const json& f : rep["runs"][0]["frames"])
    if (!f["violations"].empty()) return f["violations"][0];
  ADD_FAILURE() << plugin << ": no violation listed";
  return json();
}

// A row of examples/detectors/README.md's table: the plugin, the scene that shows its bug, the
// invariant nbscope names (the first `code` of its "what nbscope says" column).
struct ReadmeRow {
  std::string plugin, scene, invariant;
};

// The cell text between backticks, "" if none.
std::string first_code(const std::string& cell) {
  const std::size_t a = cell.find('`'), b = a == std::string::npos ? a : cell.find('`', a + 1);
  return b == std::string::npos ? "" : cell.substr(a + 1, b - a - 1);
}

std::vector<ReadmeRow> readme_rows() {
  std::istringstream in(testcli::read_text(std::string(NBSCOPE_SOURCE_DIR) + "/examples/detectors/README.md"));
  std::vector<ReadmeRow> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| `nbs_bug_", 0) != 0) continue;
    std::vector<std::string> cells;
    std::istringstream cols(line.substr(1));
    for (std::string c; std::getline(cols, c, '|');) cells.push_back(c);
    if (cells.size() < 4) continue;
    std::string scene = first_code(cells[2]);
    if (scene.size() > 5 && scene.compare(scene.size() - 5, 5, ".json") == 0) scene.resize(scene.size() - 5);
    rows.push_back({first_code(cells[0]), scene, first_code(cells[3])});
  }
  return rows;
}

// The name a plugin declares: nbs_bug_mask.so declares nbs-bug-mask.
std::string declared(std::string plugin) {
  std::replace(plugin.begin(), plugin.end(), '_', '-');
  return plugin;
}

// The README names, for each of the five bugs, the bundled scene that shows it; run as a user runs
// it (the library alone, no --algorithm), each is caught there on the invariant the table names, and
// the summary names the library's detector, not a built-in.
TEST(ExampleCli, EachBugIsCaughtOnTheSceneTheReadmeNames) {
  const std::vector<ReadmeRow> rows = readme_rows();
  ASSERT_EQ(rows.size(), 5u) << "examples/detectors/README.md's table lost a row";
  for (const ReadmeRow& row : rows) {
    SCOPED_TRACE(row.plugin + " on " + row.scene);
    ASSERT_TRUE(std::filesystem::exists(scene(row.scene))) << "the README names a scene that is not bundled";
    int exit_code = -1;
    std::string summary;
    const json v = first_violation(row.plugin, "", row.scene, exit_code, &summary);
    EXPECT_EQ(exit_code, 1);
    EXPECT_EQ(v["invariant"], row.invariant) << v.dump();
    EXPECT_NE(summary.find(", " + declared(row.plugin) + " (" + row.plugin + ".so), "), std::string::npos) << summary;
  }
}

// Each bug located from the command line (issue 37): the summary ends with the operation that
// decided its first violation, the report's "located" object says which (kind, pseudocode line),
// the frame's first broken contract leads, the pair's finding is its detail, and the sentence is the
// diagnosis the window's Stepper gives for that bug.
TEST(ExampleCli, EachBugIsLocatedInTheSummaryAndTheReport) {
  const std::map<std::string, std::pair<std::string, std::string>> expected = {
      {"nbs_bug_mask", {"visit-cell", "contract mask-relates broken: no element's mask visits its neighbour at (+1,-1)"}},
      {"nbs_bug_push", {"push", "contract list-link broken: the push of"}},
      {"nbs_bug_stale", {"phase", "this clearing leaves x-list B["}},
      {"nbs_bug_trunc", {"push", "contract list-cell broken"}},
      {"nbs_bug_strict", {"test-pair", "contract test-answer broken"}},
  };
  for (const ReadmeRow& row : readme_rows()) {
    SCOPED_TRACE(row.plugin + " on " + row.scene);
    const std::string dir = testcli::scratch_dir("example_cli_located_" + row.plugin);
    const auto r = run("headless --scene '" + scene(row.scene) + "' --frames 120 --detector-lib '" + lib(row.plugin) +
                       "' --stop-at-violation --report '" + dir + "/r.json'");
    ASSERT_EQ(r.exit_code, 1) << r.out << r.err;
    const auto& [kind, words] = expected.at(row.plugin);
    EXPECT_NE(r.out.find("; located: operation "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(words), std::string::npos) << r.out;
    const json located = json::parse(testcli::read_text(dir + "/r.json"))["runs"][0]["violations"]["located"];
    ASSERT_TRUE(located.is_object()) << located.dump();
    EXPECT_EQ(located["kind"], kind) << located.dump();
    EXPECT_FALSE(located["contract"].is_null()) << "the frame's first broken contract leads: " << located.dump();
    EXPECT_NE(located["text"].get<std::string>().find(" Detail: "), std::string::npos) << "the pair's finding under it";
    EXPECT_GT(located["operation"].get<int>(), 0);
    EXPECT_LE(located["operation"].get<int>(), located["operations"].get<int>());
    EXPECT_GT(located["line"].get<int>(), 0) << "a pseudocode line";
    EXPECT_FALSE(located["pseudocode"].get<std::string>().empty());
    EXPECT_NE(located["text"].get<std::string>().find(words), std::string::npos) << located.dump();
  }
}

// The cells check names one element as the pair (k, k), with the detector's cell and then the grid's:
// one column to the right of the grid's, left of x = 0 (world columns -1 and 0 share a key).
TEST(ExampleCli, TheCellsViolationNamesTheElementAndBothCells) {
  int exit_code = -1;
  const json v = first_violation("nbs_bug_trunc", "nbs-bug-trunc", "left-of-origin", exit_code);
  ASSERT_TRUE(v.is_object());
  EXPECT_EQ(v["pair"][0], v["pair"][1]);
  EXPECT_EQ(v["cells"][0][0].get<int>(), v["cells"][1][0].get<int>() + 1) << v.dump();
  EXPECT_EQ(v["cells"][0][1], v["cells"][1][1]) << v.dump();
}

// A stale list names the stray and the element whose walk found it, the list's cell (where the
// detector had the stray) and the finder's: the row below the finder's, within one column.
TEST(ExampleCli, TheStaleListViolationNamesTheStrayAndBothCells) {
  int exit_code = -1;
  const json v = first_violation("nbs_bug_stale", "nbs-bug-stale", "pile", exit_code);
  ASSERT_TRUE(v.is_object());
  EXPECT_NE(v["pair"][0], v["pair"][1]) << v.dump();
  EXPECT_LE(std::abs(v["cells"][0][0].get<int>() - v["cells"][1][0].get<int>()), 1) << v.dump();
  EXPECT_EQ(v["cells"][0][1].get<int>() + 1, v["cells"][1][1].get<int>()) << v.dump();
  EXPECT_NE(v["what"].get<std::string>().find("stale list"), std::string::npos) << v.dump();
}

TEST(ExampleCli, TheReferencePassesWithEveryCheck) {
  const auto r = run("headless --scene '" + scene("pile") + "' --frames 60 --quiet --detector-lib '" + lib("nbs_reference") +
                     "' --algorithm nbs-reference,nbs");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

// ---- a library without --algorithm -------------------------------------------------------------

// 600 discs of radius 0.5 scattered over a 20 x 20 square (a fixed LCG): many pairs across the
// diagonal neighbour (ix+1, iy-1) that nbs_bug_mask's contact mask leaves out.
std::string scattered_csv(const std::string& dir) {
  std::string text = "x,y,r\n";
  std::uint64_t s = 12345;
  const auto next = [&s] {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) / static_cast<double>(1ULL << 53);
  };
  for (int i = 0; i < 600; ++i) text += std::to_string(20 * next()) + "," + std::to_string(20 * next()) + ",0.5\n";
  testcli::write_text(dir + "/scattered.csv", text);
  return dir + "/scattered.csv";
}

// pairs, dump and scaling with a library alone give the library's pairs, arrays and times: the same
// as naming its detector, never the built-in nbs (whose pairs the bug's differ from).
TEST(ExampleCli, ALibraryAloneGivesItsPairsArraysAndTimes) {
  const std::string dir = testcli::scratch_dir("example_cli_alone_files");
  const std::string csv = "--input '" + scattered_csv(dir) + "' --detector-lib '" + lib("nbs_bug_mask") + "'";
  const auto alone = run("pairs " + csv), named = run("pairs " + csv + " --algorithm nbs-bug-mask"), builtin = run("pairs " + csv + " --algorithm nbs");
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  EXPECT_EQ(alone.out, named.out);
  EXPECT_NE(alone.out, builtin.out) << "the bug loses no pair here: the test cannot tell the detectors apart";
  EXPECT_EQ(alone.err.rfind("nbscope: nbs-bug-mask (nbs_bug_mask.so): 600 elements (2D), ", 0), 0u) << alone.err;

  const auto dump = run("dump " + csv);
  ASSERT_EQ(dump.exit_code, 0) << dump.err;
  EXPECT_EQ(json::parse(dump.out).at("algorithm"), "nbs-bug-mask");
  EXPECT_EQ(dump.out, run("dump " + csv + " --algorithm nbs-bug-mask").out);

  const auto scaling = run("scaling --n 1000..2000 --detector-lib '" + lib("nbs_bug_mask") + "'");
  ASSERT_EQ(scaling.exit_code, 0) << scaling.err;
  std::istringstream rows(scaling.out);
  int measured = 0;
  for (std::string line; std::getline(rows, line);) {
    if (line.rfind("algorithm", 0) == 0 || line.empty()) continue;
    EXPECT_EQ(line.rfind("nbs-bug-mask ", 0), 0u) << "a row of another detector: " << line;
    ++measured;
  }
  EXPECT_GT(measured, 0) << scaling.out;
}

// replay and the window (its no-display fallback) with the library alone catch the bug (exit 1) and
// name the library; a recording of the scene the README names for the bug.
TEST(ExampleCli, ALibraryAloneIsCaughtInReplayAndTheWindow) {
  const std::string dir = testcli::scratch_dir("example_cli_alone_frames");
  const std::string rec = dir + "/pile.nbsrec";
  ASSERT_EQ(run("headless --scene '" + scene("pile") + "' --frames 60 --quiet --record '" + rec + "'").exit_code, 0);
  const auto replay = run("replay '" + rec + "' --headless --detector-lib '" + lib("nbs_bug_mask") + "'");
  EXPECT_EQ(replay.exit_code, 1) << replay.out << replay.err;
  EXPECT_EQ(replay.out.rfind("replay: pile, nbs-bug-mask (nbs_bug_mask.so), ", 0), 0u) << replay.out;

#ifdef NBSCOPE_TEST_GUI  // the window and its off-screen fallback are built
  const auto gui = run("gui --scene '" + scene("pile") + "' --frames 60 --screenshot '" + dir + "/gui.png' --detector-lib '" +
                       lib("nbs_bug_mask") + "'", "env -u DISPLAY -u WAYLAND_DISPLAY");
  EXPECT_EQ(gui.exit_code, 1) << gui.err;
  EXPECT_NE(gui.err.find("rendered 60 frames of nbs-bug-mask (nbs_bug_mask.so) headless"), std::string::npos) << gui.err;

  if (!testcli::have_xvfb()) return;  // the window itself needs an X server
  const auto window = run("gui --scene '" + scene("pile") + "' --frames 60 --screenshot '" + dir + "/window.png' --detector-lib '" +
                          lib("nbs_bug_mask") + "'", testcli::on_display());
  EXPECT_EQ(window.exit_code, 1) << window.err;
  EXPECT_NE(window.err.find("algorithm nbs-bug-mask (nbs_bug_mask.so)"), std::string::npos) << window.err;
#endif
}

// Several libraries: a command that runs one asks which (one line naming them); headless runs all.
TEST(ExampleCli, SeveralLibrariesRunTogetherOrAskForOne) {
  const std::string libs = " --detector-lib '" + lib("nbs_bug_mask") + "' --detector-lib '" + lib("nbs_reference") + "'";
  const auto pairs = run("pairs --input '" + testpaths::nine_csv() + "'" + libs);
  EXPECT_EQ(pairs.exit_code, 2);
  EXPECT_EQ(pairs.err, "nbscope: error: --detector-lib: the libraries declare 2 detectors (nbs-bug-mask, nbs-reference): "
                       "choose one with --algorithm\n");
  const auto headless = run("headless --scene '" + scene("pile") + "' --frames 30" + libs);
  EXPECT_EQ(headless.exit_code, 1) << headless.err;
  EXPECT_EQ(headless.out.rfind("headless: pile, nbs-bug-mask (nbs_bug_mask.so),nbs-reference (nbs_reference.so), ", 0), 0u)
      << headless.out;
}

// --algorithm takes a library's file name where it names one library; two libraries of one file name
// that declare different detectors are refused, naming both.
TEST(ExampleCli, TheFileNameOfALibraryNamesItsDetector) {
  const std::string csv = "pairs --input '" + testpaths::nine_csv() + "' --detector-lib '" + lib("nbs_bug_push") + "'";
  const auto by_file = run(csv + " --algorithm nbs_bug_push");
  ASSERT_EQ(by_file.exit_code, 0) << by_file.err;
  EXPECT_EQ(by_file.err.rfind("nbscope: nbs-bug-push (nbs_bug_push.so): ", 0), 0u) << by_file.err;

  const std::string dir = testcli::scratch_dir("example_cli_file_name");
  std::filesystem::create_directories(dir + "/a");
  std::filesystem::create_directories(dir + "/b");
  std::filesystem::copy_file(lib("nbs_bug_mask"), dir + "/a/mine.so");
  std::filesystem::copy_file(lib("nbs_bug_push"), dir + "/b/mine.so");
  const auto twice = run("headless --scene '" + scene("pile") + "' --frames 1 --detector-lib '" + dir + "/a/mine.so' --detector-lib '" +
                         dir + "/b/mine.so' --algorithm mine");
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_EQ(twice.err, "nbscope: error: --algorithm: 'mine' is the file name of 2 libraries (" + dir + "/a/mine.so declares 'nbs-bug-mask', " +
                           dir + "/b/mine.so declares 'nbs-bug-push'): name the detector\n");
}

}  // namespace
}  // namespace nbscope
