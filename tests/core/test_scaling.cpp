// Scaling runs: the runner measures one row per (detector, layout, N), skips brute force above its
// cap and says so, stops when cancelled; the sizes of a plan; the CSV written and read back, and
// bad CSVs refused with their line. No assertion on a timing value: speed lives in the benchmarks.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <tuple>

#include "core/error.hpp"
#include "core/scaling.hpp"
#include "core/threads.hpp"
#include "io/scaling_csv.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

// A plan that runs in milliseconds: tiny N, one timed run a point.
ScalingPlan quick_plan() {
  ScalingPlan plan;
  plan.algorithms = {"brute", "nbs", "sort"};
  plan.layouts = {Layout::Loose, Layout::Dense};
  plan.n_min = 100;
  plan.n_max = 1000;
  plan.points_per_decade = 2;
  plan.brute_max_n = 400;
  plan.min_seconds = 0;
  return plan;
}

TEST(Scaling, SizesSpanTheRangeOnALogScale) {
  const auto sizes = scaling_sizes(1000, 1'000'000, 2);
  ASSERT_EQ(sizes.size(), 7u);
  EXPECT_EQ(sizes.front(), 1000);
  EXPECT_EQ(sizes.back(), 1'000'000);
  for (std::size_t i = 1; i < sizes.size(); ++i) EXPECT_GT(sizes[i], sizes[i - 1]);
  EXPECT_EQ(scaling_sizes(1000, 4000, 1), (std::vector<std::int64_t>{1000, 4000}));  // the end is always in
  EXPECT_EQ(scaling_sizes(500, 500, 3), (std::vector<std::int64_t>{500}));
  EXPECT_TRUE(scaling_sizes(10, 5, 2).empty());
}

TEST(Scaling, OneRowPerDetectorLayoutAndSizeBruteSkippedAboveItsCap) {
  const ScalingPlan plan = quick_plan();
  std::size_t calls = 0, last_done = 0, total = 0;
  const ScalingResult result = run_scaling(
      plan,
      [&](const ScalingProgress& p) {
        ++calls;
        EXPECT_EQ(p.done, last_done + 1);
        last_done = p.done;
        total = p.total;
      },
      nullptr);
  const auto sizes = scaling_sizes(plan.n_min, plan.n_max, plan.points_per_decade);
  EXPECT_EQ(total, scaling_point_count(plan));
  EXPECT_EQ(calls, total);
  EXPECT_FALSE(result.cancelled);
  std::set<std::tuple<std::string, std::string, std::int64_t>> expected, got;
  std::size_t skipped = 0;
  for (const std::string& a : plan.algorithms)
    for (Layout l : plan.layouts)
      for (std::int64_t n : sizes) {
        if (a == "brute" && n > plan.brute_max_n) {
          ++skipped;
          continue;
        }
        expected.emplace(a, layout_name(l), n);
      }
  for (const ScalingRow& r : result.rows) {
    EXPECT_TRUE(got.emplace(r.algorithm, r.layout, r.n).second) << r.algorithm << " " << r.layout << " " << r.n << " twice";
    EXPECT_GE(r.repeats, 1);
    EXPECT_GT(r.ns_per_element, 0);
    // The pairs are the layout's contacts, whichever detector found them.
    EXPECT_EQ(r.pairs, static_cast<std::int64_t>(testdata::brute_pairs(make_layout(*parse_layout(r.layout), r.n, 2, plan.seed)).size()));
  }
  EXPECT_EQ(got, expected);
  ASSERT_GT(skipped, 0u);
  ASSERT_EQ(result.notes.size(), skipped);
  for (const std::string& note : result.notes) EXPECT_NE(note.find("brute"), std::string::npos) << note;
}

