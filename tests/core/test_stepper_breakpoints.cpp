// The stepper's breakpoints and playback, for every list-based detector of the registry
// (support/stepper_runs.hpp): each kind of breakpoint stops at exactly the events it names, written
// out from the events' fields, forwards and backwards; playback moves by speed times time and stops
// at the end or a breakpoint.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "core/stepper.hpp"
#include "support/stepper_runs.hpp"

namespace nbscope {
namespace {

using teststepper::list_based_runs;
using teststepper::TracedRun;
using teststepper::two_pushes;

// ---- breakpoints ---------------------------------------------------------------------------

// The events a breakpoint should stop at, written out per kind from the events' fields.
std::vector<std::size_t> expected_hits(const std::vector<TraceEvent>& ev, const Breakpoint& b) {
  std::vector<std::size_t> hits;
  for (std::size_t i = 0; i < ev.size(); ++i) {
    const TraceEvent& e = ev[i];
    bool hit = false;
    if (b.kind == BreakKind::Element) hit = e.op != TraceOp::Phase && (e.element == b.element || e.other == b.element);
    if (b.kind == BreakKind::FirstPairOf) hit = e.op == TraceOp::TestPair && (e.element == b.element || e.other == b.element);
    if (b.kind == BreakKind::Cell)
      hit = e.op != TraceOp::TestPair && std::equal(e.cell, e.cell + 3, b.cell);
    if (b.kind == BreakKind::List) {
      const int head_write = e.op == TraceOp::Push ? 1 : (e.op == TraceOp::Clear ? 0 : -1);
      hit = head_write >= 0 && e.writes[head_write].array == b.array && e.writes[head_write].index == b.list;
    }
    if (hit) hits.push_back(i);
  }
  return hits;
}

// Runs forward from 0 through every hit, then backward through them, checking each landing.
void check_breakpoint(Stepper& s, const Breakpoint& b, const char* kind) {
  SCOPED_TRACE(kind);
  const std::vector<std::size_t> hits = expected_hits(s.events(), b);
  s.seek(0);
  for (std::size_t h : hits) {
    ASSERT_TRUE(s.run_to(b));
    ASSERT_EQ(s.position(), h + 1);
  }
  const std::size_t last = s.position();
  EXPECT_FALSE(s.run_to(b));
  EXPECT_EQ(s.position(), last) << "a breakpoint with no later hit must not move";
  s.seek(s.size());
  for (auto it = hits.rbegin(); it != hits.rend(); ++it) {
    if (*it + 1 == s.size()) continue;  // already the current event
    ASSERT_TRUE(s.run_back_to(b));
    ASSERT_EQ(s.position(), *it + 1);
  }
  EXPECT_FALSE(s.run_back_to(b));
}

TEST(Stepper, BreakpointsStopAtExactlyTheEventsTheyName) {
  for (const TracedRun& run : list_based_runs(40)) {
    if (run.elements.size() == 0) continue;
    SCOPED_TRACE(run.what);
    Stepper s;
    s.load(run.log);
    std::mt19937_64 rng(run.log.events().size());
    const auto pick_element = [&] {
      return static_cast<std::int32_t>(std::uniform_int_distribution<std::int64_t>(0, run.elements.size() - 1)(rng));
    };
    for (int round = 0; round < 3; ++round) {
      Breakpoint element{BreakKind::Element, pick_element()};
      check_breakpoint(s, element, "element");
      Breakpoint pair{BreakKind::FirstPairOf, pick_element()};
      check_breakpoint(s, pair, "first pair of");
      // A cell and a list taken from a random push.
      std::vector<const TraceEvent*> pushes;
      for (const TraceEvent& e : s.events())
        if (e.op == TraceOp::Push) pushes.push_back(&e);
      if (pushes.empty()) continue;
      const TraceEvent& p = *pushes[std::uniform_int_distribution<std::size_t>(0, pushes.size() - 1)(rng)];
      Breakpoint cell{BreakKind::Cell};
      std::copy(p.cell, p.cell + 3, cell.cell);
      if (cell.cell[0] >= 0 && cell.cell[1] >= 0) check_breakpoint(s, cell, "cell");
      Breakpoint list{BreakKind::List};
      list.array = p.writes[1].array;
      list.list = p.writes[1].index;
      check_breakpoint(s, list, "list");
    }
  }
}

TEST(Stepper, ABreakpointOnAnAbsentElementDoesNotMove) {
  const TraceLog log = two_pushes(0);
  Stepper s;
  s.load(log);
  s.seek(1);
  EXPECT_FALSE(s.run_to(Breakpoint{BreakKind::Element, 3}));
  EXPECT_FALSE(s.run_to(Breakpoint{BreakKind::FirstPairOf, 0}));  // no pair is ever tested here
  EXPECT_EQ(s.position(), 1u);
  EXPECT_TRUE(s.run_to(Breakpoint{BreakKind::Element, 2}));
  EXPECT_EQ(s.position(), 3u);
}

// ---- playback ------------------------------------------------------------------------------

TEST(Stepper, PlaybackAdvancesBySpeedTimesTimeAndStopsAtTheEndOrABreakpoint) {
  const std::vector<TracedRun> runs = list_based_runs(40);
  const auto longest = std::max_element(runs.begin(), runs.end(), [](const TracedRun& a, const TracedRun& b) {
    return a.log.events().size() < b.log.events().size();
  });
  ASSERT_NE(longest, runs.end());
  Stepper s;
  s.load(longest->log);
  ASSERT_GT(s.size(), 20u);
  s.set_speed(8);
  EXPECT_EQ(s.advance(1.0), 0u) << "paused: nothing moves";
  s.play();
  EXPECT_EQ(s.advance(0.3125), 2u);  // 2.5 events: two now, half owed
  EXPECT_EQ(s.advance(0.0625), 1u);  // 0.5 + 0.5
  EXPECT_EQ(s.position(), 3u);
  EXPECT_EQ(s.advance(-1), 0u);
  s.set_speed(1e6);
  EXPECT_EQ(s.advance(10), s.size() - 3);
  EXPECT_EQ(s.position(), s.size());
  EXPECT_FALSE(s.playing());
  EXPECT_EQ(s.state(), longest->log.state_after(s.size()));

  // Playing again restarts; a play breakpoint stops on its first hit.
  const Breakpoint b{BreakKind::Element, 0};
  const auto hits = expected_hits(s.events(), b);
  ASSERT_FALSE(hits.empty());
  s.set_play_breakpoint(b);
  s.play();
  EXPECT_EQ(s.position(), 0u);
  s.advance(10);
  EXPECT_EQ(s.position(), hits[0] + 1);
  EXPECT_FALSE(s.playing());
}

}  // namespace
}  // namespace nbscope
