// Golden screenshots: fixed scenes and overlays rendered headless at a fixed size and frame count,
// under each off-screen backend (OSMesa and EGL), compared with assets/golden/*.png; a proof that
// the comparison fails when an overlay is switched off; the window itself under Xvfb compared with
// the headless frame; and the rendering errors (missing shaders, unwritable screenshot, no window)
// as one line and exit 2. The backends' own choice and errors are in test_gl_backends.cpp.
//
// The cases live in assets/golden/cases.txt, shared with scripts/make_golden (which regenerates
// the references): one case a line, "name | headless arguments" (or "name | COMMAND arguments" for
// another command that takes --screenshot, e.g. verify), plus "@args" lines of arguments every case gets. On a mismatch the actual image and a diff (differing pixels red) are written
// to <build>/test-output/golden/.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

#include "io/png.hpp"
#include "support/golden_tolerance.hpp"
#include "support/run_cli.hpp"
#include "support/x_display.hpp"

namespace nbscope {
namespace {

using golden::kChannelTolerance;
using golden::kMaxDifferingShare;

const std::string kSource = NBSCOPE_SOURCE_DIR;
const std::string kOut = std::string(NBSCOPE_TEST_OUT) + "/golden";

struct Case {
  std::string name;
  std::string args;
};

// gtest names a failing case by this instead of its bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  const auto b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// Paths in the cases are relative to the source tree; the binary runs elsewhere.
std::string absolute_paths(const std::string& args) {
  std::istringstream in(args);
  std::string word, out;
  while (in >> word) out += (out.empty() ? "" : " ") + (word.rfind("assets/", 0) == 0 ? "'" + kSource + "/" + word + "'" : word);
  return out;
}

// `common` less the option `name` and its value when `args` gives that option itself (a case's own
// --size wins over the @args one).
std::string common_for(const std::string& common, const std::string& args, const std::string& name) {
  if (args.find(name + " ") == std::string::npos) return common;
  std::istringstream in(common);
  std::string word, out;
  while (in >> word) {
    if (word == name) {
      in >> word;
      continue;
    }
    out += " " + word;
  }
  return out;
}

std::vector<Case> load_cases() {
  std::ifstream in(kSource + "/assets/golden/cases.txt");
  std::vector<Case> cases;
  std::string common, line;
  while (std::getline(in, line)) {
    line = trim(line);
    if (line.empty() || line[0] == '#') continue;
    if (line.rfind("@args", 0) == 0) {
      common += " " + trim(line.substr(5));
      continue;
    }
    const auto bar = line.find('|');
    if (bar == std::string::npos) continue;
    const std::string args = trim(line.substr(bar + 1));
    cases.push_back({trim(line.substr(0, bar)), absolute_paths(args + common_for(common, args, "--size"))});
  }
  return cases;
}

// A case's command line: its arguments go to `headless ... --quiet`, unless they start with a
// command of their own ("verify --input ...": verify prints its findings and takes no --quiet).
std::string command_line(const std::string& args) {
  const bool own_command = !args.empty() && args[0] != '-';
  return own_command ? args : "headless " + args + " --quiet";
}

// Renders `args` headless into OUT_DIR/NAME.png and returns the image. `unavailable`, when
// given, receives the error of a backend that is genuinely absent here (left out of the build,
// or its library not installed), and the image is then empty; any other failure fails the test.
Image render(const std::string& name, const std::string& args, std::string* unavailable = nullptr) {
  std::filesystem::create_directories(kOut);
  const std::string path = kOut + "/" + name + ".png";
  std::filesystem::remove(path);
  const auto r = testcli::run(command_line(args) + " --screenshot '" + path + "'");
  if (unavailable != nullptr && r.exit_code == 2 &&
      (r.err.find(": not built") != std::string::npos || r.err.find(" not found") != std::string::npos)) {
    *unavailable = r.err;
    return {};
  }
  EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.err;  // 1: a case may show a failing check
  return read_png(path);
}

// Compares with the golden image; on failure keeps the actual and the diff next to the test output.
::testing::AssertionResult matches_golden(const std::string& name, const Image& actual, const std::string& golden) {
  const Image expected = read_png(kSource + "/assets/golden/" + golden + ".png");
  const ImageDiff d = compare_images(actual, expected, kChannelTolerance);
  if (d.same_size && d.share() <= kMaxDifferingShare) return ::testing::AssertionSuccess();
  write_png(kOut + "/" + name + ".actual.png", actual);
  if (d.same_size) write_png(kOut + "/" + name + ".diff.png", d.diff);
  return ::testing::AssertionFailure() << name << " vs assets/golden/" << golden << ".png: "
                                       << (d.same_size ? "" : "sizes differ; ") << d.differing << " of " << d.total
                                       << " pixels differ by more than " << kChannelTolerance << " (share " << d.share()
                                       << ", limit " << kMaxDifferingShare << ", largest channel delta "
                                       << d.max_channel_delta << "); actual and diff in " << kOut;
}

const Case& find_case(const std::string& name) {
  static const std::vector<Case> cases = load_cases();
  for (const Case& c : cases)
    if (c.name == name) return c;
  throw std::runtime_error("no golden case " + name);
}

// Every case under every off-screen backend: the same reference image, the same tolerance.
class Golden : public ::testing::TestWithParam<std::tuple<Case, std::string>> {};

TEST_P(Golden, MatchesTheReference) {
  const auto& [c, backend] = GetParam();
  // The references are llvmpipe's pictures: on a machine with a GPU, EGL would pick its driver.
  ::setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
  const std::string name = c.name + "_" + backend;
  std::string unavailable;
  const Image actual = render(name, c.args + " --gl " + backend, &unavailable);
  if (!unavailable.empty()) GTEST_SKIP() << unavailable;
  EXPECT_FALSE(is_uniform(actual)) << name << ": blank screenshot";
  EXPECT_TRUE(matches_golden(name, actual, c.name));
}

INSTANTIATE_TEST_SUITE_P(Cases, Golden, ::testing::Combine(::testing::ValuesIn(load_cases()), ::testing::Values("osmesa", "egl")),
                         [](const ::testing::TestParamInfo<std::tuple<Case, std::string>>& info) {
                           return std::get<0>(info.param).name + "_" + std::get<1>(info.param);
                         });

TEST(GoldenCases, AtLeastSixSceneOverlayCombinations) { EXPECT_GE(load_cases().size(), 6u); }

// The comparison must be able to fail: the same case with one overlay off differs from its golden.
TEST(GoldenCompare, FailsWhenAnOverlayIsSwitchedOff) {
  for (const auto& [name, overlay] : {std::pair<std::string, std::string>{"default_all", "grid"},
                                      std::pair<std::string, std::string>{"book_lists_nbs", "lists"},
                                      std::pair<std::string, std::string>{"verify_nine_bug", "lists"}}) {
    const Case& c = find_case(name);
    // Append "-overlay" to the case's own --overlays list (a second --overlays flag would be refused).
    std::string args = c.args;
    const auto at = args.find("--overlays ");
    if (at == std::string::npos) {
      args += " --overlays -" + overlay;
    } else {
      const auto end = args.find(' ', at + 11);
      args.insert(end == std::string::npos ? args.size() : end, ",-" + overlay);
    }
    const Image actual = render(name + "_without_" + overlay, args);
    const ::testing::AssertionResult result = matches_golden(name + "_without_" + overlay, actual, name);
    EXPECT_FALSE(result) << name << " with " << overlay << " off still matched its golden image";
  }
}

// ---- the window under Xvfb --------------------------------------------------------------------

// Renders `args` in the window under Xvfb and headless and expects the same picture: both draw the
// last state until ImGui's layout has settled, however few frames were asked for. `window_log`
// receives what the window said on stderr.
void expect_window_matches_headless(const std::string& name, const std::string& args, std::string* window_log = nullptr) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  std::filesystem::create_directories(kOut);
  const std::string window_png = kOut + "/window_" + name + ".png", headless_png = kOut + "/window_" + name + "_headless.png";
  std::filesystem::remove(window_png);
  const std::string log = kOut + "/window_" + name + ".log";
  const std::string cmd = testcli::on_display() + " '" + testcli::binary() + "' gui " + args +
                          " --screenshot '" + window_png + "' >'" + log + "' 2>&1";
  const int status = std::system(cmd.c_str());
  ASSERT_EQ(status, 0) << testcli::read_text(log);
  if (window_log != nullptr) *window_log = testcli::read_text(log);
  const Image window = read_png(window_png);
  EXPECT_FALSE(is_uniform(window)) << "the window's screenshot is blank";
  const auto r = testcli::run("headless " + args + " --quiet --screenshot '" + headless_png + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image headless = read_png(headless_png);
  const ImageDiff d = compare_images(window, headless, kChannelTolerance);
  if (d.same_size) write_png(kOut + "/window_" + name + ".diff.png", d.diff);
  EXPECT_TRUE(d.same_size);
  EXPECT_LE(d.share(), kMaxDifferingShare) << name << ": " << d.differing << " pixels differ; see " << kOut;
}

// --frames 30 is 30 frames in the window as in headless (it once said 31: frame 0 counted too).
TEST(Window, XvfbWindowFor30FramesMatchesTheHeadlessFrame) {
  std::string log;
  expect_window_matches_headless("default", absolute_paths("--scene assets/scenes/default.json --frames 30 --size 1280x720 --no-timings"),
                                 &log);
  EXPECT_NE(log.find("nbscope: window: 30 frames ("), std::string::npos) << log;
}

// One frame and the stepper: the Arrays dock, Pseudocode and Stepper appear in the very frames
// before the capture, so an unsettled layout would show here first.
TEST(Window, XvfbWindowOnOneFrameWithTheStepperMatchesTheHeadlessFrame) {
  expect_window_matches_headless(
      "step", absolute_paths("--scene assets/scenes/book-fig-3-15.json --frames 1 --algorithm nbs --step 56 "
                             "--book-numbering --select 3 --size 1280x720 --no-timings"));
}

// Going back through the history in the window (gui --back) shows the past frame as headless --back
// does: the same rebuilt frame, trail, Timeline cursor and panels.
TEST(Window, XvfbWindowGoingBackMatchesTheHeadlessFrame) {
  expect_window_matches_headless(
      "back", absolute_paths("--scene assets/scenes/default.json --frames 40 --back 12 --select 12 --size 1280x720 --no-timings"));
}

// ---- rendering errors: one line, exit 2, no file ------------------------------------------------

// Runs a shell command line, capturing its exit code and stderr.
testcli::Result shell(const std::string& command) {
  std::filesystem::create_directories(kOut);
  // One file per test: ctest runs the tests of this binary in parallel processes.
  const std::string err = kOut + "/shell." + ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".err";
  const int status = std::system((command + " </dev/null >/dev/null 2>'" + err + "'").c_str());
  testcli::Result r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.err = testcli::read_text(err);
  return r;
}

void expect_one_line_error(const testcli::Result& r, const std::string& needle) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("nbscope: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
}

TEST(RenderErrors, BackNeedsScriptedFrames) {
  expect_one_line_error(shell("'" + testcli::binary() + "' gui --back 5"), "--back: needs --frames N");
  expect_one_line_error(shell("'" + testcli::binary() + "' gui --frames 5 --back 6 --screenshot /tmp/nbscope_never.png"),
                        "--back: 6 is more than the 5 frames run");
}

TEST(RenderErrors, MissingShaderDirectory) {
  const std::string out = kOut + "/no_shaders.png";
  std::filesystem::remove(out);
  expect_one_line_error(testcli::run("headless " + absolute_paths("--scene assets/scenes/default.json") +
                                     " --frames 1 --shader-dir /nonexistent/shaders --screenshot '" + out + "'"),
                        "/nonexistent/shaders");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(RenderErrors, UnwritableScreenshotPath) {
  expect_one_line_error(testcli::run("headless " + absolute_paths("--scene assets/scenes/default.json") +
                                     " --frames 1 --screenshot /nonexistent-dir/shot.png"),
                        "/nonexistent-dir/shot.png");
  expect_one_line_error(testcli::run("headless " + absolute_paths("--scene assets/scenes/default.json") +
                                     " --frames 1 --screenshot '" + kSource + "'"),
                        "directory");
}

TEST(RenderErrors, UnknownOverlayPanelOrElement) {
  const std::string scene = absolute_paths("--scene assets/scenes/book-fig-3-15.json") + " --frames 1";
  const std::string out = " --screenshot '" + kOut + "/bad_flags.png'";
  expect_one_line_error(testcli::run("headless " + scene + out + " --overlays grid,+nonsense"), "nonsense");
  expect_one_line_error(testcli::run("headless " + scene + out + " --panels -nonsense"), "nonsense");
  expect_one_line_error(testcli::run("headless " + scene + out + " --select 9"), "--select");  // 9 elements: 0..8
  expect_one_line_error(testcli::run("headless " + scene + out + " --camera 1,2"), "--camera");
  expect_one_line_error(testcli::run("headless " + scene + out + " --size 10x10"), "--size");
  EXPECT_FALSE(std::filesystem::exists(kOut + "/bad_flags.png"));
}

// --select takes the number the user sees: from 0, or from 1 with --book-numbering.
TEST(RenderErrors, SelectCountsAsTheNumberingShown) {
  const std::string scene = absolute_paths("--scene assets/scenes/book-fig-3-15.json") + " --frames 1";
  const std::string png = kOut + "/select_book.png";
  std::filesystem::remove(png);
  expect_one_line_error(testcli::run("headless " + scene + " --screenshot '" + png + "' --book-numbering --select 0"),
                        "--select: element 0 does not exist (the scene has 9 elements, numbered 1..9 in book numbering)");
  expect_one_line_error(testcli::run("headless " + scene + " --screenshot '" + png + "' --book-numbering --select 10"),
                        "numbered 1..9");
  EXPECT_FALSE(std::filesystem::exists(png));
  const auto r = testcli::run("headless " + scene + " --quiet --screenshot '" + png + "' --book-numbering --select 9");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(png));
}

// The message names the format --camera takes, whatever is wrong with the value.
TEST(RenderErrors, CameraNamesItsFormat) {
  const std::string scene = absolute_paths("--scene assets/scenes/default.json") + " --frames 1 --screenshot '" + kOut + "/cam.png'";
  for (const std::string value : {"nan,0,10", "0,0,inf", "1,2", "1,2,3,4", "a,b,c", "0,0,-5", "0,0,0", ",0,1"})
    expect_one_line_error(testcli::run("headless " + scene + " --camera " + value),
                          "--camera: '" + value + "' is not X,Y,PPM");
}

// NBSCOPE_DATA_DIR moves the shader lookup with the scenes (as --shader-dir and NBSCOPE_SHADER_DIR do).
TEST(RenderErrors, DataDirectoryMovesTheShaders) {
  const std::string out = kOut + "/data_dir.png";
  std::filesystem::remove(out);
  expect_one_line_error(shell("NBSCOPE_DATA_DIR=/nonexistent-data '" + testcli::binary() + "' headless " +
                              absolute_paths("--scene assets/scenes/default.json") + " --frames 1 --screenshot '" + out + "'"),
                        "/nonexistent-data/shaders");
  EXPECT_FALSE(std::filesystem::exists(out));
  const auto ok = shell("NBSCOPE_DATA_DIR='" + kSource + "' '" + testcli::binary() + "' headless " +
                        absolute_paths("--scene assets/scenes/default.json") + " --frames 1 --quiet --screenshot '" + out + "'");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(std::filesystem::exists(out));
}

TEST(RenderErrors, OsmesaFailure) {
  // Told to offer GL 2.1 only, Mesa refuses the 3.3 core context nbscope asks for.
  const std::string out = kOut + "/osmesa_fail.png";
  std::filesystem::remove(out);
  expect_one_line_error(shell("MESA_GL_VERSION_OVERRIDE=2.1 '" + testcli::binary() + "' headless " +
                              absolute_paths("--scene assets/scenes/default.json") + " --frames 1 --screenshot '" + out +
                              "'"),
                        "osmesa");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(RenderErrors, WindowThatCannotOpen) {
  // A display that does not exist: GLFW cannot connect, so the window cannot open.
  expect_one_line_error(shell("DISPLAY=:9999 '" + testcli::binary() + "' gui " +
                              absolute_paths("--scene assets/scenes/default.json") + " --frames 1"),
                        "window");
}

}  // namespace
}  // namespace nbscope
