// --detector-lib through the nbscope binary with the test plugins of tests/plugins/: a good plugin runs
// and compares like a built-in, a wrong but well-formed one fails its checks (exit 1), one that breaks
// the API in a frame has a `contract` violation there (exit 1; one error line, exit 1, where nothing is
// checked), so does one that crashes or hangs in a detection (in its host process), and every unusable
// plugin (refused at load, crashing or hanging in its load, describe, release or own_bytes, or in a
// detection in nbscope's process) is one error line naming the library (and the call or the frame), exit 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/paths.hpp"
#include "support/run_cli.hpp"
#include "support/x_display.hpp"

namespace nbscope {
namespace {

using testcli::run;
using testpaths::nine_csv;
using testpaths::scene;

// The test plugin library built with -DPLUGIN_<VARIANT> (tests/plugins/CMakeLists.txt).
std::string plugin(const std::string& variant) { return std::string(NBSCOPE_PLUGIN_DIR) + "/test_plugin_" + variant + ".so"; }

// The one error line the run should end with, and nothing else on stderr.
void expect_error(const testcli::Result& r, const std::string& line) {
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(r.err, "nbscope: error: " + line + "\n");
}

// A plugin's own bug where no check holds it (pairs, dump, scaling): its one line, exit 1.
void expect_bug(const testcli::Result& r, const std::string& line) {
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_EQ(r.err, "nbscope: error: " + line + "\n");
}

// A plugin's own bug in a checked run (headless, replay): a `contract` violation of its frame,
// located at the api-rule it broke; the run goes on (exit 1) and stderr stays quiet.
void expect_violation(const testcli::Result& r, const std::string& what) {
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("contract api-rule broken: " + what), std::string::npos) << r.out;
}

TEST(PluginCli, GoodPluginRunsAsTheAlgorithmAndAsAComparisonLane) {
  const std::string lib = plugin("good");
  auto r = run("headless --scene '" + scene("default") + "' --frames 30 --detector-lib '" + lib + "' --algorithm test-good");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("test-good"), std::string::npos) << r.out;
  r = run("headless --scene '" + scene("default") + "' --frames 30 --detector-lib '" + lib + "' --algorithm nbs,test-good");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  r = run("pairs --input '" + nine_csv() + "' --detector-lib='" + lib + "' --algorithm test-good");
  const auto builtin = run("pairs --input '" + nine_csv() + "' --algorithm nbs");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, builtin.out);
}

