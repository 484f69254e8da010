// The cross-check (check/check.hpp, the checker): every invariant holds on a correct frame and
// breaks, naming the pair, its cells and the invariant, when its input is wrong; R is brute force up
// to the limit, and R computed beside F, G and T gives the plain order's reports. The faults are in
// test_faults.cpp, the pipeline that runs the checker in test_pipeline.cpp.
#include <gtest/gtest.h>

#include "check/check.hpp"
#include "physics/world.hpp"
#include "check/faults.hpp"
#include "core/brute.hpp"
#include "io/scene_json.hpp"

namespace nbscope {
namespace {

// ---- the checker ---------------------------------------------------------------------------

// A row of touching dynamic circles over a static floor tile, after one step.
class CheckerTest : public ::testing::Test {
 protected:
  CheckerTest()
      : world_(parse_scene_json(R"({"gravity": [0, 0], "bodies": [
          {"shape": "circle", "radius": 0.5, "position": [0, 1]},
          {"shape": "circle", "radius": 0.5, "position": [0.95, 1]},
          {"shape": "circle", "radius": 0.5, "position": [1.9, 1.2]},
          {"shape": "circle", "radius": 0.5, "position": [6, 1]},
          {"type": "static", "shape": "box", "half_extents": [0.5, 0.3], "position": [0, 0.25]}]})",
                                 "row.json")) {
    world_.step();
    BruteDetector brute;
    brute.detect(world_.elements(), DetectOptions{}, correct_);
    sort_pairs(correct_);
    grid_ = make_grid(world_.elements(), GridOptions{});
    integerise_cells(world_.elements(), grid_, cells_);
  }

  // `grid_cells`: the grid's cells when `cells` are a detector's own (the cells check runs).
  FrameReport run(const PairList& pairs, const std::vector<CellIndex>& cells, bool drop_box2d_contact = false,
                  const std::vector<CellIndex>* grid_cells = nullptr, const WalkCheck* walks = nullptr) {
    checker_.begin_frame(world_, DetectOptions{});
    CheckInput in;
    in.algorithm = "nbs";
    in.pairs = &pairs;
    in.cells = &cells;
    in.grid_cells = grid_cells;
    in.walks = walks;
    in.drop_box2d_contact = drop_box2d_contact;
    FrameReport out;
    checker_.check(in, out);
    return out;
  }

  PhysicsWorld world_;
  FrameChecker checker_;
  PairList correct_;
  Grid grid_;
  std::vector<CellIndex> cells_;
};

// Brute force's own pairs hold every invariant, and the counts are the row's (five elements, three pairs).
TEST_F(CheckerTest, CorrectPairsHoldEveryInvariant) {
  ASSERT_EQ(correct_, (PairList{{0, 1}, {0, 4}, {1, 2}}));
  const FrameReport r = run(correct_, cells_);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.frame, 1);
  EXPECT_EQ(r.reference, "brute");
  EXPECT_EQ(r.counts.elements, 5);
  EXPECT_EQ(r.counts.a, 3);
  EXPECT_EQ(r.counts.r, 3);
  EXPECT_EQ(r.counts.t, 3);
  EXPECT_EQ(r.counts.a_in_scope, 3);
  EXPECT_GE(r.counts.f, 3);
  EXPECT_TRUE(r.violations.empty());
}

// A touching pair left out is missing from A (A==R) and a touching pair not in A (T-in-A), with its cells.
TEST_F(CheckerTest, AMissingTouchingPairBreaksAEqualsRAndTInA) {
  const FrameReport r = run(PairList{{0, 1}, {0, 4}}, cells_);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.broken[static_cast<int>(Invariant::AEqualsR)], 1);
  EXPECT_EQ(r.broken[static_cast<int>(Invariant::TInA)], 1);
  EXPECT_EQ(r.broken[static_cast<int>(Invariant::AInF)], 0);
  ASSERT_EQ(r.violations.size(), 2u);
  const Violation& v = r.violations[0];
  EXPECT_EQ(v.invariant, Invariant::AEqualsR);
  EXPECT_EQ(v.pair, (Pair{1, 2}));
  EXPECT_EQ(v.frame, 1);
  EXPECT_EQ(v.cell_i, cells_[1]);
  EXPECT_EQ(v.cell_j, cells_[2]);
  EXPECT_STREQ(v.what, "missing from A (in R)");
  EXPECT_EQ(r.violations[1].invariant, Invariant::TInA);
}

// Two far circles paired are extra in A (A==R) and not in Box2D's contact list (A-in-F).
TEST_F(CheckerTest, AnExtraCirclePairBreaksAEqualsRAndAInF) {
  PairList a = correct_;
  a.push_back({2, 3});  // two dynamic circles 4 m apart: Box2D's broadphase must refute it too
  sort_pairs(a);
  const FrameReport r = run(a, cells_);
  EXPECT_EQ(r.broken[static_cast<int>(Invariant::AEqualsR)], 1);
  EXPECT_EQ(r.broken[static_cast<int>(Invariant::AInF)], 1);
  EXPECT_EQ(r.violation_count(), 2);
  EXPECT_STREQ(r.violations[0].what, "extra in A (not in R)");
  EXPECT_STREQ(r.violations[1].what, "not in Box2D's contact list");
}

