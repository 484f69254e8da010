// Worlds that break Box2D, end to end through `nbscope headless` (scenes in tests/worlds/): each
// either runs or stops with one line naming the frame (and the body) and exit 2, never a hang, a
// crash or an out-of-memory kill. Release suite only (tests/CMakeLists.txt): some build a
// million Box2D bodies. The expected numbers are derived here, not copied from a run: N bodies on
// one point make N(N-1)/2 contacts; a body that Box2D moves at most 2 m a sub-step (b2_maxTranslation)
// for 100 sub-steps a frame passes 1e6 m from 1e5 m in frame (1e6 - 1e5) / 200 + 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>

#include "support/run_cli.hpp"
#include "support/x_display.hpp"

namespace nbscope {
namespace {

using testcli::run;
using testcli::scratch_dir;
using testcli::write_text;

std::string world(const std::string& name) { return std::string(NBSCOPE_SOURCE_DIR) + "/tests/worlds/" + name + ".json"; }

// "4,498,500" for 4498500.
std::string grouped(long long n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

long long one_point_contacts(long long n) { return n * (n - 1) / 2; }

// One line on stderr, and nothing on stdout.
void expect_one_error_line(const testcli::Result& r) {
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("nbscope: error: ", 0), 0u) << r.err;
}

const char* kRaiseIt = "the limit is 1,000,000 (raise it with --max-contacts or the scene's \"max_contacts\")";

TEST(Worlds, ThirtyThousandOverlappingCirclesAreRefusedBeforeBox2DSteps) {
  const auto r = run("headless --scene '" + world("overlapping-30k") + "' --frames 3");
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("overlapping-30k.json: frame 1: Box2D would create about "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("between the fat AABBs of 30,000 bodies"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(kRaiseIt), std::string::npos) << r.err;
  // nbscope's own detection finds ~14M touching pairs of these circles; Box2D's fat AABBs more.
  std::smatch m;
  const std::string err = r.err;
  ASSERT_TRUE(std::regex_search(err, m, std::regex("about ([0-9,]+) contacts")));
  const long long contacts = std::stoll(std::regex_replace(m[1].str(), std::regex(","), ""));
  EXPECT_GT(contacts, 14'000'000);
  EXPECT_LT(contacts, one_point_contacts(30'000));
}

TEST(Worlds, ThreeThousandBodiesOnOnePointAreRefusedWithTheirContactCount) {
  const auto r = run("headless --scene '" + world("one-point-3k") + "' --frames 20");
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("frame 1: Box2D would create about " + grouped(one_point_contacts(3000)) + " contacts"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(kRaiseIt), std::string::npos) << r.err;
}

TEST(Worlds, ThirtyThousandBodiesOnOnePointAreRefusedWithTheirContactCount) {
  const auto r = run("headless --scene '" + world("one-point-30k") + "' --frames 20");
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("frame 1: Box2D would create about " + grouped(one_point_contacts(30000)) + " contacts"), std::string::npos) << r.err;
}

// The limit is exact at the boundary (the estimate counts N(N-1)/2 for N bodies on one point),
// the scene's key sets it and the flag overrides the key.
TEST(Worlds, MaxContactsFromTheSceneAndTheFlag) {
  const std::string dir = scratch_dir("worlds_max_contacts");
  const long long n = 200, contacts = one_point_contacts(n);
  const auto scene_with = [&](long long limit) {
    const std::string path = dir + "/pile-" + std::to_string(limit) + ".json";
    write_text(path, "{\"gravity\": [0, 0], \"max_contacts\": " + std::to_string(limit) +
                         ", \"generators\": [{\"kind\": \"random_box\", \"count\": " + std::to_string(n) +
                         ", \"min\": [0, 0], \"max\": [0.001, 0.001], \"body\": {\"shape\": \"circle\", \"radius\": 0.5}}]}");
    return path;
  };
  const auto refused = run("headless --scene '" + scene_with(contacts - 1) + "' --frames 2");
  expect_one_error_line(refused);
  EXPECT_NE(refused.err.find("about " + grouped(contacts) + " contacts"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("the limit is " + grouped(contacts - 1) + " "), std::string::npos) << refused.err;

  const auto runs = run("headless --scene '" + scene_with(contacts) + "' --frames 2 --quiet");
  EXPECT_EQ(runs.exit_code, 0) << runs.out << runs.err;
  const auto flag_lowers = run("headless --scene '" + scene_with(contacts) + "' --frames 2 --max-contacts " + std::to_string(contacts - 1));
  EXPECT_EQ(flag_lowers.exit_code, 2) << flag_lowers.err;
  const auto flag_raises = run("headless --scene '" + scene_with(contacts - 1) + "' --frames 2 --quiet --max-contacts " + std::to_string(contacts));
  EXPECT_EQ(flag_raises.exit_code, 0) << flag_raises.out << flag_raises.err;

  const auto bad = run("headless --scene '" + scene_with(-1) + "' --frames 2");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("max_contacts"), std::string::npos) << bad.err;
}

// Bodies flung at the scene's speed limit run: their fat AABBs stretch 10 m ahead and overlap by
// the hundred thousand, and Box2D's first frame takes a second or more. A frame past the
// slow-frame threshold (lowered here from 5 s; frame 0's detection of 2,000 elements takes
// milliseconds) says so once on stderr, which is not a terminal here.
TEST(Worlds, FlungBodiesRunAndASlowFrameSaysSoOnce) {
  const auto r = run("headless --scene '" + world("flung") + "' --frames 2 --quiet", "NBSCOPE_SLOW_FRAME_SECONDS=0.3");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("headless: flung, nbs, 3 frames, 2000 elements"), std::string::npos) << r.out;
  EXPECT_EQ(r.err.rfind("nbscope: note: frame 1 has run for ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("so far (Box2D step: 2,000 bodies, about "), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;

  // Fast frames under the default 5 s: no note.
  const auto calm = run("headless --scene '" + world("leaving") + "' --frames 10 --quiet");
  EXPECT_EQ(calm.exit_code, 0);
  EXPECT_EQ(calm.err, "");
}

// A circle of radius 1e-20 m: its float mass (pi 1e-40 kg) is a denormal whose inverse is
// infinite, and Box2D's first step would turn it NaN; 1e-300 m is 0 in float, an element of
// radius 0. Both are refused when the scene is read, naming the radius.
TEST(Worlds, ARadiusBox2DsFloatCannotHoldIsRefusedWhenTheSceneIsRead) {
  const auto r = run("headless --scene '" + world("nan") + "' --frames 5");
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("nan.json:4: bodies[0].radius: 1e-20 m at density 1 makes a mass of "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("whose inverse is infinite"), std::string::npos) << r.err;

  const std::string dir = scratch_dir("worlds_tiny_radius");
  write_text(dir + "/tiny.json", "{\"bodies\": [{\"shape\": \"circle\", \"radius\": 1},\n {\"shape\": \"circle\", \"radius\": 1e-300}]}");
  const auto tiny = run("headless --scene '" + dir + "/tiny.json' --frames 2");
  expect_one_error_line(tiny);
  EXPECT_NE(tiny.err.find("tiny.json:2: bodies[1].radius: 1e-300 m is 0 in Box2D's float: at least 1.18e-38 m"), std::string::npos) << tiny.err;
  // A generator drawing radii that small: named by the body it makes.
  write_text(dir + "/drawn.json", "{\"generators\": [{\"kind\": \"random_box\", \"count\": 5, \"min\": [0, 0], \"max\": [9, 9],\n"
                                  " \"scale\": [1e-300, 1e-299]}]}");
  const auto drawn = run("headless --scene '" + dir + "/drawn.json' --frames 2");
  expect_one_error_line(drawn);
  EXPECT_NE(drawn.err.find("drawn.json:1: generators[0].body: body #0: radius "), std::string::npos) << drawn.err;
  // A circle of 1e-4 m, 1 m from its body's origin: its inertia about the centre of mass,
  // m (r^2 / 2 + 1) - m 1, is 0 in float, and b2Body::ResetMassData's assertion aborted (signal 6).
  write_text(dir + "/inertia.json", "{\"bodies\": [{\"fixtures\": [{\"shape\": \"circle\", \"radius\": 1e-4, \"offset\": [1, 0]}]}]}");
  const auto inertia = run("headless --scene '" + dir + "/inertia.json' --frames 2");
  expect_one_error_line(inertia);
  EXPECT_NE(inertia.err.find("inertia.json:1: bodies[0]: its rotational inertia about its centre of mass is 0 in Box2D's float"), std::string::npos)
      << inertia.err;
}

// The contacts Box2D would make are held to the memory this process can get: past it the world
// is refused before Box2D steps, naming both figures, however high --max-contacts is set.
TEST(Worlds, ContactsBeyondTheMemoryThisProcessCanGetAreRefusedNamingBothFigures) {
  // 450M contacts, ~765 GB: beyond any machine's memory.
  const auto r = run("headless --scene '" + world("one-point-30k") + "' --frames 2 --max-contacts 1000000000");
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("frame 1: Box2D would create about " + grouped(one_point_contacts(30000)) + " contacts (765.0 GB)"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("; this process can get about "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--max-contacts cannot raise that)"), std::string::npos) << r.err;

  // Under `ulimit -v` (RLIMIT_AS) of 1.5 GB, 3,000 bodies on one point (4.5M contacts, 7.6 GB):
  // without the rule Box2D ran out of memory inside its step, a segfault after seconds.
  const auto limited = run("headless --scene '" + world("one-point-3k") + "' --frames 2 --max-contacts 1000000000", "ulimit -v 1500000;");
  expect_one_error_line(limited);
  EXPECT_NE(limited.err.find("frame 1: Box2D would create about " + grouped(one_point_contacts(3000)) + " contacts (7.6 GB)"), std::string::npos)
      << limited.err;
  EXPECT_NE(limited.err.find("for them (RLIMIT_AS; --max-contacts cannot raise that)"), std::string::npos) << limited.err;
}

// An emitter pouring 10 circles a frame onto one point without gravity: Box2D never parts them,
// so N bodies make N(N-1)/2 contacts. Frame f (emitting at time (f-1)/60, one body at time 0)
// has 10 (f - 1) + 1 bodies; the growth is measured from the first count of 64 bodies or more
// (71, frame 8) to the first of twice that (151, frame 16): exponent 2. At that growth the 2,849
// still to come make ~4.6M contacts: refused at frame 16, not at frame 143 when the pile itself
// passed 1,000,000 (after 44 s).
TEST(Worlds, AnEmitterPilingBodiesOnOnePointIsRefusedOnceItsGrowthShows) {
  const std::string dir = scratch_dir("worlds_pour");
  const std::string scene = dir + "/pour.json";
  write_text(scene, "{\"gravity\": [0, 0], \"generators\": [{\"kind\": \"emitter\", \"count\": 3000, \"rate\": 600, \"position\": [0, 0],\n"
                    " \"body\": {\"type\": \"dynamic\", \"shape\": \"circle\", \"radius\": 0.5}}]}");
  const auto r = run("headless --scene '" + scene + "' --frames 400");
  expect_one_error_line(r);
  const long long before = 10 * (8 - 1) + 1, now = 10 * (16 - 1) + 1;
  EXPECT_NE(r.err.find("pour.json: frame 16: the emitters' bodies pile up: " + grouped(now) + " bodies make about " +
                       grouped(one_point_contacts(now)) + " contacts, where " + grouped(before) + " made " + grouped(one_point_contacts(before)) +
                       " (contacts growing as bodies^2.0); with the " + grouped(3000 - now) + " still to come, about "),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(kRaiseIt), std::string::npos) << r.err;

  // Poured the same way onto a floor under gravity, they fall apart and the pile grows about
  // linearly: it runs.
  const std::string floor = dir + "/floor.json";
  write_text(floor, "{\"bodies\": [{\"type\": \"static\", \"shape\": \"box\", \"half_extents\": [20, 0.5], \"position\": [0, -0.5]}],\n"
                    " \"generators\": [{\"kind\": \"emitter\", \"count\": 3000, \"rate\": 600, \"position\": [0, 30]}]}");
  const auto falls = run("headless --scene '" + floor + "' --frames 40 --quiet");
  EXPECT_EQ(falls.exit_code, 0) << falls.err;
}

TEST(Worlds, ABodyLeavingTheWorldStopsTheRunNamingItAndTheFrame) {
  const auto r = run("headless --scene '" + world("leaving") + "' --frames 10000");
  expect_one_error_line(r);
  const int frame = (1'000'000 - 100'000) / 200 + 1;
  EXPECT_NE(r.err.find("leaving.json: frame " + std::to_string(frame) + ": body 1 (bodies[1]) is at ("), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("beyond +-1,000,000 m"), std::string::npos) << r.err;
  // Before that frame it runs.
  const auto before = run("headless --scene '" + world("leaving") + "' --frames " + std::to_string(frame - 1) + " --quiet");
  EXPECT_EQ(before.exit_code, 0) << before.err;
}

TEST(Worlds, AMillionOverlappingBodiesAreRefusedAtLoad) {
  const auto r = run("headless --scene '" + world("million-dense") + "' --frames 1");
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("frame 1: Box2D would create about "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("between the fat AABBs of 1,000,000 bodies"), std::string::npos) << r.err;
}

// A world that stops mid-run in the window: the message in the Scenes panel over the last good
// frame, the screenshot still taken, exit 2 with the same line.
TEST(Worlds, TheWindowShowsAWorldThatStops) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
#ifndef NBSCOPE_TEST_GUI
  GTEST_SKIP() << "built without the window";
#endif
  const std::string dir = scratch_dir("worlds_window");
  const std::string png = dir + "/stopped.png";
  const auto r = run("gui --scene '" + world("poured-on-one-point") + "' --frames 5 --panels scenes --screenshot '" + png + "'",
                     testcli::on_display());
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("nbscope: error: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("frame 2: Box2D would create about " + grouped(one_point_contacts(3000)) + " contacts"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(png));
}

// A radius Box2D's float cannot hold is a world refused, not a bad file: as a world that stops at
// load, the window opens paused on the line (its picture saved with --screenshot), then exit 2 with
// the line alone on stderr; so does the fallback without a display.
TEST(Worlds, TheWindowShowsARadiusFloatCannotHold) {
  const std::string dir = scratch_dir("worlds_window_radius");
  write_text(dir + "/tiny.json", "{\"bodies\": [{\"shape\": \"circle\", \"radius\": 1},\n {\"shape\": \"circle\", \"radius\": 1e-300}]}");
  const auto headless_png = dir + "/no-display.png";
  const auto r = run("gui --scene '" + dir + "/tiny.json' --frames 3 --panels scenes --screenshot '" + headless_png + "'",
                     "env -u DISPLAY -u WAYLAND_DISPLAY");
#ifndef NBSCOPE_TEST_GUI
  GTEST_SKIP() << "built without the window";
#endif
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_EQ(r.err, "nbscope: error: " + dir + "/tiny.json:2: bodies[1].radius: 1e-300 m is 0 in Box2D's float: at least 1.18e-38 m\n");
  EXPECT_TRUE(std::filesystem::exists(headless_png)) << r.out;

  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string png = dir + "/window.png";
  const auto w = run("gui --scene '" + world("nan") + "' --frames 5 --panels scenes --screenshot '" + png + "'", testcli::on_display());
  EXPECT_EQ(w.exit_code, 2) << w.out << w.err;
  EXPECT_NE(w.err.find("nbscope: error: "), std::string::npos) << w.err;
  EXPECT_NE(w.err.find("nan.json:4: bodies[0].radius: 1e-20 m at density 1 makes a mass of "), std::string::npos) << w.err;
  EXPECT_TRUE(std::filesystem::exists(png));
  // The interactive window opens on it (paused on the line) rather than refusing to start.
  const testcli::WindowRun opened = testcli::run_window("gui --scene '" + world("nan") + "'", "XDG_CONFIG_HOME='" + dir + "'");
  EXPECT_TRUE(opened.window_shown) << opened.err;
  EXPECT_EQ(opened.err, "");
}

}  // namespace
}  // namespace nbscope
