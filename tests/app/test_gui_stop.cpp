// The window's stop contract and its settings file, through the binary (GUI build only):
// - a world that stops at load (Box2D would create more contacts than allowed) or mid-run: `gui
//   --frames N --screenshot` in the window (Xvfb) and the no-display fallback save the picture of
//   the line in red, then exit 2 with that line as the only one on stderr; the interactive window
//   opens paused on it instead of exiting;
// - a stale settings file (an unknown algorithm, a last scene that no longer reads, wrong types,
//   not JSON) still opens the window, with one note line naming the file and what was ignored.
// Interactive sessions run on the test's own Xvfb until their window is mapped, then get SIGTERM,
// which closes the window like its close button (exit 0, and the settings file written on the way
// out shows the loop ran to its end; support/x_display.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "io/png.hpp"
#include "support/run_cli.hpp"
#include "support/x_display.hpp"

namespace nbscope {
namespace {

using testcli::run;
using testcli::scratch_dir;
using testcli::write_text;

const std::string kDefaultScene = std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/default.json";
constexpr const char* kNoDisplay = "env -u DISPLAY -u WAYLAND_DISPLAY";

std::size_t lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

// The interactive window was shown, and SIGTERM closed it as its close button does (exit 0).
void expect_closed_by_sigterm(const testcli::WindowRun& r) {
  EXPECT_TRUE(r.window_shown) << "no window was mapped: " << r.out << r.err;
  EXPECT_EQ(r.exit_code, 0) << "the window did not close normally on SIGTERM: " << r.out << r.err;
}

void expect_only_error_line(const testcli::Result& r, const std::string& needle) {
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_EQ(r.err.rfind("nbscope: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
}

// Pixels of the Scenes panel's red message text (ImGui's (1, 0.35, 0.35), antialiased).
std::int64_t red_text_pixels(const Image& image) {
  std::int64_t n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.at(x, y);
      n += p[0] > 200 && p[1] > 50 && p[1] < 130 && p[2] > 50 && p[2] < 130 && std::abs(p[1] - p[2]) < 12 ? 1 : 0;
    }
  return n;
}

// A valid, non-blank picture with the message drawn in red.
void expect_picture_of_the_message(const std::string& png) {
  ASSERT_TRUE(std::filesystem::exists(png)) << png;
  const Image image = read_png(png);
  EXPECT_EQ(image.width, 800);
  EXPECT_EQ(image.height, 600);
  EXPECT_FALSE(is_uniform(image));
  EXPECT_GT(red_text_pixels(image), 100) << "no red message in " << png;
}

// A small world that runs at load and stops in a later frame: an emitter pours 40 circles onto one
// point (40 * 39 / 2 = 780 contacts) where at most 100 are allowed.
std::string world_that_stops_mid_run(const std::string& dir) {
  const std::string path = dir + "/poured.json";
  write_text(path, R"({"name": "poured", "gravity": [0, 0], "max_contacts": 100,
    "bodies": [{"type": "dynamic", "shape": "circle", "radius": 0.5, "position": [5, 0]}],
    "generators": [{"kind": "emitter", "count": 40, "rate": 1000000, "position": [0, 0],
                    "body": {"type": "dynamic", "shape": "circle", "radius": 0.5}}]})");
  return path;
}

// ---- a world that stops at load -------------------------------------------------------------------

TEST(GuiStop, AtLoadTheWindowSavesThePictureOfTheMessageAndExits2WithOneLine) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string dir = scratch_dir("gui_stop_load_window");
  const auto r = run("gui --scene '" + kDefaultScene + "' --max-contacts 0 --frames 3 --size 800x600 --screenshot '" + dir + "/shot.png'",
                     testcli::on_display());
  expect_only_error_line(r, "default.json: frame 1: Box2D would create about ");
  EXPECT_EQ(r.out, "");
  expect_picture_of_the_message(dir + "/shot.png");
}

TEST(GuiStop, AtLoadWithoutADisplayThePictureIsRenderedHeadless) {
  const std::string dir = scratch_dir("gui_stop_load_headless");
  const auto r = run("gui --scene '" + kDefaultScene + "' --max-contacts 0 --frames 3 --size 800x600 --screenshot '" + dir + "/shot.png'",
                     kNoDisplay);
  expect_only_error_line(r, "default.json: frame 1: Box2D would create about ");
  EXPECT_EQ(r.out, "screenshot: " + dir + "/shot.png\n");
  expect_picture_of_the_message(dir + "/shot.png");
}

// Without --screenshot the fallback picks its own path in $TMPDIR, named after the scene.
TEST(GuiStop, AtLoadWithoutADisplayOrAPathThePictureGoesToTmpdir) {
  const std::string dir = scratch_dir("gui_stop_load_tmpdir");
  const auto r = run("gui --scene '" + kDefaultScene + "' --max-contacts 0 --frames 1", std::string(kNoDisplay) + " TMPDIR='" + dir + "'");
  expect_only_error_line(r, "frame 1: Box2D would create about ");
  EXPECT_TRUE(std::filesystem::exists(dir + "/nbscope-default.png")) << r.out << r.err;
}

TEST(GuiStop, AtLoadTheInteractiveWindowOpensPausedOnTheMessage) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string dir = scratch_dir("gui_stop_load_interactive");
  const auto r = testcli::run_window("gui --scene '" + kDefaultScene + "' --max-contacts 0", "XDG_CONFIG_HOME='" + dir + "'");
  expect_closed_by_sigterm(r);
  EXPECT_EQ(r.err, "");
  const std::string saved = testcli::read_text(dir + "/nbscope/settings.json");
  ASSERT_FALSE(saved.empty()) << "the window did not close normally";
  EXPECT_EQ(nlohmann::json::parse(saved).at("last_scene"), kDefaultScene);
}

