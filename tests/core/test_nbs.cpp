// Munjiza-NBS specifics: the book's memory, list representation, grid pinning and limits.
#include <gtest/gtest.h>

#include <map>

#include "core/brute.hpp"
#include "core/detector.hpp"
#include "core/error.hpp"
#include "core/nbs.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

using testdata::Layout;

PairList sorted_detect(Detector& d, const Elements& e, const DetectOptions& o = {}) {
  PairList p;
  d.detect(e, o, p);
  sort_pairs(p);
  return p;
}

TEST(Nbs, MemoryIsNyPlusTwoNxPlusTwoNIntegers) {
  for (Layout layout : {Layout::Loose, Layout::Dense, Layout::Clustered, Layout::FarAway}) {
    NbsDetector nbs;
    const Elements e = testdata::make_layout(layout, 3000, 2, 4);
    PairList p;
    nbs.detect(e, {}, p);
    const Grid& g = *nbs.last_grid();
    EXPECT_EQ(nbs.book_bytes(), sizeof(std::int32_t) * static_cast<std::size_t>(g.n[1] + 2 * g.n[0] + 2 * e.size()))
        << testdata::layout_name(layout);
  }
}

TEST(Nbs, CellSizeIsTheLargestDiameterAndOriginTheMinimumCorner) {
  const Elements e = make_elements_2d((Eigen::ArrayXd(3) << -4, 2, 7.5).finished(), (Eigen::ArrayXd(3) << 1, -3, 0).finished(),
                                      (Eigen::ArrayXd(3) << 0.5, 1.25, 0.1).finished());
  NbsDetector nbs;
  PairList p;
  nbs.detect(e, {}, p);
  const Grid& g = *nbs.last_grid();
  EXPECT_DOUBLE_EQ(g.cell_size, 2.5);
  EXPECT_DOUBLE_EQ(g.origin[0], -4);
  EXPECT_DOUBLE_EQ(g.origin[1], -3);
  EXPECT_EQ(g.n[0], 5);  // Int(11.5 / 2.5) + 1
  EXPECT_EQ(g.n[1], 2);  // Int(4 / 2.5) + 1
}

TEST(Nbs, ExactlyTouchingCirclesAreInContact) {
  // Centres 1 apart with r = 0.5 touch; the diagonal (sqrt 2 apart) does not.
  const Elements e = make_elements_2d((Eigen::ArrayXd(3) << 0, 1, 1).finished(), (Eigen::ArrayXd(3) << 0, 0, 1).finished(),
                                      Eigen::ArrayXd::Constant(3, 0.5));
  NbsDetector nbs;
  EXPECT_EQ(sorted_detect(nbs, e), (PairList{{0, 1}, {1, 2}}));
}

TEST(Nbs, ListsAreBuiltByPushingAtTheHeadAndOnlyTouchedHeadsAreCleared) {
  const Elements e = testdata::make_layout(Layout::Dense, 400, 2, 9);
  NbsDetector nbs;
  PairList p;
  TraceLog log;
  nbs.detect_traced(e, {}, p, log);
  const Grid g = *nbs.last_grid();
  ASSERT_EQ(log.arrays().size(), 4u);
  EXPECT_EQ(log.arrays()[0].name, "y_heads");
  // Replay only the y-list pushes: every row list holds its elements in reverse push order.
  std::map<std::int32_t, std::vector<ElementId>> rows;
  std::size_t y_pushes = 0, pushes = 0, clears = 0;
  std::size_t after_y = 0;
  for (std::size_t i = 0; i < log.events().size(); ++i) {
    const TraceEvent& ev = log.events()[i];
    if (ev.op == TraceOp::Push) ++pushes;
    if (ev.op == TraceOp::Clear) ++clears;
    if (ev.op == TraceOp::Push && std::string(ev.label) == "y-list") {
      ++y_pushes;
      rows[ev.index].insert(rows[ev.index].begin(), ev.element);
      after_y = i + 1;
    }
  }
  EXPECT_EQ(y_pushes, static_cast<std::size_t>(e.size()));
  const auto state = log.state_after(after_y);
  for (const auto& [iy, members] : rows) {
    std::vector<ElementId> walked;
    for (std::int32_t k = state[0][iy]; k != -1; k = state[1][k]) walked.push_back(k);
    EXPECT_EQ(walked, members) << "row " << iy;
    for (ElementId k : members) EXPECT_EQ(g.cell(e.y[k], 1), iy);
  }
  // Clearing touches at most what was pushed, and leaves every head at -1.
  EXPECT_LE(clears, pushes);
  const auto final_state = log.state_after(log.events().size());
  for (std::int32_t h : final_state[0]) EXPECT_EQ(h, -1);
  for (std::int32_t h : final_state[2]) EXPECT_EQ(h, -1);
}

