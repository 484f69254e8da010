// The frame pipeline (check/pipeline.hpp) on its own: every lane detects the same elements and agrees
// with brute force (the tests' own double loop), an injected fault reaches each lane's pairs as the
// fault's bug would and its check catches it while R stays whole, the stale-positions fault detects
// the frame before's positions, checks off count only what was detected, and the selected lane can
// be switched. Frames come from tests/support/check_context.hpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "check/pipeline.hpp"
#include "core/error.hpp"
#include "support/check_context.hpp"

namespace nbscope {
namespace {

using testcheck::CheckTestContext;
using testcheck::lane_options;
using testcheck::random_circles;
using testcheck::recorded_frame;
using testcheck::touching_pairs;

const std::vector<std::string> kComparisonLanes{"sort", "tree", "screen", "brute"};

// `pairs` without its middle pair (the one drop-pair removes): worked out here, not asked of the fault.
PairList without_middle(PairList pairs) {
  pairs.erase(pairs.begin() + static_cast<std::ptrdiff_t>(pairs.size() / 2));
  return pairs;
}

// Three frames of random circles, each its own seed.
std::vector<RecordedFrame> random_frames() {
  std::vector<RecordedFrame> frames;
  for (std::int64_t k = 0; k < 3; ++k) frames.push_back(recorded_frame(k, random_circles(400, 11 + static_cast<std::uint64_t>(k))));
  return frames;
}

// A scene of loose dynamic circles without gravity: after a step, every set of the check exists.
const char* const kCirclesScene = R"({"gravity": [0, 0], "generators": [
    {"kind": "random_box", "count": 300, "seed": 5, "min": [0, 0], "max": [30, 30], "radius": [0.3, 0.6],
     "body": {"type": "dynamic", "shape": "circle"}}]})";

// ---- lanes --------------------------------------------------------------------------------------

// On random frames, the selected lane and every comparison lane give brute force's pairs and hold.
TEST(PipelineLanes, EveryLaneGivesTheBruteForcePairsOfRandomElements) {
  auto c = CheckTestContext::recorded(random_frames(), lane_options("nbs"));
  c->pipeline().set_comparison_algorithms(kComparisonLanes);
  for (int f = 0; f < 3; ++f) {
    const FrameResult& r = f == 0 ? c->run() : c->next();
    SCOPED_TRACE("frame " + std::to_string(r.frame));
    const PairList expected = touching_pairs(c->elements());
    ASSERT_GT(expected.size(), 10u) << "a frame with pairs to lose";
    ASSERT_EQ(r.lanes.size(), 1 + kComparisonLanes.size());
    EXPECT_EQ(r.lanes[0].algorithm, "nbs");
    for (std::size_t k = 0; k < r.lanes.size(); ++k) {
      SCOPED_TRACE(r.lanes[k].algorithm);
      if (k > 0) {
        EXPECT_EQ(r.lanes[k].algorithm, kComparisonLanes[k - 1]);
      }
      EXPECT_EQ(r.lanes[k].pairs, expected);
      EXPECT_TRUE(r.lanes[k].report.ok());
      EXPECT_EQ(r.lanes[k].report.counts.a, static_cast<std::int64_t>(expected.size()));
      EXPECT_EQ(r.lanes[k].report.hash, hash_elements(c->elements()));
    }
    EXPECT_EQ(r.reference, expected);
    EXPECT_EQ(r.frame, f);
  }
}

// A live scene's frame: T (circles touching now) is the oracle's pairs, F holds A's in-scope pairs.
TEST(PipelineLanes, ASceneFrameIsCheckedAgainstBox2dsSets) {
  auto c = CheckTestContext::scene(kCirclesScene, lane_options("nbs"));
  c->run();
  const FrameResult& r = c->next();
  const PairList expected = touching_pairs(c->elements());
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(r.frame, 1);
  EXPECT_EQ(r.selected().pairs, expected);
  EXPECT_EQ(r.touching, expected) << "two circles touch exactly when their bounding circles do";
  EXPECT_TRUE(std::includes(r.tight_aabb.begin(), r.tight_aabb.end(), r.touching.begin(), r.touching.end())) << "T is in G";
  EXPECT_TRUE(std::includes(r.box2d.begin(), r.box2d.end(), expected.begin(), expected.end())) << "every pair of A in F";
  EXPECT_TRUE(r.report().box2d_checks);
  EXPECT_TRUE(r.report().ok());
}

// The selected lane switches on the next run; an unknown name is refused and the old lane kept.
TEST(PipelineLanes, SetAlgorithmSwitchesTheSelectedLaneForTheNextRun) {
  auto c = CheckTestContext::recorded(random_frames(), lane_options("nbs"));
  c->run();
  c->pipeline().set_algorithm("sort");
  EXPECT_EQ(c->pipeline().result().selected().algorithm, "sort");
  EXPECT_TRUE(c->pipeline().result().selected().pairs.empty()) << "the old lane's pairs are not the new one's";
  EXPECT_EQ(c->run().selected().pairs, touching_pairs(c->elements()));
  EXPECT_EQ(c->pipeline().detector().name(), "sort");
  EXPECT_THROW(c->pipeline().set_algorithm("no-such-detector"), Error);
  EXPECT_EQ(c->pipeline().detector().name(), "sort");
  EXPECT_THROW({ Pipeline refused(lane_options("no-such-detector")); }, Error);
}

// ---- faults ------------------------------------------------------------------------------------

