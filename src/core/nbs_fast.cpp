// Munjiza-NBS, the fast path of NbsDetector::detect() (see nbs.hpp): the book's arrays and pairs,
// in the book's order, without walking a list through memory in random order.
//
// Index: helpers | order_by_list (the counting sort that replaces walking the y-lists / z-lists) |
// 2D | 3D.
//
// Why it equals the book: every push the book makes onto a y-list (3D) or x-list is made here too,
// in the same order, onto the same heads array, which holds local indices into the buffer while a
// row (layer) is processed, so the contact tests walk the same lists in the same order and even
// the pairs come in the book's order. The book pushes an element more than once (2D: onto B[0]
// for its row, then onto B[1] for the row above; 3D: onto the x-lists of five rows' processing,
// and onto B[0] and B[1]), but each time it rebuilds the same list in the same order, so the next
// arrays get the same value each time: the value of the first push (the global id behind the head
// then) is kept in the slot and written once, when the buffer is retired.
#include <algorithm>
#include <utility>

#include "core/error.hpp"
#include "core/nbs.hpp"

namespace nbscope {

namespace {

// How many elements ahead a gather asks for the coordinates: enough to cover a memory latency.
constexpr std::size_t kPrefetchAhead = 16;

// From this many elements (6 MB of x, y and r) the next row is fetched while a row is tested (2D;
// in 3D a whole next layer is too much to fetch ahead); below it the elements stay in cache and
// the fetching only costs (BM_Detect/nbs at 1e4, 1e5).
constexpr std::int64_t kFetchNextRowFrom = std::int64_t{1} << 18;

inline void prefetch_read(const void* p) { __builtin_prefetch(p, 0, 3); }
// Into the outer caches: what is fetched a row ahead must not push this row's data out of L1.
inline void prefetch_ahead(const void* p) { __builtin_prefetch(p, 0, 2); }
inline void prefetch_write(const void* p) { __builtin_prefetch(p, 1, 3); }

}  // namespace

std::size_t NbsDetector::moved_bytes_per_element(int dim) {
  // Provisional (the layout before packed records): the columns read in order for the first lists,
  // the cell kept, the order written and read, the coordinates read in random order (a line each),
  // the next arrays written (a line read and written each).
  const std::size_t columns = dim == 3 ? 4 : 3;
  return 8 + 4 * 4 + columns * 64 + (dim == 3 ? 3 : 2) * 128;
}

void NbsDetector::order_by_list(const std::int32_t* cell_of, std::int64_t n_elements, std::int32_t cells) {
  list_end_.assign(static_cast<std::size_t>(cells) + 1, 0);
  std::int32_t* const end = list_end_.data();
  for (std::int64_t k = 0; k < n_elements; ++k) ++end[cell_of[k] + 1];
  for (std::int32_t c = 0; c < cells; ++c) end[c + 1] += end[c];
  // end[c] is now where list c starts; placing advances it to where list c ends (= where c+1 starts).
  order_.resize(static_cast<std::size_t>(n_elements));
  std::int32_t* const order = order_.data();
  for (std::int64_t k = n_elements - 1; k >= 0; --k) order[end[cell_of[k]]++] = static_cast<std::int32_t>(k);
}

void NbsDetector::push_and_order(const Elements& e, int axis, std::int32_t* heads, std::int32_t* next,
                                 std::int32_t* cell_scratch) {
  const std::int64_t n = e.size();
  const double* const v = e.axis(axis).data();
  for (std::int64_t k = 0; k < n; ++k) {
    const std::int32_t c = grid_.cell(v[k], axis);
    next[k] = heads[c];
    heads[c] = static_cast<std::int32_t>(k);
    cell_scratch[k] = c;
  }
  order_by_list(cell_scratch, n, static_cast<std::int32_t>(grid_.n[axis]));
}

template <int D>
void NbsDetector::gather(const Elements& e, std::size_t first, std::size_t count, Slot* out) const {
  const auto n = static_cast<std::size_t>(e.size());
  const std::int32_t* const order = order_.data();
  const double* const px = e.x.data();
  const double* const py = e.y.data();
  const double* const pz = D == 3 ? e.z.data() : nullptr;
  const double* const pr = e.r.data();
  for (std::size_t i = 0; i < count; ++i) {
    if (const std::size_t ahead = first + i + kPrefetchAhead; ahead < n) {
      prefetch_read(px + order[ahead]);
      prefetch_read(py + order[ahead]);
      if constexpr (D == 3) prefetch_read(pz + order[ahead]);
      prefetch_read(pr + order[ahead]);
    }
    const std::int32_t k = order[first + i];
    Slot& slot = out[i];
    slot.x = px[k];
    slot.y = py[k];
    slot.r = pr[k];
    slot.id = k;
    slot.ix = grid_.cell(px[k], 0);
    if constexpr (D == 3) {
      slot.z = pz[k];
      slot.iy = grid_.cell(py[k], 1);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// 2D: rows of cells. Per non-empty row iy: gather it, push its elements onto B[0] (in y-list
// order; B[1] holds the row below's), test the mask in y-list order, retire the row below.

void NbsDetector::run_2d_fast(const Elements& e, const DetectOptions& options, PairList& out_pairs) {
  if (e.dim != 2) throw Error("nbs: only 2D elements are supported by this detector");
  grid_ = make_grid(e, options.grid);
  prepare(e.size());
  BranchFreePairs pairs(out_pairs, options.max_pairs);

  const auto nx = static_cast<std::int32_t>(grid_.n[0]);
  const auto ny = static_cast<std::int32_t>(grid_.n[1]);
  std::int32_t* const yh = y_heads_.data();
  std::int32_t* const yn = y_next_.data();
  std::int32_t* const xn = x_next_.data();
  // B[0] (row iy's x-list heads) and B[1] (row iy-1's). Row iy-1's lists, rebuilt in B[1] by the
  // book, are the very lists it had in B[0]: its heads are kept and the two halves swap roles.
  std::int32_t* b0 = x_heads_.data();
  std::int32_t* b1 = x_heads_.data() + nx;

  // Writes the X values of a buffer's elements (none of them is pushed again), clears the heads
  // its lists used in `heads` and empties it.
  auto retire = [&](Buffer& b, std::int32_t* heads) {
    const std::size_t m = b.slots.size();
    const Slot* const s = b.slots.data();
    for (std::size_t i = 0; i < m; ++i) {
      if (i + kPrefetchAhead < m) prefetch_write(xn + s[i + kPrefetchAhead].id);
      xn[s[i].id] = s[i].last_x;
      heads[s[i].ix] = -1;
    }
    b.slots.clear();
    b.list = -1;
  };
  PairCursor cursor{pairs.data(), 0, pairs.capacity(), &pairs};
  const bool inclusive = options.touching == Touching::inclusive;
  // Tests element k against the x-list of `from` that starts at local index j.
  auto test_list = [&](const Slot& k, const Slot* from, std::int32_t j) {
    for (; j != -1; j = from[j].next) {
      const double dx = k.x - from[j].x;
      const double dy = k.y - from[j].y;
      const double rr = k.r + from[j].r;
      offer_pair(cursor, touches(dx * dx + dy * dy, rr * rr, inclusive), k.id, from[j].id);
    }
  };

  try {
    // 1. The book's y-lists (Y[k] = y_heads[iy]; y_heads[iy] = k), each element's row kept in X
    // for the counting sort (X is written again before anyone reads it).
    push_and_order(e, 1, yh, yn, xn);
    const std::int32_t* const row_end = list_end_.data();

    Buffer* cur = &buffers_[0];
    Buffer* below = &buffers_[1];
    cur->slots.clear();
    below->slots.clear();
    cur->list = below->list = -1;
    for (std::int32_t iy = 0; iy < ny; ++iy) {
      const std::int32_t first = iy == 0 ? 0 : row_end[iy - 1];
      const std::int32_t last = row_end[iy];
      if (first == last) continue;  // y_heads[iy] == -1
      const bool has_below = iy > 0 && below->list == iy - 1;
      if (!has_below) retire(*below, b1);  // the last row was not iy-1: its lists are done

      // Gather the row in y-list order, its cells integerised once.
      const auto m = static_cast<std::size_t>(last - first);
      cur->slots.resize(m);
      cur->list = iy;
      Slot* const s = cur->slots.data();
      gather<2>(e, static_cast<std::size_t>(first), m, s);
      // x-lists of row iy: X[k] = B[0][ix]; B[0][ix] = k.
      for (std::size_t i = 0; i < m; ++i) {
        const std::int32_t h = b0[s[i].ix];
        s[i].next = h;
        s[i].last_x = h == -1 ? -1 : s[h].id;
        b0[s[i].ix] = static_cast<std::int32_t>(i);
      }
      // The contact mask, element by element in y-list order. Meanwhile, when the elements are too
      // many for the caches, the next elements of the order (the next row's) are fetched, two per
      // element, so that memory works while this row computes and the next gather finds them.
      const Slot* const sb = below->slots.data();
      const std::size_t next_first = static_cast<std::size_t>(last);
      const std::size_t next_last =
          e.size() < kFetchNextRowFrom ? next_first : std::min(static_cast<std::size_t>(e.size()), next_first + 2 * m);
      for (std::size_t i = 0; i < m; ++i) {
        for (std::size_t j = next_first + 2 * i; j < std::min(next_first + 2 * i + 2, next_last); ++j) {
          const std::int32_t ahead = order_[j];
          prefetch_ahead(e.x.data() + ahead);
          prefetch_ahead(e.y.data() + ahead);
          prefetch_ahead(e.r.data() + ahead);
        }
        const Slot& k = s[i];
        const std::int32_t left = k.ix > 0 ? b0[k.ix - 1] : -1;
        const std::int32_t jx0 = std::max(k.ix - 1, 0), jx1 = std::min(k.ix + 1, nx - 1);
        test_list(k, s, k.next);  // own cell: the elements after k
        test_list(k, s, left);
        if (has_below)
          for (std::int32_t jx = jx0; jx <= jx1; ++jx) test_list(k, sb, b1[jx]);
      }
      if (has_below) retire(*below, b1);  // row iy-1 takes no more pushes
      yh[iy] = -1;
      std::swap(cur, below);  // this row, its lists and their heads serve the next row as the row below
      std::swap(b0, b1);
    }
    retire(*below, b1);
    pairs.finish(cursor.kept);
  } catch (...) {
    reset_heads();
    throw;
  }
}

// ---------------------------------------------------------------------------------------------
// 3D: layers of rows. Per non-empty layer iz: gather it, push its elements onto B[0] (in z-list
// order; B[1] holds the layer below's), process each non-empty row when the walk meets its head
// (as the book does), retire the layer below.

void NbsDetector::run_3d_fast(const Elements& e, const DetectOptions& options, PairList& out_pairs) {
  if (e.dim != 3) throw Error("nbs: internal: dimension mismatch");
  grid_ = make_grid(e, options.grid);
  prepare_3d(e.size());
  BranchFreePairs pairs(out_pairs, options.max_pairs);

  const auto nx = static_cast<std::int32_t>(grid_.n[0]);
  const auto ny = static_cast<std::int32_t>(grid_.n[1]);
  const auto nz = static_cast<std::int32_t>(grid_.n[2]);
  std::int32_t* const zh = z_heads_.data();
  std::int32_t* const zn = z_next_.data();
  // B[0] (layer iz's y-list heads) and B[1] (layer iz-1's): as in 2D, the lists the book rebuilds
  // in B[1] are the layer's lists of B[0], so those heads are kept and the halves swap roles.
  std::int32_t* b0 = y_heads_.data();
  std::int32_t* b1 = y_heads_.data() + ny;
  std::int32_t* const yn = y_next_.data();
  std::int32_t* const a = x_heads_.data();
  std::int32_t* const xn = x_next_.data();

  // Writes the X and Y values of a buffer's elements, clears its y-list heads in `heads`, empties it.
  auto retire = [&](Buffer& b, std::int32_t* heads) {
    const std::size_t m = b.slots.size();
    const Slot* const s = b.slots.data();
    for (std::size_t i = 0; i < m; ++i) {
      if (i + kPrefetchAhead < m) {
        prefetch_write(xn + s[i + kPrefetchAhead].id);
        prefetch_write(yn + s[i + kPrefetchAhead].id);
      }
      xn[s[i].id] = s[i].last_x;
      yn[s[i].id] = s[i].last_y;
      heads[s[i].iy] = -1;
    }
    b.slots.clear();
    b.list = -1;
  };
  PairCursor cursor{pairs.data(), 0, pairs.capacity(), &pairs};
  const bool inclusive = options.touching == Touching::inclusive;
  auto test_list = [&](const Slot& k, const Slot* from, std::int32_t j) {
    for (; j != -1; j = from[j].xnext) {
      const double dx = k.x - from[j].x;
      const double dy = k.y - from[j].y;
      const double dz = k.z - from[j].z;
      const double rr = k.r + from[j].r;
      offer_pair(cursor, touches(dx * dx + dy * dy + dz * dz, rr * rr, inclusive), k.id, from[j].id);
    }
  };


  try {
    // 1. The book's z-lists, each element's layer kept in X for the counting sort.
    push_and_order(e, 2, zh, zn, xn);
    const std::int32_t* const layer_end = list_end_.data();

    Buffer* cur = &buffers_[0];
    Buffer* below = &buffers_[1];
    cur->slots.clear();
    below->slots.clear();
    cur->list = below->list = -1;
    for (std::int32_t iz = 0; iz < nz; ++iz) {
      const std::int32_t first = iz == 0 ? 0 : layer_end[iz - 1];
      const std::int32_t last = layer_end[iz];
      if (first == last) continue;  // C[iz] == -1
      const bool has_below = iz > 0 && below->list == iz - 1;
      if (!has_below) retire(*below, b1);  // the last layer was not iz-1: its lists are done

      const auto m = static_cast<std::size_t>(last - first);
      cur->slots.resize(m);
      cur->list = iz;
      Slot* const s = cur->slots.data();
      gather<3>(e, static_cast<std::size_t>(first), m, s);
      // y-lists of layer iz: Y[k] = B[0][iy]; B[0][iy] = k.
      for (std::size_t i = 0; i < m; ++i) {
        const std::int32_t h = b0[s[i].iy];
        s[i].next = h;
        s[i].last_y = h == -1 ? -1 : s[h].id;
        b0[s[i].iy] = static_cast<std::int32_t>(i);
      }
      // Regroup the layer row by row, each row's elements contiguous in y-list order and the rows
      // in the order the book processes them (when the walk of the z-list meets a row's head), so
      // that the five walks of each y-list below are sequential reads, not pointer chasing.
      spare_.resize(m);
      Slot* const t = spare_.data();
      std::size_t placed = 0;
      for (std::size_t i = 0; i < m; ++i) {
        const std::int32_t iy = s[i].iy;
        if (b0[iy] != static_cast<std::int32_t>(i)) continue;
        const auto head = static_cast<std::int32_t>(placed);
        for (std::int32_t j = static_cast<std::int32_t>(i); j != -1; j = s[j].next) t[placed++] = s[j];
        t[head].run = static_cast<std::int32_t>(placed) - head;
        b0[iy] = head;
      }
      cur->slots.swap(spare_);  // the ungrouped slots are the next layer's spare
      Slot* const c = cur->slots.data();
      Slot* const sb = below->slots.data();

      // One row (iy, iz): x-lists of the five rows the mask reaches, contacts, clearing.
      auto process_row = [&](std::int32_t iy) {
        std::int32_t first[5];  // where each row's run starts, -1 for none
        Slot* from[5] = {c, c, sb, sb, sb};
        first[0] = b0[iy];
        first[1] = iy > 0 ? b0[iy - 1] : -1;
        first[2] = has_below && iy > 0 ? b1[iy - 1] : -1;
        first[3] = has_below ? b1[iy] : -1;
        first[4] = has_below && iy + 1 < ny ? b1[iy + 1] : -1;
        std::int32_t last[5];
        for (int r = 0; r < 5; ++r) last[r] = first[r] == -1 ? -1 : first[r] + from[r][first[r]].run;
        for (int r = 0; r < 5; ++r) {
          std::int32_t* const row = a + std::int64_t{r} * nx;
          Slot* const f = from[r];
          for (std::int32_t j = first[r]; j < last[r]; ++j) {
            const std::int32_t h = row[f[j].ix];
            f[j].xnext = h;
            row[f[j].ix] = j;
          }
        }
        for (std::int32_t j = first[0]; j < last[0]; ++j) c[j].last_x = c[j].xnext == -1 ? -1 : c[c[j].xnext].id;
        for (std::int32_t j = first[0]; j < last[0]; ++j) {
          const Slot& k = c[j];
          const std::int32_t left = k.ix > 0 ? a[k.ix - 1] : -1;
          const std::int32_t jx0 = std::max(k.ix - 1, 0), jx1 = std::min(k.ix + 1, nx - 1);
          test_list(k, c, k.xnext);  // own cell: the elements after k
          test_list(k, c, left);
          for (int r = 1; r < 5; ++r) {
            if (first[r] == -1) continue;
            const std::int32_t* const row = a + std::int64_t{r} * nx;
            for (std::int32_t jx = jx0; jx <= jx1; ++jx) test_list(k, from[r], row[jx]);
          }
        }
        for (int r = 0; r < 5; ++r) {
          std::int32_t* const row = a + std::int64_t{r} * nx;
          for (std::int32_t j = first[r]; j < last[r]; ++j) row[from[r][j].ix] = -1;
        }
      };
      // Each non-empty row once, in the book's order (which the regrouping kept).
      for (std::size_t i = 0; i < m; i += static_cast<std::size_t>(c[i].run)) process_row(c[i].iy);

      if (has_below) retire(*below, b1);  // layer iz-1 takes no more pushes
      zh[iz] = -1;
      std::swap(cur, below);  // this layer, its y-lists and their heads serve the next as the layer below
      std::swap(b0, b1);
    }
    retire(*below, b1);
    pairs.finish(cursor.kept);
  } catch (...) {
    reset_heads();
    throw;
  }
}

}  // namespace nbscope
