// first_broken_contract: every traced built-in keeps its contracts on every layout (no false alarm),
// and each kind of break, planted in a real nbs trace by editing its events, is the first broken
// contract at the operation that was edited (or where the missing work was due).
#include <gtest/gtest.h>

#include <optional>

#include "core/contracts.hpp"
#include "core/detector.hpp"
#include "core/layouts.hpp"
#include "support/trace_edit.hpp"

namespace nbscope {
namespace {

using testdata::first_event;
using testdata::rerecorded;
using testdata::traced;
using testdata::without;

TEST(Contracts, EveryTracedBuiltInKeepsThemOnEveryLayout) {
  for (const DetectorInfo& info : detector_infos()) {
    if (!info.traces || !info.library.empty()) continue;
    for (const int dim : {2, 3}) {
      if ((dim == 2 && !info.dim2) || (dim == 3 && !info.dim3)) continue;
      for (const Layout layout : all_layouts()) {
        SCOPED_TRACE(info.name + " " + std::to_string(dim) + "D " + layout_name(layout));
        const FrameTrace t = traced(info.name, layout, 300, dim, 11);
        const std::optional<BrokenContract> broken = first_broken_contract(t);
        EXPECT_FALSE(broken) << contract_name(broken->contract) << " at " << broken->event << ": " << broken->text;
      }
    }
  }
}

class PlantedBreak : public ::testing::Test {
 protected:
  void SetUp() override { t = traced("nbs", Layout::Dense, 400, 2, 3); }
  // The first broken contract of `t` with its log replaced by `log`; it must be one.
  BrokenContract broken_with(TraceLog log) { return testdata::broken_with(t, std::move(log)); }
  // The build phase of the first row above row 2 whose build pushes, and the phase after it (its contacts').
  void find_row_build(std::size_t& build, std::size_t& contacts) const {
    build = contacts = 0;
    for (std::size_t at = 0; at + 1 < t.log.events().size(); ++at) {
      const TraceEvent& e = t.log.events()[at];
      if (build == 0 && e.op == TraceOp::Phase && e.index > 2 && t.log.events()[at + 1].op == TraceOp::Push) build = at;
      else if (build > 0 && e.op == TraceOp::Phase) {
        contacts = at;
        return;
      }
    }
  }
  FrameTrace t;
};

TEST_F(PlantedBreak, APushThatCutsTheListIsAListLink) {
  // The second push onto one x-list: its next must be the first; written as -1 the list is cut.
  const std::size_t first = first_event(t.log, [](const TraceEvent& e) { return e.op == TraceOp::Push && e.cell[0] >= 0; });
  const TraceEvent head = t.log.events()[first];
  const std::size_t second = first_event(t.log, [&](const TraceEvent& e) {
    return e.op == TraceOp::Push && e.writes[1].array == head.writes[1].array && e.writes[1].old_value >= 0;
  });
  const BrokenContract b = broken_with(rerecorded(t.log, [&](std::size_t at, TraceEvent& e) {
    if (at == second) e.writes[0].new_value = -1;
    return true;
  }));
  EXPECT_EQ(b.contract, Contract::ListLink);
  EXPECT_EQ(b.event, second);
  EXPECT_NE(b.text.find("cuts the list"), std::string::npos) << b.text;
}

TEST_F(PlantedBreak, AHeadLeftFromTheLastFrameIsAStaleLink) {
  // y_heads[iy] holds an element when the frame begins: the first push onto it links into it.
  const std::size_t push = first_event(t.log, [](const TraceEvent& e) { return e.op == TraceOp::Push; });
  const TraceEvent p = t.log.events()[push];
  const std::int32_t stale = p.element == 0 ? 1 : 0;
  const BrokenContract b = broken_with(rerecorded(
      t.log,
      [&](std::size_t at, TraceEvent& e) {
        if (e.op == TraceOp::Push && e.writes[1].array == p.writes[1].array && e.writes[1].index == p.writes[1].index &&
            e.writes[0].new_value == -1 && at >= push)
          e.writes[0].new_value = stale;  // the first push onto that list links to the stale head
        return true;
      },
      [&](std::size_t array, std::vector<std::int32_t>& v) {
        if (static_cast<int>(array) == p.writes[1].array) v[static_cast<std::size_t>(p.writes[1].index)] = stale;
      }));
  EXPECT_EQ(b.contract, Contract::ListLink);
  EXPECT_EQ(b.event, push);
  EXPECT_NE(b.text.find("the last frame's list"), std::string::npos) << b.text;
}

TEST_F(PlantedBreak, AWrongTestAnswerIsATestAnswer) {
  const std::size_t test = first_event(t.log, [](const TraceEvent& e) { return e.op == TraceOp::TestPair && e.contact; });
  const BrokenContract b = broken_with(rerecorded(t.log, [&](std::size_t at, TraceEvent& e) {
    if (at == test) e.contact = false;
    return true;
  }));
  EXPECT_EQ(b.contract, Contract::TestAnswer);
  EXPECT_EQ(b.event, test);
  ASSERT_EQ(b.cost.size(), 1u);
}

TEST_F(PlantedBreak, AContactNotReportedIsATestReported) {
  const std::size_t test = first_event(t.log, [](const TraceEvent& e) { return e.op == TraceOp::TestPair && e.contact; });
  const TraceEvent e = t.log.events()[test];
  std::erase_if(t.pairs, [&](const Pair& p) { return (p.i == e.element && p.j == e.other) || (p.j == e.element && p.i == e.other); });
  const std::optional<BrokenContract> b = first_broken_contract(t);
  ASSERT_TRUE(b);
  EXPECT_EQ(b->contract, Contract::TestReported);
  EXPECT_EQ(b->event, test);
}

TEST_F(PlantedBreak, ATestRepeatedIsATestOnce) {
  const std::size_t test = first_event(t.log, [](const TraceEvent& e) { return e.op == TraceOp::TestPair; });
  TraceLog twice = rerecorded(t.log, [&](std::size_t, TraceEvent&) { return true; });
  const TraceEvent e = t.log.events()[test];
  twice.test_pair(e.line, e.element, e.other, e.contact);  // the same test once more, at the end
  const BrokenContract b = broken_with(std::move(twice));
  EXPECT_EQ(b.contract, Contract::TestOnce);
  EXPECT_EQ(b.event, t.log.events().size() - 1);
}

TEST_F(PlantedBreak, AMaskCellSkippedByOneElementIsAMaskCell) {
  // Drop one element's visit of a cell below it (and the tests of that walk) where the cell holds elements.
  std::size_t dropped = 0;
  std::int32_t k = -1;
  for (std::size_t at = 0; at < t.log.events().size(); ++at) {
    const TraceEvent& e = t.log.events()[at];
    if (e.op == TraceOp::VisitCell && at + 1 < t.log.events().size() && t.log.events()[at + 1].op == TraceOp::TestPair &&
        t.log.events()[at + 1].element == e.element && e.cell[1] < t.grid.cell(t.elements.y[e.element], 1)) {
      dropped = at;
      k = e.element;
      break;
    }
  }
  ASSERT_GE(k, 0);
  bool walking = false;
  TraceLog edited = rerecorded(t.log, [&](std::size_t at, TraceEvent& e) {
    if (at == dropped) walking = true;
    else if (e.op != TraceOp::TestPair) walking = false;
    return !walking;
  });
  std::size_t last_kept = 0;  // k's last visit that is left
  for (std::size_t at = 0; at < edited.events().size(); ++at)
    if (edited.events()[at].op == TraceOp::VisitCell && edited.events()[at].element == k) last_kept = at;
  const BrokenContract b = broken_with(std::move(edited));
  EXPECT_EQ(b.contract, Contract::MaskCell) << b.text;
  EXPECT_EQ(b.event, last_kept) << b.text;
}

TEST_F(PlantedBreak, ARowNeverProcessedIsARowProcessed) {
  // Drop every event of one row's phases (its x-lists, contacts and clears) but keep the other rows.
  std::int32_t row = -1;
  std::size_t next_row_start = 0;
  for (std::size_t at = 0; at < t.log.events().size(); ++at) {
    const TraceEvent& e = t.log.events()[at];
    if (e.op != TraceOp::Phase || e.index < 0) continue;
    if (row < 0 && e.index > 2) row = e.index;
    else if (row >= 0 && e.index != row) {
      next_row_start = at;
      break;
    }
  }
  ASSERT_GE(row, 0);
  ASSERT_GT(next_row_start, 0u);
  std::int32_t in_phase = -1;
  std::size_t removed = 0;
  const BrokenContract b = broken_with(rerecorded(t.log, [&](std::size_t, TraceEvent& e) {
    if (e.op == TraceOp::Phase) in_phase = e.index;
    const bool keep = in_phase != row;
    if (!keep) ++removed;
    return keep;
  }));
  EXPECT_EQ(b.contract, Contract::RowProcessed) << b.text;
  EXPECT_EQ(b.event, next_row_start - removed);  // where the loop went on past it
  EXPECT_NE(b.text.find("row " + std::to_string(row)), std::string::npos) << b.text;
}

TEST_F(PlantedBreak, AVisitOutsideTheGridIsAMaskInGrid) {
  const std::size_t visit = first_event(t.log, [](const TraceEvent& e) { return e.op == TraceOp::VisitCell; });
  const BrokenContract b = broken_with(rerecorded(t.log, [&](std::size_t at, TraceEvent& e) {
    if (at == visit) e.cell[0] = static_cast<std::int32_t>(t.grid.n[0]);
    return true;
  }));
  EXPECT_EQ(b.contract, Contract::MaskInGrid);
  EXPECT_EQ(b.event, visit);
}

TEST_F(PlantedBreak, HeadsLeftSetAtTheEndAreAHeadsCleared) {
  // Every clear of the y heads dropped: the frame ends with them set.
  const int y_heads = t.log.array_id("y_heads");
  ASSERT_GE(y_heads, 0);
  const BrokenContract b = broken_with(rerecorded(t.log, [&](std::size_t, TraceEvent& e) {
    return !(e.op == TraceOp::Clear && e.writes[0].array == y_heads);
  }));
  EXPECT_EQ(b.contract, Contract::HeadsCleared) << b.text;
  EXPECT_NE(b.text.find("y_heads["), std::string::npos) << b.text;
}

TEST_F(PlantedBreak, AWalkThatStopsShortIsAWalkComplete) {
  // The tests of one walk of a cell that is not the visitor's own dropped: the visit is left, the walk not.
  std::size_t visit = 0;
  for (std::size_t at = 0; at + 1 < t.log.events().size(); ++at) {
    const TraceEvent& e = t.log.events()[at];
    if (e.op == TraceOp::VisitCell && e.cell[0] != t.grid.cell(t.elements.x[e.element], 0) && t.log.events()[at + 1].op == TraceOp::TestPair) {
      visit = at;
      break;
    }
  }
  ASSERT_GT(visit, 0u);
  bool walking = false;
  const BrokenContract b = broken_with(rerecorded(t.log, [&](std::size_t at, TraceEvent& e) {
    if (at == visit) {
      walking = true;
      return true;
    }
    if (e.op != TraceOp::TestPair) walking = false;
    return !walking;
  }));
  EXPECT_EQ(b.contract, Contract::WalkComplete) << b.text;
  EXPECT_EQ(b.event, visit + 1) << "where the walk stopped: the operation after its visit";
}


TEST_F(PlantedBreak, AVisitOfTheMirrorOffsetIsAMaskHalfAtTheVisit) {
  // One visit of the row below moved to the row above (in the grid): the book's half mask never
  // looks up, so the visit itself is the break, whatever the offsets the rest of the trace visits.
  std::size_t visit = 0;
  std::int32_t up = -1;
  for (std::size_t at = 0; at < t.log.events().size(); ++at) {
    const TraceEvent& e = t.log.events()[at];
    if (e.op != TraceOp::VisitCell) continue;  // only a visit names an element to look up
    const std::int32_t own = t.grid.cell(t.elements.y[e.element], 1);
    if (e.cell[1] == own - 1 && own + 1 < t.grid.n[1]) {
      visit = at;
      up = own + 1;
      break;
    }
  }
  ASSERT_GE(up, 0);
  const BrokenContract b = broken_with(rerecorded(t.log, [&](std::size_t at, TraceEvent& e) {
    if (at == visit) e.cell[1] = up;
    return true;
  }));
  EXPECT_EQ(b.contract, Contract::MaskHalf) << b.text;
  EXPECT_EQ(b.event, visit) << b.text;
}

TEST_F(PlantedBreak, AMirrorHalfLateInTheFrameDoesNotRedefineTheMask) {
  // From the frame's middle visit on, every visit of the row below goes to the row above: the whole
  // trace leans both ways nearly alike (as the stale lists of a wrong clear made 3D mutants do), but
  // its first quarter keeps the book's half, so the first turned visit is the break, not an element
  // before it blamed for a mask the late visits made up.
  std::vector<std::size_t> visits;
  for (std::size_t at = 0; at < t.log.events().size(); ++at)
    if (t.log.events()[at].op == TraceOp::VisitCell) visits.push_back(at);
  ASSERT_GE(visits.size(), 64u);
  const std::size_t from = visits[visits.size() / 2];
  std::size_t first = t.log.events().size();
  const TraceLog turned = rerecorded(t.log, [&](std::size_t at, TraceEvent& e) {
    if (at < from || e.op != TraceOp::VisitCell) return true;
    const std::int32_t own = t.grid.cell(t.elements.y[e.element], 1);
    if (e.cell[1] == own - 1 && own + 1 < t.grid.n[1]) {
      e.cell[1] = own + 1;
      first = std::min(first, at);
    }
    return true;
  });
  ASSERT_LT(first, t.log.events().size());
  const BrokenContract b = broken_with(turned);
  EXPECT_EQ(b.contract, Contract::MaskHalf) << b.text;
  EXPECT_EQ(b.event, first) << b.text;
}

TEST_F(PlantedBreak, ARowWhoseContactsPhaseDoesNothingIsARowProcessedWhereItsFirstVisitWasDue) {
  // Every visit and test of one row's "contacts of row" phase dropped: its lists are built and cleared.
  std::size_t contacts = 0;
  for (std::size_t at = 0; at + 1 < t.log.events().size(); ++at) {
    const TraceEvent& e = t.log.events()[at];
    if (e.op == TraceOp::Phase && e.index > 2 && t.log.events()[at + 1].op == TraceOp::VisitCell) {
      contacts = at;
      break;
    }
  }
  ASSERT_GT(contacts, 0u);
  bool in_contacts = false;
  const BrokenContract b = broken_with(rerecorded(t.log, [&](std::size_t at, TraceEvent& e) {
    if (e.op == TraceOp::Phase) in_contacts = at == contacts;
    return !in_contacts || e.op == TraceOp::Phase;
  }));
  EXPECT_EQ(b.contract, Contract::RowProcessed) << b.text;
  EXPECT_EQ(b.event, contacts + 1) << b.text;
}

TEST_F(PlantedBreak, ARowsClearsLeftOutAreAListLinkWhereTheFirstClearWasDue) {
  // Every clear of one row's clearing phase dropped (the heads are still reset, untraced): the next
  // push onto one of those lists for another cell finds it empty, though the trace never emptied it.
  const int heads = t.log.array_id("B");
  ASSERT_GE(heads, 0);
  std::size_t clearing = 0;
  for (std::size_t at = 0; at + 1 < t.log.events().size(); ++at) {
    const TraceEvent& e = t.log.events()[at];
    const TraceEvent& next = t.log.events()[at + 1];
    if (e.op == TraceOp::Phase && e.index > 2 && next.op == TraceOp::Clear && next.writes[0].array == heads) {
      clearing = at;
      break;
    }
  }
  ASSERT_GT(clearing, 0u);
  bool in_clearing = false;
  const BrokenContract b = broken_with(rerecorded(t.log, [&](std::size_t at, TraceEvent& e) {
    if (e.op == TraceOp::Phase) in_clearing = at == clearing;
    return !(in_clearing && e.op == TraceOp::Clear);
  }));
  EXPECT_EQ(b.contract, Contract::ListLink) << b.text;
  EXPECT_EQ(b.event, clearing + 1) << b.text;
}

TEST_F(PlantedBreak, ARowWhoseOwnElementsAreLeftOutOfItsBuildIsAListCompleteWhereTheBuildBegan) {
  // The pushes of one row's own elements dropped from its build (the row below is still built): the
  // book builds a row's own lists first, so they were due at the build's first operation.
  std::size_t build = 0, contacts = 0;
  find_row_build(build, contacts);
  ASSERT_GT(contacts, 0u);
  const std::int32_t row = t.log.events()[build].index;
  std::size_t removed = 0;
  const BrokenContract b = broken_with(without(t.log, [&](std::size_t at, const TraceEvent& e) {
    return at > build && at < contacts && e.op == TraceOp::Push && e.cell[1] == row;
  }, removed));
  ASSERT_GT(removed, 0u);
  EXPECT_EQ(b.contract, Contract::ListComplete) << b.text;
  EXPECT_EQ(b.event, build + 1) << b.text;
}

TEST_F(PlantedBreak, ARowBelowLeftOutOfTheBuildIsAListCompleteWhereTheBuildEnded) {
  // The pushes of the row below dropped from one row's build: that row's masks reach cells of it whose
  // lists were never built; due at the contacts' phase, where the build ended.
  std::size_t build = 0, contacts = 0;
  find_row_build(build, contacts);
  ASSERT_GT(contacts, 0u);
  const std::int32_t row = t.log.events()[build].index;
  std::size_t removed = 0;
  const BrokenContract b = broken_with(without(t.log, [&](std::size_t at, const TraceEvent& e) {
    return at > build && at < contacts && e.op == TraceOp::Push && e.cell[1] == row - 1;
  }, removed));
  ASSERT_GT(removed, 0u);
  EXPECT_EQ(b.contract, Contract::ListComplete) << b.text;
  EXPECT_EQ(b.event, contacts - removed) << b.text;
}

TEST_F(PlantedBreak, NoRowProcessedAtAllIsARowProcessedWhereTheRowLoopWentOnPastThem) {
  // Every event of every row's phases dropped (a row test that always says "empty"): the loop over the
  // rows goes straight on to the clearing of the y-lists.
  std::int32_t in_row = -1;
  TraceLog edited = rerecorded(t.log, [&](std::size_t, TraceEvent& e) {
    if (e.op == TraceOp::Phase) in_row = e.index;
    return in_row < 0;
  });
  std::size_t push = 0;
  while (edited.events()[push].op != TraceOp::Push) ++push;
  std::size_t after = push;
  while (edited.events()[after].op != TraceOp::Phase) ++after;
  const BrokenContract b = broken_with(std::move(edited));
  EXPECT_EQ(b.contract, Contract::RowProcessed) << b.text;
  EXPECT_EQ(b.event, after) << b.text;
}

TEST_F(PlantedBreak, APushInTheBuildOfARowItsMaskDoesNotReachIsACellListAtThePush) {
  // One row's build phase named three rows up: the pushes of its rows are then in the build of a row
  // whose half mask does not reach them (the wrong row's lists were taken).
  std::size_t build = 0;
  for (std::size_t at = 0; at + 1 < t.log.events().size(); ++at) {
    const TraceEvent& e = t.log.events()[at];
    if (e.op == TraceOp::Phase && e.index > 2 && e.index + 3 < t.grid.n[1] && t.log.events()[at + 1].op == TraceOp::Push) {
      build = at;
      break;
    }
  }
  ASSERT_GT(build, 0u);
  const BrokenContract b = broken_with(rerecorded(t.log, [&](std::size_t at, TraceEvent& e) {
    if (at == build) e.index += 3;
    return true;
  }));
  EXPECT_EQ(b.contract, Contract::CellList) << b.text;
  EXPECT_EQ(b.event, build + 1) << b.text;
}

TEST_F(PlantedBreak, ACellVisitedTwiceByOneMaskIsAMaskCellAtTheSecondVisit) {
  // One element's visit of the cell to its left renamed to its own cell, which it visited first.
  std::size_t visit = 0;
  for (std::size_t at = 0; at < t.log.events().size(); ++at) {
    const TraceEvent& e = t.log.events()[at];
    if (e.op == TraceOp::VisitCell && e.cell[1] == t.grid.cell(t.elements.y[e.element], 1) && e.cell[0] + 1 == t.grid.cell(t.elements.x[e.element], 0)) {
      visit = at;
      break;
    }
  }
  ASSERT_GT(visit, 0u);
  const BrokenContract b = broken_with(rerecorded(t.log, [&](std::size_t at, TraceEvent& e) {
    if (at == visit) e.cell[0] += 1;
    return true;
  }));
  EXPECT_EQ(b.contract, Contract::MaskCell) << b.text;
  EXPECT_EQ(b.event, visit) << b.text;
}

}  // namespace
}  // namespace nbscope
