// The slow-frame note (app/frame_watch.hpp) on frames that are slow together, none alone: real
// sleeps of 40 ms a frame under a threshold of 0.3 s, so that only the sum passes it (a loaded
// machine makes the frames longer, never shorter: the note comes a frame or two earlier then).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <thread>

#include "app/frame_watch.hpp"

namespace nbscope {
namespace {

using std::chrono::milliseconds;

// A watch with the threshold `seconds` (read from the environment when it is made).
std::unique_ptr<FrameWatch> watch_with_threshold(const char* seconds) {
  ::setenv("NBSCOPE_SLOW_FRAME_SECONDS", seconds, 1);
  auto watch = std::make_unique<FrameWatch>();
  ::unsetenv("NBSCOPE_SLOW_FRAME_SECONDS");
  return watch;
}

// Frames first..last, each `step` in its first phase and `detect` after.
void run_frames(FrameWatch& watch, int first, int last, milliseconds step, milliseconds detect) {
  for (int f = first; f <= last; ++f) {
    watch.arm(f, [] { return std::string("Box2D step: 5 bodies"); });
    std::this_thread::sleep_for(step);
    watch.next_phase(f, [] { return std::string("detection (nbs) and the check of 5 elements"); });
    std::this_thread::sleep_for(detect);
    watch.disarm();
  }
}

TEST(FrameWatch, FramesSlowTogetherSaySoOnceWhenTheLastEnds) {
  const auto watch = watch_with_threshold("0.3");
  testing::internal::CaptureStderr();
  run_frames(*watch, 1, 12, milliseconds(30), milliseconds(10));
  const std::string err = testing::internal::GetCapturedStderr();
  // "nbscope: note: frames 1 to K took 0.NNN s together (Box2D step: 5 bodies)", K from 2 to 8. No
  // std::regex: GCC 12's -O1 sanitizer build warns inside it (maybe-uninitialized), and CI builds -Werror.
  const std::string head = "nbscope: note: frames 1 to ", tail = " s together (Box2D step: 5 bodies)\n";
  ASSERT_EQ(err.rfind(head, 0), 0u) << err;
  ASSERT_GE(err.size(), head.size() + tail.size()) << err;
  EXPECT_EQ(err.substr(err.size() - tail.size()), tail) << err;
  const std::string middle = err.substr(head.size(), err.size() - head.size() - tail.size());  // "K took 0.NNN"
  ASSERT_EQ(middle.rfind(" took 0.", 1), 1u) << err;
  EXPECT_GE(middle[0], '2');
  EXPECT_LE(middle[0], '8');
  const std::string fraction = middle.substr(9);  // after "K took 0."
  EXPECT_FALSE(fraction.empty()) << err;
  EXPECT_EQ(fraction.find_first_not_of("0123456789"), std::string::npos) << err;
  EXPECT_TRUE(watch->noted());
}

TEST(FrameWatch, TheNoteDescribesThePhaseThatTookMost) {
  const auto watch = watch_with_threshold("0.3");
  testing::internal::CaptureStderr();
  run_frames(*watch, 1, 12, milliseconds(5), milliseconds(35));
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find(" together (detection (nbs) and the check of 5 elements)\n"), std::string::npos) << err;
}

// Only consecutive frames of one run add up: a new run, or frames detected again rather than
// stepped, start the sum again.
TEST(FrameWatch, OnlyConsecutiveFramesOfOneRunAddUp) {
  const auto watch = watch_with_threshold("0.3");
  testing::internal::CaptureStderr();
  run_frames(*watch, 1, 4, milliseconds(45), milliseconds(0));  // 0.18 s; two such runs would pass 0.3 s
  watch->reset();
  run_frames(*watch, 1, 4, milliseconds(45), milliseconds(0));
  run_frames(*watch, 10, 13, milliseconds(45), milliseconds(0));  // not after frame 4
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  EXPECT_FALSE(watch->noted());
}

}  // namespace
}  // namespace nbscope
