// Every registered detector against brute force on the generated families (property tests).
#include <gtest/gtest.h>

#include "core/brute.hpp"
#include "core/detector.hpp"
#include "core/error.hpp"
#include "physics/box2d_detector.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

using testdata::Layout;

// "box2d" lives in physics; register it before the suites below read the registry.
const bool kPhysicsDetectorsRegistered = (register_physics_detectors(), true);

// Checks that `pairs` is exactly `ref` (sorted), each pair once with i < j.
::testing::AssertionResult same_as(const PairList& ref, PairList pairs) {
  for (const Pair& p : pairs)
    if (!(p.i < p.j)) return ::testing::AssertionFailure() << "pair (" << p.i << "," << p.j << ") is not i < j";
  sort_pairs(pairs);
  for (std::size_t k = 1; k < pairs.size(); ++k)
    if (pairs[k] == pairs[k - 1]) return ::testing::AssertionFailure() << "pair (" << pairs[k].i << "," << pairs[k].j << ") twice";
  const PairList missing = pairs_missing_from(ref, pairs);
  const PairList extra = pairs_missing_from(pairs, ref);
  if (missing.empty() && extra.empty()) return ::testing::AssertionSuccess();
  auto out = ::testing::AssertionFailure();
  out << missing.size() << " pairs missing, " << extra.size() << " extra (of " << ref.size() << ")";
  if (!missing.empty()) out << "; first missing (" << missing[0].i << "," << missing[0].j << ")";
  if (!extra.empty()) out << "; first extra (" << extra[0].i << "," << extra[0].j << ")";
  return out;
}

// Checks that `pairs` is exactly brute force's answer on `e`.
::testing::AssertionResult same_as_brute(const Elements& e, PairList pairs) { return same_as(testdata::brute_pairs(e), std::move(pairs)); }

struct Family {
  Layout layout;
  std::int64_t n;
  std::uint64_t seed;
};

#ifdef NBSCOPE_SANITIZED_BUILD
constexpr std::int64_t kLargestSet = 1500;  // brute force under ASan is ~20x slower
#else
constexpr std::int64_t kLargestSet = 5000;
#endif

// The generated sets: every layout at nine sizes from 0 to 5000, three seeds each (270 sets).
// Every element of one point or one cell touches every other, so those stop at 1000 (n(n-1)/2 pairs).
std::vector<Family> families() {
  std::vector<Family> out;
  for (Layout layout : testdata::all_layouts()) {
    const bool all_touch = layout == Layout::OnePoint || layout == Layout::OneCell;
    // Two distinct largest sizes whatever the cap (under the sanitizers kLargestSet is 1500).
    const std::int64_t biggest = std::min<std::int64_t>(all_touch ? 1000 : 5000, kLargestSet);
    const std::int64_t big = std::min<std::int64_t>(all_touch ? 800 : 2000, biggest * 2 / 3);
    for (std::int64_t n : {std::int64_t{0}, std::int64_t{1}, std::int64_t{2}, std::int64_t{3}, std::int64_t{17},
                           std::int64_t{100}, std::int64_t{640}, big, biggest}) {
      for (std::uint64_t seed = 1; seed <= 3; ++seed) out.push_back({layout, n, seed});
    }
  }
  return out;
}

// Every registered detector supporting `dim`, one instance each (reused across sets, as in a simulation).
std::vector<std::unique_ptr<Detector>> detectors_for(int dim) {
  std::vector<std::unique_ptr<Detector>> out;
  for (const DetectorInfo& info : detector_infos())
    if ((dim == 2 && info.dim2) || (dim == 3 && info.dim3)) out.push_back(info.make());
  return out;
}