// A detector whose run at the next N would pass max_run_seconds (projected from its last run) is
// skipped there and the note says why: here every run is "too long" after the first size.
TEST(Scaling, BytesPerElementOfAPointDoNotDependOnWhatRanBeforeIt) {
  // Dense at N=1000 measured alone, and after a loose run up to N=1e5: the same bytes per element
  // (a detector kept across points reported the capacity of the bigger run before, 4,063 B/el for
  // 17.4 alone).
  ScalingPlan alone;
  alone.algorithms = {"nbs", "screen", "sort"};
  alone.layouts = {Layout::Dense};
  alone.n_min = alone.n_max = 1000;
  alone.min_seconds = alone.max_seconds = 0;
  ScalingPlan after = alone;
  after.layouts = {Layout::Loose, Layout::Dense};
  after.n_max = 100'000;
  after.points_per_decade = 1;
  const ScalingResult a = run_scaling(alone, {}, nullptr);
  const ScalingResult b = run_scaling(after, {}, nullptr);
  for (const ScalingRow& first : a.rows) {
    SCOPED_TRACE(first.algorithm);
    const auto same = std::find_if(b.rows.begin(), b.rows.end(), [&](const ScalingRow& r) {
      return r.algorithm == first.algorithm && r.layout == first.layout && r.n == first.n;
    });
    ASSERT_NE(same, b.rows.end());
    EXPECT_GT(first.bytes_per_element, 0);
    EXPECT_EQ(same->bytes_per_element, first.bytes_per_element);
  }
  EXPECT_EQ(a.rows.size(), 3u);
}

TEST(Scaling, APointThatWouldRunTooLongIsSkipped) {
  ScalingPlan plan = quick_plan();
  plan.algorithms = {"nbs"};
  plan.layouts = {Layout::Loose};
  plan.max_run_seconds = 1e-12;
  const ScalingResult result = run_scaling(plan, nullptr, nullptr);
  const auto sizes = scaling_sizes(plan.n_min, plan.n_max, plan.points_per_decade);
  ASSERT_EQ(result.rows.size(), 1u);
  EXPECT_EQ(result.rows[0].n, sizes.front());
  ASSERT_EQ(result.notes.size(), sizes.size() - 1);
  EXPECT_NE(result.notes[0].find("would take over"), std::string::npos) << result.notes[0];
}

// A plan that starts above the pilot size projects even its first point, from one run at 10,000
// (box2d at 1e6 would otherwise run for a minute before anything could stop it).
TEST(Scaling, AFirstPointPastThePilotSizeIsProjectedToo) {
  ScalingPlan plan = quick_plan();
  plan.algorithms = {"nbs"};
  plan.layouts = {Layout::Loose};
  plan.n_min = plan.n_max = 200'000;
  plan.max_run_seconds = 1e-12;
  const ScalingResult result = run_scaling(plan, nullptr, nullptr);
  EXPECT_TRUE(result.rows.empty());
  ASSERT_EQ(result.notes.size(), 1u);
  EXPECT_NE(result.notes[0].find("one run at N=10000"), std::string::npos) << result.notes[0];
}

TEST(Scaling, CancelStopsTheRun) {
  ScalingPlan plan = quick_plan();
  std::atomic<bool> cancel{false};
  std::size_t calls = 0;
  const ScalingResult result = run_scaling(
      plan,
      [&](const ScalingProgress&) {
        if (++calls == 2) cancel = true;
      },
      &cancel);
  EXPECT_TRUE(result.cancelled);
  EXPECT_EQ(calls, 2u);
  EXPECT_LT(result.rows.size(), scaling_point_count(plan));

  cancel = true;  // cancelled before it starts: nothing measured
  const ScalingResult none = run_scaling(plan, nullptr, &cancel);
  EXPECT_TRUE(none.cancelled);
  EXPECT_TRUE(none.rows.empty());
}

TEST(Scaling, APlanThatCannotRunIsRefused) {
  ScalingPlan plan = quick_plan();
  plan.algorithms = {"nosuch"};
  EXPECT_THROW(check_scaling_plan(plan), Error);
  plan = quick_plan();
  plan.layouts = {Layout::OnePoint};  // N^2/2 contacts
  EXPECT_THROW(check_scaling_plan(plan), Error);
  plan = quick_plan();
  plan.layouts.clear();
  EXPECT_THROW(run_scaling(plan, nullptr, nullptr), Error);
}

