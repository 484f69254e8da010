// `nbscope headless` end to end: a passing run and its report, every fault caught by the invariant
// it breaks, comparison of algorithms on the same frames, and bad scenes and options (exit 2, one
// line naming file:line:field, no report file).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/paths.hpp"
#include "support/run_cli.hpp"

namespace nbscope {
namespace {

using nlohmann::json;
using testcli::read_text;
using testcli::run;
using testcli::scratch_dir;
using testcli::write_text;

using testpaths::scene;

TEST(Headless, DefaultScenePassesAndReportsEveryFrame) {
  const std::string dir = scratch_dir("headless_default");
  const auto r = run("headless --scene '" + scene("default") + "' --frames 90 --report '" + dir + "/r.json'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "");  // stderr is not a terminal here: no progress bar
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1);
  // Frames 0..90: frame 0 (the initial poses) is detected and checked like the others.
  EXPECT_NE(r.out.find("headless: default, nbs, 91 frames"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("all 6 invariants held in every frame (reference brute)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ms per frame: physics"), std::string::npos);

  const json rep = json::parse(read_text(dir + "/r.json"));
  EXPECT_EQ(rep["passed"], true);
  EXPECT_EQ(rep["frames_requested"], 91);
  EXPECT_EQ(rep["fault"]["name"], "none");
  EXPECT_NE(rep["a_in_f_scope"].get<std::string>().find("Box2D's filters are applied to A"), std::string::npos);
  ASSERT_EQ(rep["runs"].size(), 1u);
  const json& run0 = rep["runs"][0];
  EXPECT_EQ(run0["algorithm"], "nbs");
  ASSERT_EQ(run0["frames"].size(), 91u);
  std::int64_t frame = -1;
  for (const json& f : run0["frames"]) {
    EXPECT_EQ(f["frame"], ++frame);
    for (const char* inv : {"A==R", "A-in-F", "T-in-A", "AABB-in-cells"}) {
      // Box2D's contact list exists only after a step: frame 0 does not check A-in-F.
      const bool unchecked = frame == 0 && std::string(inv) == "A-in-F";
      EXPECT_EQ(f["held"][inv], unchecked ? json(nullptr) : json(true)) << frame << " " << inv;
    }
    EXPECT_EQ(f["pairs"]["A"], f["pairs"]["R"]);
    EXPECT_GT(f["pairs"]["T"].get<int>(), 0);
    EXPECT_GE(f["ms"]["physics"].get<double>(), 0);
    // The check's time by part: the sets, then each invariant.
    for (const char* part : {"R", "F", "G/T", "A==R", "A-in-F", "T-in-A", "AABB-in-cells"})
      EXPECT_GE(f.at("check_ms_parts").at(part).get<double>(), 0) << frame << " " << part;
    EXPECT_EQ(f["reference"], "brute");
  }
  EXPECT_GE(run0.at("check_ms_parts").at("G/T").at("mean").get<double>(), 0);
  EXPECT_NE(r.out.find(", check "), std::string::npos);
  EXPECT_NE(r.out.find("AABB-in-cells "), std::string::npos) << r.out;  // the summary's check split
  // The scene has compound bodies, statics touching statics and polygons: Box2D's filters are exercised.
  const json& last = run0["frames"].back();
  EXPECT_GT(last["left_out_of_A_in_F"]["same_body"].get<int>(), 0);
  EXPECT_GT(last["left_out_of_A_in_F"]["no_dynamic"].get<int>(), 0);
  EXPECT_GT(last["left_out_of_A_in_F"]["beyond_aabb"].get<int>(), 0);
}

struct FaultCase {
  const char* fault;
  const char* invariant;  // one invariant that must catch it
};

class HeadlessFault : public ::testing::TestWithParam<FaultCase> {};

TEST_P(HeadlessFault, IsCaughtOnTheDefaultScene) {
  const FaultCase& c = GetParam();
  // One directory per case: two cases of one fault run at once under ctest -j.
  std::string name = std::string("headless_fault_") + c.fault + "_" + c.invariant;
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_') ch = '-';
  const std::string dir = scratch_dir(name);
  const auto r = run("headless --scene '" + scene("default") + "' --frames 60 --inject-fault " + c.fault + " --report '" + dir + "/r.json'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find(std::string("fault ") + c.fault), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(std::string(c.invariant) + " "), std::string::npos) << r.out;
  const json rep = json::parse(read_text(dir + "/r.json"));
  EXPECT_EQ(rep["passed"], false);
  EXPECT_EQ(rep["fault"]["name"], c.fault);
  const json& run0 = rep["runs"][0];
  EXPECT_GT(run0["violations"]["by_invariant"][c.invariant].get<int>(), 0);
  // The violations themselves name frame, pair, both cells and the invariant.
  bool listed = false;
  for (const json& f : run0["frames"]) {
    for (const json& v : f["violations"]) {
      if (v["invariant"] != c.invariant) continue;
      listed = true;
      EXPECT_EQ(v["pair"].size(), 2u);
      EXPECT_LT(v["pair"][0].get<int>(), v["pair"][1].get<int>());
      EXPECT_EQ(v["cells"].size(), 2u);
      EXPECT_EQ(f["held"][c.invariant], false);
    }
  }
  EXPECT_TRUE(listed);
}

INSTANTIATE_TEST_SUITE_P(All, HeadlessFault,
                         ::testing::Values(FaultCase{"drop-mask-cell", "A==R"}, FaultCase{"drop-mask-cell", "T-in-A"},
                                           FaultCase{"off-by-one-cell", "A==R"}, FaultCase{"off-by-one-cell", "AABB-in-cells"},
                                           FaultCase{"stale-positions", "A==R"}, FaultCase{"drop-pair", "A==R"},
                                           FaultCase{"drop-pair", "T-in-A"}, FaultCase{"drop-box2d-contact", "A-in-F"}),
                         [](const ::testing::TestParamInfo<FaultCase>& info) {
                           std::string name = std::string(info.param.fault) + "_" + info.param.invariant;
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

TEST(Headless, ComparesSeveralAlgorithmsOnTheSameFrames) {
  const std::string dir = scratch_dir("headless_compare");
  const auto r = run("headless --scene '" + scene("default") + "' --frames 20 --algorithm nbs,box2d,brute --report '" + dir + "/r.json'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("nbs,box2d,brute"), std::string::npos) << r.out;
  const json rep = json::parse(read_text(dir + "/r.json"));
  ASSERT_EQ(rep["runs"].size(), 3u);
  EXPECT_EQ(rep["runs"][2]["algorithm"], "brute");
  EXPECT_EQ(rep["runs"][2]["frames"][0]["reference"], "sort");  // brute is never its own reference
  for (std::size_t k = 0; k < 20; ++k)
    EXPECT_EQ(rep["runs"][0]["frames"][k]["pairs"]["A"], rep["runs"][1]["frames"][k]["pairs"]["A"]);
}

TEST(Headless, AllRunsEveryTwoDimensionalDetector) {
  const auto r = run("headless --scene '" + scene("book-fig-3-15") + "' --frames 2 --algorithm all");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  for (const char* name : {"brute", "nbs", "box2d"}) EXPECT_NE(r.out.find(name), std::string::npos) << r.out;
}

TEST(Headless, BookFigureSceneKeepsTheBooksGrid) {
  const std::string dir = scratch_dir("headless_book");
  const auto r = run("headless --scene '" + scene("book-fig-3-15") + "' --frames 1 --report '" + dir + "/r.json'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const json f = json::parse(read_text(dir + "/r.json"))["runs"][0]["frames"][0];
  EXPECT_EQ(f["elements"], 9);
  EXPECT_EQ(f["pairs"]["A"], 1);  // book elements 1 and 2 (0 and 1 here) are 0.158 apart, radii 0.1
  EXPECT_EQ(f["pairs"]["F"], 0);  // static bodies never make Box2D contacts
}

struct BadRun {
  const char* name;
  const char* scene_text;  // written to in.json; nullptr: no file
  const char* args;        // after "headless --scene IN"
  const char* message;     // after "nbscope: error: "; IN stands for the scene path
};

class HeadlessBadInput : public ::testing::TestWithParam<BadRun> {};

TEST_P(HeadlessBadInput, ExitsTwoWithOneLineAndNoReport) {
  const BadRun& c = GetParam();
  const std::string dir = scratch_dir(std::string("headless_bad_") + c.name);
  const std::string in = dir + "/in.json";
  if (c.scene_text) write_text(in, c.scene_text);
  const auto r = run("headless --scene '" + in + "' --frames 3 --report '" + dir + "/r.json' " + c.args);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  std::string expected = std::string("nbscope: error: ") + c.message + "\n";
  for (auto p = expected.find("IN:"); p != std::string::npos; p = expected.find("IN:", p + in.size())) expected.replace(p, 2, in);
  if (const auto p = expected.find("ALGOS"); p != std::string::npos) {
    EXPECT_EQ(r.err.substr(0, p), expected.substr(0, p));  // the list grows with the registry
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  } else {
    EXPECT_EQ(r.err, expected);
  }
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(std::filesystem::exists(dir + "/r.json"));
}

const char* kGoodScene = R"({"bodies": [{"shape": "circle", "radius": 0.5}]})";

const BadRun kBadRuns[] = {
    {"syntax_error", "{\n  \"bodies\": [\n    {\"shape\": \"circle\",, \"radius\": 1}\n  ]\n}", "",
     "IN:3: bodies[0]: JSON syntax error: syntax error while parsing object key - unexpected ','; expected string literal"},
    {"missing_field", "{\"bodies\": [\n  {\"shape\": \"box\",\n   \"position\": [0, 0]}]}", "",
     "IN:2: bodies[0].half_extents: missing (a box needs [half width, half height])"},
    {"wrong_type", "{\n\"time_step\": \"fast\"}", "", "IN:2: time_step: must be a number, got a string \"fast\""},
    {"negative_radius", "{\"bodies\": [{\"shape\": \"circle\",\n\n \"radius\": -1}]}", "", "IN:3: bodies[0].radius: must be positive, got -1"},
    {"concave_polygon", "{\"bodies\": [{\"shape\": \"polygon\",\n \"vertices\": [[0, 0], [2, 0], [1, 0.5], [2, 2], [0, 2]]}]}", "",
     "IN:2: bodies[0].vertices[2]: polygon is not convex (concave at vertex 2)"},
    {"degenerate_polygon", "{\"bodies\": [{\"shape\": \"polygon\",\n \"vertices\": [[0, 0], [1, 1], [2, 2]]}]}", "",
     "IN:2: bodies[0].vertices[1]: degenerate polygon: vertices 0, 1, 2 are collinear"},
    {"nan", "{\"gravity\": [0,\n NaN]}", "", "IN:2: gravity: JSON syntax error: syntax error while parsing value - invalid literal; last read: 'N'"},
    {"ten_million_bodies", "{\"generators\": [{\"kind\": \"grid\", \"origin\": [0, 0], \"columns\": 10000,\n \"rows\": 1000}]}", "",
     "IN:2: generators[0].rows: 10000000 bodies requested in all; a scene holds at most 1000000"},
    {"cell_size_too_small", "{\"cell_size\": 0.5,\n \"bodies\": [{\"shape\": \"circle\", \"radius\": 1}]}", "",
     "IN:1: cell_size: smaller than the largest element's diameter 2"},
    {"cell_size_too_small_for_an_emitter", "{\"cell_size\": 1,\n \"bodies\": [{\"shape\": \"circle\", \"radius\": 0.4}],\n \"generators\": [\n"
     "  {\"kind\": \"emitter\", \"count\": 5, \"position\": [0, 5], \"rate\": 1, \"start\": 1,\n   \"body\": {\"shape\": \"circle\", \"radius\": 1}}]}", "",
     "IN:1: cell_size: smaller than the diameter 2 of the elements emitted by IN:4: generators[0]"},
    {"missing_file", nullptr, "", "IN: cannot open the scene file (no such file or not readable)"},
    {"unknown_algorithm", kGoodScene, "--algorithm quadtree", "unknown algorithm 'quadtree' (known: ALGOS)"},
    {"unknown_fault", kGoodScene, "--inject-fault gremlins",
     "--inject-fault: unknown fault 'gremlins' (known: drop-mask-cell, off-by-one-cell, stale-positions, drop-pair, drop-box2d-contact)"},
    {"bad_brute_limit", kGoodScene, "--brute-limit x", "--brute-limit: 'x' is not a whole number from 0 to 1000000"},
    {"unknown_flag", kGoodScene, "--fast", "headless: --fast is not an option of headless (see nbscope --help)"},
    {"option_of_another_command", kGoodScene, "--output x.csv", "headless: --output is not an option of headless (it is one of pairs, scaling)"},
    {"repeated_flag", kGoodScene, "--frames 4", "--frames: given more than once"},
    {"drawing_without_screenshot", kGoodScene, "--overlays grid",
     "--overlays: needs --screenshot (headless draws nothing without one)"},
};

INSTANTIATE_TEST_SUITE_P(All, HeadlessBadInput, ::testing::ValuesIn(kBadRuns),
                         [](const ::testing::TestParamInfo<BadRun>& info) { return std::string(info.param.name); });

// Counts agree in number: "1 violation in 1 frame", not "1 violations in 1 frames".
TEST(Headless, TheSummaryCountsInTheSingularWhenThereIsOne) {
  const std::string dir = scratch_dir("headless_singular");
  write_text(dir + "/two.json", R"({"gravity": [0, 0], "bodies": [{"shape": "circle", "radius": 0.5, "position": [0, 0]},
    {"shape": "circle", "radius": 0.5, "position": [0.9, 0]}]})");
  const auto r = run("headless --scene '" + dir + "/two.json' --frames 1 --inject-fault drop-box2d-contact");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.out.find(", 2 frames, 2 elements: 1 violation in 1 frame (A-in-F 1), first in frame 1"), std::string::npos) << r.out;
}

TEST(Headless, AnUnwritableReportFailsBeforeAnyFrame) {
  const std::string dir = scratch_dir("headless_bad_report");
  auto r = run("headless --scene '" + scene("default") + "' --frames 100000 --report '" + dir + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "nbscope: error: " + dir + ": cannot write: it is a directory\n");
  r = run("headless --scene '" + scene("default") + "' --frames 100000 --report '" + dir + "/no/r.json'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "nbscope: error: " + dir + "/no/r.json: cannot write: no directory " + dir + "/no\n");
}

TEST(Headless, AReportOverTheSceneOrTheRecordingIsRefused) {
  const std::string dir = scratch_dir("headless_same_paths");
  const std::string copy = dir + "/s.json";
  std::filesystem::copy_file(scene("book-fig-3-15"), copy);
  auto r = run("headless --scene '" + copy + "' --frames 2 --report '" + copy + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "nbscope: error: " + copy + ": cannot write: it is also the --scene\n");
  EXPECT_EQ(testcli::read_text(copy), testcli::read_text(scene("book-fig-3-15")));
  r = run("headless --scene '" + copy + "' --frames 2 --record '" + dir + "/x' --report '" + dir + "/x'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "nbscope: error: " + dir + "/x: cannot write: it is also the --report\n");
  EXPECT_FALSE(std::filesystem::exists(dir + "/x"));
}

TEST(Headless, SceneIsRequired) {
  const auto r = run("headless --frames 3");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "nbscope: error: headless: --scene FILE is required\n");
}

}  // namespace
}  // namespace nbscope
