// NbsDetector's two paths: detect() (the fast path, nbs_fast.cpp) leaves exactly the arrays the
// book's loops leave (detect_book(), and detect_traced() which the stepper and dump show) and finds
// the same pairs in the same order, on every generated family in 2D and 3D, derived and pinned grids.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "core/nbs.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

using testdata::Layout;

// A detector and the pairs of its last detection.
struct Outcome {
  NbsDetector detector;
  PairList pairs;
};

enum class Path { Fast, Book, Traced };

void detect_into(Outcome& out, Path path, const Elements& e, const DetectOptions& o = {}) {
  if (path == Path::Fast) {
    out.detector.detect(e, o, out.pairs);
  } else if (path == Path::Book) {
    out.detector.detect_book(e, o, out.pairs);
  } else {
    TraceLog log;
    out.detector.detect_traced(e, o, out.pairs, log);
  }
}

// Every book array and the pairs (in order) of two runs are equal.
void expect_same(const Outcome& fast, const Outcome& book, const std::string& what) {
  EXPECT_EQ(fast.detector.y_heads(), book.detector.y_heads()) << what;
  EXPECT_EQ(fast.detector.y_next(), book.detector.y_next()) << what;
  EXPECT_EQ(fast.detector.x_heads(), book.detector.x_heads()) << what;
  EXPECT_EQ(fast.detector.x_next(), book.detector.x_next()) << what;
  EXPECT_EQ(fast.detector.z_heads(), book.detector.z_heads()) << what;
  EXPECT_EQ(fast.detector.z_next(), book.detector.z_next()) << what;
  EXPECT_EQ(fast.pairs, book.pairs) << what;
}

class NbsFastPath : public ::testing::TestWithParam<std::tuple<Layout, int>> {};

TEST_P(NbsFastPath, LeavesTheBooksArraysAndPairsInTheBooksOrder) {
  const auto [layout, dim] = GetParam();
  // Every pair of a pile is tested (and traced): keep those sets small.
  const std::int64_t many = layout == Layout::OneCell || layout == Layout::OnePoint ? 500 : 2500;
  for (const std::int64_t n : {std::int64_t{0}, std::int64_t{1}, std::int64_t{2}, std::int64_t{7}, std::int64_t{300}, many}) {
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
      const Elements e = testdata::make_layout(layout, n, dim, seed);
      const std::string what = testdata::layout_name(layout) + " " + std::to_string(dim) + "D N=" + std::to_string(n) +
                               " seed " + std::to_string(seed);
      Outcome fast, book, traced;
      detect_into(fast, Path::Fast, e);
      detect_into(book, Path::Book, e);
      detect_into(traced, Path::Traced, e);
      expect_same(fast, book, what + " (book)");
      expect_same(fast, traced, what + " (traced)");
      PairList sorted = fast.pairs;
      sort_pairs(sorted);
      EXPECT_EQ(sorted, testdata::brute_pairs(e)) << what;
      if (n > 0) {
        // Every head is -1 again, so the next detection starts clean.
        for (const auto* heads : {&fast.detector.y_heads(), &fast.detector.x_heads(), &fast.detector.z_heads()})
          for (std::int32_t h : *heads) ASSERT_EQ(h, -1) << what;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryFamily, NbsFastPath,
                         ::testing::Combine(::testing::ValuesIn(testdata::all_layouts()), ::testing::Values(2, 3)),
                         [](const auto& info) {
                           return testdata::layout_name(std::get<0>(info.param)) + "_" + std::to_string(std::get<1>(info.param)) + "d";
                         });

TEST(NbsFastPath, PinnedGridsWithCentresClampedIntoTheBorderCellsAgree) {
  // An origin inside the data and too few cells: many centres are clamped into border cells.
  for (int dim : {2, 3}) {
    const Elements e = testdata::make_layout(Layout::Dense, 1500, dim, 5);
    const Bounds b = e.centre_bounds();
    DetectOptions o;
    o.grid.cell_size = 2 * e.max_radius() * 1.5;
    o.grid.origin = std::array<double, 3>{(b.min[0] + b.max[0]) / 2, (b.min[1] + b.max[1]) / 2, (b.min[2] + b.max[2]) / 2};
    o.grid.cells = std::array<std::int64_t, 3>{4, 3, dim == 3 ? 2 : 1};
    Outcome fast, book;
    detect_into(fast, Path::Fast, e, o);
    detect_into(book, Path::Book, e, o);
    expect_same(fast, book, std::to_string(dim) + "D pinned");
  }
}

TEST(NbsFastPath, TheBooksNineElementsOnTheBooksGrid) {
  DetectOptions o;
  o.grid = testdata::book_grid();
  Outcome fast, traced;
  detect_into(fast, Path::Fast, testdata::book_nine(), o);
  detect_into(traced, Path::Traced, testdata::book_nine(), o);
  expect_same(fast, traced, "Fig. 3.15");
  EXPECT_FALSE(fast.pairs.empty());
}

TEST(NbsFastPath, OneDetectorAlternatingPathsAndDimensionsStaysExact) {
  // The fast path reuses its buffers and heads between calls, as a simulation would.
  Outcome fast;
  for (int round = 0; round < 3; ++round) {
    for (int dim : {2, 3, 2}) {
      const Elements e = testdata::make_layout(round == 1 ? Layout::Clustered : Layout::Loose, 800 + 100 * round, dim, 11 + round);
      detect_into(fast, Path::Fast, e);
      Outcome book;
      detect_into(book, Path::Book, e);
      expect_same(fast, book, "round " + std::to_string(round) + " " + std::to_string(dim) + "D");
    }
  }
}

TEST(NbsFastPath, APairLimitStopsItAndTheNextDetectionIsExact) {
  for (int dim : {2, 3}) {
    const Elements pile = testdata::make_layout(Layout::OnePoint, 200, dim, 1);  // 19,900 pairs
    NbsDetector nbs;
    PairList p;
    DetectOptions small;
    small.max_pairs = 1000;
    EXPECT_THROW(nbs.detect(pile, small, p), Error);
    const Elements e = testdata::make_layout(Layout::Dense, 900, dim, 2);
    nbs.detect(e, {}, p);
    sort_pairs(p);
    EXPECT_EQ(p, testdata::brute_pairs(e)) << dim << "D";
  }
}

TEST(NbsFastPath, ItsExtraMemoryIsLinearInNAndTheGridSide) {
  for (int dim : {2, 3}) {
    const Elements e = testdata::make_layout(Layout::Loose, 20000, dim, 3);
    NbsDetector nbs;
    PairList p;
    nbs.detect(e, {}, p);
    const Grid& g = *nbs.last_grid();
    // order (N) and the list offsets (ny or nz, + 1) beside the book's arrays, plus two row buffers.
    const std::size_t side = static_cast<std::size_t>(dim == 3 ? g.n[2] : g.n[1]) + 1;
    EXPECT_GE(nbs.own_bytes(), nbs.book_bytes() + sizeof(std::int32_t) * (20000 + side)) << dim;
    EXPECT_LT(nbs.own_bytes(), nbs.book_bytes() + sizeof(std::int32_t) * (20000 + side) + 20000 * 64u) << dim;
  }
}

}  // namespace
}  // namespace nbscope
