// Munjiza-NBS in 3D (book p.123): z-lists, then per layer the y-lists of the layer and the layer
// below, then per row the x-lists of the five rows the contact mask reaches. See nbs.hpp.
#include <algorithm>

#include "core/error.hpp"
#include "core/lists.hpp"
#include "core/nbs.hpp"

namespace nbscope {

namespace {
// Pseudocode lines (TraceEvent::line) of the 3D detector.
enum Line3d : std::uint8_t {
  kLoopAll = 0,
  kPushZ,
  kLoopLayers,
  kLoopZ,
  kPushY0,
  kLoopZBelow,
  kPushY1,
  kLoopRows,
  kPushX,
  kLoopRow,
  kMaskCell,
  kTestPair,
  kClearX,
  kClearY,
  kClearZ,
};

// The rows whose x-lists the contact mask of row (iy, iz) reaches, as offsets (dy, dz); A[r] holds
// the heads of row r.
constexpr std::int32_t kRowDy[5] = {0, -1, -1, 0, 1};
constexpr std::int32_t kRowDz[5] = {0, 0, -1, -1, -1};
}  // namespace

const std::vector<const char*>& NbsDetector::pseudocode_3d() {
  static const std::vector<const char*> lines = {
      "Loop over all discrete elements k",
      "  iz = Int((z - z_min)/d); add the discrete element k onto the z_iz list: Z[k] = C[iz]; C[iz] = k",
      "Loop over all layers iz whose z_iz list is not empty",
      "  Loop over all discrete elements from the list z_iz (k=C[iz] and k=Z[k] until the end of the list, k=-1)",
      "    iy = Int((y - y_min)/d); add the discrete element k onto y_{iy,iz} list: Y[k] = B[0][iy]; B[0][iy] = k",
      "  Loop over all discrete elements from the list z_{iz-1} (k=C[iz-1] and k=Z[k] until k=-1)",
      "    iy = Int((y - y_min)/d); add the discrete element k onto y_{iy,iz-1} list: Y[k] = B[1][iy]; B[1][iy] = k",
      "  Loop over all non-empty y_{iy,iz} lists, i.e. rows of cells (iy,iz)",
      "    Loop over the y-lists of rows r = (iy,iz), (iy-1,iz), (iy-1,iz-1), (iy,iz-1), (iy+1,iz-1): ix = Int((x - x_min)/d); "
      "add the discrete element k onto the x-list of cell (ix, row r): X[k] = A[r][ix]; A[r][ix] = k",
      "    Loop over all discrete elements k from the y_{iy,iz} list",
      "      visit the cells of the contact mask: own cell, (ix-1,iy,iz), (ix-1..ix+1,iy-1,iz), "
      "(ix-1..ix+1,iy-1..iy+1,iz-1)",
      "        check k against each discrete element of that cell's x-list (own cell: those after k)",
      "    clear the heads A[r][ix] of the cells used (set to -1)",
      "  clear the heads B[0][iy], B[1][iy] of the rows used (set to -1)",
      "Clear the heads C[iz] of the z-lists (set to -1)",
  };
  return lines;
}

void NbsDetector::prepare_3d(std::int64_t n_elements) {
  const auto nx = static_cast<std::size_t>(grid_.n[0]);
  const auto ny = static_cast<std::size_t>(grid_.n[1]);
  const auto nz = static_cast<std::size_t>(grid_.n[2]);
  const auto n = static_cast<std::size_t>(n_elements);
  // All heads are -1 between runs (2D or 3D), so resizing with -1 keeps them so.
  z_heads_.resize(nz, -1);
  y_heads_.resize(2 * ny, -1);
  x_heads_.resize(5 * nx, -1);
  z_next_.resize(n);
  y_next_.resize(n);
  x_next_.resize(n);
}

template <class Trace>
void NbsDetector::run_3d(const Elements& e, const DetectOptions& options, PairList& out_pairs, Trace& trace) {
  grid_ = make_grid(e, options.grid);
  prepare_3d(e.size());
  PairCollector pairs(out_pairs, options.max_pairs);

  const auto n = static_cast<ElementId>(e.size());
  const auto nx = static_cast<std::int32_t>(grid_.n[0]);
  const auto ny = static_cast<std::int32_t>(grid_.n[1]);
  const auto nz = static_cast<std::int32_t>(grid_.n[2]);
  ListArrays zl{z_heads_.data(), z_next_.data(), -1, -1, "z-list"};
  ListArrays yl{y_heads_.data(), y_next_.data(), -1, -1, "y-list"};  // B[s][iy] at s*ny + iy
  ListArrays xl{x_heads_.data(), x_next_.data(), -1, -1, "x-list"};  // A[r][ix] at r*nx + ix
  if constexpr (Trace::enabled) {
    zl.heads_id = trace.declare_array("C", {nz}, z_heads_);
    zl.next_id = trace.declare_array("Z", {n}, z_next_);
    yl.heads_id = trace.declare_array("B", {2, ny}, y_heads_);
    yl.next_id = trace.declare_array("Y", {n}, y_next_);
    xl.heads_id = trace.declare_array("A", {5, nx}, x_heads_);
    xl.next_id = trace.declare_array("X", {n}, x_next_);
  }
  const Grid& g = grid_;
  const Touching touching = options.touching;
  const std::int32_t* const zh = zl.heads;
  const std::int32_t* const zn = zl.next;
  const std::int32_t* const b = yl.heads;
  const std::int32_t* const yn = yl.next;
  const std::int32_t* const a = xl.heads;
  const std::int32_t* const xn = xl.next;
  const double* const px = e.x.data();
  const double* const py = e.y.data();
  const double* const pz = e.z.data();

  // One row (iy, iz) of layer iz: x-lists of the rows the mask reaches, contacts, clearing.
  auto process_row = [&](std::int32_t iy, std::int32_t iz, std::int32_t iz_below, bool below) {
    // The five rows (wrapped on a periodic y: row 0's row below is row ny-1), -1 past an open edge.
    std::int32_t row_y[5];
    for (int r = 0; r < 5; ++r) row_y[r] = g.neighbour(iy, kRowDy[r], 1);
    std::int32_t source[5];  // first element of each of the five rows' y-lists, -1 for none
    for (int r = 0; r < 5; ++r) {
      const bool reachable = row_y[r] >= 0 && (kRowDz[r] == 0 || below);
      source[r] = reachable ? b[(kRowDz[r] == 0 ? 0 : std::int64_t{ny}) + row_y[r]] : -1;
    }
    trace.phase(kLoopRows, phase_label::kXListsOfRow, iy, -1, iy, iz);
    for (int r = 0; r < 5; ++r) {
      for (std::int32_t k = source[r]; k != -1; k = yn[k]) {
        const std::int32_t ix = g.cell(px[k], 0);
        push_front(trace, kPushX, xl, std::int64_t{r} * nx + ix, k, ix, row_y[r], kRowDz[r] == 0 ? iz : iz_below);
      }
    }
    trace.phase(kLoopRow, phase_label::kContactsOfRow, iy, -1, iy, iz);
    for (std::int32_t k = source[0]; k != -1; k = yn[k]) {
      const std::int32_t ix = g.cell(px[k], 0);
      trace.visit_cell(kMaskCell, k, ix, iy, iz);
      test_list(trace, kTestPair, e, touching, k, xn[k], xn, pairs);  // own cell: the elements after k
      if (const std::int32_t left = g.neighbour(ix, -1, 0); left >= 0) {
        trace.visit_cell(kMaskCell, k, left, iy, iz);
        test_list(trace, kTestPair, e, touching, k, a[left], xn, pairs);
      }
      for (int r = 1; r < 5; ++r) {
        if (source[r] == -1) continue;
        const std::int32_t* const row = a + std::int64_t{r} * nx;
        for (std::int32_t dx = -1; dx <= 1; ++dx) {
          const std::int32_t jx = g.neighbour(ix, dx, 0);
          if (jx < 0) continue;
          trace.visit_cell(kMaskCell, k, jx, row_y[r], kRowDz[r] == 0 ? iz : iz_below);
          test_list(trace, kTestPair, e, touching, k, row[jx], xn, pairs);
        }
      }
    }
    trace.phase(kClearX, phase_label::kClearXLists, iy, -1, iy, iz);
    for (int r = 0; r < 5; ++r) {
      for (std::int32_t k = source[r]; k != -1; k = yn[k]) {
        clear_head(trace, kClearX, xl, std::int64_t{r} * nx + g.cell(px[k], 0));
      }
    }
  };

  try {
    // 1. z-lists: one pass over all elements.
    trace.phase(kLoopAll, phase_label::kZLists, -1);
    for (ElementId k = 0; k < n; ++k) {
      const std::int32_t iz = g.cell(pz[k], 2);
      push_front(trace, kPushZ, zl, iz, k, -1, -1, iz);
    }

    // 2. layers: y-lists of layer iz (B[0]) and iz-1 (B[1]), then every non-empty row of layer iz.
    for (std::int32_t iz = 0; iz < nz; ++iz) {
      if (zh[iz] == -1) continue;
      const std::int32_t iz_below = g.neighbour(iz, -1, 2);  // on a periodic z, layer 0's is layer nz-1
      const bool below = iz_below >= 0 && zh[iz_below] != -1;
      trace.phase(kLoopLayers, phase_label::kYListsOfLayer, iz, -1, -1, iz);
      for (std::int32_t k = zh[iz]; k != -1; k = zn[k]) {
        const std::int32_t iy = g.cell(py[k], 1);
        push_front(trace, kPushY0, yl, iy, k, -1, iy, iz);
      }
      if (below) {
        for (std::int32_t k = zh[iz_below]; k != -1; k = zn[k]) {
          const std::int32_t iy = g.cell(py[k], 1);
          push_front(trace, kPushY1, yl, std::int64_t{ny} + iy, k, -1, iy, iz_below);
        }
      }
      // Each non-empty row once: when the loop meets the element at its head. O(N), never O(ny nz).
      for (std::int32_t k = zh[iz]; k != -1; k = zn[k]) {
        const std::int32_t iy = g.cell(py[k], 1);
        if (b[iy] == k) process_row(iy, iz, iz_below, below);
      }
      trace.phase(kClearY, phase_label::kClearYListsOfLayer, iz, -1, -1, iz);
      for (std::int32_t k = zh[iz]; k != -1; k = zn[k]) clear_head(trace, kClearY, yl, g.cell(py[k], 1));
      if (below) {
        for (std::int32_t k = zh[iz_below]; k != -1; k = zn[k])
          clear_head(trace, kClearY, yl, std::int64_t{ny} + g.cell(py[k], 1));
      }
    }

    // 3. clear the z heads that were set.
    trace.phase(kClearZ, phase_label::kClearZLists, -1);
    for (ElementId k = 0; k < n; ++k) clear_head(trace, kClearZ, zl, g.cell(pz[k], 2));
  } catch (...) {
    reset_heads();
    throw;
  }
}

void NbsDetector::detect_3d(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                            TraceLog* trace) {
  if (elements.dim != 3) throw Error("nbs: internal: dimension mismatch");
  if (trace == nullptr) {
    NullTrace none;
    run_3d(elements, options, out_pairs, none);
  } else {
    trace->reset();
    run_3d(elements, options, out_pairs, *trace);
  }
}

}  // namespace nbscope
