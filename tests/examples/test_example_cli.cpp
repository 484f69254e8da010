// The example plugins through the nbscope binary, as a user runs them: headless --detector-lib on the
// scene that shows the bug stops at the first violation with exit 1, and the report names the
// invariant (and for the cells check, the element and both cells); the reference passes.
#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

#include "support/paths.hpp"
#include "support/run_cli.hpp"

namespace nbscope {
namespace {

using nlohmann::json;
using testcli::run;
using testpaths::scene;

std::string lib(const std::string& name) { return std::string(NBSCOPE_EXAMPLES_DIR) + "/" + name + ".so"; }

// headless --stop-at-violation with the plugin as the algorithm; the first violation of the report.
json first_violation(const std::string& plugin, const std::string& algorithm, const std::string& on, int& exit_code) {
  // One folder per test and plugin: ctest runs tests side by side, and two of them run nbs_bug_trunc.
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::string dir = testcli::scratch_dir("example_cli_" + test + "_" + plugin);
  const auto r = run("headless --scene '" + scene(on) + "' --frames 120 --detector-lib '" + lib(plugin) + "' --algorithm " + algorithm +
                     " --stop-at-violation --quiet --report '" + dir + "/r.json'");
  exit_code = r.exit_code;
  EXPECT_EQ(r.err, "") << r.err;
  const json rep = json::parse(testcli::read_text(dir + "/r.json"));
  for (const json& f : rep["runs"][0]["frames"])
    if (!f["violations"].empty()) return f["violations"][0];
  ADD_FAILURE() << plugin << ": no violation listed";
  return json();
}

TEST(ExampleCli, EachBugStopsTheRunOnItsInvariant) {
  const struct {
    const char *plugin, *algorithm, *scene, *invariant;
  } cases[] = {{"nbs_bug_mask", "nbs-bug-mask", "pile", "A==R"},
               {"nbs_bug_trunc", "nbs-bug-trunc", "left-of-origin", "cells"},
               {"nbs_bug_push", "nbs-bug-push", "pile", "A==R"},
               {"nbs_bug_strict", "nbs-bug-strict", "lattice", "A==R"},
               {"nbs_bug_stale", "nbs-bug-stale", "pile", "cells"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.plugin);
    int exit_code = -1;
    const json v = first_violation(c.plugin, c.algorithm, c.scene, exit_code);
    EXPECT_EQ(exit_code, 1);
    EXPECT_EQ(v["invariant"], c.invariant) << v.dump();
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

}  // namespace
}  // namespace nbscope
