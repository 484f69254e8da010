// The window's frame split (app/window_pacing.hpp: FrameSplitClock; ui/frame_split.hpp): every
// part of a frame named where the loop does it, so that the Stats panel's parts add up to the frame
// time beside FPS, and a paused window that sleeps until input says so. Synthetic clock readings:
// no timing of this machine is asserted.
#include <gtest/gtest.h>

#include <cmath>

#include "app/window_pacing.hpp"
#include "ui/frame_split.hpp"

namespace nbscope {
namespace {

using std::chrono::microseconds;

// One frame of 40 ms: 2 ms waiting for input, 5 ms of the view's parts, a 3 ms detection and check,
// a 20 ms swap; the rest (10 ms) is the loop's own work.
ui::DrawTimings frame_parts() {
  ui::DrawTimings p;
  p.trace_ms = 1;
  p.overlay_ms = 1;
  p.render_ms = 1;
  p.ui_ms = 2;
  p.detection_ms = 2;
  p.check_ms = 1;
  return p;
}

TEST(FrameSplit, ThePartsOfAWindowsFrameAddUpToItsTime) {
  FrameSplitClock clock;
  Clock::time_point t{};
  for (int k = 0; k < 20; ++k) {  // 20 frames of 40 ms: 0.8 s, past the half-second average
    clock.frame_start(t);
    clock.waited(t + microseconds(2000), false);
    clock.presented(20.0, frame_parts());
    t += microseconds(40'000);
  }
  clock.frame_start(t);
  const ui::DrawTimings& d = clock.average();
  ASSERT_TRUE(d.measured);
  EXPECT_FALSE(d.idle);
  EXPECT_DOUBLE_EQ(d.frame_ms, 40.0);
  EXPECT_DOUBLE_EQ(d.wait_ms, 2.0);
  EXPECT_DOUBLE_EQ(d.swap_ms, 20.0);
  const auto rows = ui::frame_split_rows(d, FrameTimings{});
  double sum = 0;
  for (const ui::FrameSplitRow& r : rows)
    if (r.counted) sum += r.ms;
  EXPECT_NEAR(sum, d.frame_ms, 1e-9);
  const auto named = [&](const std::string& name) {
    for (const ui::FrameSplitRow& r : rows)
      if (r.name == name) return r.ms;
    ADD_FAILURE() << "no row " << name;
    return -1.0;
  };
  EXPECT_DOUBLE_EQ(named("event wait"), 2.0);
  EXPECT_DOUBLE_EQ(named("swap"), 20.0);
  EXPECT_DOUBLE_EQ(named("detection"), 2.0);
  EXPECT_DOUBLE_EQ(named("other (loop)"), 10.0);
  // FPS and the frame time are of the same frames: 25 FPS beside 40 ms.
  EXPECT_EQ(ui::frame_rate_line(d, 26.3), "25.0 FPS   frame 40.0 ms");
}

TEST(FrameSplit, APausedWindowAsleepSaysSoInsteadOfAFrameRate) {
  FrameSplitClock clock;
  Clock::time_point t{};
  for (int k = 0; k < 4; ++k) {  // paused: each frame sleeps 250 ms for input that does not come
    clock.frame_start(t);
    clock.waited(t + microseconds(250'000), true);
    clock.presented(0.5, ui::DrawTimings{});
    t += microseconds(251'000);
  }
  clock.frame_start(t);
  const ui::DrawTimings& d = clock.average();
  ASSERT_TRUE(d.measured);
  EXPECT_TRUE(d.idle);
  EXPECT_EQ(ui::frame_rate_line(d, 3.5), "idle: waiting for input");
  EXPECT_EQ(ui::frame_split_rows(d, FrameTimings{}).front().name, "idle sleep");
}

TEST(FrameSplit, OffScreenFramesKeepTheViewsPartsAndSayThereIsNoFrameRate) {
  ui::DrawTimings d;  // not measured: a headless frame
  d.render_ms = 3;
  FrameTimings pipeline;
  pipeline.detection_ms = 2;
  const auto rows = ui::frame_split_rows(d, pipeline);
  ASSERT_EQ(rows.size(), 7u);  // physics, detection, check, trace, overlays, render, panels: as screenshots show them
  EXPECT_EQ(rows[1].name, "detection");
  EXPECT_DOUBLE_EQ(rows[1].ms, 2.0);
  EXPECT_EQ(ui::frame_rate_line(d, 0), "off-screen frame (no FPS)");
}

// A frame detected and checked on the worker: its detection and check rows say "overlapped" and,
// off-screen, are left out of the view's own sum as a worker's physics is.
TEST(FrameSplit, DetectionOnTheWorkerIsMarkedOverlapped) {
  ui::DrawTimings d;
  d.detection_overlapped = true;
  FrameTimings pipeline;
  pipeline.detection_ms = 2;
  pipeline.check_ms = 5;
  const auto rows = ui::frame_split_rows(d, pipeline);
  EXPECT_EQ(rows[1].note, "overlapped");
  EXPECT_FALSE(rows[1].counted);
  EXPECT_EQ(rows[2].note, "overlapped");
  EXPECT_FALSE(rows[2].counted);
  d.detection_overlapped = false;
  EXPECT_TRUE(ui::frame_split_rows(d, pipeline)[1].counted);
}

// The simulation's own rate (SimRate): a worker finishing a frame every 100 ms while the window
// draws at 30 FPS reads 10 frames/s, apart from the FPS; a paused simulation falls to 0 within the
// window; a new run (the count going down) starts again. Synthetic clock readings.
TEST(SimRate, CountsTheSimulationsFramesApartFromTheDisplaysFrames) {
  SimRate rate;
  EXPECT_EQ(rate.rate(), 0.0);
  std::int64_t done = 0;
  double t = 0;
  for (int k = 0; k < 90; ++k) {  // 3 s of display frames at 30 FPS
    t = k / 30.0;
    done = static_cast<std::int64_t>(t * 10.0 + 1e-9);  // a frame completed every 100 ms
    rate.sample(done, t);
  }
  EXPECT_NEAR(rate.rate(), 10.0, 0.6);
  for (int k = 90; k < 90 + 75; ++k) rate.sample(done, k / 30.0);  // paused 2.5 s: nothing completes
  EXPECT_EQ(rate.rate(), 0.0);
  rate.sample(0, t + 3);  // a restart: the count goes down
  EXPECT_EQ(rate.rate(), 0.0);
  rate.sample(5, t + 3.5);
  EXPECT_NEAR(rate.rate(), 10.0, 1e-9);
  // A fault: counting every display frame as a simulated one is caught.
  SimRate wrong;
  for (int k = 0; k < 90; ++k) wrong.sample(k, k / 30.0);
  EXPECT_GT(std::abs(wrong.rate() - 10.0), 5.0);
}

TEST(SimRate, TheStatsPanelShowsItBesideTheFrameRate) {
  ui::DrawTimings d;
  d.measured = true;
  d.frame_ms = 25;
  EXPECT_EQ(ui::sim_rate_text(d, 10.24), "sim 10.2 frames/s");
  EXPECT_EQ(ui::sim_rate_text(d, -1), "");  // not measured (off-screen)
  d.idle = true;
  EXPECT_EQ(ui::sim_rate_text(d, 0), "");  // asleep until input: nothing runs
}

}  // namespace
}  // namespace nbscope
