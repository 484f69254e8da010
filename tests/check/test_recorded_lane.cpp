// The `recorded` lane (check/recorded_lane.hpp): a recording's own pairs as a lane beside the
// detectors'. Its detector hands back the frame's pairs normalised to i < j (repeats and i == j kept
// for the check to name), refuses a frame without pairs; the lane refuses the faults that act on
// detection's input or on Box2D's side; through the pipeline its pairs are held to brute force (the
// tests' own double loop) with the recorded wording, and it has no trace to step through.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "check/pipeline.hpp"
#include "check/recorded_lane.hpp"
#include "core/error.hpp"
#include "support/check_context.hpp"

namespace nbscope {
namespace {

using testcheck::CheckTestContext;
using testcheck::lane_options;
using testcheck::random_circles;
using testcheck::recorded_frame;
using testcheck::touching_pairs;

// ---- the detector --------------------------------------------------------------------------------

// Pairs come back in the recording's order, each turned to i < j; repeats and i == j stay for the check.
TEST(RecordedLane, DetectorReturnsTheFramesPairsEachWithISmallerThanJ) {
  RecordedPairsDetector d;
  const PairList given{{3, 1}, {0, 2}, {0, 2}, {4, 4}};
  d.set_pairs(&given);
  PairList out;
  d.detect(Elements{}, DetectOptions{}, out);
  EXPECT_EQ(out, (PairList{{1, 3}, {0, 2}, {0, 2}, {4, 4}}));
  EXPECT_EQ(d.name(), "recorded");
}

// A frame without a pairs block, or more pairs than the limit, is refused with an Error.
TEST(RecordedLane, DetectorRefusesAFrameWithoutPairsOrPastThePairLimit) {
  RecordedPairsDetector d;
  PairList out;
  EXPECT_THROW(d.detect(Elements{}, DetectOptions{}, out), Error);
  const PairList given{{0, 1}, {1, 2}, {2, 3}};
  d.set_pairs(&given);
  DetectOptions two;
  two.max_pairs = 2;
  EXPECT_THROW(d.detect(Elements{}, two, out), Error);
  two.max_pairs = 3;
  EXPECT_NO_THROW(d.detect(Elements{}, two, out));
}

// `recorded` is declared 2D and 3D, with no trace and no lists; an unknown lane name mentions it.
TEST(RecordedLane, DeclaresBothDimensionsNoTraceAndNoLists) {
  const DetectorInfo& info = algorithm_info("recorded");
  EXPECT_EQ(info.name, "recorded");
  EXPECT_TRUE(info.dim2);
  EXPECT_TRUE(info.dim3);
  EXPECT_FALSE(info.traces);
  EXPECT_FALSE(info.has_lists);
  EXPECT_EQ(algorithm_info("nbs").name, "nbs") << "other names are the registry's";
  EXPECT_EQ(make_lane_detector("recorded")->name(), "recorded");
  try {
    (void)make_lane_detector("no-such-detector");
    FAIL() << "an unknown lane name was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("recorded"), std::string::npos) << e.what();
  }
}

// ---- the faults it takes -----------------------------------------------------------------------

// Faults on detection's input or cells, and Box2D's, are refused; none and drop-pair pass.
TEST(RecordedLane, RefusesEveryFaultButDropPair) {
  for (const Fault f : {Fault::StalePositions, Fault::DropMaskCell, Fault::OffByOneCell, Fault::DropBox2dContact}) {
    SCOPED_TRACE(fault_name(f));
    EXPECT_THROW(check_recorded_fault(f), Error);
    EXPECT_THROW({ Pipeline refused(lane_options("recorded", f)); }, Error);
  }
  EXPECT_NO_THROW(check_recorded_fault(Fault::None));
  EXPECT_NO_THROW(check_recorded_fault(Fault::DropPair));
  EXPECT_NO_THROW({ Pipeline accepted(lane_options("recorded", Fault::DropPair)); });
}

// Switching a lane to `recorded` asks the caller first, and a refusal leaves the old lane in place.
TEST(RecordedLane, SwitchingToItAsksTheCallerWhoMayRefuse) {
  Pipeline p(lane_options("nbs"));
  int asked = 0;
  p.set_algorithm("recorded", [&] { ++asked; });
  EXPECT_EQ(asked, 1);
  EXPECT_TRUE(p.has_recorded_lane());
  p.set_algorithm("nbs");
  EXPECT_FALSE(p.has_recorded_lane());
  EXPECT_THROW(p.set_comparison_algorithms({"sort", "recorded"}, [] { throw Error("no pairs in this source"); }), Error);
  EXPECT_TRUE(p.comparison_algorithms().empty());
  EXPECT_FALSE(p.has_recorded_lane());
}

// ---- through the pipeline ----------------------------------------------------------------------

// A recording's pairs with one contact lost and one far pair added: both named, in the recorded words.
TEST(RecordedLane, RecordedPairsAreHeldToBruteForce) {
  const Elements e = random_circles(300, 21);
  const PairList truth = touching_pairs(e);
  ASSERT_GT(truth.size(), 3u);
  PairList given = truth;
  const Pair lost = given[1];
  given.erase(given.begin() + 1);
  std::swap(given[0].i, given[0].j);  // written j,i: the same contact
  Pair far{0, 0};
  for (ElementId j = 1; far.j == 0; ++j)
    if (!std::binary_search(truth.begin(), truth.end(), Pair{0, j})) far = Pair{0, j};
  given.push_back(far);
  std::vector<RecordedFrame> frames{recorded_frame(0, e, truth), recorded_frame(1, e, given)};
  auto c = CheckTestContext::recorded(std::move(frames), lane_options("recorded"), true);
  c->pipeline().set_comparison_algorithms({"nbs"});
  const FrameResult& clean = c->run();
  EXPECT_TRUE(clean.report().ok());
  EXPECT_FALSE(clean.report().box2d_checks) << "a recording has no Box2D world";
  const FrameResult& r = c->next();
  EXPECT_EQ(r.lanes[1].pairs, truth) << "the detector beside it is not given the recorded pairs";
  EXPECT_TRUE(r.lanes[1].report.ok());
  const FrameReport& report = r.report();
  EXPECT_EQ(report.counts.a, static_cast<std::int64_t>(truth.size()));
  EXPECT_EQ(report.broken[static_cast<std::size_t>(Invariant::AEqualsR)], 2);
  ASSERT_EQ(report.violations.size(), 2u);
  EXPECT_EQ(report.violations[0].pair, lost);
  EXPECT_STREQ(report.violations[0].what, "in contact (in R) but missing from the recorded pairs");
  EXPECT_EQ(report.violations[1].pair, far);
  EXPECT_STREQ(report.violations[1].what, "in the recorded pairs but not in contact (not in R)");
}

// drop-pair acts on the recorded pairs themselves: the middle of the sorted pairs goes.
TEST(RecordedLane, DropPairDropsTheMiddleRecordedPair) {
  const Elements e = random_circles(300, 22);
  const PairList truth = touching_pairs(e);
  ASSERT_GT(truth.size(), 2u);
  auto c = CheckTestContext::recorded({recorded_frame(0, e, truth)}, lane_options("recorded", Fault::DropPair), true);
  const FrameResult& r = c->run();
  PairList expected = truth;
  expected.erase(expected.begin() + static_cast<std::ptrdiff_t>(truth.size() / 2));
  EXPECT_EQ(r.selected().pairs, expected);
  ASSERT_EQ(r.report().violations.size(), 1u);
  EXPECT_EQ(r.report().violations[0].pair, truth[truth.size() / 2]);
}

// Its trace is a refusal in words: the pairs were read, not detected.
TEST(RecordedLane, HasNoTraceToStepThrough) {
  const Elements e = random_circles(50, 23);
  auto c = CheckTestContext::recorded({recorded_frame(0, e, touching_pairs(e))}, lane_options("recorded"), true);
  c->pipeline().set_record_traces(true);
  c->run();
  const std::shared_ptr<const FrameTrace> trace = c->trace();
  ASSERT_NE(trace, nullptr);
  EXPECT_EQ(trace->refusal, recorded_trace_refusal());
  EXPECT_TRUE(trace->log.events().empty());
}

}  // namespace
}  // namespace nbscope
