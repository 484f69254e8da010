// core/pair_scan: the checks of a plugin's pairs (range, order, the first repeat) against the plain
// sorting reference, on hand-made lists and on many random ones with and without repeats.
#include <gtest/gtest.h>

#include <random>

#include "core/pair_scan.hpp"

namespace nbscope {
namespace {

// scan_pairs' first repeat of a copy of `pairs`.
std::int64_t first_repeated_pair(PairList pairs, std::int64_t n, PairScanScratch& table) {
  return scan_pairs(pairs, n, table).first_repeat;
}

TEST(ScanPairs, OrdersEachGoodPairAndKeepsABadOneAsGiven) {
  PairScanScratch table;
  PairList pairs{{2, 1}, {0, 3}, {3, 3}, {-1, 2}, {4, 0}, {1, 2}};
  const PairScan scan = scan_pairs(pairs, 4, table);
  EXPECT_FALSE(scan.all_valid);
  EXPECT_EQ(pairs, (PairList{{1, 2}, {0, 3}, {3, 3}, {-1, 2}, {4, 0}, {1, 2}}));
  EXPECT_EQ(scan.first_repeat, 5);  // (2, 1) then (1, 2): the same pair, whichever way round
  PairList good{{3, 0}, {1, 2}, {2, 0}};
  const PairScan fine = scan_pairs(good, 4, table);
  EXPECT_TRUE(fine.all_valid);
  EXPECT_EQ(fine.first_repeat, -1);
  EXPECT_EQ(good, (PairList{{0, 3}, {1, 2}, {0, 2}}));
  PairList none;
  EXPECT_TRUE(scan_pairs(none, 0, table).all_valid);
  PairList lone{{0, 0}};
  EXPECT_FALSE(scan_pairs(lone, 1, table).all_valid);
}

TEST(ScanPairs, FindsTheFirstRepeatAnywhere) {
  PairScanScratch table;
  EXPECT_EQ(first_repeated_pair({{0, 1}, {0, 2}, {1, 2}}, 3, table), -1);
  EXPECT_EQ(first_repeated_pair({{1, 2}, {0, 1}, {0, 2}, {1, 2}}, 3, table), 3);
  EXPECT_EQ(first_repeated_pair({{3, 4}, {0, 1}, {3, 4}}, 5, table), 2);
  // After a larger call the scratch holds its leftovers: a smaller one must still see only its own pairs.
  EXPECT_EQ(first_repeated_pair({{0, 1}, {2, 3}, {4, 5}, {6, 7}, {1, 2}, {0, 7}}, 8, table), -1);
  EXPECT_EQ(first_repeated_pair({{1, 2}, {0, 1}, {0, 1}, {1, 2}}, 3, table), 2);  // the first pair given before
  EXPECT_EQ(first_repeated_pair({{0, 2}, {1, 2}}, 3, table), -1);
  // Thousands of pairs sharing elements, one repeat far from the pair it repeats.
  PairList many;
  for (std::int32_t i = 0; i < 60; ++i)
    for (std::int32_t j = i + 1; j < 60; ++j) many.push_back({i, j});
  for (const std::int64_t n : {std::int64_t{60}, std::int64_t{65535}, std::int64_t{65536}, std::int64_t{1} << 30})
    EXPECT_EQ(first_repeated_pair(many, n, table), -1) << n;
  many.push_back({1, 7});
  many.push_back({2, 3});
  for (const std::int64_t n : {std::int64_t{60}, std::int64_t{65535}, std::int64_t{65536}, std::int64_t{1} << 30})
    EXPECT_EQ(first_repeated_pair(many, n, table), static_cast<std::int64_t>(many.size()) - 2) << n;
  // Keys at the top of the 16-bit range, and past 2^31 elements' worth of n.
  EXPECT_EQ(first_repeated_pair({{65533, 65534}, {0, 65534}, {65533, 65534}}, 65535, table), 2);
  EXPECT_EQ(first_repeated_pair({{65533, 65534}, {65532, 65534}, {0, 1}}, 65535, table), -1);
  EXPECT_EQ(first_repeated_pair_sorted(many), static_cast<std::int64_t>(many.size()) - 2);
  many.pop_back();
  many.pop_back();
  EXPECT_EQ(first_repeated_pair_sorted(many), -1);
  EXPECT_EQ(first_repeated_pair_sorted({{1, 2}, {0, 1}, {0, 1}, {1, 2}}), 2);
}


// The reference: the valid pairs ordered, then the first repeat among them by sorting.
PairScan reference_scan(const PairList& given, std::int64_t n) {
  PairScan scan;
  PairList valid;
  std::vector<std::int64_t> at;
  for (std::size_t k = 0; k < given.size(); ++k) {
    const Pair p = given[k];
    if (p.i < 0 || p.j < 0 || p.i >= n || p.j >= n || p.i == p.j) {
      scan.all_valid = false;
      continue;
    }
    valid.push_back({std::min(p.i, p.j), std::max(p.i, p.j)});
    at.push_back(static_cast<std::int64_t>(k));
  }
  const std::int64_t r = first_repeated_pair_sorted(valid);
  scan.first_repeat = r < 0 ? -1 : at[static_cast<std::size_t>(r)];
  return scan;
}

TEST(ScanPairs, AgreesWithSortingOnRandomLists) {
  std::mt19937 rng(2311);
  PairScanScratch scratch;  // one for all: each call must ignore what the last left
  int repeats_seen = 0;
  for (int round = 0; round < 3000; ++round) {
    // Few elements (many repeats), some, and past 65535 (the table's 64-bit keys).
    const std::int64_t most = round % 3 == 0 ? 12 : round % 3 == 1 ? 5000 : (std::int64_t{1} << 31) - 1;
    const std::int64_t n = std::uniform_int_distribution<std::int64_t>(1, most)(rng);
    const std::size_t count = std::uniform_int_distribution<std::size_t>(0, round % 50 == 0 ? 20000 : 300)(rng);
    std::uniform_int_distribution<std::int32_t> element(0, static_cast<std::int32_t>(n - 1));
    PairList given;
    for (std::size_t k = 0; k < count; ++k) given.push_back({element(rng), element(rng)});
    if (round % 4 == 1 && !given.empty()) {  // a repeat of a random earlier pair, either way round
      const Pair p = given[std::uniform_int_distribution<std::size_t>(0, given.size() - 1)(rng)];
      given.insert(given.begin() + static_cast<std::ptrdiff_t>(std::uniform_int_distribution<std::size_t>(0, given.size())(rng)),
                   round % 8 == 1 ? Pair{p.j, p.i} : p);
    }
    if (round % 7 == 3 && !given.empty()) given[given.size() / 2] = {-1 - round % 3, static_cast<std::int32_t>(n + round % 2)};
    const PairScan want = reference_scan(given, n);
    PairList pairs = given;
    const PairScan got = scan_pairs(pairs, n, scratch);
    ASSERT_EQ(got.all_valid, want.all_valid) << "round " << round;
    ASSERT_EQ(got.first_repeat, want.first_repeat) << "round " << round << ", n " << n << ", " << given.size() << " pairs";
    for (std::size_t k = 0; k < given.size(); ++k) {
      const Pair p = given[k];
      const bool valid = p.i >= 0 && p.j >= 0 && p.i < n && p.j < n && p.i != p.j;
      const Pair want_pair = valid ? Pair{std::min(p.i, p.j), std::max(p.i, p.j)} : p;
      ASSERT_EQ(pairs[k], want_pair) << "round " << round << ", pair " << k;
    }
    repeats_seen += want.first_repeat >= 0;
  }
  EXPECT_GT(repeats_seen, 500);  // both answers were asked for often
}

TEST(ScanPairs, DistinctPairsOfEveryElementHaveNoRepeat) {
  PairScanScratch scratch;
  for (const std::int32_t n : {2, 3, 64, 300}) {  // every pair of n elements: the filter fills up
    PairList all;
    for (std::int32_t i = 0; i < n; ++i)
      for (std::int32_t j = 0; j < i; ++j) all.push_back({i, j});
    PairList pairs = all;
    EXPECT_EQ(scan_pairs(pairs, n, scratch).first_repeat, -1) << n;
    pairs = all;
    pairs.push_back(all.front());
    EXPECT_EQ(scan_pairs(pairs, n, scratch).first_repeat, static_cast<std::int64_t>(all.size())) << n;
  }
}

TEST(ScanPairs, PairsThatAllCollideAreSortedAndStillExact) {
  // 64 pairs of 65535 elements whose keys (i * n + j) all hash to the first of the 128 slots a table
  // for 64 pairs has (Fibonacci hashing, the top 7 bits of key * 0x9E3779B1): probing would take
  // 64^2 / 2 steps, past the budget of 8 a pair, so the scan sorts instead.
  constexpr std::uint32_t n = 65535;
  PairList colliding;
  for (std::uint32_t i = 0; colliding.size() < 64; ++i)
    for (std::uint32_t j = i + 1; j < i + 200 && colliding.size() < 64; ++j)
      if (static_cast<std::uint32_t>((i * n + j) * 0x9E3779B1u) >> 25 == 0)
        colliding.push_back({static_cast<std::int32_t>(j), static_cast<std::int32_t>(i)});  // given as j, i
  PairScanScratch scratch;
  PairList pairs = colliding;
  PairScan scan = scan_pairs(pairs, n, scratch);
  EXPECT_TRUE(scan.sorted);
  EXPECT_TRUE(scan.all_valid);
  EXPECT_EQ(scan.first_repeat, -1);
  EXPECT_EQ(pairs[5], (Pair{colliding[5].j, colliding[5].i}));  // ordered on this path too
  pairs = colliding;
  pairs.insert(pairs.begin() + 40, colliding[17]);
  pairs.push_back({-3, 2});
  scan = scan_pairs(pairs, n, scratch);
  EXPECT_TRUE(scan.sorted);
  EXPECT_FALSE(scan.all_valid);
  EXPECT_EQ(scan.first_repeat, 40);
  EXPECT_EQ(pairs.back(), (Pair{-3, 2}));  // a bad pair kept as given
}

TEST(ScanPairs, EveryPairTwiceIsFoundAtTheFirstSecond) {
  PairScanScratch scratch;
  PairList pairs;
  for (std::int32_t i = 0; i < 2000; ++i) pairs.push_back({i, i + 1});
  for (std::int32_t i = 1999; i >= 0; --i) pairs.push_back({i + 1, i});
  const PairScan scan = scan_pairs(pairs, 2001, scratch);
  EXPECT_EQ(scan.first_repeat, 2000);
  EXPECT_FALSE(scan.sorted);
  EXPECT_EQ(pairs[3999], (Pair{0, 1}));  // the pairs after the first repeat are still ordered
}

}  // namespace
}  // namespace nbscope
