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
  ASSERT_TRUE(loop.source().replaying());
  EXPECT_EQ(loop.source().recorded_frames(), 3);
  EXPECT_EQ(loop.source().scene().name, "three");
  const std::int64_t numbers[] = {3, 4, 9};
  const double times[] = {0.5, 0.75, 0.75};
  for (int k = 0; k < 3; ++k) {
    if (k > 0) loop.step();
    const Recording rec = three_frames();
    EXPECT_EQ(loop.source().frame(), numbers[k]);
    EXPECT_EQ(loop.source().time(), times[k]);
    EXPECT_TRUE((loop.source().elements().x == rec.frames[static_cast<std::size_t>(k)].elements.x).all());
    EXPECT_EQ(loop.result().selected().pairs, testdata::brute_pairs(rec.frames[static_cast<std::size_t>(k)].elements)) << "frame " << k;
    EXPECT_TRUE(loop.result().report().checked);
    EXPECT_TRUE(loop.result().report().ok());
    EXPECT_FALSE(loop.result().report().box2d_checks) << "no Box2D world: only A==R ran";
    EXPECT_EQ(loop.source().at_end(), k == 2);
    std::vector<BodyShape> shapes;
    loop.source().body_shapes(shapes);
    EXPECT_EQ(static_cast<std::int64_t>(shapes.size()), loop.source().elements().size()) << "one circle per element";
  }
  loop.step();  // at the end: nothing happens
  EXPECT_EQ(loop.source().frame(), 9);
  loop.restart();
  EXPECT_EQ(loop.source().frame(), 3);
  EXPECT_FALSE(loop.source().at_end());
}

TEST(ReplayFrameLoop, FaultIsCaughtWithoutBox2d) {
  FrameLoopOptions o;
  o.fault = Fault::DropPair;
  FrameLoop loop(o);
  loop.load_recording(three_frames());
  EXPECT_FALSE(loop.result().report().ok());
  EXPECT_GT(loop.result().report().broken[static_cast<std::size_t>(Invariant::AEqualsR)], 0);
}

