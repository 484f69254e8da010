// FrameLoop on recorded frames: the recording's numbers, times and elements frame by frame, the end
// of the recording, restart, the checks without Box2D, and a scene replacing the recording.
#include <gtest/gtest.h>

#include "app/frame_loop.hpp"
#include "core/error.hpp"
#include "io/recording.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

Recording three_frames() {
  return parse_recording(
      "nbsrec 1\nframe 3 0.5\n0,0,1\n1.5,0,1\n5,5,1\nframe 4 0.75\n0,0,1\n3,0,1\nframe 9 0.75\n0,0,1\n0.5,0,1\n1,0,1\n",
      "three.nbsrec");
}

TEST(ReplayFrameLoop, WalksTheRecordedFramesAndStopsAtTheEnd) {
  FrameLoop loop;
  loop.load_recording(three_frames());
  ASSERT_TRUE(loop.replaying());
  EXPECT_EQ(loop.recorded_frames(), 3);
  EXPECT_EQ(loop.scene().name, "three");
  const std::int64_t numbers[] = {3, 4, 9};
  const double times[] = {0.5, 0.75, 0.75};
  for (int k = 0; k < 3; ++k) {
    if (k > 0) loop.step();
    const Recording rec = three_frames();
    EXPECT_EQ(loop.frame(), numbers[k]);
    EXPECT_EQ(loop.time(), times[k]);
    EXPECT_TRUE((loop.elements().x == rec.frames[static_cast<std::size_t>(k)].elements.x).all());
    EXPECT_EQ(loop.pairs(), testdata::brute_pairs(rec.frames[static_cast<std::size_t>(k)].elements)) << "frame " << k;
    EXPECT_TRUE(loop.report().checked);
    EXPECT_TRUE(loop.report().ok());
    EXPECT_FALSE(loop.report().box2d_checks) << "no Box2D world: only A==R ran";
    EXPECT_EQ(loop.at_end(), k == 2);
    std::vector<BodyShape> shapes;
    loop.body_shapes(shapes);
    EXPECT_EQ(static_cast<std::int64_t>(shapes.size()), loop.elements().size()) << "one circle per element";
  }
  loop.step();  // at the end: nothing happens
  EXPECT_EQ(loop.frame(), 9);
  loop.restart();
  EXPECT_EQ(loop.frame(), 3);
  EXPECT_FALSE(loop.at_end());
}

TEST(ReplayFrameLoop, FaultIsCaughtWithoutBox2d) {
  FrameLoopOptions o;
  o.fault = Fault::DropPair;
  FrameLoop loop(o);
  loop.load_recording(three_frames());
  EXPECT_FALSE(loop.report().ok());
  EXPECT_GT(loop.report().broken[static_cast<std::size_t>(Invariant::AEqualsR)], 0);
}

TEST(ReplayFrameLoop, ASceneReplacesTheRecording) {
  FrameLoop loop;
  loop.load_recording(three_frames());
  loop.load_scene_file(std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/book-fig-3-15.json");
  EXPECT_FALSE(loop.replaying());
  EXPECT_TRUE(loop.report().box2d_checks);
  EXPECT_FALSE(loop.at_end());
}

}  // namespace
}  // namespace nbscope