// A far pair with a polygon breaks A==R only: A-in-F leaves it out and counts why (beyond its AABB).
TEST_F(CheckerTest, AnExtraPolygonPairIsLeftOutOfAInFAndCounted) {
  PairList a = correct_;
  a.push_back({3, 4});  // circle and floor box far apart: a polygon's bounding circle is no AABB
  sort_pairs(a);
  const FrameReport r = run(a, cells_);
  EXPECT_EQ(r.broken[static_cast<int>(Invariant::AEqualsR)], 1);
  EXPECT_EQ(r.broken[static_cast<int>(Invariant::AInF)], 0);
  EXPECT_EQ(r.counts.beyond_aabb, 1);
}

// An element integerised three cells off breaks AABB-in-cells for the pair whose AABBs overlap.
TEST_F(CheckerTest, WrongCellsBreakAabbInCells) {
  std::vector<CellIndex> cells = cells_;
  cells[2].ix += 3;  // element 2 integerised three cells too far right
  const FrameReport r = run(correct_, cells);
  EXPECT_EQ(r.broken[static_cast<int>(Invariant::AabbInCells)], 1);
  EXPECT_EQ(r.violations[0].pair, (Pair{1, 2}));
  EXPECT_EQ(r.violations[0].cell_j, cells[2]);
}

// A detector that integerises by itself (a plugin) and puts one element in the next column: the
// cells check names that element as (k, k), its cell and the grid's; its own cells equal to the
// grid's hold it.
TEST_F(CheckerTest, ADetectorsOwnWrongCellBreaksCells) {
  EXPECT_TRUE(run(correct_, cells_, false, &cells_).ok());
  std::vector<CellIndex> own = cells_;
  own[3].ix += 1;  // element 3, alone far right: no pair changes, only its cell
  const FrameReport r = run(correct_, own, false, &cells_);
  EXPECT_EQ(r.broken[static_cast<int>(Invariant::Cells)], 1);
  EXPECT_EQ(r.violation_count(), 1);
  ASSERT_EQ(r.violations.size(), 1u);
  EXPECT_EQ(r.violations[0].invariant, Invariant::Cells);
  EXPECT_EQ(r.violations[0].pair, (Pair{3, 3}));
  EXPECT_EQ(r.violations[0].cell_i, own[3]);
  EXPECT_EQ(r.violations[0].cell_j, cells_[3]);
  // Without the grid's cells (a built-in: its cells are the grid's) the same cells are not compared.
  EXPECT_EQ(run(correct_, own, false).broken[static_cast<int>(Invariant::Cells)], 0);
}

// A plugin's walk check that found strays: each kept one is a `cells` violation (stray, finder) with
// the walked list's cell and the finder's; the count is the walk check's, not the kept ones'.
TEST_F(CheckerTest, StrayTestsOnAWalkedListBreakCells) {
  EXPECT_FALSE(run(correct_, cells_).cells_checked);  // a built-in: nothing for `cells` to compare
  WalkCheck clean;
  const FrameReport held = run(correct_, cells_, false, nullptr, &clean);
  EXPECT_TRUE(held.ok());
  EXPECT_TRUE(held.cells_checked);  // Stats counts it among the invariants that held
  WalkCheck walks;
  walks.first.push_back(StrayTest{4, 2, CellIndex{cells_[2].ix, cells_[2].iy + 1}, cells_[2], cells_[4]});
  walks.count = 3;  // two more found than kept
  const FrameReport r = run(correct_, cells_, false, nullptr, &walks);
  EXPECT_EQ(r.broken[static_cast<int>(Invariant::Cells)], 3);
  ASSERT_EQ(r.violations.size(), 1u);
  EXPECT_EQ(r.violations[0].invariant, Invariant::Cells);
  EXPECT_EQ(r.violations[0].pair, (Pair{2, 4}));
  EXPECT_EQ(r.violations[0].cell_i, (CellIndex{cells_[2].ix, cells_[2].iy + 1}));
  EXPECT_EQ(r.violations[0].cell_j, cells_[4]);
  EXPECT_NE(std::string(r.violations[0].what).find("stale list"), std::string::npos);
}

// Box2D's contact list losing a pair A needs breaks A-in-F once.
TEST_F(CheckerTest, ALostBox2dContactBreaksAInF) {
  const FrameReport r = run(correct_, cells_, true);
  EXPECT_EQ(r.broken[static_cast<int>(Invariant::AInF)], 1);
  EXPECT_EQ(r.violation_count(), 1);
}