// Runs every detector of `dim` on every generated set of `layout`; brute force runs once per set.
// Returns the number of sets checked.
int check_layout_against_brute(Layout layout, int dim, std::int64_t max_n) {
  auto detectors = detectors_for(dim);
  EXPECT_GE(detectors.size(), 2u);
  PairList pairs;
  int sets = 0;
  for (const Family& f : families()) {
    if (f.layout != layout || f.n > max_n) continue;
    const Elements e = testdata::make_layout(f.layout, f.n, dim, f.seed);
    const PairList ref = testdata::brute_pairs(e);
    for (auto& detector : detectors) {
      SCOPED_TRACE(std::string(detector->name()) + " " + testdata::layout_name(f.layout) + " " + std::to_string(dim) +
                   "D n=" + std::to_string(f.n) + " seed=" + std::to_string(f.seed));
      detector->detect(e, DetectOptions{}, pairs);
      EXPECT_TRUE(same_as(ref, pairs));
      if (::testing::Test::HasFailure()) return sets;
    }
    ++sets;
  }
  return sets;
}

class EveryLayout : public ::testing::TestWithParam<Layout> {};

TEST_P(EveryLayout, EveryDetectorMatchesBruteForceIn2D) {
  EXPECT_EQ(check_layout_against_brute(GetParam(), 2, kLargestSet), 27);  // 9 sizes x 3 seeds: 270 sets in all
}

TEST_P(EveryLayout, EveryDetectorMatchesBruteForceIn3D) {
  EXPECT_EQ(check_layout_against_brute(GetParam(), 3, kLargestSet), 27);  // the same 270 sets in 3D
}

TEST(Generators, EverySetOfAFamilyIsDistinct) {
  // Sets repeated under another seed or size would inflate the count without testing more.
  std::vector<std::pair<Layout, std::vector<double>>> seen;
  for (const Family& f : families()) {
    if (f.n < 2) continue;
    const Elements e = testdata::make_layout(f.layout, f.n, 2, f.seed);
    std::vector<double> key(e.x.data(), e.x.data() + e.size());
    key.insert(key.end(), e.y.data(), e.y.data() + e.size());
    key.insert(key.end(), e.r.data(), e.r.data() + e.size());
    for (const auto& [layout, other] : seen)
      EXPECT_FALSE(layout == f.layout && other == key) << testdata::layout_name(f.layout) << " n=" << f.n << " seed=" << f.seed;
    seen.emplace_back(f.layout, std::move(key));
  }
}

TEST(Generators, CellBordersHoldsContactsAsFarApartAsRoundingAllows) {
  // Each pair (1,2), (3,4), ...: in contact, and one ulp further apart it would not be.
  for (int dim : {2, 3})
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const Elements e = testdata::make_layout(Layout::CellBorders, 41, dim, seed);
      for (ElementId i = 1; i + 1 < 41; i += 2) {
        ASSERT_TRUE(in_contact(e, i, i + 1, Touching::inclusive)) << seed;
        Elements moved = e;
        for (int a = 0; a < dim; ++a) {
          Eigen::ArrayXd& col = a == 0 ? moved.x : (a == 1 ? moved.y : moved.z);
          if (col[i] != col[i + 1]) col[i + 1] = std::nextafter(col[i + 1], HUGE_VAL);
        }
        EXPECT_FALSE(in_contact(moved, i, i + 1, Touching::inclusive)) << seed;
      }
    }
}

INSTANTIATE_TEST_SUITE_P(Families, EveryLayout, ::testing::ValuesIn(testdata::all_layouts()),
                         [](const auto& info) { return testdata::layout_name(info.param); });

class EveryDetector : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryDetector, TracedRunFindsTheSamePairs) {
  auto detector = make_detector(GetParam());
  for (int dim : {2, 3}) {
    if (!detector->supports_dim(dim)) continue;
    for (Layout layout : testdata::all_layouts()) {
      const Elements e = testdata::make_layout(layout, 300, dim, 11);
      PairList plain, traced;
      TraceLog log;
      detector->detect(e, DetectOptions{}, plain);
      detector->detect_traced(e, DetectOptions{}, traced, log);
      sort_pairs(plain);
      sort_pairs(traced);
      EXPECT_EQ(plain, traced) << testdata::layout_name(layout) << " " << dim << "D";
      // Every contact the detector reports was tested in the trace (list-based detectors).
      std::size_t hits = 0;
      for (const TraceEvent& ev : log.events()) hits += ev.op == TraceOp::TestPair && ev.contact;
      if (hits > 0) {
        EXPECT_EQ(hits, traced.size());
      }
    }
  }
}

