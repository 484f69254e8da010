#include "core/screen.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/cells.hpp"
#include "core/error.hpp"
#include "core/lists.hpp"

namespace nbscope {

namespace {
// Pseudocode lines (TraceEvent::line).
enum Line : std::uint8_t { kLoopMap = 0, kPush, kLoopContacts, kMaskCell, kTestPair, kClear };

std::string human_bytes(double bytes) {
  const char* unit[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (bytes >= 1000.0 && u < 6) {
    bytes /= 1000.0;
    ++u;
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.1f %s", bytes, unit[u]);
  return buf;
}
}  // namespace

void check_screen_array_size(const Grid& grid, std::int64_t n_elements) {
  // In double: three sides of up to 2^24 cells overflow int64.
  const double cells = static_cast<double>(grid.n[0]) * static_cast<double>(grid.n[1]) * static_cast<double>(grid.n[2]);
  if (cells <= static_cast<double>(kScreenMaxCells)) return;
  const double n = static_cast<double>(n_elements);
  const double nbs_ints = grid.dim == 3 ? static_cast<double>(grid.n[2]) + 2.0 * static_cast<double>(grid.n[1]) +
                                              5.0 * static_cast<double>(grid.n[0]) + 3.0 * n
                                        : static_cast<double>(grid.n[1]) + 2.0 * static_cast<double>(grid.n[0]) + 2.0 * n;
  std::string sides = std::to_string(grid.n[0]) + " x " + std::to_string(grid.n[1]);
  if (grid.dim == 3) sides += " x " + std::to_string(grid.n[2]);
  char count[64];
  std::snprintf(count, sizeof count, "%.0f", cells);
  throw Error(std::string("screen: the screen array ") + (grid.dim == 3 ? "C[nx][ny][nz]" : "C[nx][ny]") +
              " would need " + sides + " = " + count + " cells, " + human_bytes(cells * 4.0) +
              " (limit " + std::to_string(kScreenMaxCells) + " cells, " +
              human_bytes(static_cast<double>(kScreenMaxCells) * 4.0) +
              "): the world is sparse for its cell size; use --algorithm nbs, whose memory here is " +
              human_bytes(nbs_ints * 4.0) + ", or a larger --cell-size");
}

const std::vector<const char*>& ScreenDetector::pseudocode(int dim) const {
  static const std::vector<const char*> lines_2d = {
      "Loop over all discrete elements k",
      "  ix = Int((x - x_min)/d), iy = Int((y - y_min)/d); add the discrete element k onto the list of "
      "cell (ix,iy): E[k] = C[ix][iy]; C[ix][iy] = k",
      "Loop over all discrete elements k",
      "  visit the cells of the contact mask: (ix,iy), (ix-1,iy), (ix-1,iy-1), (ix,iy-1), (ix+1,iy-1)",
      "    check k against each discrete element of that cell's list (own cell: those after k)",
      "Loop over all discrete elements k: C[ix][iy] = -1, the list is empty again",
  };
  static const std::vector<const char*> lines_3d = {
      "Loop over all discrete elements k",
      "  ix, iy, iz = Int((x - x_min)/d), ...; add the discrete element k onto the list of cell "
      "(ix,iy,iz): E[k] = C[ix][iy][iz]; C[ix][iy][iz] = k",
      "Loop over all discrete elements k",
      "  visit the cells of the contact mask: own cell, (ix-1,iy,iz), (ix-1..ix+1,iy-1,iz), "
      "(ix-1..ix+1,iy-1..iy+1,iz-1)",
      "    check k against each discrete element of that cell's list (own cell: those after k)",
      "Loop over all discrete elements k: C[ix][iy][iz] = -1, the list is empty again",
  };
  return dim == 3 ? lines_3d : lines_2d;
}

std::size_t ScreenDetector::own_bytes() const { return (heads_.size() + next_.size()) * sizeof(std::int32_t); }

template <int D, class Trace>
void ScreenDetector::run(const Elements& e, const DetectOptions& options, PairList& out_pairs, Trace& trace) {
  if (e.dim != D) throw Error("screen: internal: dimension mismatch");
  refuse_periodic(e, "screen");
  grid_ = make_grid(e, options.grid);
  check_screen_array_size(grid_, e.size());  // before a single byte of C is allocated
  const auto cells = static_cast<std::size_t>(grid_.cell_count());
  heads_.resize(cells, -1);  // every head is -1 between runs, so resizing keeps them so
  if (heads_.capacity() > 4 * cells + 4096) heads_.shrink_to_fit();
  next_.resize(static_cast<std::size_t>(e.size()));
  PairCollector pairs(out_pairs, options.max_pairs);

  const auto n = static_cast<ElementId>(e.size());
  ListArrays lists{heads_.data(), next_.data(), -1, -1, "cell list"};
  if constexpr (Trace::enabled) {
    std::vector<std::int64_t> shape = {grid_.n[0], grid_.n[1]};
    if (D == 3) shape.push_back(grid_.n[2]);
    lists.heads_id = trace.declare_array("C", shape, heads_);
    lists.next_id = trace.declare_array("E", {n}, next_);
  }
  const Grid& g = grid_;
  const std::int32_t* const next = next_.data();
  const std::int32_t* const heads = heads_.data();
  constexpr const auto& mask = half_mask<D>();
  auto cell_of = [&](ElementId k, std::int32_t c[3]) {
    c[0] = g.cell(e.x[k], 0);
    c[1] = g.cell(e.y[k], 1);
    c[2] = D == 3 ? g.cell(e.z[k], 2) : 0;
  };
  auto iz_of = [](const std::int32_t c[3]) { return D == 3 ? c[2] : -1; };

  try {
    trace.phase(kLoopMap, phase_label::kMap, -1);
    for (ElementId k = 0; k < n; ++k) {
      std::int32_t c[3];
      cell_of(k, c);
      push_front(trace, kPush, lists, g.flat(c[0], c[1], c[2]), k, c[0], c[1], iz_of(c));
    }

    trace.phase(kLoopContacts, phase_label::kContacts, -1);
    for (ElementId k = 0; k < n; ++k) {
      std::int32_t c[3];
      cell_of(k, c);
      trace.visit_cell(kMaskCell, k, c[0], c[1], iz_of(c));
      test_list(trace, kTestPair, e, options.touching, k, next[k], next, pairs);  // own cell: the elements after k
      for (const CellOffset& o : mask) {
        const std::int32_t jx = c[0] + o.dx, jy = c[1] + o.dy, jz = c[2] + o.dz;
        if (jx < 0 || jy < 0 || jz < 0 || jx >= g.n[0] || jy >= g.n[1] || jz >= g.n[2]) continue;
        trace.visit_cell(kMaskCell, k, jx, jy, D == 3 ? jz : -1);
        test_list(trace, kTestPair, e, options.touching, k, heads[g.flat(jx, jy, jz)], next, pairs);
      }
    }

    trace.phase(kClear, phase_label::kClear, -1);
    for (ElementId k = 0; k < n; ++k) {
      std::int32_t c[3];
      cell_of(k, c);
      clear_head(trace, kClear, lists, g.flat(c[0], c[1], c[2]));
    }
  } catch (...) {
    std::fill(heads_.begin(), heads_.end(), -1);
    throw;
  }
}

template class DimensionalDetector<ScreenDetector>;

}  // namespace nbscope
