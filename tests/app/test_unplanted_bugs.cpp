// Bugs nobody planted (issue 37), through the binary: nbs_reference.c with one line changed
// (tests/plugins/CMakeLists.txt), each diagnosed by the contract it breaks in the headless summary
// and the report, and never a hang or an API error.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "support/paths.hpp"
#include "support/run_cli.hpp"

namespace nbscope {
namespace {

using nlohmann::json;
using testcli::run;
using testpaths::scene;

std::string bug(const std::string& variant) { return std::string(NBSCOPE_PLUGIN_DIR) + "/test_bug_" + variant + ".so"; }

struct Diagnosed {
  testcli::Result run;
  json report;
};

// A headless run of the bug on pile.json for `frames` frames, with its report.
Diagnosed diagnose(const std::string& variant, int frames) {
  const std::string dir = testcli::scratch_dir("unplanted_" + variant);
  Diagnosed d;
  d.run = run("headless --scene '" + scene("pile") + "' --frames " + std::to_string(frames) + " --detector-timeout 60 --detector-lib '" +
              bug(variant) + "' --report '" + dir + "/r.json'");
  d.report = json::parse(testcli::read_text(dir + "/r.json"));
  return d;
}

// The row loop stops one row early: the top row's x-lists are never built and its contacts never
// tested. Its cells on x are never written either (the reference writes them in the row loop), an
// API rule broken only after the call: the row not processed comes first, at the loop that skipped it.
TEST(UnplantedBugs, ARowLoopThatStopsEarlyIsARowNotProcessed) {
  const Diagnosed d = diagnose("row_early", 2);
  EXPECT_EQ(d.run.exit_code, 1) << d.run.out << d.run.err;
  EXPECT_EQ(d.run.err, "");
  EXPECT_NE(d.run.out.find("located: operation "), std::string::npos) << d.run.out;
  EXPECT_NE(d.run.out.find("contract row-processed broken: row 39 holds elements"), std::string::npos) << d.run.out;
  const json& located = d.report["runs"][0]["violations"]["located"];
  ASSERT_TRUE(located.is_object()) << d.report.dump();
  EXPECT_EQ(located["contract"], "row-processed");
  EXPECT_EQ(located["kind"], "phase");
  EXPECT_EQ(located["line"], 3) << "the loop over the rows: " << located.dump();
  const json& frame0 = d.report["runs"][0]["frames"][0];
  EXPECT_EQ(frame0["held"]["contract"], false);
  EXPECT_EQ(frame0["contract"].get<std::string>().rfind("row-processed: row 39", 0), 0u) << frame0.dump();
}

// The y heads are never reset: frame 0 ends with its y heads set (heads-cleared, at the clearing of
// the y-lists, the bug's own line); frame 1's first push links into frame 0's list (a stale link), its
// lists close into cycles, and nbscope stops the call there instead of waiting for the watchdog.
TEST(UnplantedBugs, HeadsKeptBetweenFramesAreAStaleLinkAndTheCycleEndsTheFrameNotTheRun) {
  const Diagnosed d = diagnose("heads_kept", 3);
  EXPECT_EQ(d.run.exit_code, 1) << d.run.out << d.run.err;
  EXPECT_EQ(d.run.err, "") << "no hang, no API error";
  const json& located = d.report["runs"][0]["violations"]["located"];
  ASSERT_TRUE(located.is_object()) << d.report.dump();
  EXPECT_EQ(located["frame"], 0);
  EXPECT_EQ(located["contract"], "heads-cleared");
  EXPECT_EQ(located["kind"], "phase");
  EXPECT_EQ(located["line"], 10) << "the clearing of the y heads: " << located.dump();
  EXPECT_NE(located["text"].get<std::string>().find("y_heads["), std::string::npos) << located.dump();
  const json& frames = d.report["runs"][0]["frames"];
  ASSERT_EQ(frames.size(), 4u) << "every frame ran: the cycle ended its frame only";
  const std::string frame1 = frames[1]["contract"].get<std::string>();
  EXPECT_EQ(frame1.rfind("list-link: ", 0), 0u) << frame1;
  EXPECT_NE(frame1.find("runs on into the last frame's list"), std::string::npos) << frame1;
  EXPECT_NE(frame1.find("cycle: "), std::string::npos) << "the cycle that ended the call, named: " << frame1;
  for (int f = 0; f <= 3; ++f) {
    EXPECT_EQ(frames[f]["held"]["contract"], false) << "frame " << f;
  }
}

// A 3D NBS (3D-only, as nbs3d_reference.c) whose mask leaves out the cell (+1, +1, -1) of the layer
// below: replayed on the LIGGGHTS pour's 3D frame, the mask relates no two cells that way.
TEST(UnplantedBugs, A3DMaskThatLeavesOutACellOfTheLayerBelowRelatesNoCellsThatWay) {
  const std::string dir = testcli::scratch_dir("unplanted_mask3d");
  const auto r = run("replay --headless --dump '" + std::string(NBSCOPE_SOURCE_DIR) + "/assets/examples/pour3d/atoms.6000.dump' --detector-lib '" +
                     bug("mask3d") + "' --report '" + dir + "/r.json'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_EQ(r.err, "") << "a 3D-only plugin replays a 3D dump";
  EXPECT_NE(r.out.find("contract mask-relates broken: no element's mask visits its neighbour at (+1,+1,-1) nor at (-1,-1,+1)"),
            std::string::npos) << r.out;
  const json located = json::parse(testcli::read_text(dir + "/r.json"))["runs"][0]["violations"]["located"];
  ASSERT_TRUE(located.is_object());
  EXPECT_EQ(located["contract"], "mask-relates");
  EXPECT_EQ(located["kind"], "visit-cell");
  EXPECT_EQ(located["line"], 11) << "the mask's pseudocode line: " << located.dump();
}

// A crash and a hang inside a traced call take only the plugin's host process down: each is its
// frame's api-rule violation (exit 1), located after the last operation the call traced, with the
// trace recorded again up to it (the Stepper goes there). In nbscope's process (--detector-isolation
// none) the one line (exit 2) names that operation instead.
TEST(UnplantedBugs, ACrashOrAHangInATracedCallIsLocatedAtItsLastOperation) {
  for (const std::string& variant : {std::string("crash_traced"), std::string("hang_traced")}) {
    SCOPED_TRACE(variant);
    const std::string dir = testcli::scratch_dir("unplanted_last_" + variant);
    const std::string what = variant == "crash_traced" ? "crashed with SIGSEGV" : "did not return within 2 s";
    const std::string flags = " --frames 2 --detector-timeout 2 --detector-lib '" + bug(variant) + "'";
    auto r = run("headless --scene '" + scene("pile") + "'" + flags + " --report '" + dir + "/r.json'");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_NE(r.out.find("contract api-rule broken: " + what + " in nbscope_detect() on frame 0, after operation "), std::string::npos)
        << r.out;
    const json located = json::parse(testcli::read_text(dir + "/r.json"))["runs"][0]["violations"]["located"];
    ASSERT_TRUE(located.is_object());
    EXPECT_EQ(located["contract"], "api-rule");
    EXPECT_EQ(located["line"], 7) << "the visit of the mask: " << located.dump();
    const std::string at = std::to_string(located["operation"].get<long long>());
    EXPECT_NE(r.out.find("located: after operation " + at + " of " + at + ": "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("after operation " + at + " of its trace (visit-cell, pseudocode line 7)"), std::string::npos) << r.out;

    r = run("headless --scene '" + scene("pile") + "'" + flags + " --detector-isolation none");
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(what + " in nbscope_detect() on frame 0, after operation "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(" of its trace (visit-cell, pseudocode line 7)\n"), std::string::npos) << r.err;
  }
}

// A write past the cells buffer (a loop one element too far) faults on its guard page inside the
// plugin's call: a located crash, never nbscope's own heap corrupted (glibc's "free(): invalid size").
TEST(UnplantedBugs, AWritePastTheCellsIsALocatedCrashNotACorruptedHeap) {
  for (const std::string isolation : {"process", "none"}) {
    SCOPED_TRACE(isolation);
    const auto r = run("headless --scene '" + scene("pile") + "' --frames 2 --detector-isolation " + isolation + " --detector-lib '" +
                       bug("cells_past") + "'");
    EXPECT_EQ(r.exit_code, isolation == "none" ? 2 : 1) << r.out << r.err;
    const std::string& said = isolation == "none" ? r.err : r.out;
    EXPECT_NE(said.find("crashed with SIGSEGV in nbscope_detect() on frame 0, after operation "), std::string::npos) << said;
    EXPECT_NE(said.find(" of its trace (push, pseudocode line 2)"), std::string::npos) << said;
    EXPECT_EQ(r.err.find("free()"), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace nbscope
