// The off-screen backends through the binary: --gl osmesa and --gl egl each render and name
// themselves, auto takes OSMesa when its library loads and EGL otherwise, both draw the same
// picture within the golden tolerance, and every way a backend can be missing or fail is one
// line and exit 2 with no screenshot written. Faults are injected through the environment: the
// library a backend opens (NBSCOPE_OSMESA_LIBRARY, NBSCOPE_EGL_LIBRARY), glvnd's vendor list and
// Mesa's GL version.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "io/png.hpp"
#include "support/golden_tolerance.hpp"
#include "support/run_cli.hpp"

namespace nbscope {
namespace {

const std::string kSource = NBSCOPE_SOURCE_DIR;
const std::string kOut = std::string(NBSCOPE_TEST_OUT) + "/gl_backends";

// Runs `env nbscope <args>` (env: shell assignments, e.g. "A=1 B=2"), capturing exit code and stderr.
testcli::Result run_env(const std::string& env, const std::string& args) {
  std::filesystem::create_directories(kOut);
  // One file per test: ctest runs the tests of this binary in parallel processes.
  const std::string err = kOut + "/" + ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".err";
  const std::string cmd = env + " '" + testcli::binary() + "' " + args + " </dev/null >/dev/null 2>'" + err + "'";
  const int status = std::system(cmd.c_str());
  testcli::Result r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.err = testcli::read_text(err);
  return r;
}

// A small headless render of the book's nine elements into `png` with `flags` added.
std::string small_render(const std::string& png, const std::string& flags) {
  return "headless --scene '" + kSource + "/assets/scenes/book-fig-3-15.json' --frames 1 --size 320x200 " + flags +
         " --screenshot '" + png + "'";
}

// The screenshot line names the backend that drew it: "screenshot PNG (320x200, BACKEND): ...".
void expect_drawn_by(const std::string& env, const std::string& gl, const std::string& backend) {
  const std::string png = kOut + "/named_" + backend + "_" + std::to_string(::getpid()) + ".png";
  std::filesystem::remove(png);
  const auto r = run_env(env, small_render(png, gl.empty() ? "" : "--gl " + gl));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("nbscope: screenshot " + png + " (320x200, " + backend + "): "), std::string::npos)
      << (gl.empty() ? "(no --gl)" : "--gl " + gl) << " with '" << env << "': " << r.err;
  EXPECT_FALSE(is_uniform(read_png(png))) << png;
}

TEST(GlBackends, EachBackendRendersAndNamesItself) {
  expect_drawn_by("", "osmesa", "osmesa");
  expect_drawn_by("", "egl", "egl");
}

TEST(GlBackends, AutoTakesOsmesaWhenItsLibraryLoadsElseEgl) {
  expect_drawn_by("", "", "osmesa");  // auto is the default
  expect_drawn_by("", "auto", "osmesa");
  expect_drawn_by("NBSCOPE_OSMESA_LIBRARY=/nonexistent/libOSMesa.so.8", "auto", "egl");
  // The variable names the library, it does not switch OSMesa off: the real one still loads.
  expect_drawn_by("NBSCOPE_OSMESA_LIBRARY=libOSMesa.so.8", "auto", "osmesa");
}

// The same scene, overlays and panels under both backends: within the golden tolerance of each
// other (they are the same llvmpipe here); with one overlay off they are not, so the comparison
// can fail.
TEST(GlBackends, BothBackendsDrawTheSamePicture) {
  ::setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);  // llvmpipe under both, even where EGL finds a GPU
  const std::string scene = "headless --scene '" + kSource +
                            "/assets/scenes/mixed-sizes.json' --frames 15 --overlays all --select 7 --panels all "
                            "--size 1280x720 --no-timings --quiet";
  Image images[3];
  const std::string runs[3][2] = {{"osmesa", "--gl osmesa"}, {"egl", "--gl egl"}, {"egl_without_grid", "--gl egl --overlays all,-grid"}};
  for (int i = 0; i < 3; ++i) {
    const std::string png = kOut + "/same_" + runs[i][0] + ".png";
    std::filesystem::remove(png);
    std::string args = scene + " " + runs[i][1];
    if (i == 2) args.replace(args.find("--overlays all "), 15, "");
    const auto r = run_env("", args + " --screenshot '" + png + "'");
    ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.err;
    images[i] = read_png(png);
    EXPECT_FALSE(is_uniform(images[i])) << png;
  }
  const ImageDiff same = compare_images(images[0], images[1], golden::kChannelTolerance);
  ASSERT_TRUE(same.same_size);
  if (same.differing > 0) write_png(kOut + "/same.diff.png", same.diff);
  EXPECT_LE(same.share(), golden::kMaxDifferingShare)
      << same.differing << " of " << same.total << " pixels differ by more than " << golden::kChannelTolerance
      << " between osmesa and egl (largest channel delta " << same.max_channel_delta << "); see " << kOut;
  const ImageDiff other = compare_images(images[0], images[2], golden::kChannelTolerance);
  EXPECT_GT(other.share(), golden::kMaxDifferingShare) << "switching the grid off went unnoticed";
}