TEST(Nbs, PinnedOriginInsideTheDataAndLargerCellsStayCorrect) {
  const Elements e = testdata::make_layout(Layout::Dense, 2000, 2, 3);
  BruteDetector brute;
  NbsDetector nbs;
  const PairList ref = sorted_detect(brute, e);
  DetectOptions o;
  o.grid.origin = std::array<double, 3>{e.x.mean(), e.y.mean(), 0};
  EXPECT_EQ(sorted_detect(nbs, e, o), ref);
  o.grid.cell_size = 3.7;
  EXPECT_EQ(sorted_detect(nbs, e, o), ref);
}

TEST(Nbs, RefusesACellSmallerThanTheLargestDiameter) {
  const Elements e = testdata::make_layout(Layout::Loose, 50, 2, 3);
  NbsDetector nbs;
  DetectOptions o;
  o.grid.cell_size = 0.5;
  PairList p;
  EXPECT_THROW(nbs.detect(e, o, p), Error);
  o.grid.cell_size = -1;
  EXPECT_THROW(nbs.detect(e, o, p), Error);
}

TEST(Nbs, RefusesAGridWiderThanTheLimitInsteadOfAllocatingIt) {
  // Two specks 1e12 apart: 1e12 cells along x.
  const Elements e = make_elements_2d((Eigen::ArrayXd(2) << 0, 1e12).finished(), (Eigen::ArrayXd(2) << 0, 0).finished(),
                                      Eigen::ArrayXd::Constant(2, 0.5));
  NbsDetector nbs;
  PairList p;
  try {
    nbs.detect(e, {}, p);
    FAIL() << "expected an Error";
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("cell-size"), std::string::npos) << err.what();
  }
  DetectOptions o;
  o.grid.cell_size = 1e6;  // the suggested way out works
  nbs.detect(e, o, p);
  EXPECT_TRUE(p.empty());
}

TEST(Grid, ACellClearlyLargerThanTheDiameterIntegerisesExactlyAsTheBook) {
  // Fig. 3.15's grid: d = 1, elements of diameter 0.2. Int((x - 0)/1) exactly, borders included.
  const Elements e = make_elements_2d((Eigen::ArrayXd(2) << 5.0, 0.3).finished(), (Eigen::ArrayXd(2) << 7.0, 0.1).finished(),
                                      Eigen::ArrayXd::Constant(2, 0.1));
  GridOptions o;
  o.cell_size = 1.0;
  o.origin = std::array<double, 3>{0, 0, 0};
  const Grid g = make_grid(e, o);
  EXPECT_EQ(g.inv_cell_size, 1.0);
  EXPECT_EQ(g.cell(5.0, 0), 5);
  EXPECT_EQ(g.cell(7.0, 1), 7);
}

TEST(Grid, RoundingNeverPutsAContactTwoCellsApart) {
  // d is the diameter 0.6; elements 1 and 2 are 0.59999999999994 apart, a contact. With x - xmin
  // rounded, (x - xmin)/d put them two cells apart and every grid detector missed the pair.
  const Elements e = make_elements_2d((Eigen::ArrayXd(3) << -569.6134599278031, 189.38654007219682, 189.98654007219676).finished(),
                                      Eigen::ArrayXd::Zero(3), Eigen::ArrayXd::Constant(3, 0.3));
  ASSERT_TRUE(in_contact(e, 1, 2, Touching::inclusive));
  const Grid g = make_grid(e, {});
  EXPECT_EQ(g.cell_size, 0.6);  // d itself is the book's; only the integerisation is guarded
  EXPECT_LE(std::abs(g.cell(e.x[2], 0) - g.cell(e.x[1], 0)), 1);
  for (const DetectorInfo& info : detector_infos()) {
    PairList p;
    info.make()->detect(e, {}, p);
    EXPECT_EQ(p, (PairList{{1, 2}})) << info.name;
  }
}

TEST(Grid, IntegerisationIsTheBookFormulaClampedToTheGrid) {
  Grid g;
  g.cell_size = 2;
  g.inv_cell_size = 0.5;
  g.origin[0] = -1;
  g.n[0] = 4;
  EXPECT_EQ(g.cell(-1.0, 0), 0);
  EXPECT_EQ(g.cell(0.999, 0), 0);
  EXPECT_EQ(g.cell(1.0, 0), 1);
  EXPECT_EQ(g.cell(6.5, 0), 3);
  EXPECT_EQ(g.cell(1e300, 0), 3);   // beyond the grid: the last cell
  EXPECT_EQ(g.cell(-1e300, 0), 0);  // before the origin: the first cell
  EXPECT_EQ(g.cell(std::nan(""), 0), 0);
}

}  // namespace
}  // namespace nbscope
