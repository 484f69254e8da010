// The check's report types (check/report.hpp) on hand-made frames: a frame's verdict and violation
// count, a run's totals, first violation and timings as AlgorithmRun adds its frames, a headless
// run's verdict (RunReport), the invariants' names and which need Box2D, the check timings' parts
// and the boundary text. Every expected value is summed by hand in the test.
#include <gtest/gtest.h>

#include <string>

#include "check/report.hpp"

namespace nbscope {
namespace {

constexpr std::size_t index_of(Invariant invariant) { return static_cast<std::size_t>(invariant); }

// A checked frame with `broken` violations of each invariant listed in full, one per pair (k, k+1).
FrameReport frame_report(std::int64_t frame, std::array<std::int64_t, kInvariantCount> broken, const std::string& reference = "brute") {
  FrameReport r;
  r.frame = frame;
  r.checked = true;
  r.reference = reference;
  r.broken = broken;
  for (std::size_t k = 0; k < broken.size(); ++k)
    for (std::int64_t n = 0; n < broken[k]; ++n)
      r.violations.push_back({frame, static_cast<Invariant>(k), Pair{static_cast<ElementId>(n), static_cast<ElementId>(n + 1)}, {}, {}, "test"});
  return r;
}

// ---- one frame ----------------------------------------------------------------------------------

// A frame passes only when it was checked and nothing broke; the count is the sum over invariants.
TEST(FrameReportVerdict, OkOnlyWhenCheckedAndNothingBroke) {
  FrameReport unchecked;
  EXPECT_FALSE(unchecked.ok()) << "not checked is not passed";
  EXPECT_EQ(unchecked.violation_count(), 0);
  EXPECT_TRUE(frame_report(0, {}).ok());
  const FrameReport broke = frame_report(0, {2, 0, 1, 0, 0, 3});
  EXPECT_FALSE(broke.ok());
  EXPECT_EQ(broke.violation_count(), 6);  // 2 + 1 + 3
}

// ---- a run --------------------------------------------------------------------------------------

// Frames 0 (clean), 1 (2 A==R, 1 T-in-A), 2 (1 cells, reference sort): totals summed by hand.
TEST(AlgorithmRunTotals, AddsEveryFramesCountsAndKeepsTheFirstViolation) {
  AlgorithmRun run("nbs");
  FrameReport f0 = frame_report(0, {});
  f0.timings = {1.0, 2.0, 3.0};
  f0.counts.elements = 10;
  FrameReport f1 = frame_report(1, {2, 0, 1, 0, 0, 0});
  f1.timings = {5.0, 4.0, 1.0};
  FrameReport f2 = frame_report(2, {0, 0, 0, 0, 1, 0}, "sort");
  f2.timings = {3.0, 6.0, 2.0};
  f2.counts.elements = 12;
  for (const FrameReport* f : {&f0, &f1, &f2}) run.add(*f);

  EXPECT_EQ(run.algorithm, "nbs");
  EXPECT_EQ(run.frames_run, 3);
  EXPECT_FALSE(run.passed());
  EXPECT_EQ(run.violations, 4);
  EXPECT_EQ(run.listed, 4);
  EXPECT_EQ(run.broken[index_of(Invariant::AEqualsR)], 2);
  EXPECT_EQ(run.broken[index_of(Invariant::TInA)], 1);
  EXPECT_EQ(run.broken[index_of(Invariant::Cells)], 1);
  EXPECT_EQ(run.frames_with_violations, 2);
  EXPECT_EQ(run.first_violation_frame, 1);
  ASSERT_TRUE(run.first_listed.has_value());
  EXPECT_EQ(run.first_listed->frame, 1);
  EXPECT_EQ(run.first_listed->invariant, Invariant::AEqualsR);
  EXPECT_EQ(run.references.at("brute"), 2);
  EXPECT_EQ(run.references.at("sort"), 1);
  EXPECT_EQ(run.last_elements, 12);
  EXPECT_DOUBLE_EQ(run.physics.total, 9.0);
  EXPECT_DOUBLE_EQ(run.physics.max, 5.0);
  EXPECT_DOUBLE_EQ(run.detection.mean(run.frames_run), 4.0);  // (2 + 4 + 6) / 3
  EXPECT_DOUBLE_EQ(run.check.max, 3.0);
}

// Clean checked frames pass; one unchecked frame among them fails the run though it broke nothing.
TEST(AlgorithmRunTotals, PassesOnlyWhenEveryFrameWasCheckedAndHeld) {
  AlgorithmRun clean("sort");
  for (std::int64_t f = 0; f < 3; ++f) clean.add(frame_report(f, {}));
  EXPECT_TRUE(clean.passed());
  EXPECT_EQ(clean.violations, 0);
  EXPECT_EQ(clean.first_violation_frame, std::nullopt);
  clean.add(FrameReport{});
  EXPECT_FALSE(clean.passed());
  EXPECT_EQ(clean.violations, 0);
}

// The mean of no frames is 0, not a division by zero.
TEST(AlgorithmRunTotals, TheMeanOfNoFramesIsZero) {
  TimingStats none;
  EXPECT_EQ(none.mean(0), 0.0);
  none.add(3.0);
  none.add(1.0);
  EXPECT_DOUBLE_EQ(none.mean(2), 2.0);
  EXPECT_DOUBLE_EQ(none.max, 3.0);
}

// A headless run passes when every algorithm ran every requested frame and held, and nothing diverged.
TEST(RunReportVerdict, PassesOnlyWhenEveryRunRanEveryFrameAndHeld) {
  RunReport report;
  report.frames_requested = 2;
  EXPECT_FALSE(report.passed()) << "no run at all";
  AlgorithmRun nbs("nbs"), sort("sort");
  for (std::int64_t f = 0; f < 2; ++f) {
    nbs.add(frame_report(f, {}));
    sort.add(frame_report(f, {}));
  }
  report.runs = {nbs, sort};
  EXPECT_TRUE(report.passed());
  report.frames_requested = 3;
  EXPECT_FALSE(report.passed()) << "a frame short";
  report.frames_requested = 2;
  report.rewind = RunReport::Rewind{5, 2, std::nullopt};
  EXPECT_TRUE(report.passed()) << "a rewind that repeated itself";
  report.rewind->diverged_at = 4;
  EXPECT_FALSE(report.passed()) << "a rewind that diverged";
  report.rewind.reset();
  report.runs[1].add(frame_report(2, {1, 0, 0, 0, 0, 0}));
  report.runs[1].frames_run = 2;
  EXPECT_FALSE(report.passed()) << "one algorithm broke";
}

// ---- names and parts ------------------------------------------------------------------------------

// The invariants' names are the reports' words; A-in-F, T-in-A and AABB-in-cells need Box2D's world.
TEST(InvariantWords, NamesAndWhichNeedBox2d) {
  const char* const names[kInvariantCount] = {"A==R", "A-in-F", "T-in-A", "AABB-in-cells", "cells", "contract"};
  const bool box2d[kInvariantCount] = {false, true, true, true, false, false};
  for (int k = 0; k < kInvariantCount; ++k) {
    const auto invariant = static_cast<Invariant>(k);
    EXPECT_STREQ(invariant_name(invariant), names[k]);
    EXPECT_EQ(needs_box2d(invariant), box2d[k]) << names[k];
    EXPECT_STRNE(invariant_description(invariant), "") << names[k];
  }
}

// The check time's parts are R, F, G/T, then each invariant in order, with the values set for them.
TEST(InvariantWords, CheckTimingsPartsAreTheSetsThenTheInvariants) {
  CheckTimings t;
  t.r_ms = 1;
  t.f_ms = 2;
  t.g_t_ms = 3;
  for (int k = 0; k < kInvariantCount; ++k) t.invariant_ms[static_cast<std::size_t>(k)] = 10 + k;
  ASSERT_EQ(CheckTimings::kParts, 9);
  EXPECT_STREQ(CheckTimings::part_name(0), "R");
  EXPECT_STREQ(CheckTimings::part_name(2), "G/T");
  EXPECT_STREQ(CheckTimings::part_name(3), "A==R");
  EXPECT_STREQ(CheckTimings::part_name(8), "contract");
  EXPECT_EQ(t.part(1), 2.0);
  EXPECT_EQ(t.part(3), 10.0);
  EXPECT_EQ(t.part(8), 15.0);
}

// A tie says so; a pair within the precision band gives its gap and resolution to three digits.
TEST(InvariantWords, BoundaryTextSaysTieOrGapAndResolution) {
  BoundaryPair tie;
  tie.tie = true;
  EXPECT_NE(boundary_text(tie).find("an exact tie (gap 0)"), std::string::npos);
  BoundaryPair near;
  near.gap = -3.14159e-8;
  near.resolution = 8.7e-8;
  EXPECT_EQ(boundary_text(near), "at the boundary, within the data's precision (gap -3.14e-08, resolution 8.7e-08)");
}

}  // namespace
}  // namespace nbscope