// ---- errors: one line, exit 2, no screenshot ----------------------------------------------------

void expect_error(const std::string& env, const std::string& gl, const std::string& message) {
  const std::string png = kOut + "/error_" + std::to_string(::getpid()) + ".png";
  std::filesystem::remove(png);
  const auto r = run_env(env, small_render(png, "--gl " + gl));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err, "nbscope: error: " + message + "\n") << "env: " << env;
  EXPECT_FALSE(std::filesystem::exists(png));
}

TEST(GlBackendErrors, UnknownBackend) {
  expect_error("", "bogus", "--gl: 'bogus' is not one of osmesa, egl, auto");
  expect_error("", "OSMesa", "--gl: 'OSMesa' is not one of osmesa, egl, auto");
}

TEST(GlBackendErrors, LibraryNotInstalled) {
  const std::string no_osmesa = "NBSCOPE_OSMESA_LIBRARY=/nonexistent/libOSMesa.so.8";
  const std::string no_egl = "NBSCOPE_EGL_LIBRARY=/nonexistent/libEGL.so.1";
  expect_error(no_osmesa, "osmesa",
               "--gl osmesa: /nonexistent/libOSMesa.so.8 (from NBSCOPE_OSMESA_LIBRARY) not found; use --gl egl");
  expect_error(no_egl, "egl",
               "--gl egl: no EGL display (/nonexistent/libEGL.so.1 (from NBSCOPE_EGL_LIBRARY) not found)");
  expect_error(no_osmesa + " " + no_egl, "auto",
               "--gl auto: no off-screen renderer (osmesa: /nonexistent/libOSMesa.so.8 (from NBSCOPE_OSMESA_LIBRARY) "
               "not found; egl: /nonexistent/libEGL.so.1 (from NBSCOPE_EGL_LIBRARY) not found)");
}

TEST(GlBackendErrors, LibraryThatIsNotTheBackend) {
  // A library that loads but is not OSMesa / EGL (zlib is always there).
  expect_error("NBSCOPE_OSMESA_LIBRARY=libz.so.1", "osmesa", "--gl osmesa: the OSMesa library has no OSMesaCreateContextAttribs");
  expect_error("NBSCOPE_EGL_LIBRARY=libz.so.1", "egl", "--gl egl: the EGL library has no eglQueryString");
}

TEST(GlBackendErrors, EglWithoutAnyVendor) {
  // glvnd's libEGL with no vendor library: no platform is offered, so there is no display.
  expect_error("__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/vendor.json __EGL_VENDOR_LIBRARY_DIRS=/nonexistent", "egl",
               "--gl egl: no EGL display (neither EGL_MESA_platform_surfaceless nor EGL_EXT_platform_device is offered)");
}

TEST(GlBackendErrors, ContextWithoutGl33Core) {
  // Told to offer GL 2.1 only, Mesa refuses the 3.3 core context nbscope asks for, under both.
  expect_error("MESA_GL_VERSION_OVERRIDE=2.1", "egl", "--gl egl: cannot create a GL 3.3 core context (EGL_BAD_MATCH)");
  expect_error("MESA_GL_VERSION_OVERRIDE=2.1", "osmesa", "--gl osmesa: cannot create a GL 3.3 core context");
  expect_error("MESA_GL_VERSION_OVERRIDE=2.1", "auto", "--gl auto (osmesa): cannot create a GL 3.3 core context");
  expect_error("MESA_GL_VERSION_OVERRIDE=2.1 NBSCOPE_OSMESA_LIBRARY=/nonexistent/libOSMesa.so.8", "auto",
               "--gl auto (egl): cannot create a GL 3.3 core context (EGL_BAD_MATCH)");
}

}  // namespace
}  // namespace nbscope
