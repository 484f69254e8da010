// The verify view through the binary: `verify --screenshot` and `gui --input --arrays` (the window
// under Xvfb, and headless without a display) draw the same picture of the book's nine elements with
// a planted bug; right arrays exit 0; bad flags are one line and exit 2.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>

#include "io/png.hpp"
#include "support/run_cli.hpp"
#include "support/x_display.hpp"

namespace nbscope {
namespace {

// As the golden tests compare (test_golden.cpp).
constexpr int kChannelTolerance = 24;
constexpr double kMaxDifferingShare = 0.001;

const std::string kSource = NBSCOPE_SOURCE_DIR;
const std::string kNine = "'" + kSource + "/assets/examples/nine.csv'";
const std::string kBug = "'" + kSource + "/assets/examples/nine_screen_bug_book.json'";
const std::string kArgs = "--input " + kNine + " --arrays " + kBug + " --base 1 --size 1280x720 --no-timings";

struct Shell {
  int exit_code = -1;
  std::string out, err;
};

// Runs a shell command line in `dir`, capturing exit code, stdout and stderr.
Shell shell(const std::string& dir, const std::string& command) {
  const int status = std::system(("cd '" + dir + "' && { " + command + "; } </dev/null >out.txt 2>err.txt").c_str());
  Shell r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = testcli::read_text(dir + "/out.txt");
  r.err = testcli::read_text(dir + "/err.txt");
  return r;
}

std::string nbscope() { return "'" + testcli::binary() + "'"; }

::testing::AssertionResult same_picture(const std::string& a, const std::string& b) {
  const ImageDiff d = compare_images(read_png(a), read_png(b), kChannelTolerance);
  if (d.same_size && d.share() <= kMaxDifferingShare) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " vs " << b << ": " << d.differing << " pixels differ";
}

// verify --screenshot says what it drew; the picture is the golden's (verify_nine_bug).
TEST(VerifyScreenshot, SaysWhatItDrewAndMatchesTheGolden) {
  const std::string dir = testcli::scratch_dir("verify_screenshot");
  const Shell r = shell(dir, nbscope() + " verify " + kArgs + " --screenshot shot.png");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.out.find("screenshot shot.png (1280x720, osmesa): 4 lists on 9 elements, 1 problem (the first selected)"),
            std::string::npos)
      << r.out;
  EXPECT_TRUE(same_picture(dir + "/shot.png", kSource + "/assets/golden/verify_nine_bug.png"));
}

// Without a display, gui --arrays renders headless and says where; the picture is verify's.
TEST(VerifyGui, WithoutADisplayRendersHeadlessAndSaysWhere) {
  const std::string dir = testcli::scratch_dir("verify_gui_headless");
  const Shell r = shell(dir, "env -u DISPLAY -u WAYLAND_DISPLAY TMPDIR='" + dir + "' " + nbscope() + " gui " + kArgs);
  EXPECT_EQ(r.exit_code, 1) << r.err;  // the arrays have a problem
  const std::string png = dir + "/nbscope-verify-nine_screen_bug_book.png";
  EXPECT_NE(r.out.find("screenshot: " + png), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("no display"), std::string::npos) << r.err;
  ASSERT_TRUE(std::filesystem::exists(png));
  EXPECT_TRUE(same_picture(png, kSource + "/assets/golden/verify_nine_bug.png"));
}

// The window under Xvfb draws what verify --screenshot draws.
TEST(VerifyGui, XvfbWindowMatchesTheHeadlessPicture) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string dir = testcli::scratch_dir("verify_gui_window");
  const Shell r = shell(dir, testcli::on_display() + " " + nbscope() + " gui " + kArgs + " --frames 1 --screenshot window.png");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("nbscope: window: 6 frames drawn; screenshot window.png"), std::string::npos) << r.err;
  ASSERT_TRUE(std::filesystem::exists(dir + "/window.png")) << r.err;
  EXPECT_FALSE(is_uniform(read_png(dir + "/window.png")));
  EXPECT_TRUE(same_picture(dir + "/window.png", kSource + "/assets/golden/verify_nine_bug.png"));
}

// Arrays nbscope dumped itself are right: exit 0, the legend says so.
TEST(VerifyGui, RightArraysExitZero) {
  const std::string dir = testcli::scratch_dir("verify_gui_right");
  const Shell dump = shell(dir, nbscope() + " dump --input " + kNine + " --algorithm screen --cell-size 1 --origin 0,0 --cells 10,10 >right.json");
  ASSERT_EQ(dump.exit_code, 0) << dump.err;
  const Shell r = shell(dir, "env -u DISPLAY -u WAYLAND_DISPLAY " + nbscope() + " gui --input " + kNine +
                                 " --arrays right.json --frames 1 --screenshot right.png");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("4 lists on 9 elements, 0 problems"), std::string::npos) << r.err;
}

