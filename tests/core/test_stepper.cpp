// The stepper: exact array state at every position forwards and backwards, phase jumps and the
// highlighting queries, for every list-based detector of the registry (support/stepper_runs.hpp);
// breakpoints and playback: test_stepper_breakpoints.cpp.
//
// Index: state at every step | long seeks (checkpoints) | corrupted traces refused | phase jumps |
// loop variables and lists (nbs) | the book's worked example.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "core/detector.hpp"
#include "core/error.hpp"
#include "core/stepper.hpp"
#include "support/generators.hpp"
#include "support/stepper_runs.hpp"

namespace nbscope {
namespace {

using teststepper::list_based_runs;
using teststepper::names_of;
using teststepper::TracedRun;
using teststepper::two_pushes;
using testdata::Layout;

TEST(Stepper, TheRegistryHasListBasedDetectorsToStepThrough) {
  const auto names = names_of(list_based_runs(7));
  EXPECT_NE(std::find(names.begin(), names.end(), "nbs"), names.end());
  std::string all;
  for (const auto& n : names) all += n + " ";
  RecordProperty("list_based", all);
}

// ---- state at every step --------------------------------------------------------------------

TEST(Stepper, ForwardThenBackMatchesAFreshReplayAtEveryStep) {
  for (const TracedRun& run : list_based_runs(40)) {
    SCOPED_TRACE(run.what);
    Stepper s;
    s.load(run.log);
    const std::size_t n = run.log.events().size();
    ASSERT_EQ(s.size(), n);
    ASSERT_EQ(s.position(), 0u);
    ASSERT_EQ(s.current(), nullptr);
    std::vector<ArrayState> reference;
    reference.reserve(n + 1);
    for (std::size_t p = 0; p <= n; ++p) reference.push_back(run.log.state_after(p));
    ASSERT_EQ(s.state(), reference[0]);
    for (std::size_t p = 1; p <= n; ++p) {
      ASSERT_TRUE(s.step_forward());
      ASSERT_EQ(s.position(), p);
      ASSERT_EQ(s.current(), &s.events()[p - 1]);
      ASSERT_EQ(s.state(), reference[p]) << "after " << p << " events, stepping forward";
    }
    EXPECT_FALSE(s.step_forward());
    for (std::size_t p = n; p-- > 0;) {
      ASSERT_TRUE(s.step_back());
      ASSERT_EQ(s.state(), reference[p]) << "after " << p << " events, stepping back";
    }
    EXPECT_FALSE(s.step_back());
    EXPECT_EQ(s.position(), 0u);
  }
}

// The replays above trust the trace. Here a fresh detection is watched as it runs: before every
// event is recorded, the detector's own arrays must equal the replay of the events so far, so the
// stepper shows at step K exactly what the detector had written after K operations. Sort maps
// every element in one vectorised integerisation and sorts with std::sort, then reports the
// results entry by entry: its arrays match at its phase boundaries, where each phase is complete.
TEST(Stepper, TheTraceHoldsWhatTheDetectorReallyWroteAtEveryStep) {
  const std::vector<Layout> layouts = {Layout::Loose, Layout::Dense, Layout::Clustered, Layout::OneCell, Layout::Touching};
  int watched = 0;
  for (const DetectorInfo& info : detector_infos()) {
    for (int dim : {2, 3}) {
      if ((dim == 2 && !info.dim2) || (dim == 3 && !info.dim3)) continue;
      std::uint64_t seed = 1;
      for (Layout layout : layouts) {
        for (std::int64_t n : {std::int64_t{7}, std::int64_t{40}}) {
          const Elements e = testdata::make_layout(layout, n, dim, seed++);
          SCOPED_TRACE(info.name + " " + std::to_string(dim) + "D " + testdata::layout_name(layout) + " n=" + std::to_string(n));
          TraceLog log;
          std::vector<std::vector<std::int32_t>> replayed;
          std::size_t applied = 0, mismatches = 0, compared = 0;
          const bool atomic_phases = info.name == "sort";
          log.set_probe([&](std::size_t position, const TraceEvent& upcoming, const std::vector<std::vector<std::int32_t>>& live) {
            if (atomic_phases && upcoming.op != TraceOp::Phase) return;
            if (replayed.size() != log.arrays().size()) {  // arrays declared since: start from their contents
              replayed = log.state_after(position);
              applied = position;
            }
            for (; applied < position; ++applied) TraceLog::apply(log.events()[applied], replayed);
            ++compared;
            if (live != replayed && mismatches++ == 0) ADD_FAILURE() << "the detector's arrays differ from the trace after " << position << " events";
          });
          PairList pairs;
          info.make()->detect_traced(e, DetectOptions{}, pairs, log);
          if (log.arrays().empty()) break;  // not list-based: no arrays to watch
          EXPECT_EQ(mismatches, 0u);
          EXPECT_GE(compared, atomic_phases ? 2u : log.events().size() - 1);  // sort: at "sort" and "contacts"
          ++watched;
        }
      }
    }
  }
  EXPECT_GE(watched, 40);  // tree, sort, screen and nbs, in 2D and 3D
}

TEST(Stepper, LongSeeksThroughCheckpointsAreExact) {
  int long_traces = 0;
  for (const TracedRun& run : list_based_runs(400)) {
    const std::size_t n = run.log.events().size();
    Stepper s;
    s.load(run.log);
    if (n < 3 * s.checkpoint_interval()) continue;
    ++long_traces;
    SCOPED_TRACE(run.what);
    std::mt19937_64 rng(n);
    std::uniform_int_distribution<std::size_t> any(0, n + 5);  // past the end clamps
    for (int i = 0; i < 60; ++i) {
      const std::size_t target = any(rng);
      s.seek(target);
      ASSERT_EQ(s.position(), std::min(target, n));
      ASSERT_EQ(s.state(), run.log.state_after(target)) << "after seeking to " << target;
    }
    // A seek just past a checkpoint and back, then single steps across a checkpoint boundary.
    s.seek(2 * s.checkpoint_interval() + 1);
    s.seek(1);
    s.seek(s.checkpoint_interval() - 1);
    ASSERT_TRUE(s.step_forward());
    ASSERT_TRUE(s.step_forward());
    ASSERT_EQ(s.state(), run.log.state_after(s.checkpoint_interval() + 1));
  }
  EXPECT_GT(long_traces, 0) << "no trace was long enough to use a checkpoint";
}

// ---- corrupted traces are refused (the check that makes undo exact) ----------------------------


TEST(Stepper, ACorruptedTraceIsRefusedNamingTheEventAndArray) {
  Stepper s;
  ASSERT_NO_THROW(s.load(two_pushes(0)));
  EXPECT_EQ(s.list_members(0, 1), std::vector<std::int32_t>{});
  s.seek(3);
  EXPECT_EQ(s.list_members(0, 1), (std::vector<std::int32_t>{2, 0}));

  // The fault: the second push claims the head held -1. Undo would then "restore" -1 where the
  // replay from the start has 0, so stepping back would not be exact; load() must refuse it.
  const TraceLog bad = two_pushes(-1);
  ArrayState walked = bad.state_after(3);
  TraceLog::undo(bad.events()[2], walked);
  EXPECT_NE(walked, bad.state_after(2)) << "the injected fault would not even be visible";
  try {
    s.load(bad);
    FAIL() << "a corrupted trace was accepted";
  } catch (const Error& err) {
    const std::string what = err.what();
    EXPECT_NE(what.find("event 2"), std::string::npos) << what;
    EXPECT_NE(what.find("C[1]"), std::string::npos) << what;
  }
  EXPECT_EQ(s.size(), 0u) << "a refused trace must leave the stepper empty";

  TraceLog outside;
  const std::vector<std::int32_t> heads(2, -1);
  const int h = outside.declare_array("C", {2}, heads);
  outside.clear(0, "list", h, 5, -1);
  EXPECT_THROW(s.load(outside), Error);
}

// ---- phase jumps ---------------------------------------------------------------------------

std::vector<std::size_t> phase_events(const std::vector<TraceEvent>& ev) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < ev.size(); ++i)
    if (ev[i].op == TraceOp::Phase) out.push_back(i);
  return out;
}

