// first_broken_contract on 3D traces: breaks planted in a real 3D nbs trace, located where a layer's
// build stopped, and the rows of a plugin's phases (which name only an index) read off the trace.
#include <gtest/gtest.h>

#include <optional>

#include "support/trace_edit.hpp"

namespace nbscope {
namespace {

using testdata::rerecorded;
using testdata::traced;
using testdata::without;

class PlantedBreak3D : public ::testing::Test {
 protected:
  void SetUp() override { t = traced("nbs", Layout::Dense, 600, 3, 7); }
  BrokenContract broken_with(TraceLog log) { return testdata::broken_with(t, std::move(log)); }
  // The phase of the first layer above layer 0 whose build pushes, and its first row's phase.
  void find_layer_build(std::size_t& layer, std::size_t& first_row) const {
    layer = first_row = 0;
    const std::vector<TraceEvent>& ev = t.log.events();
    for (std::size_t at = 0; at + 1 < ev.size(); ++at) {
      const TraceEvent& e = ev[at];
      if (e.op != TraceOp::Phase) continue;
      if (layer == 0 && e.cell[1] < 0 && e.cell[2] > 0 && ev[at + 1].op == TraceOp::Push) layer = at;
      else if (layer > 0 && e.cell[1] >= 0) {
        first_row = at;
        return;
      }
    }
  }
  FrameTrace t;
};

TEST_F(PlantedBreak3D, ALayerBelowLeftOutOfALayersBuildIsAListCompleteWhereTheBuildEnded) {
  // The pushes of the layer below dropped from a layer's y-list build (a "below" flag never set): the
  // rows of that layer its mask reaches were due on the y-lists where the build ended.
  std::size_t layer = 0, first_row = 0;
  find_layer_build(layer, first_row);
  ASSERT_GT(first_row, 0u);
  const std::int32_t iz = t.log.events()[layer].cell[2];
  std::size_t removed = 0;
  const BrokenContract b = broken_with(without(t.log, [&](std::size_t at, const TraceEvent& e) {
    return at > layer && at < first_row && e.op == TraceOp::Push && e.cell[2] == iz - 1;
  }, removed));
  ASSERT_GT(removed, 0u);
  EXPECT_EQ(b.contract, Contract::ListComplete) << b.text;
  EXPECT_EQ(b.event, first_row - removed) << b.text;
}

TEST_F(PlantedBreak3D, ALayerWithNoRowIsCheckedWhereItsBuildEnded) {
  // The layer below dropped from a layer's build and every row of that layer dropped too: the build is
  // checked at the next phase (the layer's clearing), where the y-lists of the layer below were due.
  std::size_t layer = 0, first_row = 0;
  find_layer_build(layer, first_row);
  ASSERT_GT(first_row, 0u);
  const std::int32_t iz = t.log.events()[layer].cell[2];
  std::size_t clearing = first_row;
  while (clearing < t.log.events().size() && !(t.log.events()[clearing].op == TraceOp::Phase && t.log.events()[clearing].cell[1] < 0)) ++clearing;
  ASSERT_LT(clearing, t.log.events().size());
  std::size_t removed = 0;
  const BrokenContract b = broken_with(without(t.log, [&](std::size_t at, const TraceEvent& e) {
    return (at > layer && at < first_row && e.op == TraceOp::Push && e.cell[2] == iz - 1) || (at >= first_row && at < clearing);
  }, removed));
  EXPECT_EQ(b.contract, Contract::ListComplete) << b.text;
  EXPECT_EQ(b.event, clearing - removed) << b.text;
}

TEST_F(PlantedBreak3D, ALayersOwnLoopThatStopsEarlyIsAListCompleteAfterItsLastPush) {
  // The last three pushes of a layer's own elements dropped (its loop stopped three short): due at the
  // operation after the last push it made.
  std::size_t layer = 0, first_row = 0;
  find_layer_build(layer, first_row);
  ASSERT_GT(first_row, 0u);
  const std::int32_t iz = t.log.events()[layer].cell[2];
  std::vector<std::size_t> own;
  for (std::size_t at = layer + 1; at < first_row; ++at)
    if (t.log.events()[at].op == TraceOp::Push && t.log.events()[at].cell[2] == iz) own.push_back(at);
  ASSERT_GT(own.size(), 4u);
  const std::size_t first_dropped = own[own.size() - 3];
  const BrokenContract b = broken_with(rerecorded(t.log, [&](std::size_t at, TraceEvent&) {
    return at < first_dropped || at > own.back();
  }));
  EXPECT_EQ(b.contract, Contract::ListComplete) << b.text;
  EXPECT_EQ(b.event, first_dropped) << b.text;
}

TEST_F(PlantedBreak3D, ARowBuildThatPushesNothingAnywhereIsStillReadAsTheRowsBuild) {
  // A plugin's phases name only an index. With no row's build pushing anything, no segment says the
  // build phases are a row's; the contacts phase that follows each at once does, and the first row's
  // own elements were due at its build's first operation.
  TraceLog edited = rerecorded(t.log, [](std::size_t, TraceEvent& e) {
    if (e.op == TraceOp::Phase) e.cell[0] = e.cell[1] = e.cell[2] = -1;  // as a plugin traces it
    return !(e.op == TraceOp::Push && e.cell[0] >= 0);                  // every x-list push dropped
  });
  std::size_t build = 0;
  for (std::size_t at = 0; at + 1 < edited.events().size(); ++at) {
    const TraceEvent& e = edited.events()[at];
    const TraceEvent& next = edited.events()[at + 1];
    if (e.op == TraceOp::Phase && next.op == TraceOp::Phase && next.index == e.index && e.index >= 0) {
      build = at;
      break;
    }
  }
  ASSERT_GT(build, 0u);
  const std::int32_t row = edited.events()[build].index;
  const BrokenContract b = broken_with(std::move(edited));
  EXPECT_EQ(b.contract, Contract::ListComplete) << b.text;
  EXPECT_EQ(b.event, build + 1) << b.text;
  // The row's own elements are named, not a row its mask reaches (what a build read as no row's blames).
  EXPECT_EQ(b.text.rfind("row " + std::to_string(row) + " of layer", 0), 0u) << b.text;
}

}  // namespace
}  // namespace nbscope
