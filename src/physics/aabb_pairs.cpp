#include "physics/aabb_pairs.hpp"

#include <algorithm>
#include <cmath>

namespace nbscope {

namespace {

// Boxes covering more cells than this are tested against every box instead of entering the grid.
constexpr std::int64_t kMaxCellsPerBox = 64;

bool finite_box(const b2AABB& b) {
  return std::isfinite(b.lowerBound.x) && std::isfinite(b.lowerBound.y) && std::isfinite(b.upperBound.x) &&
         std::isfinite(b.upperBound.y) && b.lowerBound.x <= b.upperBound.x && b.lowerBound.y <= b.upperBound.y;
}

// The grid's cell of one coordinate: monotone non-decreasing in v, clamped to [0, cells).
struct Axis {
  double origin = 0, inv = 1;
  std::int32_t cells = 1;
  [[nodiscard]] std::int32_t cell(float v) const {
    const double t = (static_cast<double>(v) - origin) * inv;
    if (!(t > 0)) return 0;
    if (t >= static_cast<double>(cells - 1)) return cells - 1;
    return static_cast<std::int32_t>(t);
  }
};

}  // namespace

void AabbPairFinder::find(const b2AABB* boxes, std::size_t n, PairList& out) {
  out.clear();
  if (n < 2) return;

  // The grid's extent, and the typical box's size (boxes far larger than the mean are left out of it).
  wide_.assign(n, 0);
  double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY, sum = 0;
  std::size_t finite = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const b2AABB& b = boxes[i];
    if (!finite_box(b)) {
      wide_[i] = 1;
      continue;
    }
    lo_x = std::min(lo_x, static_cast<double>(b.lowerBound.x));
    lo_y = std::min(lo_y, static_cast<double>(b.lowerBound.y));
    hi_x = std::max(hi_x, static_cast<double>(b.upperBound.x));
    hi_y = std::max(hi_y, static_cast<double>(b.upperBound.y));
    sum += std::max(static_cast<double>(b.upperBound.x) - b.lowerBound.x, static_cast<double>(b.upperBound.y) - b.lowerBound.y);
    ++finite;
  }
  Axis ax, ay;
  if (finite > 0) {
    const double mean = sum / static_cast<double>(finite);
    double h = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (wide_[i] != 0) continue;
      const b2AABB& b = boxes[i];
      const double e = std::max(static_cast<double>(b.upperBound.x) - b.lowerBound.x,
                                static_cast<double>(b.upperBound.y) - b.lowerBound.y);
      if (e <= 2 * mean) h = std::max(h, e);
    }
    const double w = hi_x - lo_x, hh = hi_y - lo_y;
    if (!(h > 0)) h = std::max(w, hh) / std::sqrt(static_cast<double>(finite));
    if (!(h > 0) || !std::isfinite(h)) h = 1;
    // O(N) cells at most: a few scattered boxes must not make a huge grid.
    const double max_cells = 2.0 * static_cast<double>(n) + 64;
    while ((std::floor(w / h) + 1) * (std::floor(hh / h) + 1) > max_cells) h *= 2;
    ax = {lo_x, 1 / h, static_cast<std::int32_t>(std::floor(w / h)) + 1};
    ay = {lo_y, 1 / h, static_cast<std::int32_t>(std::floor(hh / h)) + 1};
  }

  // Cell ranges, then the boxes of each cell (counting sort by cell; ids ascend within a cell).
  const std::size_t cells = static_cast<std::size_t>(ax.cells) * static_cast<std::size_t>(ay.cells);
  range_.resize(n);
  start_.assign(cells + 1, 0);
  wide_ids_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (wide_[i] == 0) {
      const b2AABB& b = boxes[i];
      const Range r{ax.cell(b.lowerBound.x), ay.cell(b.lowerBound.y), ax.cell(b.upperBound.x), ay.cell(b.upperBound.y)};
      range_[i] = r;
      const std::int64_t covered = std::int64_t{r.x1 - r.x0 + 1} * (r.y1 - r.y0 + 1);
      if (covered <= kMaxCellsPerBox) {
        for (std::int32_t y = r.y0; y <= r.y1; ++y)
          for (std::int32_t x = r.x0; x <= r.x1; ++x) ++start_[static_cast<std::size_t>(y) * static_cast<std::size_t>(ax.cells) + static_cast<std::size_t>(x) + 1];
        continue;
      }
      wide_[i] = 1;
    }
    wide_ids_.push_back(static_cast<std::int32_t>(i));
  }
  for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
  items_.resize(static_cast<std::size_t>(start_[cells]));
  {
    std::vector<std::int32_t>& fill = range_fill_;
    fill.assign(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) {
      if (wide_[i] != 0) continue;
      const Range& r = range_[i];
      for (std::int32_t y = r.y0; y <= r.y1; ++y)
        for (std::int32_t x = r.x0; x <= r.x1; ++x)
          items_[static_cast<std::size_t>(fill[static_cast<std::size_t>(y) * static_cast<std::size_t>(ax.cells) + static_cast<std::size_t>(x)]++)] =
              static_cast<std::int32_t>(i);
    }
  }

  // Each box against the later boxes of its cells (a pair once: in its intersection's lower cell),
  // and against the later wide boxes; then its group sorted by j.
  for (std::size_t i = 0; i < n; ++i) {
    const auto id = static_cast<ElementId>(i);
    const std::size_t group = out.size();
    const b2AABB& bi = boxes[i];
    if (wide_[i] != 0) {
      for (std::size_t j = i + 1; j < n; ++j)
        if (b2TestOverlap(bi, boxes[j])) out.push_back({id, static_cast<ElementId>(j)});
      continue;
    }
    const Range ri = range_[i];
    for (std::int32_t y = ri.y0; y <= ri.y1; ++y) {
      for (std::int32_t x = ri.x0; x <= ri.x1; ++x) {
        const std::size_t c = static_cast<std::size_t>(y) * static_cast<std::size_t>(ax.cells) + static_cast<std::size_t>(x);
        for (std::int32_t k = start_[c + 1] - 1; k >= start_[c]; --k) {
          const std::int32_t j = items_[static_cast<std::size_t>(k)];
          if (j <= id) break;  // ascending within the cell: the rest are earlier boxes
          const Range& rj = range_[static_cast<std::size_t>(j)];
          if (std::max(ri.x0, rj.x0) != x || std::max(ri.y0, rj.y0) != y) continue;  // found in another cell
          if (b2TestOverlap(bi, boxes[j])) out.push_back({id, j});
        }
      }
    }
    for (auto it = std::upper_bound(wide_ids_.begin(), wide_ids_.end(), id); it != wide_ids_.end(); ++it)
      if (b2TestOverlap(bi, boxes[static_cast<std::size_t>(*it)])) out.push_back({id, *it});
    sort_run_by_j(out.begin() + static_cast<std::ptrdiff_t>(group), out.end());
  }
}

}  // namespace nbscope