TEST(Stepper, PhaseJumpsLandOnEveryPhaseEventInOrder) {
  for (const TracedRun& run : list_based_runs(40)) {
    SCOPED_TRACE(run.what);
    const std::vector<std::size_t> expected = phase_events(run.log.events());
    Stepper s;
    s.load(run.log);
    ASSERT_EQ(s.phases().size(), expected.size());
    // Before anything, a phase marked at the first event is the one the stepper stands in: the first
    // jump goes to the phase after it (it moved one event, which looked like a single step).
    const std::size_t first = !expected.empty() && expected.front() == 0 ? 1 : 0;
    if (first == 1) {
      ASSERT_TRUE(s.next_phase());
      ASSERT_EQ(s.position(), expected.size() > 1 ? expected[1] + 1 : std::size_t{0}) << "the first jump from 0";
      s.seek(expected[0] + 1);
    }
    for (std::size_t i = first; i < expected.size(); ++i) {
      ASSERT_TRUE(s.next_phase());
      ASSERT_EQ(s.position(), expected[i] + 1);
      ASSERT_EQ(s.current()->op, TraceOp::Phase);
      ASSERT_EQ(s.current_phase(), static_cast<std::int64_t>(i));
    }
    const std::size_t before = s.position();
    EXPECT_FALSE(s.next_phase());
    EXPECT_EQ(s.position(), before);

    // Backwards from the end: first to the start of the phase we are in, then one phase each.
    s.seek(s.size());
    std::vector<std::size_t> back;
    while (s.prev_phase()) back.push_back(s.position() - 1);
    std::vector<std::size_t> expected_back(expected.rbegin(), expected.rend());
    if (!expected.empty() && expected.back() + 1 == s.size()) expected_back.erase(expected_back.begin());
    EXPECT_EQ(back, expected_back);

    // From the middle of a phase, prev goes to that phase's own start.
    for (std::size_t i = 0; i + 1 < expected.size(); ++i) {
      if (expected[i + 1] - expected[i] < 3) continue;
      s.seek(expected[i] + 3);
      ASSERT_TRUE(s.prev_phase());
      EXPECT_EQ(s.position(), expected[i] + 1);
      s.seek_phase(i + 1);
      EXPECT_EQ(s.position(), expected[i + 1] + 1);
      break;
    }
  }
}