TEST(PluginCli, GoodPluginReplaysAndScales) {
  const std::string lib = plugin("good");
  const std::string dir = testcli::scratch_dir("plugin_replay");
  auto r = run("headless --scene '" + scene("default") + "' --frames 5 --record '" + dir + "/r.nbsrec'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run("replay '" + dir + "/r.nbsrec' --headless --detector-lib '" + lib + "' --algorithm nbs,test-good");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("nbs,test-good"), std::string::npos) << r.out;
  r = run("scaling --detector-lib '" + lib + "' --algorithm test-good --n 1e3..1e3 --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("test-good loose"), std::string::npos) << r.out;
}

#ifdef NBSCOPE_TEST_GUI
// The window (on the test's own Xvfb): the plugin is an algorithm of the window, and its breach is a
// violation of its frame there too: the window stays open on it.
TEST(PluginCli, WindowRunsThePluginAndShowsItsBreachAsAViolation) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string dir = testcli::scratch_dir("plugin_window");
  std::string lib = plugin("good");
  auto r = run("gui --scene '" + scene("default") + "' --frames 3 --screenshot '" + dir + "/good.png' --detector-lib '" + lib +
                   "' --algorithm test-good",
               testcli::on_display());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  lib = plugin("self_pair");
  r = run("gui --scene '" + scene("default") + "' --frames 3 --screenshot '" + dir + "/bad.png' --detector-lib '" + lib +
              "' --algorithm test-self-pair",
          testcli::on_display());
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;  // violations, as headless says them
  EXPECT_EQ(r.err.find("nbscope: error:"), std::string::npos) << r.err;
  // A crash in a traced detection takes only the plugin's host down: the window stays open on the
  // frame and shows it as its violation.
  lib = std::string(NBSCOPE_PLUGIN_DIR) + "/test_bug_crash_traced.so";
  r = run("gui --scene '" + scene("pile") + "' --frames 2 --screenshot '" + dir + "/crash.png' --detector-lib '" + lib + "'",
          testcli::on_display());
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_EQ(r.err.find("nbscope: error:"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(dir + "/crash.png"));
  // A bug that only the trace shows (a push traced with another row's cell, the lists and pairs right)
  // is found in the window, which records a tracing plugin's every frame for its contracts.
  lib = std::string(NBSCOPE_PLUGIN_DIR) + "/test_bug_trace_cell.so";
  const std::string scene_flags = "--scene '" + scene("pile") + "' --frames 2 --detector-lib '" + lib + "'";
  r = run("gui " + scene_flags + " --screenshot '" + dir + "/trace_cell.png'", testcli::on_display());
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  r = run("headless " + scene_flags);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("violations in 3 frames (contract 3)"), std::string::npos) << r.out;
}
#endif

// One call a frame (docs/plugins.md, "When nbscope calls it"): a stateful plugin that refuses a frame
// given twice in a row, and logs every call, runs through headless, replay, pairs, a headless
// screenshot with the lists overlay and the window with it; only --repeat calls it twice, as it says.
class CallLog {
 public:
  // A directory of its own: scratch_dir() empties the one it names, and the tests that log calls run in
  // parallel (one shared directory let the window test wipe the headless test's log mid-run).
  explicit CallLog(const std::string& name) : path_(testcli::scratch_dir("plugin_calls_" + name) + "/calls") {
    std::remove(path_.c_str());
    ::setenv("NBSCOPE_TEST_CALLS", path_.c_str(), 1);
  }
  ~CallLog() { ::unsetenv("NBSCOPE_TEST_CALLS"); }
  // The frames of the calls, in order.
  [[nodiscard]] std::vector<long long> frames() const {
    std::vector<long long> out;
    std::ifstream in(path_);
    for (long long f = 0; in >> f;) out.push_back(f);
    return out;
  }

 private:
  std::string path_;
};

// True when no frame was given twice in a row, and every frame 0..last once.
void expect_once_each(const std::vector<long long>& calls, long long last, const std::string& what) {
  std::vector<long long> want(static_cast<std::size_t>(last + 1));
  for (long long f = 0; f <= last; ++f) want[static_cast<std::size_t>(f)] = f;
  EXPECT_EQ(calls, want) << what;
}

TEST(PluginCli, AStatefulPluginIsCalledOncePerFrame) {
  const std::string lib = plugin("once_per_frame");
  const std::string with = " --detector-lib '" + lib + "' --algorithm test-once-per-frame";
  {
    const CallLog log("headless");
    const auto r = run("headless --scene '" + scene("default") + "' --frames 10 --quiet" + with);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    expect_once_each(log.frames(), 10, "headless");
  }
#ifdef NBSCOPE_TEST_GUI  // a screenshot needs the rendering this build may leave out
  {
    const CallLog log("screenshot");
    const std::string dir = testcli::scratch_dir("plugin_once");
    const auto r = run("headless --scene '" + scene("default") + "' --frames 4 --quiet --overlays +lists --screenshot '" + dir + "/s.png'" + with);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    expect_once_each(log.frames(), 4, "headless --screenshot with the lists overlay");
  }
#endif
  const auto once = run("pairs --input '" + nine_csv() + "'" + with);
  EXPECT_EQ(once.exit_code, 0) << once.err;
  const auto twice = run("pairs --input '" + nine_csv() + "' --repeat 2" + with);
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_NE(twice.err.find("frame 0: nbscope_detect returned 1: called twice for this frame"), std::string::npos) << twice.err;
}

#ifdef NBSCOPE_TEST_GUI
TEST(PluginCli, AStatefulPluginIsCalledOncePerFrameInTheWindowWithItsLists) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const CallLog log("window");
  const std::string dir = testcli::scratch_dir("plugin_once_window");
  const auto r = run("gui --scene '" + scene("default") + "' --frames 5 --overlays +lists --screenshot '" + dir + "/w.png' --detector-lib '" +
                         plugin("once_per_frame") + "' --algorithm test-once-per-frame",
                     testcli::on_display());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::vector<long long> calls = log.frames();
  // Frame 0 was detected before the window asked for its lists (a documented second call); from
  // frame 1 on each frame's one detection records them.
  ASSERT_GE(calls.size(), 6u);
  for (std::size_t k = 1; k < calls.size(); ++k) {
    if (calls[k] != 0) {
      EXPECT_NE(calls[k], calls[k - 1]) << "frame " << calls[k] << " given twice in a row";
    }
  }
}
#endif