// Repeats, self-pairs, unknown elements and disorder in A are A==R violations named for what they are.
TEST_F(CheckerTest, MalformedPairsAreFlaggedNotTrusted) {
  const FrameReport r = run(PairList{{0, 1}, {0, 1}, {0, 4}, {1, 2}, {2, 2}, {3, 99}}, cells_);
  EXPECT_EQ(r.broken[static_cast<int>(Invariant::AEqualsR)], 3);
  EXPECT_EQ(r.counts.a, 3);
  // Each is named for what is wrong with it, so that a user's planted bug reads as that bug.
  ASSERT_EQ(r.violations.size(), 3u);
  EXPECT_EQ(r.violations[0].pair, (Pair{0, 1}));
  EXPECT_STREQ(r.violations[0].what, "given twice in A");
  EXPECT_EQ(r.violations[1].pair, (Pair{2, 2}));
  EXPECT_STREQ(r.violations[1].what, "an element paired with itself in A");
  EXPECT_EQ(r.violations[2].pair, (Pair{3, 99}));
  EXPECT_STREQ(r.violations[2].what, "not an element of this frame (i or j outside 0..N-1)");
  const FrameReport unsorted = run(PairList{{1, 2}, {0, 1}}, cells_);
  ASSERT_FALSE(unsorted.violations.empty());
  EXPECT_EQ(unsorted.violations[0].pair, (Pair{0, 1}));
  EXPECT_STREQ(unsorted.violations[0].what, "out of order in A (not i < j, or not sorted)");
}

// One begin_frame serves several algorithms' checks, each judged on its own pairs.
TEST_F(CheckerTest, SeveralAlgorithmsShareOneFrame) {
  checker_.begin_frame(world_, DetectOptions{});
  const PairList wrong{{0, 1}};
  for (const PairList* a : std::initializer_list<const PairList*>{&correct_, &wrong, &correct_}) {
    CheckInput in;
    in.algorithm = "sort";
    in.pairs = a;
    in.cells = &cells_;
    FrameReport out;
    checker_.check(in, out);
    EXPECT_EQ(out.ok(), a == &correct_);
  }
}

// R is brute up to the limit, then sort (nbs when sort is tested, and for brute itself).
TEST(FrameChecker, ReferenceIsBruteForceUpToTheLimitThenAnotherDetector) {
  FrameChecker c(CheckOptions{100});
  EXPECT_EQ(c.reference_for(100, "nbs"), "brute");
  EXPECT_EQ(c.reference_for(101, "nbs"), "sort");
  EXPECT_EQ(c.reference_for(101, "sort"), "nbs");
  EXPECT_EQ(c.reference_for(5, "brute"), "sort");
  EXPECT_NE(c.reference_policy().find("100"), std::string::npos);
}

// ---- R beside F, G and T ------------------------------------------------------------------

// A world large enough for begin_frame() to compute R on a second thread; its reports must be
// those of the plain order (R computed by check()), also when A is wrong.
TEST(CheckerParallelReference, GivesTheReportsOfThePlainOrderAndCatchesADroppedPair) {
  PhysicsWorld world(parse_scene_json(R"({"gravity": [0, -10], "generators": [
      {"kind": "random_box", "count": 6000, "seed": 3, "min": [0, 0], "max": [60, 60], "radius": [0.3, 0.5],
       "body": {"type": "dynamic", "shape": "circle"}}]})",
                                      "many.json"));
  world.step();
  ASSERT_GE(world.elements().size(), FrameChecker::kParallelReferenceFrom);
  const Grid grid = make_grid(world.elements(), GridOptions{});
  std::vector<CellIndex> cells;
  integerise_cells(world.elements(), grid, cells);
  PairList good;
  BruteDetector().detect(world.elements(), DetectOptions{}, good);
  sort_pairs(good);
  PairList dropped = good;
  std::vector<CellIndex> dropped_cells = cells;
  apply_output_fault(Fault::DropPair, grid, dropped_cells, dropped);
  ASSERT_EQ(dropped.size() + 1, good.size());

  for (const PairList* a : {&good, &dropped}) {
    FrameReport plain, parallel;
    CheckInput in;
    in.algorithm = "nbs";
    in.pairs = a;
    in.cells = &cells;
    FrameChecker one, two;
    one.begin_frame(world, DetectOptions{});
    one.check(in, plain);
    two.begin_frame(world, DetectOptions{}, "nbs");
    two.check(in, parallel);
    EXPECT_EQ(parallel.reference, "sort");
    EXPECT_EQ(parallel.counts.r, plain.counts.r);
    EXPECT_EQ(parallel.broken, plain.broken);
    EXPECT_EQ(parallel.violations.size(), plain.violations.size());
    EXPECT_EQ(two.reference_pairs(), one.reference_pairs());
    const bool wrong = a == &dropped;
    EXPECT_EQ(parallel.broken[static_cast<std::size_t>(Invariant::AEqualsR)], wrong ? 1 : 0);
  }
}

}  // namespace
}  // namespace nbscope
