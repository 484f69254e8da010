// The run's history (check/history.hpp) on hand-made frames: FrameHistory keeps a summary for every
// frame and the newest states within its byte budget, dropping the oldest first and marking them not
// kept (never the newest), truncates after a frame, and keeps at most its maximum of summaries;
// ViolationLog keeps every violation in frame order, a frame checked again replacing its own.
// Every expected value is worked out by hand in the test's comment.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "check/history.hpp"
#include "physics/box2d_frame.hpp"

namespace nbscope {
namespace {

// ---- FrameHistory --------------------------------------------------------------------------------

// A state standing for frame `frame` (the history never looks inside it).
std::shared_ptr<const WorldState> state_of(std::int64_t frame) {
  auto s = std::make_shared<WorldState>();
  s->frame = frame;
  return s;
}

// The summary of a frame that has a state (kept) and `violations` violations.
FrameSummary kept_summary(std::int64_t frame, std::int64_t violations = 0) {
  FrameSummary s;
  s.frame = frame;
  s.kept = true;
  s.checked = true;
  s.violations = violations;
  return s;
}

// Pushes frames `first`..`last`, each with a state of `bytes` bytes; returns the states pushed.
std::vector<std::shared_ptr<const WorldState>> push_frames(FrameHistory& h, std::int64_t first, std::int64_t last, std::size_t bytes) {
  std::vector<std::shared_ptr<const WorldState>> pushed;
  for (std::int64_t f = first; f <= last; ++f) {
    pushed.push_back(state_of(f));
    h.push(kept_summary(f), pushed.back(), bytes);
  }
  return pushed;
}

// Budget 250 B, five 100 B states: frames 1, 2, 3 are dropped in that order, 4 and 5 stay (200 B).
TEST(FrameHistory, TheBudgetDropsTheOldestStatesFirstAndMarksThemNotKept) {
  FrameHistory h;
  h.set_budget(250);
  const auto pushed = push_frames(h, 1, 5, 100);
  ASSERT_EQ(h.size(), 5u) << "every summary stays";
  EXPECT_EQ(h.dropped(), 3);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_FALSE(h.at(k).kept) << "frame " << h.at(k).frame;
    EXPECT_EQ(h.state(k), nullptr) << "frame " << h.at(k).frame;
  }
  EXPECT_TRUE(h.at(3).kept);
  EXPECT_EQ(h.state(3), pushed[3]);
  EXPECT_EQ(h.state(4), pushed[4]);
  EXPECT_EQ(h.first_kept(), 4);
  EXPECT_EQ(h.bytes(), 200 + 5 * sizeof(FrameSummary));
}

// A budget smaller than one state still keeps the newest; lowering the budget drops at once.
TEST(FrameHistory, TheNewestStateStaysWhateverTheBudget) {
  FrameHistory h;
  h.set_budget(50);
  push_frames(h, 0, 0, 100);
  EXPECT_TRUE(h.at(0).kept);
  EXPECT_EQ(h.first_kept(), 0);
  push_frames(h, 1, 1, 100);
  EXPECT_FALSE(h.at(0).kept);
  EXPECT_TRUE(h.at(1).kept);

  FrameHistory roomy;  // three 100 B states in the default budget, then a budget of one
  push_frames(roomy, 0, 2, 100);
  EXPECT_EQ(roomy.dropped(), 0);
  roomy.set_budget(0);
  EXPECT_EQ(roomy.dropped(), 2);
  EXPECT_EQ(roomy.first_kept(), 2);
  EXPECT_EQ(roomy.bytes(), 100 + 3 * sizeof(FrameSummary));
}

// A frame without a state (a recorded one) is summarised and costs no state bytes, whatever it is said to weigh.
TEST(FrameHistory, AFrameWithoutAStateCostsNoStateBytes) {
  FrameHistory h;
  FrameSummary s;
  s.frame = 7;
  h.push(s, nullptr, 1000);
  EXPECT_FALSE(h.at(0).kept);
  EXPECT_EQ(h.first_kept(), std::nullopt);
  EXPECT_EQ(h.bytes(), sizeof(FrameSummary));
}

// Frames 10..50 by tens, truncated after 30: 40 and 50 go with their bytes; the run goes on from 31.
TEST(FrameHistory, TruncateAfterDropsTheLaterFramesAndTheirBytes) {
  FrameHistory h;
  for (std::int64_t f = 10; f <= 50; f += 10) h.push(kept_summary(f), state_of(f), 100);
  h.truncate_after(30);
  ASSERT_EQ(h.size(), 3u);
  EXPECT_EQ(h.summaries().back().frame, 30);
  EXPECT_EQ(h.find(40), std::nullopt);
  EXPECT_EQ(h.find(30), 2u);
  EXPECT_EQ(h.bytes(), 300 + 3 * sizeof(FrameSummary));
  h.push(kept_summary(31), state_of(31), 100);
  EXPECT_EQ(h.find(31), 3u);
  h.truncate_after(-1);
  EXPECT_TRUE(h.empty());
  EXPECT_EQ(h.bytes(), 0u);
}

// find() is by frame number, gaps and all.
TEST(FrameHistory, FindsAFrameByItsNumberAndTheFirstFromAFrame) {
  FrameHistory h;
  for (const std::int64_t f : {0, 5, 9}) h.push(kept_summary(f), nullptr, 0);
  EXPECT_EQ(h.find(0), 0u);
  EXPECT_EQ(h.find(5), 1u);
  EXPECT_EQ(h.find(9), 2u);
  EXPECT_EQ(h.find(4), std::nullopt);
  EXPECT_EQ(h.find(10), std::nullopt);
  // Where a trail starts: the first summary at or after a frame, past the end when none is.
  EXPECT_EQ(h.first_from(-3), 0u);
  EXPECT_EQ(h.first_from(4), 1u);
  EXPECT_EQ(h.first_from(5), 1u);
  EXPECT_EQ(h.first_from(10), 3u);
}

// At most 3 summaries: after frames 0..4, frames 2, 3 and 4 remain, and the states of 0 and 1 went with them.
TEST(FrameHistory, MaxSummariesDropsTheOldestFramesWithTheirStates) {
  FrameHistory h;
  h.set_max_summaries(3);
  push_frames(h, 0, 4, 100);
  ASSERT_EQ(h.size(), 3u);
  EXPECT_EQ(h.at(0).frame, 2);
  EXPECT_EQ(h.first_kept(), 2);
  EXPECT_EQ(h.bytes(), 300 + 3 * sizeof(FrameSummary));
  h.set_max_summaries(0);  // at least one is kept
  push_frames(h, 5, 5, 100);
  ASSERT_EQ(h.size(), 1u);
  EXPECT_EQ(h.at(0).frame, 5);
}

// A frame detected again replaces its counts; whether it is kept does not change.
TEST(FrameHistory, UpdateReplacesTheCountsAndKeepsTheKeptFlag) {
  FrameHistory h;
  push_frames(h, 0, 1, 100);
  FrameSummary again;
  again.frame = 0;
  again.violations = 4;
  again.kept = false;
  h.update(0, again);
  EXPECT_EQ(h.at(0).violations, 4);
  EXPECT_TRUE(h.at(0).kept);
}

// clear() forgets frames, states and the dropped count.
TEST(FrameHistory, ClearForgetsEveryFrame) {
  FrameHistory h;
  h.set_budget(100);
  push_frames(h, 0, 2, 100);
  h.clear();
  EXPECT_TRUE(h.empty());
  EXPECT_EQ(h.dropped(), 0);
  EXPECT_EQ(h.bytes(), 0u);
  EXPECT_EQ(h.budget(), 100u) << "the budget is a setting, not a frame";
}

// ---- ViolationLog --------------------------------------------------------------------------------

// A report of frame `frame` listing one violation of `invariant` per pair.
FrameReport report_of(std::int64_t frame, Invariant invariant, const PairList& pairs) {
  FrameReport r;
  r.frame = frame;
  r.checked = true;
  r.broken[static_cast<std::size_t>(invariant)] = static_cast<std::int64_t>(pairs.size());
  for (const Pair& p : pairs) r.violations.push_back({frame, invariant, p, {}, {}, "test"});
  return r;
}

std::int64_t count_of(const ViolationLog& log, Invariant invariant) { return log.by_invariant()[static_cast<std::size_t>(invariant)]; }

// Frame 3 with two A==R violations, checked again with one A-in-F: the log holds only the second.
TEST(ViolationLog, AFrameCheckedAgainReplacesItsOwnViolations) {
  ViolationLog log;
  log.set_frame(report_of(3, Invariant::AEqualsR, {{0, 1}, {2, 3}}));
  EXPECT_EQ(log.total(), 2);
  log.set_frame(report_of(3, Invariant::AInF, {{4, 5}}));
  ASSERT_EQ(log.listed().size(), 1u);
  EXPECT_EQ(log.listed()[0].pair, (Pair{4, 5}));
  EXPECT_EQ(count_of(log, Invariant::AEqualsR), 0);
  EXPECT_EQ(count_of(log, Invariant::AInF), 1);
  EXPECT_EQ(log.total(), 1);
  EXPECT_EQ(log.frames(), 1);
}

// Frames arriving 5, 2, 8 are listed 2, 5, 8; a clean report of 2 removes it.
TEST(ViolationLog, ListsInFrameOrderWhateverOrderFramesArriveIn) {
  ViolationLog log;
  log.set_frame(report_of(5, Invariant::TInA, {{1, 2}}));
  log.set_frame(report_of(2, Invariant::AEqualsR, {{0, 1}, {0, 2}}));
  log.set_frame(report_of(8, Invariant::Cells, {{3, 3}}));
  std::vector<std::int64_t> frames;
  for (const Violation& v : log.listed()) frames.push_back(v.frame);
  EXPECT_EQ(frames, (std::vector<std::int64_t>{2, 2, 5, 8}));
  EXPECT_EQ(log.first_frame(), 2);
  EXPECT_EQ(log.frames(), 3);
  log.set_frame(report_of(2, Invariant::AEqualsR, {}));
  EXPECT_EQ(log.first_frame(), 5);
  EXPECT_EQ(log.total(), 2);
}

// Truncating after frame 5 drops 8's violations and keeps 2's and 5's.
TEST(ViolationLog, TruncateAfterDropsTheLaterFrames) {
  ViolationLog log;
  for (const std::int64_t f : {2, 5, 8}) log.set_frame(report_of(f, Invariant::AEqualsR, {{0, 1}}));
  log.truncate_after(5);
  EXPECT_EQ(log.frames(), 2);
  EXPECT_EQ(log.total(), 2);
  EXPECT_EQ(log.listed().back().frame, 5);
  log.clear();
  EXPECT_EQ(log.total(), 0);
  EXPECT_EQ(log.first_frame(), std::nullopt);
}

// A frame that broke 500 times but listed 2 counts 500 and lists 2.
TEST(ViolationLog, CountsStayExactBeyondTheListedViolations) {
  ViolationLog log;
  FrameReport r = report_of(1, Invariant::AEqualsR, {{0, 1}, {0, 2}});
  r.broken[static_cast<std::size_t>(Invariant::AEqualsR)] = 500;
  log.set_frame(r);
  EXPECT_EQ(log.total(), 500);
  EXPECT_EQ(log.listed().size(), 2u);
}

// Every change bumps the generation, also a frame checked again with as many violations.
TEST(ViolationLog, EveryChangeBumpsTheGeneration) {
  ViolationLog log;
  std::uint64_t seen = log.generation();
  const auto bumped = [&] {
    const bool changed = log.generation() != seen;
    seen = log.generation();
    return changed;
  };
  log.set_frame(report_of(1, Invariant::AEqualsR, {{0, 1}}));
  EXPECT_TRUE(bumped());
  log.set_frame(report_of(1, Invariant::AEqualsR, {{0, 2}}));
  EXPECT_TRUE(bumped());
  log.truncate_after(0);
  EXPECT_TRUE(bumped());
  log.clear();
  EXPECT_TRUE(bumped());
}

}  // namespace
}  // namespace nbscope