TEST(PluginCli, AlgorithmsListsThePlugin) {
  const auto r = run("algorithms --detector-lib '" + plugin("good") + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("test-good"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the test plugin: brute force"), std::string::npos) << r.out;
  // Repeatable: two libraries, two algorithms, run side by side (the wrong one fails its checks).
  const auto both = run("headless --scene '" + scene("default") + "' --frames 5 --detector-lib '" + plugin("good") +
                        "' --detector-lib '" + plugin("drop_pair") + "' --algorithm test-good,test-drop-pair");
  EXPECT_EQ(both.exit_code, 1) << both.out << both.err;
  EXPECT_NE(both.out.find("test-good (test_plugin_good.so),test-drop-pair (test_plugin_drop_pair.so), "), std::string::npos) << both.out;
}

TEST(PluginCli, WrongButWellFormedPluginFailsItsChecks) {
  const auto r = run("headless --scene '" + scene("default") + "' --frames 30 --detector-lib '" + plugin("drop_pair") +
                     "' --algorithm test-drop-pair");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("A==R"), std::string::npos) << r.out;
}

TEST(PluginCli, LibrariesThatAreNotPluginsAreRefusedAtLoad) {
  std::string lib = plugin("no_version");
  expect_error(run("algorithms --detector-lib '" + lib + "'"), lib + ": no symbol nbscope_api_version: not an nbscope detector plugin");
  lib = plugin("version_2");
  expect_error(run("algorithms --detector-lib '" + lib + "'"), lib + ": built for plugin API version 2; this nbscope speaks 1");
  lib = plugin("no_detect");
  expect_error(run("algorithms --detector-lib '" + lib + "'"), lib + ": no symbol nbscope_detect (plugin API version 1 requires it)");
  lib = plugin("bad_name");
  expect_error(run("algorithms --detector-lib '" + lib + "'"), lib + ": its name 'Test Plugin!' is not 1 to 64 of [a-z0-9_-]");
  lib = plugin("nbs_name");
  expect_error(run("algorithms --detector-lib '" + lib + "'"), lib + ": its name 'nbs' is a built-in detector's");
  lib = plugin("good_twin");  // another file, the same name
  expect_error(run("algorithms --detector-lib '" + plugin("good") + "' --detector-lib '" + lib + "'"),
               lib + ": its name 'test-good' is taken by " + plugin("good") + ", loaded before it");
  lib = plugin("good");
  const auto twice = run("algorithms --detector-lib '" + lib + "' --detector-lib '" + lib + "'");  // one file: loaded once
  EXPECT_EQ(twice.exit_code, 0) << twice.err;
  const auto missing = run("headless --scene '" + scene("default") + "' --detector-lib /nonexistent/x.so");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.err.rfind("nbscope: error: /nonexistent/x.so: cannot load: ", 0), 0u) << missing.err;
  expect_error(run("verify --input '" + nine_csv() + "' --detector-lib '" + lib + "'"),
               "verify: --detector-lib is not an option of verify (it is one of gui, headless, replay, watch, pairs, dump, scaling, "
               "algorithms)");
}