TEST(ReplayFrameLoop, ASceneReplacesTheRecording) {
  FrameLoop loop;
  loop.load_recording(three_frames());
  load_scene_file(loop, std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/book-fig-3-15.json");
  EXPECT_FALSE(loop.source().replaying());
  EXPECT_TRUE(loop.result().report().box2d_checks);
  EXPECT_FALSE(loop.source().at_end());
}

// ---- `recorded`: the recording's own pairs (check/recorded_lane.hpp) ------------------------------

// Frames 3, 4, 9 of three_frames() with their contact pairs; frame 4's are wrong (a pair of elements
// that do not touch, and element 1 paired with itself).
Recording three_frames_with_pairs() {
  return parse_recording(
      "nbsrec 1\nframe 3 0.5\n0,0,1\n1.5,0,1\n5,5,1\npairs\n1,0\nframe 4 0.75\n0,0,1\n3,0,1\npairs\n0,1\n1,1\n"
      "frame 9 0.75\n0,0,1\n0.5,0,1\n1,0,1\npairs\n0,1\n0,2\n1,2\n",
      "three.nbsrec");
}

TEST(ReplayFrameLoopRecorded, ChecksEachFramesOwnPairsAndGoesBackToTheBadOne) {
  FrameLoopOptions o;
  o.algorithm = "recorded";
  FrameLoop loop(o);
  loop.load_recording(three_frames_with_pairs());
  EXPECT_TRUE(loop.source().carries_pairs());
  EXPECT_EQ(loop.result().selected().pairs, (PairList{{0, 1}})) << "1,0 normalised";
  EXPECT_TRUE(loop.result().report().ok());
  loop.step();
  EXPECT_EQ(loop.source().frame(), 4);
  EXPECT_FALSE(loop.result().report().ok());
  ASSERT_EQ(loop.result().report().violations.size(), 2u);
  loop.step();
  EXPECT_EQ(loop.source().frame(), 9);
  EXPECT_TRUE(loop.result().report().ok());
  // Go to the violation (as the Violations panel does): frame 4 and its own pairs again.
  ASSERT_EQ(loop.history().violation_log().listed().size(), 2u);
  const Violation v = loop.history().violation_log().listed().front();
  EXPECT_EQ(v.frame, 4);
  loop.show_frame(v.frame);
  EXPECT_EQ(loop.source().frame(), 4);
  EXPECT_EQ(loop.result().selected().pairs, (PairList{{0, 1}, {1, 1}}));
  ASSERT_EQ(loop.result().report().violations.size(), 2u);
  EXPECT_STREQ(loop.result().report().violations[0].what, "an element paired with itself in the recorded pairs");
  EXPECT_EQ(loop.result().report().violations[0].pair, (Pair{1, 1}));
  EXPECT_STREQ(loop.result().report().violations[1].what, "in the recorded pairs but not in contact (not in R)");
  EXPECT_EQ(loop.result().report().violations[1].pair, (Pair{0, 1}));
  // Nothing to step through or draw as lists: said, not broken.
  const auto trace = loop.pipeline().frame_trace();
  ASSERT_NE(trace, nullptr);
  EXPECT_TRUE(trace->log.events().empty());
  EXPECT_NE(trace->refusal.find("read from the file, not detected here"), std::string::npos) << trace->refusal;
}

TEST(ReplayFrameLoopRecorded, IsRefusedWhereThereAreNoPairsAndTheOldStateStays) {
  FrameLoop loop;
  loop.load_recording(three_frames());  // no pairs blocks
  EXPECT_FALSE(loop.source().carries_pairs());
  EXPECT_THROW(loop.redetect_with_algorithm("recorded"), Error);
  EXPECT_EQ(loop.pipeline().algorithm(), "nbs");
  EXPECT_THROW(loop.redetect_with_comparisons({"recorded"}), Error);
  EXPECT_TRUE(loop.pipeline().comparison_algorithms().empty());

  loop.load_recording(three_frames_with_pairs());
  loop.redetect_with_algorithm("recorded");
  EXPECT_THROW(loop.load_recording(three_frames()), Error) << "the recording without pairs is refused";
  EXPECT_TRUE(loop.source().carries_pairs()) << "the old recording stays";
  EXPECT_THROW(load_scene_file(loop, std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/book-fig-3-15.json"), Error);
  EXPECT_TRUE(loop.source().replaying()) << "a scene has no pairs for recorded";

  FrameLoopOptions o;
  o.algorithm = "recorded";
  FrameLoop scene_loop(o);
  EXPECT_THROW(load_scene_file(scene_loop, std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/book-fig-3-15.json"), Error);
  EXPECT_FALSE(scene_loop.source().has_scene());
}

TEST(ReplayFrameLoopRecorded, OnlyTheFaultThatActsOnThePairsIsTaken) {
  FrameLoopOptions o;
  o.algorithm = "recorded";
  FrameLoop loop(o);
  loop.load_recording(three_frames_with_pairs());
  for (const Fault f : {Fault::StalePositions, Fault::DropMaskCell, Fault::OffByOneCell, Fault::DropBox2dContact}) {
    EXPECT_THROW(loop.redetect_with_fault(f), Error) << fault_name(f);
    EXPECT_EQ(loop.pipeline().fault(), Fault::None);
  }
  loop.redetect_with_fault(Fault::DropPair);
  EXPECT_TRUE(loop.result().selected().pairs.empty()) << "frame 3's only pair dropped";
  EXPECT_FALSE(loop.result().report().ok());
  loop.redetect_with_fault(Fault::None);
  loop.redetect_with_algorithm("nbs");
  loop.redetect_with_fault(Fault::StalePositions);  // a detector takes it
  EXPECT_THROW(loop.redetect_with_algorithm("recorded"), Error);
  EXPECT_EQ(loop.pipeline().algorithm(), "nbs");
  o.fault = Fault::OffByOneCell;
  EXPECT_THROW(FrameLoop{o}, Error);
}

}  // namespace
}  // namespace nbscope
