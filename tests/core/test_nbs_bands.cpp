// NbsDetector::detect() on threads (DetectOptions::threads, bands of rows in 2D and of layers in 3D)
// leaves exactly the arrays the book's serial loops leave (a fresh detector's detect_book()) and finds
// the same pairs in the same order: every generated layout, 2D and 3D, N 0..1e5, odd and even splits,
// bands of one row, one band, the pair limit, a periodic frame, and one detector reused throughout.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/nbs.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

using testdata::Layout;

#ifdef NBSCOPE_SANITIZED_BUILD
constexpr bool kSanitized = true;  // ASan or TSan: the sets stop at 1e3 (CI time), the release build runs them to 1e5
#else
constexpr bool kSanitized = false;
#endif

// The book's six arrays and the pairs of one detection, copied out of the detector.
struct BookState {
  static constexpr int kArrays = 6;
  std::vector<std::int32_t> arrays[kArrays];
  PairList pairs;
};
constexpr const char* kArrayNames[BookState::kArrays] = {"y_heads", "y_next", "x_heads", "x_next", "z_heads", "z_next"};

BookState capture(const NbsDetector& d, PairList pairs) {
  BookState s;
  s.arrays[0] = d.y_heads();
  s.arrays[1] = d.y_next();
  s.arrays[2] = d.x_heads();
  s.arrays[3] = d.x_next();
  s.arrays[4] = d.z_heads();
  s.arrays[5] = d.z_next();
  s.pairs = std::move(pairs);
  return s;
}

std::string pair_text(const Pair& p) { return "(" + std::to_string(p.i) + "," + std::to_string(p.j) + ")"; }

// "" when `got` and `want` hold the same arrays and the same pairs in the same order; otherwise the
// first difference, e.g. "x_next[17]: 4, book 9" or "pairs[3]: (1,2), book (1,5)".
std::string first_difference(const BookState& got, const BookState& want) {
  for (int a = 0; a < BookState::kArrays; ++a) {
    const auto& g = got.arrays[a];
    const auto& w = want.arrays[a];
    if (g == w) continue;
    const std::size_t common = std::min(g.size(), w.size());
    for (std::size_t k = 0; k < common; ++k)
      if (g[k] != w[k])
        return std::string(kArrayNames[a]) + "[" + std::to_string(k) + "]: " + std::to_string(g[k]) + ", book " +
               std::to_string(w[k]);
    if (g.size() != w.size())
      return std::string(kArrayNames[a]) + ": " + std::to_string(g.size()) + " entries, book " + std::to_string(w.size());
  }
  if (got.pairs == want.pairs) return "";
  const std::size_t common = std::min(got.pairs.size(), want.pairs.size());
  for (std::size_t k = 0; k < common; ++k)
    if (!(got.pairs[k] == want.pairs[k]))
      return "pairs[" + std::to_string(k) + "]: " + pair_text(got.pairs[k]) + ", book " + pair_text(want.pairs[k]);
  if (got.pairs.size() != want.pairs.size())
    return "pairs: " + std::to_string(got.pairs.size()) + ", book " + std::to_string(want.pairs.size());
  return "";
}

// The reference: a fresh detector's book loops.
BookState book_of(const Elements& e, const DetectOptions& o = {}) {
  NbsDetector d;
  PairList p;
  d.detect_book(e, o, p);
  return capture(d, std::move(p));
}

// Options that band even a handful of elements on `threads` threads.
DetectOptions banded(int threads) {
  DetectOptions o;
  o.threads = threads;
  o.min_band_elements = 1;
  return o;
}

BookState detect_on(NbsDetector& d, const Elements& e, const DetectOptions& o) {
  PairList p;
  d.detect(e, o, p);
  return capture(d, std::move(p));
}

// The lines (rows in 2D, layers in 3D) of the last detection's grid that hold elements: how many,
// and how many elements the lowest holds.
struct Lines {
  int occupied = 0;
  std::int64_t in_lowest = 0;
};

Lines occupied_lines(const NbsDetector& d, const Elements& e) {
  const int axis = e.dim - 1;
  std::vector<std::int64_t> count(static_cast<std::size_t>(d.last_grid()->n[axis]), 0);
  for (std::int64_t k = 0; k < e.size(); ++k) ++count[static_cast<std::size_t>(d.last_grid()->cell(e.axis(axis)[k], axis))];
  Lines lines;
  for (const std::int64_t c : count) {
    if (c == 0) continue;
    if (lines.occupied++ == 0) lines.in_lowest = c;
  }
  return lines;
}

