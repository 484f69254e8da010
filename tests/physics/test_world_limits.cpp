// The contact estimate's counter (physics/world_limits.hpp) against a loop over all pairs, on
// random boxes with many exact ties (touching boxes overlap, as b2TestOverlap says), bodies of
// several fixtures and non-dynamic bodies; and the digits grouped in messages. The memory budget,
// Box2D's floats and its allocations have their own files (test_memory_budget.cpp,
// test_world_checks.cpp, test_box2d_memory.cpp).
#include <gtest/gtest.h>

#include <random>

#include "physics/world_limits.hpp"

namespace nbscope {
namespace {

std::int64_t count_by_loop(const std::vector<CountBox>& boxes) {
  std::int64_t n = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const CountBox &a = boxes[i], &b = boxes[j];
      if (a.body == b.body || (!a.dynamic && !b.dynamic)) continue;
      if (a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1) ++n;
    }
  return n;
}

TEST(ContactEstimate, CountsWhatALoopOverAllPairsCounts) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + static_cast<int>(rng() % 300);
    const int span = 2 + static_cast<int>(rng() % 40);  // small integer grids: many shared edges
    std::uniform_int_distribution<int> at(0, span), size(0, 4);
    std::vector<CountBox> boxes;
    std::int32_t body = 0;
    while (static_cast<int>(boxes.size()) < n) {
      const int fixtures = 1 + static_cast<int>(rng() % 3);
      const bool dynamic = rng() % 4 != 0;
      for (int f = 0; f < fixtures; ++f) {
        const float x = static_cast<float>(at(rng)), y = static_cast<float>(at(rng));
        boxes.push_back({x, y, x + static_cast<float>(size(rng)), y + static_cast<float>(size(rng)), body, dynamic});
      }
      ++body;
    }
    ASSERT_EQ(count_overlapping_boxes(boxes), count_by_loop(boxes)) << "trial " << trial;
  }
}

TEST(ContactEstimate, EveryBoxOnOnePointPairsWithEveryOther) {
  std::vector<CountBox> boxes;
  for (std::int32_t b = 0; b < 1000; ++b) boxes.push_back({0, 0, 1, 1, b, true});
  EXPECT_EQ(count_overlapping_boxes(boxes), 1000 * 999 / 2);
  boxes.push_back({1, 1, 2, 2, 1000, false});  // touching at one corner: a pair with each
  EXPECT_EQ(count_overlapping_boxes(boxes), 1000 * 999 / 2 + 1000);
  boxes.push_back({1.5f, 1.5f, 3, 3, 1001, false});  // two static boxes never pair
  EXPECT_EQ(count_overlapping_boxes(boxes), 1000 * 999 / 2 + 1000);
}

TEST(ContactEstimate, GroupsDigits) {
  EXPECT_EQ(grouped(0), "0");
  EXPECT_EQ(grouped(999), "999");
  EXPECT_EQ(grouped(1000), "1,000");
  EXPECT_EQ(grouped(4498500), "4,498,500");
  EXPECT_EQ(grouped(-1234567), "-1,234,567");
}

}  // namespace
}  // namespace nbscope