// drop-pair reaches every lane's pairs (one fault for the frame) and each lane's A==R names the pair; R stays whole.
TEST(PipelineFaults, ADroppedPairIsCaughtInEveryLaneWhileRStaysWhole) {
  auto c = CheckTestContext::recorded(random_frames(), lane_options("nbs", Fault::DropPair));
  c->pipeline().set_comparison_algorithms(kComparisonLanes);
  const FrameResult& r = c->run();
  const PairList whole = touching_pairs(c->elements());
  const Pair lost = whole[whole.size() / 2];
  EXPECT_EQ(r.reference, whole);
  for (const LaneResult& lane : r.lanes) {
    SCOPED_TRACE(lane.algorithm);
    EXPECT_EQ(lane.pairs, without_middle(whole));
    EXPECT_FALSE(lane.report.ok());
    EXPECT_EQ(lane.report.violation_count(), 1);
    EXPECT_EQ(lane.report.broken[static_cast<std::size_t>(Invariant::AEqualsR)], 1);
    ASSERT_EQ(lane.report.violations.size(), 1u);
    EXPECT_EQ(lane.report.violations[0].pair, lost);
    EXPECT_STREQ(lane.report.violations[0].what, "missing from A (in R)");
  }
}

// drop-box2d-contact leaves A alone and breaks A-in-F once, on a live scene.
TEST(PipelineFaults, ADroppedBox2dContactBreaksAInFAndLeavesAAlone) {
  auto c = CheckTestContext::scene(kCirclesScene, lane_options("nbs", Fault::DropBox2dContact));
  c->run();
  const FrameResult& r = c->next();
  EXPECT_EQ(r.selected().pairs, touching_pairs(c->elements()));
  EXPECT_EQ(r.report().broken[static_cast<std::size_t>(Invariant::AEqualsR)], 0);
  EXPECT_EQ(r.report().broken[static_cast<std::size_t>(Invariant::AInF)], 1);
}

// Hand-worked: b moves into a's reach and c appears beside b's old place; stale positions see the old b.
TEST(PipelineFaults, StalePositionsDetectTheFrameBeforesPositionsAndNewElementsAtTheirOwn) {
  Elements before, now;
  before.push_back(0, 0, 0, 0.5);  // a
  before.push_back(3, 0, 0, 0.5);  // b, 3 m from a
  now.push_back(0, 0, 0, 0.5);     // a
  now.push_back(0.9, 0, 0, 0.5);   // b, now touching a
  now.push_back(3.5, 0, 0, 0.5);   // c, new: 0.5 m from b's old place, 2.6 m from its new one
  std::vector<RecordedFrame> frames{recorded_frame(0, before), recorded_frame(1, now)};
  auto c = CheckTestContext::recorded(std::move(frames), lane_options("nbs", Fault::StalePositions));
  EXPECT_TRUE(c->run().report().ok()) << "the first frame's stale positions are its own";
  const FrameResult& r = c->next();
  EXPECT_EQ(r.selected().pairs, (PairList{{1, 2}}));
  EXPECT_EQ(r.reference, (PairList{{0, 1}}));
  EXPECT_EQ(r.report().broken[static_cast<std::size_t>(Invariant::AEqualsR)], 2);
  ASSERT_EQ(r.report().violations.size(), 2u);
  EXPECT_EQ(r.report().violations[0].pair, (Pair{0, 1}));
  EXPECT_STREQ(r.report().violations[0].what, "missing from A (in R)");
  EXPECT_EQ(r.report().violations[1].pair, (Pair{1, 2}));
  EXPECT_STREQ(r.report().violations[1].what, "extra in A (not in R)");
}

// On a live scene, frame 1 is detected on frame 0's elements (remembered at the step), checked against its own.
TEST(PipelineFaults, StalePositionsOnALiveSceneDetectTheStepsStartingPositions) {
  const char* const falling = R"({"gravity": [0, -10], "generators": [
      {"kind": "random_box", "count": 300, "seed": 9, "min": [0, 0], "max": [20, 20], "radius": [0.3, 0.6],
       "body": {"type": "dynamic", "shape": "circle"}}]})";
  auto c = CheckTestContext::scene(falling, lane_options("nbs", Fault::StalePositions));
  c->run();
  const PairList at_frame_0 = touching_pairs(c->elements());
  const FrameResult& r = c->next();
  const PairList at_frame_1 = touching_pairs(c->elements());
  ASSERT_NE(at_frame_0, at_frame_1) << "the step must change some pair";
  EXPECT_EQ(r.selected().pairs, at_frame_0);
  EXPECT_EQ(r.reference, at_frame_1);
  EXPECT_FALSE(r.report().ok());
}

// ---- checks off ---------------------------------------------------------------------------------

// With checks off the lanes still detect; the report counts elements and A, and nothing is checked.
TEST(PipelineChecks, ChecksOffCountOnlyWhatWasDetected) {
  auto c = CheckTestContext::recorded(random_frames(), lane_options("nbs", Fault::DropPair));
  c->pipeline().set_checks(false);
  const FrameResult& r = c->run();
  const PairList expected = without_middle(touching_pairs(c->elements()));
  EXPECT_EQ(r.selected().pairs, expected);
  EXPECT_FALSE(r.report().checked);
  EXPECT_FALSE(r.report().ok()) << "not checked is not passed";
  EXPECT_EQ(r.report().violation_count(), 0);
  EXPECT_EQ(r.report().counts.a, static_cast<std::int64_t>(expected.size()));
  EXPECT_EQ(r.report().counts.elements, 400);
  EXPECT_TRUE(r.reference.empty());
  c->pipeline().set_checks(true);
  EXPECT_EQ(c->run().report().broken[static_cast<std::size_t>(Invariant::AEqualsR)], 1) << "checked again, caught";
}

}  // namespace
}  // namespace nbscope