// A scene that cannot be read is not a world that stops: there is nothing to show (one line, no file).
TEST(GuiStop, ASceneThatFailsToLoadIsAnErrorWithoutAPicture) {
  const std::string dir = scratch_dir("gui_stop_bad_scene");
  write_text(dir + "/bad.json", "{\"bodies\": [{\"shape\": \"circle\", \"radius\": -1}]}");
  const auto r = run("gui --scene '" + dir + "/bad.json' --frames 3 --screenshot '" + dir + "/shot.png'", kNoDisplay);
  expect_only_error_line(r, "bad.json:1: bodies[0].radius");
  EXPECT_FALSE(std::filesystem::exists(dir + "/shot.png"));
}

// ---- a world that stops mid-run -------------------------------------------------------------------

TEST(GuiStop, MidRunTheWindowSavesThePictureAndPrintsOnlyTheError) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string dir = scratch_dir("gui_stop_mid_window");
  const auto r = run("gui --scene '" + world_that_stops_mid_run(dir) + "' --frames 5 --size 800x600 --screenshot '" + dir + "/shot.png'",
                     testcli::on_display());
  expect_only_error_line(r, "poured.json: frame ");
  EXPECT_NE(r.err.find("Box2D would create about 780 contacts"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  expect_picture_of_the_message(dir + "/shot.png");
}

TEST(GuiStop, MidRunWithoutADisplayThePictureIsRenderedHeadless) {
  const std::string dir = scratch_dir("gui_stop_mid_headless");
  const auto r = run("gui --scene '" + world_that_stops_mid_run(dir) + "' --frames 5 --size 800x600 --screenshot '" + dir + "/shot.png'",
                     kNoDisplay);
  expect_only_error_line(r, "Box2D would create about 780 contacts");
  EXPECT_EQ(r.out, "screenshot: " + dir + "/shot.png\n");
  expect_picture_of_the_message(dir + "/shot.png");
}

// ---- a stale settings file --------------------------------------------------------------------------

// Runs the interactive window until it is shown, then closes it, with `settings` as its settings file.
testcli::WindowRun window_with_settings(const std::string& dir, const std::string& settings, const std::string& args = "") {
  std::filesystem::create_directories(dir + "/nbscope");
  write_text(dir + "/nbscope/settings.json", settings);
  return testcli::run_window("gui" + args, "XDG_CONFIG_HOME='" + dir + "'");
}

void expect_one_note(const testcli::WindowRun& r, const std::string& dir, const std::vector<std::string>& needles) {
  expect_closed_by_sigterm(r);
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_EQ(r.err.rfind("nbscope: note: " + dir + "/nbscope/settings.json: ignored ", 0), 0u) << r.err;
  for (const std::string& n : needles) EXPECT_NE(r.err.find(n), std::string::npos) << n << " not in " << r.err;
}

TEST(GuiSettings, AnUnknownAlgorithmAndWrongTypesAreIgnoredAndTheWindowOpens) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string dir = scratch_dir("gui_settings_stale");
  const auto r = window_with_settings(dir, R"({"version": 1, "algorithm": "bogus", "speed": "fast", "history_mb": 64,
    "overlays": {"grid": "yes", "ids": true}})");
  expect_one_note(r, dir, {"algorithm \"bogus\" (not one of ", "speed \"fast\" (not a number", "overlays.grid \"yes\" (not true or false)"});
  // Written back on closing: the defaults for what was ignored, the rest kept.
  const auto saved = nlohmann::json::parse(testcli::read_text(dir + "/nbscope/settings.json"));
  EXPECT_EQ(saved.at("algorithm"), "nbs");
  EXPECT_EQ(saved.at("speed"), 1.0);
  EXPECT_EQ(saved.at("history_mb"), 64);
  EXPECT_EQ(saved.at("overlays").at("ids"), true);
}