// detect() on `threads` equals the book, and its band count is plausible: at most one per line
// and per thread, and (once bands have landed) more than one wherever the balanced split can cut:
// bands are balanced by elements and cut between lines, so a second band starts once the lowest
// line holds at most (T-1)/T of the elements (T the threads used, at most one per element).
void expect_banded_matches(NbsDetector& d, const Elements& e, int threads, const Lines& lines, const BookState& book,
                           const std::string& what) {
  const BookState got = detect_on(d, e, banded(threads));
  const std::string diff = first_difference(got, book);
  EXPECT_EQ(diff, "") << what << " threads " << threads;
  const std::string where = what + " threads " + std::to_string(threads) + ", lines " + std::to_string(lines.occupied);
  EXPECT_GE(d.last_bands(), 1) << where;
  EXPECT_LE(d.last_bands(), std::max(1, std::min(threads, lines.occupied))) << where;
  const std::int64_t used = std::min<std::int64_t>(threads, e.size());
  const bool can_cut = used > 1 && lines.occupied > 1 && e.size() * (used - 1) / used >= lines.in_lowest;
  if (can_cut) {
    EXPECT_GT(d.last_bands(), 1) << where;
  }
}

TEST(NbsBands, DetectRunsOnMoreThanOneBand) {
  // Two full rows of 32 and two threads: one band each (a regression to serial fails here).
  Elements e;
  for (int k = 0; k < 64; ++k) e.push_back(0.5 + (k % 8), 0.5 + 7.0 * (k / 32), 0, 0.4);
  NbsDetector d;
  PairList p;
  d.detect(e, banded(2), p);
  EXPECT_EQ(d.last_bands(), 2);
}

class NbsBands : public ::testing::TestWithParam<std::tuple<Layout, int>> {};