TEST(PluginCli, BrokenPairsAreNamedWithTheFrame) {
  struct Case {
    std::string variant, what, in_scene;  // the line on nine.csv's 9 elements, and on the default scene's 448
  };
  for (const auto& [variant, what, in_scene] :
       {Case{"pair_range", "add_pair(0, 9): element 9 is out of range [0, 9)", "add_pair(0, 448): element 448 is out of range [0, 448)"},
        Case{"self_pair", "add_pair(0, 0): an element paired with itself", "add_pair(0, 0): an element paired with itself"},
        Case{"pair_twice", "add_pair: pair (0, 1) given twice", "add_pair: pair (0, 1) given twice"}}) {
    const std::string lib = plugin(variant);
    std::string name = "test-" + variant;
    std::replace(name.begin(), name.end(), '_', '-');
    expect_bug(run("pairs --input '" + nine_csv() + "' --detector-lib '" + lib + "' --algorithm " + name),
               lib + " (" + name + "): frame 0: " + what);
    // In a headless run each is its frame's violation, located.
    expect_violation(run("headless --scene '" + scene("default") + "' --frames 3 --detector-lib '" + lib + "' --algorithm " + name),
                     in_scene);
  }
}

TEST(PluginCli, BrokenTraceCallsAreNamed) {
  std::string lib = plugin("undeclared");
  expect_bug(run("dump --input '" + nine_csv() + "' --detector-lib '" + lib + "' --algorithm test-undeclared"),
             lib + " (test-undeclared): frame 0: trace set: array 7 was not declared (1 declared)");
  lib = plugin("index_shape");
  expect_bug(run("dump --input '" + nine_csv() + "' --detector-lib '" + lib + "' --algorithm test-index-shape"),
             lib + " (test-index-shape): frame 0: trace set: index 23 is outside array 0 of 18 entries");
}

// In a host process of its own (the default) a crash is frame 3's violation and the run goes on;
// in nbscope's it ends the run with one line naming the library and the frame.
TEST(PluginCli, CrashIsFrame3sViolationOrInProcessOneLineNamingTheLibraryAndFrame) {
  const std::string lib = plugin("crash");
  const std::string command = "headless --scene '" + scene("default") + "' --frames 30 --detector-lib '" + lib + "' --algorithm test-crash";
  const auto r = run(command);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("first in frame 3: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("contract api-rule broken: crashed with SIGSEGV in nbscope_detect() on frame 3"), std::string::npos) << r.out;
  expect_error(run(command + " --detector-isolation none"), lib + " (test-crash): crashed with SIGSEGV in nbscope_detect() on frame 3");
  expect_error(run(command + " --detector-isolation thread"), "--detector-isolation: 'thread' is not process or none");
}

TEST(PluginCli, CrashWhileDescribingItselfIsNamedToo) {
  const std::string lib = plugin("describe_crash");
  expect_error(run("algorithms --detector-lib '" + lib + "'"), lib + ": crashed with SIGSEGV in nbscope_detector_describe()");
}

TEST(PluginCli, HangIsStoppedByTheWatchdog) {
  const std::string lib = plugin("hang");
  expect_error(run("headless --scene '" + scene("default") + "' --frames 30 --detector-timeout 1 --detector-isolation none --detector-lib '" +
                   lib + "' --algorithm test-hang"),
               lib + " (test-hang): did not return within 1 s in nbscope_detect() on frame 2");
  const auto r = run("headless --scene '" + scene("default") + "' --frames 3 --detector-timeout 1 --detector-lib '" + lib + "' --algorithm test-hang");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("contract api-rule broken: did not return within 1 s in nbscope_detect() on frame 2"), std::string::npos) << r.out;
  expect_error(run("headless --scene '" + scene("default") + "' --detector-timeout -1"),
               "--detector-timeout: the seconds must be from 0 (no limit) to 1e6");
}

// Every call into a library is guarded as nbscope_detect is (issue 36): its constructors at dlopen,
// describe, release and own_bytes each end in one line naming the library and the call, exit 2, with
// the same --detector-timeout (1 s here: a hang costs a second).
TEST(PluginCli, CrashOrHangWhileLoadingIsNamed) {
  std::string lib = plugin("load_crash");
  expect_error(run("algorithms --detector-lib '" + lib + "'"), lib + ": crashed with SIGSEGV while loading (dlopen, in its constructors)");
  lib = plugin("load_hang");
  expect_error(run("algorithms --detector-timeout 1 --detector-lib '" + lib + "'"),
               lib + ": did not return within 1 s while loading (dlopen, in its constructors)");
}