void expect_one_line_error(const Shell& r, const std::string& needle) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("nbscope: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
}

TEST(VerifyGui, BadFlagsAreOneLineAndExitTwo) {
  const std::string dir = testcli::scratch_dir("verify_gui_errors");
  const std::string gui = "env -u DISPLAY -u WAYLAND_DISPLAY " + nbscope() + " gui ";
  // (`gui --input E.csv` alone opens the window on the elements: test_window_layers.cpp.)
  expect_one_line_error(shell(dir, gui + "--arrays " + kBug), "--input: missing");
  expect_one_line_error(shell(dir, gui + kArgs + " --scene x.json"), "--scene: does not apply to gui --arrays");
  expect_one_line_error(shell(dir, gui + kArgs + " --screenshot x.png"), "--screenshot: needs --frames N");
  expect_one_line_error(shell(dir, gui + kArgs + " --panels problems,nonsense"), "--panels: 'nonsense' is not one of all, none, overlays, problems, lists");
  expect_one_line_error(shell(dir, gui + kArgs + " --select 10"), "--select: element 10 does not exist");
  expect_one_line_error(shell(dir, gui + "--input " + kNine + " --arrays '" + kSource + "/assets/examples/nine_screen_bug.json' --book-numbering"),
                        "--book-numbering: the arrays are drawn numbered as their file counts, from 0 here");
  expect_one_line_error(shell(dir, nbscope() + " verify " + kArgs + " --step 3 --screenshot x.png"), "--step: does not apply to a verify run");
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.png"));
}

// 3D arrays are drawn one layer at a time: --layer K, else the first problem's layer. Eight spheres
// (r 0.2) on a grid of cell 1 from the origin, 4 x 4 x 3 cells: five in layer 0 (the busiest),
// 5 and 6 in layer 1, 7 in layer 2. Their screen arrays are nbscope's own; checked against the same
// elements with element 6 moved up into layer 2, its list (cell (2,2,1)) is wrong, and that one
// problem's element lies in layer 2.
TEST(VerifyScreenshot, ThreeDimensionalArraysAreDrawnOneLayerAtATime) {
  const std::string dir = testcli::scratch_dir("verify_gui_layers");
  const std::string rows = "x,y,z,r\n0.5,0.5,0.5,0.2\n1.5,0.5,0.5,0.2\n2.5,0.5,0.5,0.2\n0.5,1.5,0.5,0.2\n1.5,1.5,0.5,0.2\n0.5,0.5,1.5,0.2\n";
  testcli::write_text(dir + "/e.csv", rows + "2.5,2.5,1.5,0.2\n3.5,3.5,2.5,0.2\n");
  testcli::write_text(dir + "/moved.csv", rows + "2.5,2.5,2.5,0.2\n3.5,3.5,2.5,0.2\n");
  const Shell d = shell(dir, nbscope() + " dump --input e.csv --algorithm screen --cell-size 1 --origin 0,0,0 --cells 4,4,3 > a.json");
  ASSERT_EQ(d.exit_code, 0) << d.err;
  const std::string verify = nbscope() + " verify --arrays a.json --size 640x360 --screenshot v.png --input ";
  const Shell right = shell(dir, verify + "e.csv");
  EXPECT_EQ(right.exit_code, 0) << right.out << right.err;
  EXPECT_NE(right.out.find("; layer 0 of 3 shown"), std::string::npos) << "no problem: the busiest layer. " << right.out;
  const Shell wrong = shell(dir, verify + "moved.csv");
  EXPECT_EQ(wrong.exit_code, 1) << wrong.out << wrong.err;
  EXPECT_NE(wrong.out.find("; layer 2 of 3 shown"), std::string::npos) << "the problem's layer: " << wrong.out;
  const Shell chosen = shell(dir, verify + "moved.csv --layer 1");
  EXPECT_EQ(chosen.exit_code, 1) << chosen.out << chosen.err;
  EXPECT_NE(chosen.out.find("; layer 1 of 3 shown"), std::string::npos) << chosen.out;
  EXPECT_TRUE(std::filesystem::exists(dir + "/v.png"));
  const Shell past = shell(dir, verify + "e.csv --layer 3");
  EXPECT_EQ(past.exit_code, 2) << past.err;
  EXPECT_EQ(past.err, "nbscope: error: --layer: 3 is past the top layer 2 (the grid has 3 layers)\n");
}

}  // namespace
}  // namespace nbscope