TEST_P(NbsBands, EqualTheBooksArraysAndPairsOnEveryThreadCount) {
  const auto [layout, dim] = GetParam();
  // Every pair of a pile is in contact: past 1000 the pairs would pass the pair limit. Unequal
  // radii (3D cells of the largest diameter hold dozens) and cell borders (magnitudes to 1e9) cost
  // five times the others per element: 1e4 keeps the file's time small.
  const bool pile = layout == Layout::OneCell || layout == Layout::OnePoint;
  const bool costly = layout == Layout::UnequalRadii || layout == Layout::CellBorders;
  const std::int64_t largest = kSanitized ? 1'000 : costly ? 10'000 : 100'000;
  for (const std::int64_t n : {0, 1, 2, 3, 5, 17, 100, 1000, 10'000, 100'000}) {
    if (n > largest || (pile && n > 1000)) continue;
    const Elements e = testdata::make_layout(layout, n, dim, 7);
    const std::string what = testdata::layout_name(layout) + " " + std::to_string(dim) + "D N=" + std::to_string(n);
    NbsDetector reference;
    PairList reference_pairs;
    reference.detect_book(e, {}, reference_pairs);
    const Lines lines = n > 0 ? occupied_lines(reference, e) : Lines{};
    const BookState book = capture(reference, std::move(reference_pairs));
    for (const int threads : {2, 3, 4, 7, 64}) {
      NbsDetector d;
      expect_banded_matches(d, e, threads, lines, book, what);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryLayout, NbsBands,
                         ::testing::Combine(::testing::ValuesIn(testdata::all_layouts()), ::testing::Values(2, 3)),
                         [](const auto& info) {
                           return testdata::layout_name(std::get<0>(info.param)) + "_" + std::to_string(std::get<1>(info.param)) + "d";
                         });

// Lines (rows in 2D, layers in 3D) holding 1, 50, 3, 200, 0, 7, 40, 1, 120 elements, shuffled: the
// balanced split falls inside and between lines of very different weight.
Elements unequal_lines(int dim) {
  const int counts[] = {1, 50, 3, 200, 0, 7, 40, 1, 120};
  Elements e;
  e.dim = dim;
  std::uint64_t h = 12345;
  auto next = [&h] { return (h = h * 6364136223846793005ULL + 1442695040888963407ULL) >> 33; };
  std::vector<std::array<double, 3>> centres;
  for (int line = 0; line < 9; ++line) {
    for (int k = 0; k < counts[line]; ++k) {
      const double across = 0.5 + static_cast<double>(next() % 4000) / 1000.0;  // 0.5..4.5: five cells
      const double along = 0.2 + static_cast<double>(next() % 600) / 1000.0;    // inside the line's cells
      if (dim == 2) centres.push_back({across, line + along, 0});
      else centres.push_back({across, 0.5 + static_cast<double>(next() % 3000) / 1000.0, line + along});
    }
  }
  for (std::size_t k = centres.size(); k > 1; --k) std::swap(centres[k - 1], centres[next() % k]);
  for (const auto& c : centres) e.push_back(c[0], c[1], c[2], 0.3);
  return e;
}

TEST(NbsBandsSplit, OddAndEvenSplitsOfUnequallyFilledLines) {
  for (int dim : {2, 3}) {
    const Elements e = unequal_lines(dim);
    DetectOptions pinned;
    pinned.grid.cell_size = 1.0;
    pinned.grid.origin = std::array<double, 3>{0, 0, 0};
    for (const bool pin : {false, true}) {
      const DetectOptions ref = pin ? pinned : DetectOptions{};
      const BookState book = book_of(e, ref);
      ASSERT_FALSE(book.pairs.empty());
      for (const int threads : {2, 3, 4}) {
        NbsDetector d;
        DetectOptions o = banded(threads);
        o.grid = ref.grid;
        EXPECT_EQ(first_difference(detect_on(d, e, o), book), "") << dim << "D threads " << threads << (pin ? " pinned" : "");
        EXPECT_GT(d.last_bands(), 1) << dim << "D threads " << threads;
      }
    }
  }
}

TEST(NbsBandsSplit, ElementsAllInOneLineMakeOneBand) {
  for (int dim : {2, 3}) {
    Elements e = testdata::make_layout(Layout::Dense, 3000, dim, 4);
    (dim == 2 ? e.y : e.z).setConstant(1.25);  // one row (2D), one layer (3D)
    const BookState book = book_of(e);
    for (const int threads : {2, 4, 64}) {
      NbsDetector d;
      EXPECT_EQ(first_difference(detect_on(d, e, banded(threads)), book), "") << dim << "D threads " << threads;
      EXPECT_EQ(d.last_bands(), 1) << dim << "D threads " << threads;
    }
  }
}

TEST(NbsBandsSplit, ThePairLimitThrowsTheSerialMessageAndTheNextDetectionIsExact) {
  for (int dim : {2, 3}) {
    // A pile in one cell (19,900 pairs) beside loose elements, so the limit is passed in one band.
    Elements e = testdata::make_layout(Layout::Loose, 4000, dim, 3);
    const Elements pile = testdata::make_layout(Layout::OnePoint, 200, dim, 1);
    for (std::int64_t k = 0; k < pile.size(); ++k) e.push_back(pile.x[k], pile.y[k], dim == 3 ? pile.z[k] : 0, pile.r[k]);
    DetectOptions serial;
    serial.max_pairs = 1000;
    std::string serial_message;
    try {
      NbsDetector book;
      PairList p;
      book.detect_book(e, serial, p);
    } catch (const Error& error) {
      serial_message = error.what();
    }
    ASSERT_FALSE(serial_message.empty()) << dim << "D: the book's loops did not stop at the limit";
    const Elements next = testdata::make_layout(Layout::Dense, 2000, dim, 2);
    const BookState book = book_of(next);
    for (const int threads : {2, 3, 7}) {
      NbsDetector d;
      DetectOptions o = banded(threads);
      o.max_pairs = serial.max_pairs;
      PairList p;
      try {
        d.detect(e, o, p);
        ADD_FAILURE() << dim << "D threads " << threads << ": no Error past the pair limit";
      } catch (const Error& error) {
        EXPECT_EQ(std::string(error.what()), serial_message) << dim << "D threads " << threads;
      }
      EXPECT_EQ(first_difference(detect_on(d, next, banded(threads)), book), "") << dim << "D threads " << threads << " after the limit";
    }
  }
}

TEST(NbsBandsSplit, APeriodicFrameRunsTheBooksLoopsOnOneBand) {
  for (int dim : {2, 3}) {
    Elements e = testdata::make_layout(Layout::Dense, 2000, dim, 9);
    const Bounds b = e.centre_bounds();
    for (int a = 0; a < dim; ++a) {
      e.box.periodic[a] = true;
      e.box.lo[a] = b.min[a];
      e.box.hi[a] = b.max[a] + 0.5 * e.max_radius();  // every centre in [lo, hi)
    }
    const BookState book = book_of(e);
    ASSERT_FALSE(book.pairs.empty());
    for (const int threads : {2, 4}) {
      NbsDetector d;
      EXPECT_EQ(first_difference(detect_on(d, e, banded(threads)), book), "") << dim << "D threads " << threads;
      EXPECT_EQ(d.last_bands(), 1) << dim << "D threads " << threads;
    }
  }
}

TEST(NbsBandsSplit, OneDetectorReusedAcrossSizesAndThreadCountsKeepsNoScratch) {
  struct Call {
    Layout layout;
    std::int64_t n;
    int dim;
    int threads;
  };
  const Call calls[] = {
      {Layout::Loose, 5000, 2, 4},  {Layout::Dense, 300, 2, 2},      {Layout::Clustered, 2000, 3, 7},
      {Layout::Loose, 0, 2, 3},     {Layout::OnePoint, 100, 3, 64},  {Layout::Dense, 8000, 2, 1},
      {Layout::Loose, 5000, 2, 3},  {Layout::Touching, 900, 3, 2},   {Layout::UnequalRadii, 40, 2, 64},
      {Layout::Dense, 6000, 3, 4},  {Layout::Loose, 17, 3, 7},       {Layout::Dense, 6000, 3, 2},
  };
  NbsDetector d;
  int k = 0;
  for (const Call& c : calls) {
    const Elements e = testdata::make_layout(c.layout, c.n, c.dim, 20 + static_cast<std::uint64_t>(k));
    const std::string what = "call " + std::to_string(k) + ": " + testdata::layout_name(c.layout) + " " +
                             std::to_string(c.dim) + "D N=" + std::to_string(c.n) + " threads " + std::to_string(c.threads);
    EXPECT_EQ(first_difference(detect_on(d, e, banded(c.threads)), book_of(e)), "") << what;
    if (k % 4 == 3) {
      // The book's loops on the same detector in between: the two paths share the arrays.
      PairList p;
      d.detect_book(e, {}, p);
    }
    ++k;
  }
}

TEST(NbsBandsCompare, TheComparisonReportsEveryInjectedFault) {
  for (int dim : {2, 3}) {
    const Elements e = testdata::make_layout(Layout::Dense, 500, dim, 5);
    const BookState book = book_of(e);
    ASSERT_GE(book.pairs.size(), 3u);
    EXPECT_EQ(first_difference(book, book), "");

    BookState swapped = book;  // two pairs in the wrong order: the same set, not the same order
    std::swap(swapped.pairs[1], swapped.pairs[2]);
    EXPECT_EQ(first_difference(swapped, book).rfind("pairs[1]: ", 0), 0u) << first_difference(swapped, book);

    BookState dropped = book;
    dropped.pairs.pop_back();
    EXPECT_EQ(first_difference(dropped, book).rfind("pairs: ", 0), 0u) << first_difference(dropped, book);

    for (int a = 0; a < BookState::kArrays; ++a) {
      if (book.arrays[a].empty()) continue;  // z arrays in 2D
      BookState changed = book;
      const std::size_t at = changed.arrays[a].size() / 2;
      changed.arrays[a][at] += 1;
      EXPECT_EQ(first_difference(changed, book), std::string(kArrayNames[a]) + "[" + std::to_string(at) + "]: " +
                                                      std::to_string(book.arrays[a][at] + 1) + ", book " +
                                                      std::to_string(book.arrays[a][at]));
      BookState shorter = book;
      shorter.arrays[a].pop_back();
      EXPECT_EQ(first_difference(shorter, book).rfind(std::string(kArrayNames[a]) + ": ", 0), 0u);
    }
    EXPECT_TRUE(book.arrays[4].empty() == (dim == 2)) << "z arrays exist in 3D only";
  }
}

}  // namespace
}  // namespace nbscope
