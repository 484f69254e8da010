// Periodic frames (Elements::box): nbs and brute find contacts across the boundary by the minimum
// image, checked against a minimum-image brute force written here independently; the grid on a
// periodic axis; wrap_into_box, contact_gap and the hash; the refusals of every other detector.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "core/brute.hpp"
#include "core/detector.hpp"
#include "core/error.hpp"
#include "core/locate.hpp"
#include "core/nbs.hpp"
#include "physics/box2d_detector.hpp"

namespace nbscope {
namespace {

const bool kPhysicsDetectorsRegistered = (register_physics_detectors(), true);

// The reference: every pair, each axis difference folded by rounding to the nearest period (not
// the detectors' one-step fold), inclusive or strict.
PairList periodic_reference(const Elements& e, bool inclusive) {
  PairList out;
  for (ElementId i = 0; i < e.size(); ++i) {
    for (ElementId j = i + 1; j < e.size(); ++j) {
      double d2 = 0;
      for (int a = 0; a < e.dim; ++a) {
        double d = e.axis(a)[i] - e.axis(a)[j];
        if (e.box.periodic[a]) d -= e.box.length(a) * std::nearbyint(d / e.box.length(a));
        d2 += d * d;
      }
      const double rr = e.r[i] + e.r[j];
      if (inclusive ? d2 <= rr * rr : d2 < rr * rr) out.push_back({i, j});
    }
  }
  return out;
}

// Pairs that only the wrap finds: in the reference but not in contact in open space.
std::size_t across_boundary(const Elements& e, const PairList& ref) {
  Elements open = e;
  open.box = PeriodicBox{};
  std::size_t count = 0;
  for (const Pair& p : ref) count += in_contact(open, p.i, p.j, Touching::inclusive) ? 0 : 1;
  return count;
}

// A random set in a box [lo, lo + L) with the given periodic axes, radii up to r_max, L = cells * 2 r_max
// on every axis; some centres on the boundary (x == lo, just below hi).
Elements random_periodic(int dim, const bool periodic[3], int cells, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double r_max = 0.05 + 0.2 * unit(rng);
  const double d = 2 * r_max;
  Elements e;
  e.dim = dim;
  for (int a = 0; a < dim; ++a) {
    e.box.periodic[a] = periodic[a];
    e.box.lo[a] = -5.0 + 10.0 * unit(rng);
    e.box.hi[a] = e.box.lo[a] + cells * d + (seed % 3 == 0 ? 0.0 : 0.9 * d * unit(rng));
  }
  const int n = 40 + static_cast<int>(rng() % 120);
  for (int k = 0; k < n; ++k) {
    double c[3] = {0, 0, 0};
    for (int a = 0; a < dim; ++a) {
      c[a] = e.box.lo[a] + (e.box.hi[a] - e.box.lo[a]) * unit(rng);
      const auto edge = rng() % 8;  // a quarter of the centres on or next to a boundary
      if (edge == 0) c[a] = e.box.lo[a];
      if (edge == 1) c[a] = std::nextafter(e.box.hi[a], -HUGE_VAL);
      if (c[a] >= e.box.hi[a]) c[a] = e.box.lo[a];
    }
    // The largest a hair below r_max: L is then at least `cells` cells of the largest diameter even
    // when integerisation widens them by a few ulps (grid.hpp).
    e.push_back(c[0], c[1], c[2], r_max * (k == 0 ? 0.999 : 0.3 + 0.69 * unit(rng)));
  }
  return e;
}

// nbs (fast entry, book, traced) and brute on `e` against the reference.
void expect_wraps(const Elements& e, const std::string& what) {
  const PairList ref = periodic_reference(e, true);
  DetectOptions options;
  for (const char* name : {"nbs", "brute"}) {
    PairList pairs;
    make_detector(name)->detect(e, options, pairs);
    sort_pairs(pairs);
    EXPECT_EQ(pairs, ref) << name << " " << what;
  }
  NbsDetector nbs;
  PairList book, traced;
  TraceLog trace;
  nbs.detect_book(e, options, book);
  nbs.detect_traced(e, options, traced, trace);
  sort_pairs(book);
  sort_pairs(traced);
  EXPECT_EQ(book, ref) << "nbs book " << what;
  EXPECT_EQ(traced, ref) << "nbs traced " << what;
}

TEST(Periodic, NbsAndBruteMatchTheMinimumImageOnRandomSets) {
  std::size_t wrapped = 0;
  for (int dim : {2, 3}) {
    for (int mask = 1; mask < (1 << dim); ++mask) {  // every non-empty set of periodic axes, the rest open
      const bool periodic[3] = {(mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0};
      for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        const int cells = 3 + static_cast<int>(seed % 5);
        const Elements e = random_periodic(dim, periodic, cells, seed * 131 + static_cast<std::uint64_t>(mask));
        expect_wraps(e, std::to_string(dim) + "D axes " + std::to_string(mask) + " seed " + std::to_string(seed));
        wrapped += across_boundary(e, periodic_reference(e, true));
      }
    }
  }
  EXPECT_GT(wrapped, 100u);  // the sets do put contacts across the boundary
}

TEST(Periodic, ElementsOnTheBoundaryAndSpanningIt) {
  for (int dim : {2, 3}) {
    Elements e;
    e.dim = dim;
    for (int a = 0; a < dim; ++a) {
      e.box.periodic[a] = true;
      e.box.lo[a] = -1.0;
      e.box.hi[a] = 2.0;  // L = 3: 3 cells (d = 0.75 a few ulps wider, the last cell 1.5 wide)
    }
    const double below_hi = std::nextafter(2.0, 0.0);
    const double r = 0.375;
    e.push_back(-1.0, 0.5, 0.5, r);      // 0: on lo
    e.push_back(below_hi, 0.5, 0.5, r);  // 1: just below hi, a hair from 0 across the boundary
    e.push_back(1.8, 0.5, 0.5, r);       // 2: spans hi: reaches 2.175 = -0.825, overlapping 0
    e.push_back(0.5, -1.0, 0.5, r);      // 3: on lo in y
    e.push_back(0.5, 1.25, 0.5, r);      // 4: touching 3 exactly across y: -1 + 3 - 1.25 = 0.75 = r + r
    e.push_back(below_hi, below_hi, dim == 3 ? below_hi : 0.0, r);  // 5: the far corner, next to 0's images
    const PairList ref = periodic_reference(e, true);
    EXPECT_TRUE(std::binary_search(ref.begin(), ref.end(), Pair{0, 1}));
    EXPECT_TRUE(std::binary_search(ref.begin(), ref.end(), Pair{0, 2}));
    EXPECT_TRUE(std::binary_search(ref.begin(), ref.end(), Pair{3, 4}));
    expect_wraps(e, std::to_string(dim) + "D boundary");
  }
}

TEST(Periodic, ExactlyThreeCellsAndTheRefusalOfTwo) {
  Elements e;
  e.box.periodic[0] = true;
  e.box.hi[0] = 0.012;  // 3 cells of 0.004
  e.push_back(0.0, 0.0, 0, 0.0019);
  e.push_back(0.0105, 0.0, 0, 0.0019);  // 0.0015 from 0 across x = 0
  e.push_back(0.006, 0.0, 0, 0.0019);
  DetectOptions options;
  options.grid.cell_size = 0.004;
  EXPECT_EQ(make_grid(e, options.grid).n[0], 3);
  PairList pairs;
  make_detector("nbs")->detect(e, options, pairs);
  EXPECT_EQ(pairs, (PairList{{0, 1}}));
  NbsDetector book;
  book.detect_book(e, options, pairs);
  EXPECT_EQ(pairs, (PairList{{0, 1}}));

  e.box.hi[0] = 0.01;
  e.x[1] = 0.0085;
  for (const char* name : {"nbs"}) {
    try {
      make_detector(name)->detect(e, options, pairs);
      ADD_FAILURE() << name << " accepted 2 cells on a periodic axis";
    } catch (const Error& err) {
      EXPECT_EQ(std::string(err.what()),
                "x is periodic over L = 0.01 with cell size 0.004: 2 cells; the wrap needs at least 3 (a cell's left and "
                "right neighbour would be the same cell)");
    }
  }
  // brute has no cells: two images of one period are still one pair, by the minimum image.
  make_detector("brute")->detect(e, {}, pairs);
  EXPECT_EQ(pairs.size(), periodic_reference(e, true).size());
}

TEST(Periodic, GridSpansTheBoxAndRefusesPinsThatDisagree) {
  Elements e;
  e.box.periodic[1] = true;
  e.box.lo[1] = 1.0;
  e.box.hi[1] = 2.05;  // 10 cells of 0.1, the last 0.15 wide
  e.push_back(5.0, 1.5, 0, 0.05);
  e.push_back(5.2, 2.0, 0, 0.05);
  const Grid g = make_grid(e, {});
  EXPECT_EQ(g.origin[1], 1.0);
  EXPECT_EQ(g.n[1], 10);
  EXPECT_EQ(g.cell(2.04, 1), 9);
  EXPECT_EQ(g.neighbour(0, -1, 1), 9);
  EXPECT_EQ(g.neighbour(9, 1, 1), 0);
  EXPECT_EQ(g.neighbour(0, -1, 0), -1);  // x is open
  GridOptions pinned;
  pinned.origin = std::array<double, 3>{5.0, 0.5, 0.0};
  EXPECT_THROW((void)make_grid(e, pinned), Error);
  pinned.origin = std::array<double, 3>{5.0, 1.0, 0.0};
  EXPECT_NO_THROW((void)make_grid(e, pinned));
  GridOptions cells;
  cells.cells = std::array<std::int64_t, 3>{4, 12, 1};
  EXPECT_THROW((void)make_grid(e, cells), Error);
  cells.cells = std::array<std::int64_t, 3>{4, 10, 1};
  EXPECT_NO_THROW((void)make_grid(e, cells));
  e.y[0] = 2.05;  // at hi: outside [lo, hi)
  EXPECT_THROW((void)make_grid(e, {}), Error);
  PairList pairs;
  EXPECT_THROW(make_detector("brute")->detect(e, {}, pairs), Error);
}

// A periodic frame with no elements yet (a dump's first frame, before the first insertion) has
// nothing to find, and a small box must not be refused for cells of the default size 1.
TEST(Periodic, AnEmptyFrameInASmallPeriodicBoxIsDetected) {
  for (const double period : {0.04, 0.3, 5.0}) {
    Elements e;
    e.dim = 3;
    e.box.periodic[0] = e.box.periodic[1] = true;
    e.box.hi[0] = e.box.hi[1] = period;
    const Grid g = make_grid(e, {});
    EXPECT_GE(g.n[0], 3) << period;
    PairList pairs;
    for (const char* name : {"nbs", "brute"}) {
      EXPECT_NO_THROW(make_detector(name)->detect(e, {}, pairs)) << name << " " << period;
      EXPECT_TRUE(pairs.empty());
    }
  }
}

TEST(Periodic, OtherDetectorsRefuseByName) {
  Elements e;
  e.box.periodic[0] = e.box.periodic[1] = true;
  e.box.hi[0] = e.box.hi[1] = 1.0;
  e.push_back(0.02, 0.1, 0, 0.05);
  e.push_back(0.97, 0.1, 0, 0.05);  // 0.05 from 0 across x = 0
  int refused = 0;
  for (const DetectorInfo& info : detector_infos()) {
    PairList pairs;
    if (info.periodic) {
      EXPECT_NO_THROW(info.make()->detect(e, {}, pairs)) << info.name;
      EXPECT_EQ(pairs, (PairList{{0, 1}})) << info.name;
      continue;
    }
    try {
      info.make()->detect(e, {}, pairs);
      ADD_FAILURE() << info.name << " accepted a periodic frame";
    } catch (const Error& err) {
      ++refused;
      EXPECT_EQ(std::string(err.what()),
                info.name + ": the frame is periodic in x, y; only nbs and brute find contacts across a periodic boundary");
    }
  }
  EXPECT_GE(refused, 4);  // tree, sort, screen, box2d
  // A 2D frame whose z is flagged periodic (as LAMMPS writes 2D runs) is open space for everyone.
  Elements flat;
  flat.box.periodic[2] = true;
  flat.box.hi[2] = 1.0;
  flat.push_back(0.02, 0.1, 0, 0.05);
  flat.push_back(0.09, 0.1, 0, 0.05);
  for (const DetectorInfo& info : detector_infos()) {
    PairList pairs;
    EXPECT_NO_THROW(info.make()->detect(flat, {}, pairs)) << info.name;
    EXPECT_EQ(pairs, (PairList{{0, 1}})) << info.name;
  }
  EXPECT_TRUE(detector_info("nbs").periodic);
  EXPECT_TRUE(detector_info("brute").periodic);
}

TEST(Periodic, TracedNbsVisitsTheWrappedCells) {
  Elements e;
  e.box.periodic[0] = e.box.periodic[1] = true;
  e.box.hi[0] = e.box.hi[1] = 1.0;  // 10 x 10 cells of 0.098, the last wider
  e.push_back(0.01, 0.01, 0, 0.049);  // cell (0, 0)
  e.push_back(0.98, 0.98, 0, 0.049);  // cell (9, 9): the diagonal neighbour across both boundaries
  NbsDetector nbs;
  PairList pairs;
  TraceLog trace;
  nbs.detect_traced(e, {}, pairs, trace);
  EXPECT_EQ(pairs, (PairList{{0, 1}}));
  bool visited = false, tested = false;
  for (const TraceEvent& ev : trace.events()) {
    visited = visited || (ev.op == TraceOp::VisitCell && ev.element == 0 && ev.cell[0] == 9 && ev.cell[1] == 9);
    tested = tested || (ev.op == TraceOp::TestPair && ev.contact);
  }
  EXPECT_TRUE(visited);
  EXPECT_TRUE(tested);
}

TEST(Periodic, LocateKnowsWrappedNeighbours) {
  // A trace where element 0 (cell (0, 0)) visits cell (9, 9) across both boundaries and tests nothing.
  std::vector<TraceEvent> events(1);
  events[0].op = TraceOp::VisitCell;
  events[0].element = 0;
  events[0].cell[0] = events[0].cell[1] = 9;
  PairCells cells;
  cells.i = {0, 0, -1};
  cells.j = {9, 9, -1};
  EXPECT_NE(locate_pair(events, 0, 1, cells, 2).finding, PairFinding::CellVisited);  // open: not neighbours
  cells.wrap = {10, 10, 0};
  const PairLocation at = locate_pair(events, 0, 1, cells, 2);
  EXPECT_EQ(at.finding, PairFinding::CellVisited);
  EXPECT_EQ(at.scanner, 0);
  cells.j = {5, 9, -1};  // not a neighbour even wrapped
  EXPECT_EQ(locate_pair(events, 0, 1, cells, 2).finding, PairFinding::NotInTrace);
}

TEST(Periodic, WrapIntoBox) {
  Elements e;
  e.dim = 3;
  e.box.periodic[0] = e.box.periodic[2] = true;
  e.box.lo[0] = -1.0;
  e.box.hi[0] = 3.0;
  e.box.lo[2] = 0.0;
  e.box.hi[2] = 0.5;
  e.push_back(3.0, 7.0, 0.5, 1.0);       // exactly hi -> lo; y is open: left alone
  e.push_back(-1.0, -9.0, 0.25, 1.0);    // exactly lo: stays
  e.push_back(41.5, 0.0, -10.125, 1.0);  // ten periods over in x; z 20.25 periods under
  e.push_back(-5.5, 0.0, 0.49, 1.0);     // one period under
  wrap_into_box(e);
  EXPECT_EQ(e.x[0], -1.0);
  EXPECT_EQ(e.y[0], 7.0);
  EXPECT_EQ(e.z[0], 0.0);
  EXPECT_EQ(e.x[1], -1.0);
  EXPECT_EQ(e.y[1], -9.0);
  EXPECT_EQ(e.x[2], 1.5);
  EXPECT_EQ(e.z[2], 0.375);
  EXPECT_EQ(e.x[3], 2.5);
  EXPECT_EQ(e.z[3], 0.49);
}

TEST(Periodic, GapHashAndAxesName) {
  Elements e;
  e.box.periodic[0] = true;
  e.box.hi[0] = 10.0;
  e.push_back(0.5, 0.0, 0, 1.0);
  e.push_back(9.0, 0.0, 0, 0.5);
  EXPECT_NEAR(contact_gap(e, 0, 1), 1.5 - 1.5, 1e-12);  // 1.5 apart across x = 0
  EXPECT_TRUE(in_contact(e, 0, 1, Touching::inclusive));
  EXPECT_EQ(periodic_axes(e), "x");
  Elements open = e;
  open.box = PeriodicBox{};
  EXPECT_NEAR(contact_gap(open, 0, 1), 8.5 - 1.5, 1e-12);
  EXPECT_EQ(periodic_axes(open), "");
  EXPECT_NE(hash_elements(e), hash_elements(open));
  Elements longer = e;
  longer.box.hi[0] = 11.0;
  EXPECT_NE(hash_elements(e), hash_elements(longer));
}

}  // namespace
}  // namespace nbscope
