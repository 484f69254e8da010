// Munjiza-NBS, the fast path of NbsDetector::detect() (see nbs.hpp): the book's arrays and pairs,
// in the book's order, without walking a list through memory in random order, on one thread or on
// bands of rows (3D: layers) each detected by its own thread.
//
// Index: helpers | run_fast (threads, bands, pairs) | gather | 2D rows | 3D layers.
//
// Why it equals the book: every push the book makes onto a y-list (3D) or x-list is made here too,
// in the same order, onto the same heads array, which holds local indices into the buffer while a
// row (layer) is processed, so the contact tests walk the same lists in the same order and even
// the pairs come in the book's order. The book pushes an element more than once (2D: onto B[0]
// for its row, then onto B[1] for the row above; 3D: onto the x-lists of five rows' processing,
// and onto B[0] and B[1]), but each time it rebuilds the same list in the same order, so the next
// arrays get the same value each time: the value of the first push (the global id behind the head
// then) is kept in the slot and written once, when the buffer is retired.
//
// Why bands equal the serial loops: a row's (layer's) lists and tests depend only on that row and
// the one below it. A band of rows [first, last) therefore loads row first - 1 into its own buffer
// and its own heads, as the serial loop left it, without testing it or writing its X (the band
// below owns it), and then runs the serial loop over its rows. Every element's X (Y) is written by
// exactly one band, every head is cleared by the band that set it, and the bands' pairs, appended
// in band order, are the serial loop's pairs in the serial loop's order.
#include <algorithm>
#include <utility>

#include "core/error.hpp"
#include "core/nbs.hpp"