// A plugin chosen in the window is chosen again at the next start: its library is saved with it and
// loaded before the saved algorithm is looked up (else the algorithm would be ignored as unknown).
TEST(GuiSettings, ADetectorLibraryIsRememberedWithItsAlgorithm) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string dir = scratch_dir("gui_settings_detector_lib");
  const std::string library = std::string(NBSCOPE_PLUGIN_DIR) + "/test_plugin_good.so";
  const auto first = window_with_settings(dir, R"({"version": 1})", " --detector-lib '" + library + "' --algorithm test-good");
  expect_closed_by_sigterm(first);
  auto saved = nlohmann::json::parse(testcli::read_text(dir + "/nbscope/settings.json"));
  EXPECT_EQ(saved.at("algorithm"), "test-good");
  ASSERT_EQ(saved.at("detector_libs").size(), 1u);
  EXPECT_EQ(std::filesystem::path(saved.at("detector_libs")[0].get<std::string>()), std::filesystem::canonical(library));

  const auto second = testcli::run_window("gui", "XDG_CONFIG_HOME='" + dir + "'");
  expect_closed_by_sigterm(second);
  EXPECT_EQ(second.err, "");  // nothing ignored: the library loaded, so its algorithm was known
  saved = nlohmann::json::parse(testcli::read_text(dir + "/nbscope/settings.json"));
  EXPECT_EQ(saved.at("algorithm"), "test-good");
}

TEST(GuiSettings, ALastSceneThatNoLongerReadsFallsBackToTheDefaultScene) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string dir = scratch_dir("gui_settings_last_scene");
  write_text(dir + "/broken.json", "{\"bodies\": [");
  const auto r = window_with_settings(dir, R"({"version": 1, "last_scene": ")" + dir + R"(/broken.json"})");
  expect_one_note(r, dir, {"last_scene (" + dir + "/broken.json:1: "});
  EXPECT_EQ(nlohmann::json::parse(testcli::read_text(dir + "/nbscope/settings.json")).at("last_scene"), kDefaultScene);
}

TEST(GuiSettings, ALastSceneThatIsGoneFallsBackToTheDefaultScene) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string gone = scratch_dir("gui_settings_last_scene_gone");
  const auto g = window_with_settings(gone, R"({"version": 1, "last_scene": "/no/such/scene.json"})");
  expect_one_note(g, gone, {"last_scene \"/no/such/scene.json\" (no such file)"});
}

TEST(GuiSettings, ACorruptFileIsIgnoredWhole) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string dir = scratch_dir("gui_settings_corrupt");
  const auto r = window_with_settings(dir, "{\"version\": 1, \"speed\": ");
  expect_one_note(r, dir, {"ignored the whole file (not JSON: ", "; the defaults are used"});
}

// ---- the window's size ------------------------------------------------------------------------------

// Without --size the window opens to the screen's work area (the test's Xvfb: 1280x720) and the size
// it closed at is saved; a saved size opens again (within the work area); --size wins over both.
TEST(GuiSettings, TheWindowOpensToTheWorkAreaAndRemembersItsSize) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string dir = scratch_dir("gui_settings_window_size");
  const auto size_saved = [&] { return nlohmann::json::parse(testcli::read_text(dir + "/nbscope/settings.json")).at("window_size"); };
  expect_closed_by_sigterm(window_with_settings(dir, R"({"version": 1})"));
  EXPECT_EQ(size_saved(), nlohmann::json::parse("[1280, 720]"));
  expect_closed_by_sigterm(window_with_settings(dir, R"({"version": 1, "window_size": [900, 600]})"));
  EXPECT_EQ(size_saved(), nlohmann::json::parse("[900, 600]"));
  expect_closed_by_sigterm(window_with_settings(dir, R"({"version": 1, "window_size": [4000, 600]})"));
  EXPECT_EQ(size_saved(), nlohmann::json::parse("[1280, 600]")) << "a saved size larger than the screen";
  expect_closed_by_sigterm(window_with_settings(dir, R"({"version": 1, "window_size": [900, 600]})", " --size 700x450"));
  EXPECT_EQ(size_saved(), nlohmann::json::parse("[700, 450]"));
}

}  // namespace
}  // namespace nbscope