TEST(PluginCli, HangWhileDescribingItselfIsStoppedByTheWatchdog) {
  const std::string lib = plugin("describe_hang");
  expect_error(run("algorithms --detector-timeout 1 --detector-lib '" + lib + "'"),
               lib + ": did not return within 1 s in nbscope_detector_describe()");
}

TEST(PluginCli, CrashOrHangInReleaseIsNamed) {
  std::string lib = plugin("release_crash");
  auto r = run("pairs --input '" + nine_csv() + "' --detector-lib '" + lib + "'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  // The summary line of the detection that ran, then the one error line.
  EXPECT_NE(r.err.find("\nnbscope: error: " + lib + " (test-release-crash): crashed with SIGSEGV in nbscope_release()\n"),
            std::string::npos)
      << r.err;
  lib = plugin("release_hang");
  r = run("pairs --input '" + nine_csv() + "' --detector-timeout 1 --detector-lib '" + lib + "'");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("\nnbscope: error: " + lib + " (test-release-hang): did not return within 1 s in nbscope_release()\n"),
            std::string::npos)
      << r.err;
}

TEST(PluginCli, CrashOrHangInOwnBytesIsNamed) {
  std::string lib = plugin("own_bytes_crash");
  auto r = run("dump --input '" + nine_csv() + "' --detector-lib '" + lib + "'");
  expect_error(r, lib + " (test-own-bytes-crash): crashed with SIGSEGV in nbscope_own_bytes()");
  EXPECT_EQ(r.out, "");  // asked before the dump is written: no half-written document
  lib = plugin("own_bytes_hang");
  r = run("scaling --n 1e3..1e3 --quiet --detector-timeout 1 --detector-lib '" + lib + "'");
  expect_error(r, lib + " (test-own-bytes-hang): did not return within 1 s in nbscope_own_bytes()");
}

// A plugin that breaks the API stops every command that runs it with the same line and exit 2;
// `scaling` skipped it with a note and exit 0.
TEST(PluginCli, EveryCommandNamesABreachAlike) {
  const std::string lib = plugin("self_pair");
  const std::string dir = testcli::scratch_dir("plugin_breach_alike");
  const auto recorded = run("headless --scene '" + scene("default") + "' --frames 3 --record '" + dir + "/r.nbsrec'");
  ASSERT_EQ(recorded.exit_code, 0) << recorded.err;
  const std::string what = "add_pair(0, 0): an element paired with itself";
  for (const std::string& command : {"headless --scene '" + scene("default") + "' --frames 3", "replay '" + dir + "/r.nbsrec' --headless"}) {
    SCOPED_TRACE(command);
    expect_violation(run(command + " --detector-lib '" + lib + "'"), what);
  }
  for (const std::string& command :
       {"pairs --input '" + nine_csv() + "'", "dump --input '" + nine_csv() + "'", std::string("scaling --n 1e3..1e3 --quiet")}) {
    SCOPED_TRACE(command);
    expect_bug(run(command + " --detector-lib '" + lib + "'"), lib + " (test-self-pair): frame 0: " + what);
  }
}

TEST(PluginCli, AMegabyteFailMessageIsCutToOneShortLine) {
  const std::string lib = plugin("long_fail");
  expect_error(run("pairs --input '" + nine_csv() + "' --detector-lib '" + lib + "'"),
               lib + " (test-long-fail): frame 0: nbscope_detect returned 1: " + std::string(300, 'x') +
                   "... (1,048,276 more bytes)");  // docs/plugins.md: 300 bytes kept of 2^20
}

TEST(PluginCli, AnArrayNamedNullIsRefused) {
  const std::string lib = plugin("null_array_name");
  const auto r = run("dump --input '" + nine_csv() + "' --detector-lib '" + lib + "'");
  expect_bug(r, lib + " (test-null-array-name): frame 0: trace declare_array: array 0's name is NULL (name it as the book does: "
                      "heads, next, ...)");
  EXPECT_EQ(r.out, "");  // no "bytes": {"": 16}
}

}  // namespace
}  // namespace nbscope