// The registry's declarations are true: a detector that says it traces records events, one that
// says it has lists pushes elements onto them (and one that says neither records neither), on a
// small random scene with contacts; its declared dimensions are the ones it supports.
TEST_P(EveryDetector, DeclaresWhatATracedRunRecords) {
  const DetectorInfo& info = detector_info(GetParam());
  auto detector = info.make();
  EXPECT_EQ(info.dim2, detector->supports_dim(2));
  EXPECT_EQ(info.dim3, detector->supports_dim(3));
  for (int dim : {2, 3}) {
    if (!detector->supports_dim(dim)) continue;
    const Elements e = testdata::make_layout(Layout::Dense, 60, dim, 7);
    PairList pairs;
    TraceLog log;
    detector->detect_traced(e, DetectOptions{}, pairs, log);
    ASSERT_FALSE(pairs.empty()) << dim << "D: the scene should have contacts";
    bool pushes = false;
    for (const TraceEvent& ev : log.events()) pushes = pushes || ev.op == TraceOp::Push;
    EXPECT_EQ(info.traces, !log.events().empty()) << dim << "D: declared traces = " << info.traces;
    EXPECT_EQ(info.has_lists, pushes) << dim << "D: declared has_lists = " << info.has_lists;
  }
}

TEST(Registry, UnknownNameIsAnError) { EXPECT_THROW(detector_info("no-such-algorithm"), Error); }

TEST_P(EveryDetector, StopsAtThePairLimit) {
  auto detector = make_detector(GetParam());
  const int dim = detector->supports_dim(2) ? 2 : 3;
  const Elements e = testdata::make_layout(Layout::OnePoint, 200, dim, 1);  // 19,900 pairs
  DetectOptions options;
  options.max_pairs = 1000;
  PairList pairs;
  EXPECT_THROW(detector->detect(e, options, pairs), Error);
  // And the detector is still usable afterwards (its arrays were left consistent).
  const Elements small = testdata::make_layout(Layout::Dense, 500, dim, 2);
  detector->detect(small, DetectOptions{}, pairs);
  EXPECT_TRUE(same_as_brute(small, pairs));
}

std::vector<std::string> registered_names() {
  std::vector<std::string> names;
  for (const DetectorInfo& d : detector_infos()) names.push_back(d.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryDetector, ::testing::ValuesIn(registered_names()),
                         [](const auto& info) { return info.param; });

// The comparison itself must be able to fail: a detector that drops one pair is caught.
TEST(BruteComparison, CatchesADroppedPair) {
  const Elements e = testdata::make_layout(Layout::Dense, 300, 2, 5);
  PairList pairs = testdata::brute_pairs(e);
  ASSERT_FALSE(pairs.empty());
  pairs.pop_back();
  EXPECT_FALSE(same_as_brute(e, pairs));
}

TEST(BruteComparison, CatchesADuplicateAndAnExtraPair) {
  const Elements e = testdata::make_layout(Layout::Loose, 300, 2, 5);
  PairList pairs = testdata::brute_pairs(e);
  ASSERT_FALSE(pairs.empty());
  PairList dup = pairs;
  dup.push_back(pairs.front());
  EXPECT_FALSE(same_as_brute(e, dup));
  PairList extra = pairs;
  extra.push_back({0, static_cast<ElementId>(e.size() - 1)});
  if (!in_contact(e, 0, static_cast<ElementId>(e.size() - 1), Touching::inclusive)) {
    EXPECT_FALSE(same_as_brute(e, extra));
  }
  PairList reversed = pairs;
  std::swap(reversed[0].i, reversed[0].j);
  EXPECT_FALSE(same_as_brute(e, reversed));
}

}  // namespace
}  // namespace nbscope