// ---- loop variables, writes and lists, checked against the grid (nbs) -------------------------

TEST(Stepper, NbsLoopVariablesWritesAndListsAgreeWithTheGrid) {
  const Elements e = testdata::make_layout(Layout::Dense, 120, 2, 5);
  auto nbs = make_detector("nbs");
  PairList pairs;
  TraceLog log;
  nbs->detect_traced(e, DetectOptions{}, pairs, log);
  const Grid g = *nbs->last_grid();
  Stepper s;
  s.load(log);
  const int y_heads = s.array_id("y_heads");
  ASSERT_GE(y_heads, 0);
  EXPECT_EQ(s.next_array_of(y_heads), s.array_id("Y"));

  std::int64_t last_write = -1;
  std::size_t pushes = 0, tests = 0;
  while (s.step_forward()) {
    const TraceEvent& ev = *s.current();
    const LoopVars v = s.loop_vars();
    if (ev.write_count > 0) last_write = static_cast<std::int64_t>(s.position() - 1);
    ASSERT_EQ(s.last_write_event().has_value(), last_write >= 0);
    if (last_write >= 0) {
      ASSERT_EQ(static_cast<std::int64_t>(*s.last_write_event()), last_write);
    }
    ASSERT_EQ(s.current_writes().size(), ev.write_count);
    if (ev.op == TraceOp::Push) {
      ++pushes;
      const std::int32_t k = ev.element;
      ASSERT_EQ(v.k, k);
      ASSERT_EQ(v.iy, g.cell(e.y[k], 1));
      if (v.ix >= 0) {
        ASSERT_EQ(v.ix, g.cell(e.x[k], 0));
      }
      ASSERT_EQ(v.head, k) << "a push makes k the head of its list";
      ASSERT_EQ(s.current_writes()[1].new_value, k);
      ASSERT_EQ(s.list_members(v.heads_array, v.list).front(), k);
    }
    if (ev.op == TraceOp::TestPair) {
      ++tests;
      // The mask cell shown for a test is the cell of the element k is tested against.
      ASSERT_EQ(v.k, ev.element);
      ASSERT_EQ(v.j, ev.other);
      ASSERT_EQ(v.ix, g.cell(e.x[v.j], 0));
      ASSERT_EQ(v.iy, g.cell(e.y[v.j], 1));
      ASSERT_LE(std::abs(v.ix - g.cell(e.x[v.k], 0)), 1);
      ASSERT_LE(std::abs(v.iy - g.cell(e.y[v.k], 1)), 1);
    }
    if (std::string(v.phase) == "y-lists" && s.position() == static_cast<std::size_t>(e.size()) + 1) {
      // All y-lists built: row iy lists its elements in decreasing id (pushed at the head).
      for (std::int32_t iy = 0; iy < g.n[1]; ++iy) {
        std::vector<std::int32_t> row;
        for (std::int32_t k = static_cast<std::int32_t>(e.size()); k-- > 0;)
          if (g.cell(e.y[k], 1) == iy) row.push_back(k);
        ASSERT_EQ(s.list_members(y_heads, iy), row) << "row " << iy;
      }
    }
  }
  EXPECT_GE(pushes, 2 * static_cast<std::size_t>(e.size()));
  EXPECT_GT(tests, 0u);
}

