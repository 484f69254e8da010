// How LAMMPS split the box among ranks (subdomain_grid.hpp).
#include "core/subdomain_grid.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace nbscope {

namespace {

// Orders of the axes, fastest first, in the order ties are given: LAMMPS's `map cart` (z fastest)
// first, then its `processors ... map xyz` and the others.
constexpr std::array<std::array<int, 3>, 6> kOrders{{{2, 1, 0}, {0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}}};

// At most this many atoms are looked at: enough to tell the splits apart, cheap on a 1e6-atom frame.
constexpr std::int64_t kMaxSampled = 50'000;

int cell_index(const std::array<int, 3>& cell, const std::array<int, 3>& grid) { return cell[0] + grid[0] * (cell[1] + grid[1] * cell[2]); }

std::array<int, 3> cell_in(const std::array<int, 3>& grid, const std::array<int, 3>& order, int rank) {
  std::array<int, 3> cell{0, 0, 0};
  for (const int axis : order) {
    const auto a = static_cast<std::size_t>(axis);
    cell[a] = rank % grid[a];
    rank /= grid[a];
  }
  return cell;
}

}  // namespace

std::array<int, 3> Subdomains::cell_of(int rank) const { return cell_in(grid, order, rank); }

Bounds Subdomains::bounds_of(int rank) const {
  const std::array<int, 3> cell = cell_of(rank);
  Bounds b;
  for (std::size_t a = 0; a < 3; ++a) {
    const double step = (box.max[a] - box.min[a]) / grid[a];
    b.min[a] = box.min[a] + step * cell[a];
    b.max[a] = cell[a] + 1 == grid[a] ? box.max[a] : box.min[a] + step * (cell[a] + 1);
  }
  return b;
}

std::optional<Subdomains> infer_subdomains(const Elements& e, std::span<const std::int32_t> ranks, int rank_count, const Bounds& box) {
  const std::int64_t n = std::min<std::int64_t>(e.size(), static_cast<std::int64_t>(ranks.size()));
  if (rank_count < 2 || n == 0) return std::nullopt;
  const int axes = e.dim == 3 ? 3 : 2;
  const std::int64_t stride = std::max<std::int64_t>(1, n / kMaxSampled);
  std::optional<Subdomains> best;
  std::int64_t best_inside = -1, looked = 0;
  std::vector<std::int64_t> counts;  // [rank][cell]: atoms of the rank in the cell
  for (int px = 1; px <= rank_count; ++px) {
    if (rank_count % px != 0) continue;
    for (int py = 1; py <= rank_count / px; ++py) {
      if ((rank_count / px) % py != 0) continue;
      const std::array<int, 3> grid{px, py, rank_count / px / py};
      bool possible = true;  // an axis split only when it has one to split (not z in 2D, nor a box of zero extent)
      for (int a = 0; a < 3; ++a)
        if (grid[static_cast<std::size_t>(a)] > 1 && (a >= axes || !(box.max[a] > box.min[a]))) possible = false;
      if (!possible) continue;
      counts.assign(static_cast<std::size_t>(rank_count) * static_cast<std::size_t>(rank_count), 0);
      looked = 0;
      for (std::int64_t k = 0; k < n; k += stride) {
        const std::int32_t r = ranks[static_cast<std::size_t>(k)];
        if (r < 0 || r >= rank_count) continue;
        std::array<int, 3> cell{0, 0, 0};
        for (int a = 0; a < axes; ++a) {
          const int g = grid[static_cast<std::size_t>(a)];
          const double t = (e.axis(a)[k] - box.min[a]) / (box.max[a] - box.min[a]);
          cell[static_cast<std::size_t>(a)] = g == 1 ? 0 : std::clamp(static_cast<int>(std::floor(t * g)), 0, g - 1);
        }
        ++counts[static_cast<std::size_t>(r) * static_cast<std::size_t>(rank_count) + static_cast<std::size_t>(cell_index(cell, grid))];
        ++looked;
      }
      for (const std::array<int, 3>& order : kOrders) {
        std::int64_t inside = 0;
        for (int r = 0; r < rank_count; ++r)
          inside += counts[static_cast<std::size_t>(r) * static_cast<std::size_t>(rank_count) +
                           static_cast<std::size_t>(cell_index(cell_in(grid, order, r), grid))];
        if (inside <= best_inside) continue;
        best_inside = inside;
        best = Subdomains{grid, order, box, looked > 0 ? static_cast<double>(inside) / static_cast<double>(looked) : 0};
      }
    }
  }
  return best;
}

}  // namespace nbscope
