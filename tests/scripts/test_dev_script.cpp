// scripts/dev, the README's two commands, run as the README writes them:
// - `scripts/dev run` under a display of the test's own (Xvfb) opens the window on the default scene
//   (the window's summary line, and its screenshot is the scene's picture, not a blank frame);
// - `scripts/dev run` with no display renders that frame into build/run/nbscope.png and says where;
// - every other subcommand is reached by its dispatch (`--dry-run`: what it would build and run).
// `run` builds build/release first (nothing to do when this test is part of that build), so these
// tests run only where the binary under test is the source tree's build/release one.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "io/png.hpp"
#include "support/golden_tolerance.hpp"
#include "support/run_cli.hpp"
#include "support/x_display.hpp"

namespace nbscope {
namespace {

const std::string kRoot = NBSCOPE_SOURCE_DIR;
const std::string kDev = "'" + kRoot + "/scripts/dev'";
constexpr const char* kNoDisplay = "env -u DISPLAY -u WAYLAND_DISPLAY";

#define SKIP_UNLESS_THE_README_BUILD()                                                                         \
  do {                                                                                                         \
    if (std::filesystem::path(testcli::binary()) != std::filesystem::path(kRoot + "/build/release/src/app/nbscope")) \
      GTEST_SKIP() << "scripts/dev builds build/release; the binary under test is " << testcli::binary();      \
  } while (false)

// Runs `scripts/dev ARGS` after `prefix` (environment assignments); output captured as run() does.
testcli::Result dev(const std::string& args, const std::string& prefix = "") {
  static int calls = 0;
  const std::string dir = testcli::scratch_dir("dev_capture_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
                                               "_" + std::to_string(calls++));
  return testcli::run_shell(prefix + " " + kDev + " " + args, dir + "/out", dir + "/err");
}

// The default scene after `frames` frames as `headless --screenshot` draws it (`flags` added): what the
// window shows.
Image default_scene_picture(const std::string& dir, int frames, const std::string& flags) {
  const std::string png = dir + "/headless.png";
  const auto r = testcli::run("headless --scene '" + kRoot + "/assets/scenes/default.json' --frames " + std::to_string(frames) +
                              " --quiet --screenshot '" + png + "' " + flags);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return read_png(png);
}

// `png` is the default scene's picture after `frames` frames: at most `share` of its pixels differ
// from headless's (with `flags`), and it is not a blank frame.
::testing::AssertionResult shows_the_default_scene(const std::string& png, const std::string& dir, int frames, const std::string& flags,
                                                   double share) {
  if (!std::filesystem::exists(png)) return ::testing::AssertionFailure() << png << " was not written";
  const Image shot = read_png(png);
  if (is_uniform(shot)) return ::testing::AssertionFailure() << png << " is a blank frame";
  const ImageDiff d = compare_images(shot, default_scene_picture(dir, frames, flags), golden::kChannelTolerance);
  if (!d.same_size || d.share() > share)
    return ::testing::AssertionFailure() << png << " is not the default scene's picture: " << d.differing << " pixels differ";
  return ::testing::AssertionSuccess();
}

// The last line of `text` ("" if none).
std::string last_line(std::string text) {
  if (!text.empty() && text.back() == '\n') text.pop_back();
  const std::size_t start = text.rfind('\n');
  return start == std::string::npos ? text : text.substr(start + 1);
}

// ---- run ------------------------------------------------------------------------------------------

// `scripts/dev run`, exactly: the window opens on the default scene and stays open until closed
// (SIGTERM closes it as its close button does, and it saves its settings on the way out).
TEST(DevRun, UnderADisplayOpensTheWindow) {
  SKIP_UNLESS_THE_README_BUILD();
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string dir = testcli::scratch_dir("dev_run_window");
  const testcli::WindowRun r = testcli::run_until_window_then_term("XDG_CONFIG_HOME='" + dir + "' " + kDev + " run", 2.0);
  EXPECT_TRUE(r.window_shown) << "no window: " << r.out << r.err;
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::string saved = testcli::read_text(dir + "/nbscope/settings.json");
  ASSERT_FALSE(saved.empty()) << "the window did not close normally: " << r.err;
  EXPECT_EQ(nlohmann::json::parse(saved).at("last_scene"), kRoot + "/assets/scenes/default.json");
}

// Its arguments go on to the window: a scripted run prints the window's own summary line, and its
// screenshot is the default scene's picture.
TEST(DevRun, UnderADisplayPassesItsArgumentsToTheWindow) {
  SKIP_UNLESS_THE_README_BUILD();
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string dir = testcli::scratch_dir("dev_run_window_args");
  const auto r = dev("run --frames 60 --no-timings --screenshot '" + dir + "/window.png'", testcli::on_display());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("nbscope: window: 60 frames ("), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("no display"), std::string::npos) << r.err;
  EXPECT_TRUE(shows_the_default_scene(dir + "/window.png", dir, 60, "--no-timings", golden::kMaxDifferingShare));
}

// `scripts/dev run` with no display: the same frame headless, into build/run/nbscope.png, said where.
TEST(DevRun, WithoutADisplayWritesBuildRunNbscopePng) {
  SKIP_UNLESS_THE_README_BUILD();
  const std::string dir = testcli::scratch_dir("dev_run_headless");
  const std::string png = kRoot + "/build/run/nbscope.png";
  std::filesystem::remove(png);
  const auto r = dev("run", kNoDisplay);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(last_line(r.out), "screenshot: " + png) << r.out << r.err;  // (the build's lines come first)
  EXPECT_NE(r.err.find("no display"), std::string::npos) << r.err;
  // The Stats panel's timings differ from run to run (~0.2% of the pixels); another scene or a
  // blank frame differs in far more.
  EXPECT_TRUE(shows_the_default_scene(png, dir, 120, "", 0.01));
}

// ---- the dispatch of every subcommand -------------------------------------------------------------

// `scripts/dev --dry-run ...`: exit 0 and the steps it would take, each "dev: would run: ...".
std::string plan(const std::string& args, const std::string& prefix = "") {
  const auto r = dev("--dry-run " + args, prefix);
  EXPECT_EQ(r.exit_code, 0) << args << ": " << r.err;
  EXPECT_EQ(r.out, "") << args;
  return r.err;
}

bool says(const std::string& text, const std::string& step) { return text.find("dev: would run: " + step) != std::string::npos; }

TEST(DevDispatch, RunOpensTheWindowWithTheArgumentsOrRendersHeadless) {
  SKIP_UNLESS_THE_README_BUILD();  // it asks the built binary whether it has the window
  const std::string bin = "build/release/src/app/nbscope";
  EXPECT_TRUE(says(plan("run --scene book-fig-3-15.json", "env DISPLAY=:97"), bin + " gui --scene book-fig-3-15.json\n"));
  const std::string headless = plan("run --scene book-fig-3-15.json", kNoDisplay);
  EXPECT_TRUE(says(headless, bin + " gui --frames 120 --screenshot " + kRoot + "/build/run/nbscope.png --scene book-fig-3-15.json\n"))
      << headless;
  // A --frames or --screenshot of the user's replaces the default one.
  EXPECT_TRUE(says(plan("run --frames 5 --screenshot /tmp/x.png", kNoDisplay), bin + " gui --frames 5 --screenshot /tmp/x.png\n"));
}

TEST(DevDispatch, TestBuildsAndRunsCtest) {
  const std::string release = plan("test");
  EXPECT_TRUE(says(release, "cmake --build --preset release")) << release;
  EXPECT_TRUE(says(release, "ctest --preset release\n")) << release;
  const std::string asan = plan("test --asan -R Cli");
  EXPECT_TRUE(says(asan, "cmake --build --preset asan")) << asan;
  EXPECT_TRUE(says(asan, "ctest --preset asan -R Cli\n")) << asan;
}

TEST(DevDispatch, TsanBenchGoldenAndFuzzReachTheirSteps) {
  const std::string tsan = plan("tsan");
  EXPECT_TRUE(says(tsan, "cmake --build --preset tsan")) << tsan;
  EXPECT_TRUE(says(tsan, "build/tsan/tests/nbscope_unit_tests --gtest_filter=*NbsBands*")) << tsan;
  EXPECT_TRUE(says(plan("bench BM_Detect"), "build/release/bench/nbscope_bench --benchmark_filter=BM_Detect,"));
  EXPECT_TRUE(says(plan("golden --only default"), "scripts/make_golden build/release/src/app/nbscope --only default\n"));
  const std::string fuzz = plan("fuzz 7");
  EXPECT_TRUE(says(fuzz, "cmake --build --preset fuzz")) << fuzz;
  EXPECT_TRUE(says(fuzz, "each target's planted faults, then each of csv scene")) << fuzz;
  EXPECT_NE(fuzz.find(" for 7 s"), std::string::npos) << fuzz;
}

TEST(DevDispatch, HelpAndBadInput) {
  const auto help = dev("help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* sub : {"run", "test", "tsan", "bench", "golden", "fuzz", "--dry-run"})
    EXPECT_NE(help.out.find(std::string("scripts/dev ") + sub), std::string::npos) << sub << " not in\n" << help.out;
  EXPECT_EQ(dev("--help").out, help.out);
  const auto unknown = dev("bogus");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(unknown.out, help.out);  // the usage, so the user sees what there is
  const auto seconds = dev("--dry-run fuzz soon");
  EXPECT_EQ(seconds.exit_code, 2);
  EXPECT_EQ(seconds.err, "dev: fuzz: SECONDS must be a positive whole number, got 'soon'\n");
}

}  // namespace
}  // namespace nbscope
