// The AABB-pair grid (physics/aabb_pairs.hpp), G's finder, against a loop over all pairs tested with
// b2TestOverlap, on random boxes with exact ties and on the odd cases.
#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "physics/aabb_pairs.hpp"

namespace nbscope {
namespace {

// Every pair i < j of `boxes` that b2TestOverlap calls overlapping: all pairs looked at.
PairList all_overlapping(const std::vector<b2AABB>& boxes) {
  PairList out;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      if (b2TestOverlap(boxes[i], boxes[j])) out.push_back({static_cast<ElementId>(i), static_cast<ElementId>(j)});
  return out;
}

b2AABB box(float x0, float y0, float x1, float y1) {
  b2AABB b;
  b.lowerBound.Set(x0, y0);
  b.upperBound.Set(x1, y1);
  return b;
}

// On random boxes (lattice ties, points, long walls, duplicates) the grid finds exactly the pairs
// b2TestOverlap accepts among all pairs.
TEST(AabbPairFinder, EqualsEveryPairTestedOnRandomBoxes) {
  AabbPairFinder finder;
  PairList found;
  for (std::uint32_t seed = 0; seed < 60; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-20, 20), size(0, 1.5f), unit(0, 1);
    const std::size_t n = 1 + seed * 7 % 400;
    std::vector<b2AABB> boxes;
    for (std::size_t k = 0; k < n; ++k) {
      const float u = unit(rng);
      if (u < 0.3f) {
        // On an integer lattice: unit boxes that touch exactly, edge to edge and corner to corner.
        const float x = std::round(pos(rng) / 4), y = std::round(pos(rng) / 4);
        boxes.push_back(box(x, y, x + 1, y + 1));
      } else if (u < 0.35f) {
        const float x = pos(rng), y = pos(rng);
        boxes.push_back(box(x, y, x, y));  // a point
      } else if (u < 0.38f) {
        const float x = pos(rng), y = pos(rng);
        boxes.push_back(box(x - 15 * size(rng), y, x + 15 * size(rng), y + 0.5f));  // a long wall
      } else if (u < 0.40f && !boxes.empty()) {
        boxes.push_back(boxes[static_cast<std::size_t>(rng()) % boxes.size()]);  // a duplicate
      } else {
        const float x = pos(rng), y = pos(rng);
        boxes.push_back(box(x, y, x + size(rng), y + size(rng)));
      }
    }
    finder.find(boxes.data(), boxes.size(), found);
    ASSERT_EQ(found, all_overlapping(boxes)) << "seed " << seed;
  }
}

// No boxes, touching corners, equal points, NaN, infinite, inverted and far boxes: the loop's pairs.
TEST(AabbPairFinder, HandlesTheOddCases) {
  AabbPairFinder finder;
  PairList found;
  finder.find(nullptr, 0, found);
  EXPECT_TRUE(found.empty());
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const std::vector<std::vector<b2AABB>> cases = {
      {box(0, 0, 1, 1)},
      {box(0, 0, 1, 1), box(1, 1, 2, 2)},                      // corners touching
      {box(0, 0, 0, 0), box(0, 0, 0, 0), box(0, 0, 0, 0)},     // three equal points
      {box(0, 0, 1, 1), box(nan, 0, 1, 1), box(5, 5, 6, 6)},   // b2TestOverlap calls a NaN box overlapping
      {box(0, 0, 1, 1), box(-inf, -1, inf, 0.5f), box(3, 3, 4, 4)},
      {box(0, 0, 1, 1), box(2, 2, 1.5f, 3), box(1.2f, 2.5f, 3, 4)},  // an inverted box
      {box(-1e30f, -1e30f, -1e30f, -1e30f), box(0, 0, 1, 1), box(1e30f, 1e30f, 1e30f, 1e30f), box(0.5f, 0.5f, 2, 2)},
      {box(-1e6f, 0, -1e6f + 0.5f, 0.5f), box(-1e6f + 0.5f, 0.5f, -1e6f + 1, 1), box(1e6f, 0, 1e6f + 1, 1)},
  };
  for (std::size_t c = 0; c < cases.size(); ++c) {
    finder.find(cases[c].data(), cases[c].size(), found);
    EXPECT_EQ(found, all_overlapping(cases[c])) << "case " << c;
  }
}

}  // namespace
}  // namespace nbscope