TEST(Scaling, PlanCoveringRowsNamesWhatTheyMeasure) {
  const std::vector<ScalingRow> rows = {{"sort", "dense", 1000, 1, 1, 1, 1}, {"nbs", "dense", 10000, 1, 1, 1, 1, 4},
                                        {"sort", "loose", 100000, 1, 1, 1, 1}, {"nbs", "loose", 1000, 1, 1, 1, 1}};
  const ScalingPlan plan = plan_covering(rows);
  EXPECT_EQ(plan.algorithms, (std::vector<std::string>{"sort", "nbs"}));
  EXPECT_EQ(plan.layouts, (std::vector<Layout>{Layout::Dense, Layout::Loose}));
  EXPECT_EQ(plan.n_min, 1000);
  EXPECT_EQ(plan.n_max, 100000);
  EXPECT_EQ(plan.points_per_decade, 1);
  EXPECT_EQ(plan.threads, (std::vector<int>{1, 4}));
}

// --threads N compares 1 and N: nbs (the detector that uses threads) is measured at both, every
// other detector once, on one thread; the rows say which, and the pairs agree whatever the threads.
TEST(Scaling, NbsIsMeasuredAtEachThreadCountTheOthersOnce) {
  EXPECT_EQ(scaling_threads(1), (std::vector<int>{1}));
  EXPECT_EQ(scaling_threads(2), (std::vector<int>{1, 2}));
  EXPECT_EQ(series_name("nbs", 1), "nbs");
  EXPECT_EQ(series_name("nbs", 2), "nbs x2");
  ScalingPlan plan = quick_plan();
  plan.algorithms = {"sort", "nbs", "brute"};
  plan.layouts = {Layout::Loose};
  plan.threads = scaling_threads(2);
  EXPECT_EQ(threads_measured(plan, "nbs"), (std::vector<int>{1, 2}));
  EXPECT_EQ(threads_measured(plan, "sort"), (std::vector<int>{1}));
  std::vector<std::string> points;
  const ScalingResult result = run_scaling(plan, [&](const ScalingProgress& p) { points.push_back(p.point); }, nullptr);
  const auto sizes = scaling_sizes(plan.n_min, plan.n_max, plan.points_per_decade);
  EXPECT_EQ(points.size(), scaling_point_count(plan));
  EXPECT_EQ(scaling_point_count(plan), 4 * sizes.size());  // sort, nbs, nbs x2, brute
  std::set<std::tuple<std::string, int, std::int64_t>> got, expected;
  for (std::int64_t n : sizes) {
    expected.emplace("sort", 1, n);
    expected.emplace("nbs", 1, n);
    expected.emplace("nbs", 2, n);
    if (n <= plan.brute_max_n) expected.emplace("brute", 1, n);
  }
  for (const ScalingRow& r : result.rows) {
    EXPECT_TRUE(got.emplace(r.algorithm, r.threads, r.n).second) << series_name(r.algorithm, r.threads) << " N=" << r.n << " twice";
    const auto sort = std::find_if(result.rows.begin(), result.rows.end(),
                                   [&](const ScalingRow& s) { return s.algorithm == "sort" && s.n == r.n; });
    ASSERT_NE(sort, result.rows.end());
    EXPECT_EQ(r.pairs, sort->pairs) << series_name(r.algorithm, r.threads) << " N=" << r.n;
  }
  EXPECT_EQ(got, expected);
  // In plan order: at each N, sort, then nbs on 1 and 2 threads, then brute.
  ASSERT_GE(result.rows.size(), 3u);
  EXPECT_EQ(series_name(result.rows[1].algorithm, result.rows[1].threads), "nbs");
  EXPECT_EQ(series_name(result.rows[2].algorithm, result.rows[2].threads), "nbs x2");
  EXPECT_NE(std::find(points.begin(), points.end(), "nbs x2 loose N=100"), points.end());
}

TEST(Scaling, APlanOfBadThreadCountsIsRefused) {
  for (const std::vector<int>& threads : {std::vector<int>{}, {0}, {1, kMaxThreads + 1}, {2, 2}}) {
    ScalingPlan plan = quick_plan();
    plan.threads = threads;
    EXPECT_THROW(check_scaling_plan(plan), Error) << threads.size();
  }
}

TEST(ScalingCsv, RoundTrip) {
  ScalingPlan plan = quick_plan();
  plan.threads = {1, 2};  // the threads column too
  const ScalingResult result = run_scaling(plan, nullptr, nullptr);
  std::ostringstream out;
  write_scaling_csv(out, result.rows);
  EXPECT_EQ(out.str().substr(0, out.str().find('\n')), kScalingCsvHeader);
  EXPECT_EQ(parse_scaling_csv(out.str(), "mem"), result.rows);  // every number exactly
}