namespace nbscope {

namespace {

// How many elements ahead the last pass asks for the line of a next value it reads: enough to cover a memory latency.
constexpr std::int64_t kPrefetchAhead = 16;

}  // namespace


// ---------------------------------------------------------------------------------------------
// run_fast: the first lists and records (nbs_order.cpp), then the bands, then their pairs in order.

void NbsDetector::run_fast(const Elements& e, const DetectOptions& options, PairList& out_pairs) {
  const int dim = e.dim;
  grid_ = make_grid(e, options.grid);
  if (dim == 3) {
    prepare_3d(e.size());
  } else {
    prepare(e.size());
  }
  const std::int64_t n = e.size();
  const int axis = dim - 1;
  const auto lists = static_cast<std::int32_t>(grid_.n[axis]);
  // As many threads as asked, but none with fewer than min_band_elements elements to do.
  const std::int64_t per_thread = std::max<std::int64_t>(options.min_band_elements, 1);
  const int threads = static_cast<int>(
      std::clamp<std::int64_t>(std::min<std::int64_t>(options.threads, n / per_thread), 1, kMaxThreads));
  if (threads > 1 && !pool_) pool_ = std::make_unique<WorkerPool>();
  try {
    order_and_pack(e, threads);
    x_sorted_.resize(static_cast<std::size_t>(n));
    y_sorted_.resize(dim == 3 ? static_cast<std::size_t>(n) : 0);
    // Bands of whole rows (layers), each starting at the row that holds its share of the elements;
    // a row too full to split leaves fewer bands.
    std::int32_t starts[kMaxThreads + 1];
    int bands = 1;
    starts[0] = 0;
    for (int b = 1; b < threads; ++b) {
      const std::int64_t at = n * b / threads;
      const auto c = static_cast<std::int32_t>(std::upper_bound(list_end(), list_end() + lists, at) - list_end());
      if (c > starts[bands - 1] && c < lists) starts[bands++] = c;
    }
    starts[bands] = lists;
    if (bands_.size() < static_cast<std::size_t>(bands)) bands_.resize(static_cast<std::size_t>(bands));
    const std::size_t own_heads = static_cast<std::size_t>(dim == 3 ? 2 * grid_.n[1] : 2 * grid_.n[0]);
    for (int b = 1; b < bands; ++b) {
      Band& band = bands_[static_cast<std::size_t>(b)];
      band.heads.resize(own_heads, -1);  // all -1 between runs, so resizing with -1 keeps them so
      if (dim == 3) band.rows.resize(static_cast<std::size_t>(5 * grid_.n[0]), -1);
    }
    auto run_band = [&](int b) {
      Band& band = bands_[static_cast<std::size_t>(b)];
      PairList& out = b == 0 ? out_pairs : band.pairs;
      if (dim == 3) {
        layers_3d(band, b == 0 ? y_heads_.data() : band.heads.data(), b == 0 ? x_heads_.data() : band.rows.data(),
                  starts[b], starts[b + 1], options, out);
      } else {
        rows_2d(band, b == 0 ? x_heads_.data() : band.heads.data(), starts[b], starts[b + 1], options, out);
      }
    };
    if (bands == 1) {
      run_band(0);
    } else {
      pool_->run(bands, run_band);
    }
    scatter_next(e.dim, threads);
    last_bands_ = bands;
    if (bands > 1) {
      std::size_t total = out_pairs.size();
      for (int b = 1; b < bands; ++b) total += bands_[static_cast<std::size_t>(b)].pairs.size();
      if (total > options.max_pairs) throw_pair_limit(options.max_pairs);
      out_pairs.reserve(total);
      for (int b = 1; b < bands; ++b) {
        const PairList& p = bands_[static_cast<std::size_t>(b)].pairs;
        out_pairs.insert(out_pairs.end(), p.begin(), p.end());
      }
    }
  } catch (...) {
    reset_heads();
    for (Band& band : bands_) {
      std::fill(band.heads.begin(), band.heads.end(), -1);
      std::fill(band.rows.begin(), band.rows.end(), -1);
    }
    throw;
  }
}

void NbsDetector::scatter_next(int dim, int chunks) {
  const std::int64_t n = static_cast<std::int64_t>(where_.size());
  const bool prefetch = n >= std::int64_t{1} << 18;  // below, everything is in cache
  auto pass = [&](int t) {
    const std::int32_t* const where = where_.data();
    const std::int32_t* const xs = x_sorted_.data();
    const std::int32_t* const ys = y_sorted_.data();
    std::int32_t* const xn = x_next_.data();
    std::int32_t* const yn = y_next_.data();
    const std::int64_t end = n * (t + 1) / chunks;
    for (std::int64_t k = n * t / chunks; k < end; ++k) {
      if (prefetch && k + kPrefetchAhead < end) {
        __builtin_prefetch(xs + where[k + kPrefetchAhead], 0, 3);
        if (dim == 3) __builtin_prefetch(ys + where[k + kPrefetchAhead], 0, 3);
      }
      xn[k] = xs[where[k]];
      if (dim == 3) yn[k] = ys[where[k]];
    }
  };
  if (chunks == 1) {
    pass(0);
  } else {
    pool_->run(chunks, pass);
  }
}

template <int D>
void NbsDetector::gather(std::size_t first, std::size_t count, Slot* out) const {
  const double* p = packed_.data() + first * (D + 1);
  const std::int32_t* const ids = order_.data() + first;
  const AxisCells cell_x(grid_, 0), cell_y(grid_, 1);
  for (std::size_t i = 0; i < count; ++i, p += D + 1) {
    Slot& slot = out[i];
    slot.x = p[0];
    slot.y = p[1];
    slot.r = p[D];
    slot.id = ids[i];
    slot.at = static_cast<std::int32_t>(first + i);
    slot.ix = cell_x(p[0]);
    if constexpr (D == 3) {
      slot.z = p[2];
      slot.iy = cell_y(p[1]);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// 2D: rows of cells. Per non-empty row iy: gather it, push its elements onto B[0] (in y-list
// order; B[1] holds the row below's), test the mask in y-list order, retire the row below.

void NbsDetector::rows_2d(Band& band, std::int32_t* b, std::int32_t first_row, std::int32_t last_row,
                          const DetectOptions& options, PairList& out_pairs) {
  BranchFreePairs pairs(out_pairs, options.max_pairs);
  const auto nx = static_cast<std::int32_t>(grid_.n[0]);
  std::int32_t* const yh = y_heads_.data();
  std::int32_t* const xs = x_sorted_.data();
  // B[0] (row iy's x-list heads) and B[1] (row iy-1's). Row iy-1's lists, rebuilt in B[1] by the
  // book, are the very lists it had in B[0]: its heads are kept and the two halves swap roles.
  std::int32_t* b0 = b;
  std::int32_t* b1 = b + nx;
  const std::int32_t* const row_end = list_end();

  // Keeps the X values of a buffer's elements (none of them is pushed again) at their places in
  // list order when the band owns them (scatter_next() writes X from there), clears the heads its
  // lists used in `heads` and empties it.
  auto retire = [&](Buffer& buf, std::int32_t* heads) {
    const std::size_t m = buf.slots.size();
    const Slot* const s = buf.slots.data();
    if (buf.owned) {
      for (std::size_t i = 0; i < m; ++i) {
        xs[s[i].at] = s[i].last_x;
        heads[s[i].ix] = -1;
      }
    } else {
      for (std::size_t i = 0; i < m; ++i) heads[s[i].ix] = -1;
    }
    buf.empty();
  };
  // Gathers row iy into `buf` in y-list order and builds its x-lists: X[k] = heads[ix]; heads[ix] = k.
  auto load = [&](Buffer& buf, std::int32_t iy, std::int32_t* heads) {
    const std::int32_t first = list_begin(iy);
    const auto m = static_cast<std::size_t>(row_end[iy] - first);
    buf.slots.resize(m);
    buf.list = iy;
    Slot* const s = buf.slots.data();
    gather<2>(static_cast<std::size_t>(first), m, s);
    for (std::size_t i = 0; i < m; ++i) {
      const std::int32_t h = heads[s[i].ix];
      s[i].next = h;
      s[i].last_x = h == -1 ? -1 : s[h].id;
      heads[s[i].ix] = static_cast<std::int32_t>(i);
    }
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

  Buffer* cur = &band.buffers[0];
  Buffer* below = &band.buffers[1];
  cur->empty();
  below->empty();
  // The row below the band, as the serial loop leaves it for the band's first row: its lists in
  // B[1], neither tested nor retired here (the band below owns it).
  if (first_row > 0 && list_begin(first_row - 1) < row_end[first_row - 1]) {
    load(*below, first_row - 1, b1);
    below->owned = false;
  }
  for (std::int32_t iy = first_row; iy < last_row; ++iy) {
    if (list_begin(iy) == row_end[iy]) continue;  // y_heads[iy] == -1
    const bool has_below = iy > 0 && below->list == iy - 1;
    if (!has_below) retire(*below, b1);  // the last row was not iy-1: its lists are done
    load(*cur, iy, b0);
    const Slot* const s = cur->slots.data();
    const std::size_t m = cur->slots.size();
    const Slot* const sb = below->slots.data();
    // The contact mask, element by element in y-list order.
    for (std::size_t i = 0; i < m; ++i) {
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
}

// ---------------------------------------------------------------------------------------------
// 3D: layers of rows. Per non-empty layer iz: gather it, push its elements onto B[0] (in z-list
// order; B[1] holds the layer below's), process each non-empty row when the walk meets its head
// (as the book does), retire the layer below.

void NbsDetector::layers_3d(Band& band, std::int32_t* b, std::int32_t* a, std::int32_t first_layer,
                            std::int32_t last_layer, const DetectOptions& options, PairList& out_pairs) {
  BranchFreePairs pairs(out_pairs, options.max_pairs);
  const auto nx = static_cast<std::int32_t>(grid_.n[0]);
  const auto ny = static_cast<std::int32_t>(grid_.n[1]);
  std::int32_t* const zh = z_heads_.data();
  // B[0] (layer iz's y-list heads) and B[1] (layer iz-1's): as in 2D, the lists the book rebuilds
  // in B[1] are the layer's lists of B[0], so those heads are kept and the halves swap roles.
  std::int32_t* b0 = b;
  std::int32_t* b1 = b + ny;
  std::int32_t* const xs = x_sorted_.data();
  std::int32_t* const ys = y_sorted_.data();
  const std::int32_t* const layer_end = list_end();

  // Keeps the X and Y values of a buffer's elements at their places when the band owns them, clears its y-list
  // heads in `heads`, empties it.
  auto retire = [&](Buffer& buf, std::int32_t* heads) {
    const std::size_t m = buf.slots.size();
    const Slot* const s = buf.slots.data();
    if (buf.owned) {
      for (std::size_t i = 0; i < m; ++i) {
        xs[s[i].at] = s[i].last_x;
        ys[s[i].at] = s[i].last_y;
        heads[s[i].iy] = -1;
      }
    } else {
      for (std::size_t i = 0; i < m; ++i) heads[s[i].iy] = -1;
    }
    buf.empty();
  };
  // Gathers layer iz into `buf`, builds its y-lists (Y[k] = heads[iy]; heads[iy] = k) and regroups
  // it row by row: each row's elements contiguous in y-list order and the rows in the order the
  // book processes them (when the walk of the z-list meets a row's head), so that the five walks of
  // each y-list below are sequential reads, not pointer chasing. heads[iy] then holds where row iy starts.
  auto load = [&](Buffer& buf, std::int32_t iz, std::int32_t* heads) {
    const std::int32_t first = list_begin(iz);
    const auto m = static_cast<std::size_t>(layer_end[iz] - first);
    buf.slots.resize(m);
    buf.list = iz;
    Slot* const s = buf.slots.data();
    gather<3>(static_cast<std::size_t>(first), m, s);
    for (std::size_t i = 0; i < m; ++i) {
      const std::int32_t h = heads[s[i].iy];
      s[i].next = h;
      s[i].last_y = h == -1 ? -1 : s[h].id;
      heads[s[i].iy] = static_cast<std::int32_t>(i);
    }
    band.spare.resize(m);
    Slot* const t = band.spare.data();
    std::size_t placed = 0;
    for (std::size_t i = 0; i < m; ++i) {
      const std::int32_t iy = s[i].iy;
      if (heads[iy] != static_cast<std::int32_t>(i)) continue;
      const auto head = static_cast<std::int32_t>(placed);
      for (std::int32_t j = static_cast<std::int32_t>(i); j != -1; j = s[j].next) t[placed++] = s[j];
      t[head].run = static_cast<std::int32_t>(placed) - head;
      heads[iy] = head;
    }
    buf.slots.swap(band.spare);  // the ungrouped slots are the next layer's spare
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

  Buffer* cur = &band.buffers[0];
  Buffer* below = &band.buffers[1];
  cur->empty();
  below->empty();
  // The layer below the band, as the serial loop leaves it: its y-lists in B[1], its rows grouped.
  if (first_layer > 0 && list_begin(first_layer - 1) < layer_end[first_layer - 1]) {
    load(*below, first_layer - 1, b1);
    below->owned = false;
  }
  for (std::int32_t iz = first_layer; iz < last_layer; ++iz) {
    if (list_begin(iz) == layer_end[iz]) continue;  // C[iz] == -1
    const bool has_below = iz > 0 && below->list == iz - 1;
    if (!has_below) retire(*below, b1);  // the last layer was not iz-1: its lists are done
    load(*cur, iz, b0);
    const std::size_t m = cur->slots.size();
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
}

}  // namespace nbscope
