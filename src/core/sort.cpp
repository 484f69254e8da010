#include "core/sort.hpp"

#include <algorithm>
#include <array>
#include <numeric>

#include "core/cells.hpp"
#include "core/error.hpp"
#include "core/lists.hpp"

namespace nbscope {

namespace {
// Pseudocode lines (TraceEvent::line).
enum Line : std::uint8_t { kLoopMap = 0, kMapCell, kSortLine, kLoopSorted, kOwnRun, kMaskCell, kTestPair };
}  // namespace

const std::vector<const char*>& SortDetector::pseudocode(int dim) const {
  static const std::vector<const char*> lines_2d = {
      "Loop over all discrete elements k (Step 1: map discrete elements onto cells)",
      "  ix[k] = Int((x - x_min)/d); iy[k] = Int((y - y_min)/d); order[k] = k",
      "Sort array order by cell (ix, iy): the discrete elements of one cell become one run",
      "Loop over the sorted array: k = order[p]",
      "  check k against the discrete elements after it in the run of its own cell",
      "  find the runs of the cells of the contact mask (ix-1,iy), (ix-1,iy-1), (ix,iy-1), (ix+1,iy-1)",
      "    check k against each discrete element of that run",
  };
  static const std::vector<const char*> lines_3d = {
      "Loop over all discrete elements k (Step 1: map discrete elements onto cells)",
      "  ix[k] = Int((x - x_min)/d); iy[k] = Int((y - y_min)/d); iz[k] = Int((z - z_min)/d); order[k] = k",
      "Sort array order by cell (ix, iy, iz): the discrete elements of one cell become one run",
      "Loop over the sorted array: k = order[p]",
      "  check k against the discrete elements after it in the run of its own cell",
      "  find the runs of the cells of the contact mask (ix-1,iy,iz), (ix-1..ix+1,iy-1,iz), "
      "(ix-1..ix+1,iy-1..iy+1,iz-1)",
      "    check k against each discrete element of that run",
  };
  return dim == 3 ? lines_3d : lines_2d;
}

std::size_t SortDetector::own_bytes() const {
  return (cell_[0].size() + cell_[1].size() + cell_[2].size() + order_.size()) * sizeof(std::int32_t);
}

template <int D, class Trace>
void SortDetector::run(const Elements& e, const DetectOptions& options, PairList& out_pairs, Trace& trace) {
  if (e.dim != D) throw Error("sort: internal: dimension mismatch");
  refuse_periodic(e, "sort");
  grid_ = make_grid(e, options.grid);
  const auto n = static_cast<ElementId>(e.size());
  for (int a = 0; a < 3; ++a) cell_[a].resize(a < D ? static_cast<std::size_t>(n) : 0);
  order_.resize(static_cast<std::size_t>(n));
  PairCollector pairs(out_pairs, options.max_pairs);

  static const char* const names[3] = {"ix", "iy", "iz"};
  [[maybe_unused]] int ids[3] = {-1, -1, -1};
  [[maybe_unused]] int order_id = -1;
  [[maybe_unused]] std::vector<std::int32_t> before[D + 1];
  if constexpr (Trace::enabled) {
    for (int a = 0; a < D; ++a) ids[a] = trace.declare_array(names[a], {n}, cell_[a]);
    order_id = trace.declare_array("order", {n}, order_);
    for (int a = 0; a < D; ++a) before[a] = cell_[a];
    before[D] = order_;
  }

  // Step 1: every element onto its cell, as one vectorised integerisation per axis.
  trace.phase(kLoopMap, phase_label::kMap, -1);
  for (int a = 0; a < D; ++a) integerise(e, grid_, a, cell_[a]);
  std::iota(order_.begin(), order_.end(), 0);
  if constexpr (Trace::enabled) {
    for (ElementId k = 0; k < n; ++k) {
      for (int a = 0; a < D; ++a) trace.set(kMapCell, "cell", ids[a], k, before[a][k], cell_[a][k], k);
      trace.set(kMapCell, "order", order_id, k, before[D][k], k, k);
    }
  }

  using Key = std::array<std::int32_t, D>;
  const std::int32_t* const cx = cell_[0].data();
  const std::int32_t* const cy = cell_[1].data();
  const std::int32_t* const cz = cell_[D == 3 ? 2 : 1].data();
  auto key_of = [&](std::int32_t k) -> Key {
    if constexpr (D == 3) {
      return {cx[k], cy[k], cz[k]};
    } else {
      return {cx[k], cy[k]};
    }
  };

  trace.phase(kSortLine, phase_label::kSort, -1);
  std::sort(order_.begin(), order_.end(), [&](std::int32_t a, std::int32_t b) {
    const Key ka = key_of(a), kb = key_of(b);
    return ka < kb || (ka == kb && a < b);
  });
  if constexpr (Trace::enabled) {
    for (ElementId p = 0; p < n; ++p) {
      if (order_[p] != p) trace.set(kSortLine, "sorted", order_id, p, p, order_[p], order_[p]);
    }
  }

  // The sweep: runs of equal keys are cells; for a fixed mask offset the target key only grows.
  trace.phase(kLoopSorted, phase_label::kContacts, -1);
  const std::int32_t* const order = order_.data();
  constexpr const auto& mask = half_mask<D>();
  std::array<ElementId, mask.size()> cursor{};
  auto test = [&](ElementId k, ElementId m) {
    const bool contact = in_contact(e, k, m, options.touching);
    trace.test_pair(kTestPair, k, m, contact);
    if (contact) pairs.add(k, m);
  };
  for (ElementId p = 0; p < n; ++p) {
    const ElementId k = order[p];
    const Key c = key_of(k);
    trace.visit_cell(kOwnRun, k, c[0], c[1], D == 3 ? c[D - 1] : -1);
    for (ElementId q = p + 1; q < n && key_of(order[q]) == c; ++q) test(k, order[q]);
    for (std::size_t m = 0; m < mask.size(); ++m) {
      Key t = c;
      t[0] += mask[m].dx;
      t[1] += mask[m].dy;
      if constexpr (D == 3) t[2] += mask[m].dz;
      bool inside = true;
      for (int a = 0; a < D; ++a) inside = inside && t[a] >= 0 && t[a] < grid_.n[a];
      if (!inside) continue;
      trace.visit_cell(kMaskCell, k, t[0], t[1], D == 3 ? t[D - 1] : -1);
      ElementId& cur = cursor[m];
      while (cur < n && key_of(order[cur]) < t) ++cur;
      for (ElementId q = cur; q < n && key_of(order[q]) == t; ++q) test(k, order[q]);
    }
  }
}

template class DimensionalDetector<SortDetector>;

}  // namespace nbscope