// A CSV written before the threads column reads as it did, every row on one thread.
TEST(ScalingCsv, TheHeaderWithoutThreadsReadsAsOneThread) {
  const auto rows = parse_scaling_csv(std::string(kScalingCsvHeaderOneThread) + "\nnbs,loose,1000,20.5,8.4,90,10\n", "old.csv");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].threads, 1);
  EXPECT_EQ(rows[0].repeats, 10);
}

// The message of parsing `text` as a scaling CSV called "s.csv" ("" when it parses).
std::string error_of(const std::string& text) {
  try {
    parse_scaling_csv(text, "s.csv");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ScalingCsv, BadRowsAreRefusedWithTheirLine) {
  const std::string h = std::string(kScalingCsvHeader) + "\n";
  const std::string good = "nbs,loose,1000,20.5,8.4,90,10,1\n";
  EXPECT_EQ(error_of("# made by hand\n" + h + good), "");
  EXPECT_EQ(error_of(h + good + "nbs,loose,1000,12.5,8.4,90,10,2\n"), "");  // nbs and nbs x2: two series
  EXPECT_EQ(error_of("x,y,r\n1,2,3\n").rfind("s.csv:1: expected the header", 0), 0u) << error_of("x,y,r\n");
  EXPECT_EQ(error_of(h).rfind("s.csv: no rows", 0), 0u);
  EXPECT_EQ(error_of("").rfind("s.csv: no header", 0), 0u);
  const std::pair<std::string, std::string> cases[] = {
      {"nbs,loose,1000,20.5,8.4,90,10\n", "s.csv:3: 7 columns; expected 8"},
      {"nosuch,loose,1000,20.5,8.4,90,10,1\n", "s.csv:3: algorithm: 'nosuch'"},
      {"nbs,fluffy,1000,20.5,8.4,90,10,1\n", "s.csv:3: layout: 'fluffy'"},
      {"nbs,loose,0,20.5,8.4,90,10,1\n", "s.csv:3: n: 0 is less than 1"},
      {"nbs,loose,1e3,20.5,8.4,90,10,1\n", "s.csv:3: n: '1e3' is not a whole number"},
      {"nbs,loose,1000,-1,8.4,90,10,1\n", "s.csv:3: ns_per_element: -1 is negative"},
      {"nbs,loose,1000,nan,8.4,90,10,1\n", "s.csv:3: ns_per_element: 'nan' is not a finite number"},
      {"nbs,loose,1000,20.5,x,90,10,1\n", "s.csv:3: bytes_per_element: 'x' is not a number"},
      {"nbs,loose,1000,20.5,8.4,-2,10,1\n", "s.csv:3: pairs: -2 is less than 0"},
      {"nbs,loose,1000,20.5,8.4,90,0,1\n", "s.csv:3: repeats: 0 is less than 1"},
      {"nbs,loose,1000,20.5,8.4,90,10,0\n", "s.csv:3: threads: 0 is less than 1"},
      {"nbs,loose,1000,20.5,8.4,90,10,65\n", "s.csv:3: threads: 65 is more than 64"},
      {"nbs,loose,1000,20.5,8.4,90,10,two\n", "s.csv:3: threads: 'two' is not a whole number"},
  };
  for (const auto& [row, message] : cases) {
    const std::string e = error_of("\n" + h + row);
    EXPECT_EQ(e.rfind(message, 0), 0u) << "got: " << e << "\nexpected: " << message;
  }
  const std::string twice = error_of(h + good + good);
  EXPECT_EQ(twice.rfind("s.csv:3: nbs loose N=1000 is given twice", 0), 0u) << twice;
  const std::string twice2 = error_of(h + "nbs,loose,1000,12.5,8.4,90,10,2\n" + "nbs,loose,1000,12.5,8.4,90,10,2\n");
  EXPECT_EQ(twice2.rfind("s.csv:3: nbs x2 loose N=1000 is given twice", 0), 0u) << twice2;
}

}  // namespace
}  // namespace nbscope
