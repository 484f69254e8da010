// How LAMMPS split the box among ranks (core/subdomain_grid.hpp), found from each atom's rank: the
// grid and the rank order that put every atom in its rank's subdomain, for splits along one axis, two
// and three, each rank order, and the atoms a rank keeps a little outside its subdomain until the next
// reneighbouring. The atoms' ranks are assigned here from a grid of the test's own.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "core/subdomain_grid.hpp"

namespace nbscope {
namespace {

struct Split {
  Elements elements;
  std::vector<std::int32_t> ranks;
  Bounds box;
};

// Atoms scattered over `box`, each given the rank of the cell of grid `grid` it lies in, ranks
// numbered with axis `order[0]` fastest; `stray` of them then moved up to `skin` past their cell's edge.
Split scatter(std::array<int, 3> grid, std::array<int, 3> order, int dim, int n, int stray = 0, double skin = 0) {
  Split s;
  s.elements.dim = dim;
  for (int a = 0; a < 3; ++a) s.box.max[a] = a == 2 ? 20 : 10;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < n; ++k) {
    std::array<double, 3> p{};
    std::array<int, 3> cell{};
    for (std::size_t a = 0; a < 3; ++a) {
      p[a] = s.box.max[a] * u(rng);
      cell[a] = static_cast<int>(p[a] / s.box.max[a] * grid[a]);
    }
    int rank = 0;
    for (int k2 = 2; k2 >= 0; --k2) rank = rank * grid[static_cast<std::size_t>(order[static_cast<std::size_t>(k2)])] + cell[static_cast<std::size_t>(order[static_cast<std::size_t>(k2)])];
    if (k < stray) p[0] += skin;  // moved, its rank kept (LAMMPS migrates atoms at reneighbouring only)
    s.elements.push_back(p[0], p[1], dim == 3 ? p[2] : 0, 0.1);
    s.ranks.push_back(rank);
  }
  return s;
}

TEST(Subdomains, TheGridAndOrderThatHoldEachRanksAtoms) {
  struct Case {
    std::array<int, 3> grid, order;
    int dim;
  };
  for (const Case& c : {Case{{2, 1, 1}, {2, 1, 0}, 3}, Case{{2, 2, 1}, {2, 1, 0}, 3}, Case{{2, 2, 1}, {0, 1, 2}, 3},
                        Case{{1, 2, 2}, {2, 1, 0}, 3}, Case{{3, 2, 2}, {2, 1, 0}, 3}, Case{{2, 3, 1}, {0, 1, 2}, 2}, Case{{4, 1, 1}, {2, 1, 0}, 2}}) {
    const Split s = scatter(c.grid, c.order, c.dim, 3000);
    const auto found = infer_subdomains(s.elements, s.ranks, c.grid[0] * c.grid[1] * c.grid[2], s.box);
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(found->grid, c.grid) << c.grid[0] << "x" << c.grid[1] << "x" << c.grid[2];
    EXPECT_DOUBLE_EQ(found->contained, 1.0);
    for (std::size_t k = 0; k < s.ranks.size(); k += 97) {  // each atom inside its rank's subdomain
      const Bounds b = found->bounds_of(s.ranks[k]);
      EXPECT_GE(s.elements.x[static_cast<Eigen::Index>(k)], b.min[0]);
      EXPECT_LE(s.elements.x[static_cast<Eigen::Index>(k)], b.max[0]);
      EXPECT_GE(s.elements.y[static_cast<Eigen::Index>(k)], b.min[1]);
      EXPECT_LE(s.elements.y[static_cast<Eigen::Index>(k)], b.max[1]);
    }
  }
}

TEST(Subdomains, LammpsOrderRanksZFastestAndCutsTheBoxEvenly) {
  Subdomains s;
  s.grid = {2, 2, 1};
  for (int a = 0; a < 3; ++a) s.box.max[a] = 10;
  // map cart: z fastest, then y, then x: rank 1 is (0, 1), rank 2 (1, 0).
  EXPECT_EQ(s.cell_of(1), (std::array<int, 3>{0, 1, 0}));
  EXPECT_EQ(s.cell_of(2), (std::array<int, 3>{1, 0, 0}));
  const Bounds b = s.bounds_of(3);
  EXPECT_DOUBLE_EQ(b.min[0], 5);
  EXPECT_DOUBLE_EQ(b.max[0], 10);
  EXPECT_DOUBLE_EQ(b.min[1], 5);
}

TEST(Subdomains, AtomsAStepPastTheirSubdomainDoNotChangeTheSplit) {
  const Split s = scatter({2, 2, 1}, {2, 1, 0}, 3, 2000, 150, 0.4);
  const auto found = infer_subdomains(s.elements, s.ranks, 4, s.box);
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->grid, (std::array<int, 3>{2, 2, 1}));
  EXPECT_EQ(found->cell_of(1), (std::array<int, 3>{0, 1, 0}));
  EXPECT_LT(found->contained, 1.0);
  EXPECT_GT(found->contained, 0.95);
}

TEST(Subdomains, NoneWithoutRanksOrAtomsAndNoZSplitIn2D) {
  Split s = scatter({2, 1, 1}, {2, 1, 0}, 2, 100);
  EXPECT_FALSE(infer_subdomains(s.elements, s.ranks, 1, s.box).has_value());
  EXPECT_FALSE(infer_subdomains(Elements{}, {}, 2, s.box).has_value());
  const auto found = infer_subdomains(s.elements, s.ranks, 2, s.box);
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->grid[2], 1);
}

}  // namespace
}  // namespace nbscope