// ---- the book's worked example ---------------------------------------------------------------

TEST(Stepper, ScreenOnTheBooksNineElementsShowsFig320OnceMappedAndWhileTesting) {
  // Fig. 3.15's centres (assets/examples/nine.csv) on the book's 10x10 grid of unit cells.
  const Elements e = testdata::book_nine();
  DetectOptions o;
  o.grid = testdata::book_grid();
  auto screen = make_detector("screen");
  PairList pairs;
  TraceLog log;
  screen->detect_traced(e, o, pairs, log);
  Stepper s;
  s.load(std::move(log));
  const int c = s.array_id("C"), next = s.array_id("E");
  ASSERT_GE(c, 0);
  ASSERT_GE(next, 0);
  // Fig. 3.20 in the book's 1-based numbering: C[5][7]=4, C[5][6]=6, C[6][6]=8, C[2][7]=9,
  // E = -1 1 -1 2 3 -1 5 -1 7; every other head of the 100 is -1.
  const auto book_c = [&](int ix, int iy) { return s.state()[c][static_cast<std::size_t>((ix - 1) * 10 + (iy - 1))] + 1; };
  const std::vector<std::int32_t> book_e = {-1, 1, -1, 2, 3, -1, 5, -1, 7};
  for (std::size_t step : {std::size_t{10}, std::size_t{20}}) {  // the golden screenshots' steps
    s.seek(step);
    SCOPED_TRACE("after " + std::to_string(step) + " events");
    EXPECT_EQ(book_c(5, 7), 4);
    EXPECT_EQ(book_c(5, 6), 6);
    EXPECT_EQ(book_c(6, 6), 8);
    EXPECT_EQ(book_c(2, 7), 9);
    EXPECT_EQ(std::count(s.state()[c].begin(), s.state()[c].end(), -1), 96);
    std::vector<std::int32_t> shown_e;
    for (std::int32_t v : s.state()[next]) shown_e.push_back(v < 0 ? v : v + 1);
    EXPECT_EQ(shown_e, book_e);
  }
  // Step 5 (golden): four elements mapped, the list {4,2,1} of C[5][7] complete (book numbers).
  s.seek(5);
  EXPECT_EQ(s.list_members(c, 4 * 10 + 6), (std::vector<std::int32_t>{3, 1, 0}));
  // Step 20 (golden): element 2 tested against element 1, in contact (book numbers).
  s.seek(20);
  ASSERT_EQ(s.current()->op, TraceOp::TestPair);
  EXPECT_EQ(s.current()->element, 1);
  EXPECT_EQ(s.current()->other, 0);
  EXPECT_TRUE(s.current()->contact);
}

}  // namespace
}  // namespace nbscope
