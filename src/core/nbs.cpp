#include "core/nbs.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/lists.hpp"

namespace nbscope {

namespace {
// Pseudocode lines (TraceEvent::line) of the 2D detector.
enum Line2d : std::uint8_t {
  kLoopAll = 0,
  kPushY,
  kLoopRows,
  kPushX0,
  kPushX1,
  kLoopRow,
  kMaskCell,
  kTestPair,
  kClearX,
  kClearY,
};

constexpr const char* kYList = "y-list";
constexpr const char* kXList = "x-list";
}  // namespace

const std::vector<const char*>& NbsDetector::pseudocode_2d() {
  static const std::vector<const char*> lines = {
      "Loop over all discrete elements k",
      "  iy = Int((y - y_min)/d); add the discrete element k onto the y_iy list: Y[k] = y_heads[iy]; y_heads[iy] = k",
      "Loop over all rows iy whose y_iy list is not empty",
      "  Loop over all discrete elements from the list y_iy: ix = Int((x - x_min)/d); add the discrete element k "
      "onto the x-list of cell (ix,iy): X[k] = B[0][ix]; B[0][ix] = k",
      "  Loop over all discrete elements from the list y_{iy-1}: ix = Int((x - x_min)/d); add the discrete element k "
      "onto the x-list of cell (ix,iy-1): X[k] = B[1][ix]; B[1][ix] = k",
      "  Loop over all discrete elements k from the y_iy list",
      "    visit the cells of the contact mask: (ix,iy), (ix-1,iy), (ix-1,iy-1), (ix,iy-1), (ix+1,iy-1)",
      "      check k against each discrete element of that cell's x-list (own cell: those after k)",
      "  Clear the heads B[0][ix], B[1][ix] of the cells used (set to -1)",
      "Clear the heads of the y lists (set to -1)",
  };
  return lines;
}

std::size_t NbsDetector::book_bytes() const {
  // 2D: ny + 2nx + 2N integers (book p.102); 3D: nz + 2ny + 5nx + 3N; for the last detection.
  return (y_heads_.size() + x_heads_.size() + y_next_.size() + x_next_.size() + z_heads_.size() + z_next_.size()) *
         sizeof(std::int32_t);
}

std::size_t NbsDetector::own_bytes() const {
  std::size_t scratch = (order_.capacity() + chunk_lists_.capacity()) * sizeof(std::int32_t);
  scratch += packed_.capacity() * sizeof(double);
  scratch += (where_.capacity() + x_sorted_.capacity() + y_sorted_.capacity()) * sizeof(std::int32_t);
  for (const Band& band : bands_) {
    scratch += (band.spare.capacity() + band.buffers[0].slots.capacity() + band.buffers[1].slots.capacity()) * sizeof(Slot);
    scratch += (band.heads.capacity() + band.rows.capacity()) * sizeof(std::int32_t);
    scratch += band.pairs.capacity() * sizeof(Pair);
  }
  return book_bytes() + scratch;
}

void NbsDetector::prepare(std::int64_t n_elements) {
  const auto nx = static_cast<std::size_t>(grid_.n[0]);
  const auto ny = static_cast<std::size_t>(grid_.n[1]);
  // All heads are -1 between runs, so shrinking or growing with -1 keeps them so.
  y_heads_.resize(ny, -1);
  x_heads_.resize(2 * nx, -1);
  y_next_.resize(static_cast<std::size_t>(n_elements));
  x_next_.resize(static_cast<std::size_t>(n_elements));
  z_heads_.clear();  // the 3D layer lists take no memory in 2D
  z_next_.clear();
}

void NbsDetector::reset_heads() {
  std::fill(y_heads_.begin(), y_heads_.end(), -1);
  std::fill(x_heads_.begin(), x_heads_.end(), -1);
  std::fill(z_heads_.begin(), z_heads_.end(), -1);
}

template <class Trace>
void NbsDetector::run_2d(const Elements& e, const DetectOptions& options, PairList& out_pairs, Trace& trace) {
  if (e.dim != 2) throw Error("nbs: only 2D elements are supported by this detector");
  grid_ = make_grid(e, options.grid);
  prepare(e.size());
  PairCollector pairs(out_pairs, options.max_pairs);

  const auto n = static_cast<ElementId>(e.size());
  const std::int32_t nx = static_cast<std::int32_t>(grid_.n[0]);
  const std::int32_t ny = static_cast<std::int32_t>(grid_.n[1]);
  std::int32_t* const yh = y_heads_.data();
  std::int32_t* const yn = y_next_.data();
  std::int32_t* const b0 = x_heads_.data();
  std::int32_t* const b1 = x_heads_.data() + nx;
  std::int32_t* const xn = x_next_.data();
  const double* const px = e.x.data();
  const double* const py = e.y.data();
  const Grid& g = grid_;

  [[maybe_unused]] int a_yh = -1, a_yn = -1, a_b = -1, a_xn = -1;
  if constexpr (Trace::enabled) {
    a_yh = trace.declare_array("y_heads", {ny}, y_heads_);
    a_yn = trace.declare_array("Y", {n}, y_next_);
    a_b = trace.declare_array("B", {2, nx}, x_heads_);
    a_xn = trace.declare_array("X", {n}, x_next_);
  }

  // Tests k against every element of the x list starting at m.
  auto test_list = [&](ElementId k, std::int32_t m) {
    for (; m != -1; m = xn[m]) {
      const bool contact = in_contact(e, k, m, options.touching);
      trace.test_pair(kTestPair, k, m, contact);
      if (contact) pairs.add(k, m);
    }
  };

  try {
    // 1. y-lists: one pass over all elements.
    trace.phase(kLoopAll, phase_label::kYLists, -1);
    for (ElementId k = 0; k < n; ++k) {
      const std::int32_t iy = g.cell(py[k], 1);
      trace.push(kPushY, kYList, a_yh, iy, a_yn, k, yh[iy], yn[k], -1, iy, -1);
      yn[k] = yh[iy];
      yh[iy] = k;
    }

    // 2. rows: x-lists of row iy (B[0]) and iy-1 (B[1]), the contact mask, then clearing.
    for (std::int32_t iy = 0; iy < ny; ++iy) {
      if (yh[iy] == -1) continue;
      const std::int32_t iy_below = g.neighbour(iy, -1, 1);  // on a periodic y, row 0's is row ny-1
      const bool below = iy_below >= 0 && yh[iy_below] != -1;
      trace.phase(kLoopRows, phase_label::kXListsOfRow, iy);
      for (std::int32_t k = yh[iy]; k != -1; k = yn[k]) {
        const std::int32_t ix = g.cell(px[k], 0);
        trace.push(kPushX0, kXList, a_b, ix, a_xn, k, b0[ix], xn[k], ix, iy, -1);
        xn[k] = b0[ix];
        b0[ix] = k;
      }
      if (below) {
        for (std::int32_t k = yh[iy_below]; k != -1; k = yn[k]) {
          const std::int32_t ix = g.cell(px[k], 0);
          trace.push(kPushX1, kXList, a_b, std::int64_t{nx} + ix, a_xn, k, b1[ix], xn[k], ix, iy_below, -1);
          xn[k] = b1[ix];
          b1[ix] = k;
        }
      }

      trace.phase(kLoopRow, phase_label::kContactsOfRow, iy);
      for (std::int32_t k = yh[iy]; k != -1; k = yn[k]) {
        const std::int32_t ix = g.cell(px[k], 0);
        trace.visit_cell(kMaskCell, k, ix, iy, -1);
        test_list(k, xn[k]);  // same cell: only the elements after k, so each pair once
        if (const std::int32_t left = g.neighbour(ix, -1, 0); left >= 0) {
          trace.visit_cell(kMaskCell, k, left, iy, -1);
          test_list(k, b0[left]);
        }
        if (below) {
          for (std::int32_t dx = -1; dx <= 1; ++dx) {
            const std::int32_t jx = g.neighbour(ix, dx, 0);
            if (jx < 0) continue;
            trace.visit_cell(kMaskCell, k, jx, iy_below, -1);
            test_list(k, b1[jx]);
          }
        }
      }

      trace.phase(kClearX, phase_label::kClearXLists, iy);
      for (std::int32_t k = yh[iy]; k != -1; k = yn[k]) {
        const std::int32_t ix = g.cell(px[k], 0);
        if (b0[ix] != -1) {
          trace.clear(kClearX, kXList, a_b, ix, b0[ix]);
          b0[ix] = -1;
        }
      }
      if (below) {
        for (std::int32_t k = yh[iy_below]; k != -1; k = yn[k]) {
          const std::int32_t ix = g.cell(px[k], 0);
          if (b1[ix] != -1) {
            trace.clear(kClearX, kXList, a_b, std::int64_t{nx} + ix, b1[ix]);
            b1[ix] = -1;
          }
        }
      }
    }

    // 3. clear the y heads that were set.
    trace.phase(kClearY, phase_label::kClearYLists, -1);
    for (ElementId k = 0; k < n; ++k) {
      const std::int32_t iy = g.cell(py[k], 1);
      if (yh[iy] != -1) {
        trace.clear(kClearY, kYList, a_yh, iy, yh[iy]);
        yh[iy] = -1;
      }
    }
  } catch (...) {
    reset_heads();
    throw;
  }
}

void NbsDetector::detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) {
  // The fast path does not wrap: a periodic frame runs the book's loops, which do. Only the frame's
  // own axes count (a 2D LAMMPS dump flags z periodic).
  bool wraps = false;
  for (int a = 0; a < elements.dim; ++a) wraps = wraps || elements.box.periodic[a];
  if (wraps) return detect_book(elements, options, out_pairs);
  if (elements.dim != 2 && elements.dim != 3) throw Error("nbs: only 2D and 3D elements are supported");
  run_fast(elements, options, out_pairs);
}

void NbsDetector::detect_book(const Elements& elements, const DetectOptions& options, PairList& out_pairs) {
  if (elements.dim == 3) return detect_3d(elements, options, out_pairs, nullptr);
  NullTrace none;
  run_2d(elements, options, out_pairs, none);
}

void NbsDetector::detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                                TraceLog& out_trace) {
  if (elements.dim == 3) return detect_3d(elements, options, out_pairs, &out_trace);
  out_trace.reset();
  run_2d(elements, options, out_pairs, out_trace);
}

}  // namespace nbscope
