// Munjiza-NBS fast path, first part (see nbs.hpp): the book's first lists (2D y-lists, 3D z-lists)
// and the elements' packed records in list order, so that the rest reads one record per element,
// in order, instead of following lists through memory.
//
// Index: moved_bytes_per_element | order_and_pack (three passes, each on `chunks` threads).
//
// Why packed records sorted by list: three layouts measured back to back (2D loose and dense, 1e6
// elements in random memory order, one thread, best of 7, ns per element):
// - the columns gathered in list order, prefetched 16 elements ahead (the fast path before; this
//   frame's order as the prefetch order): three random lines per element, 47.8 and 107.6;
// - records packed in k order, gathered in list order: one random line per element, 53.4 and 106.9;
// - records placed straight into list order by the counting sort (kept): every record is written
//   once, into one of ny streams that each fill their cache lines in turn, and read once in order,
//   37.7 and 91.2. The only random access left is one read per element when X (3D: and Y) is
//   written by k (scatter_next, nbs_fast.cpp).
#include <algorithm>

#include "core/nbs.hpp"

namespace nbscope {

namespace {
// How many elements ahead the placing pass asks for the line a record will be written to.
constexpr std::int64_t kPlaceAhead = 16;
// From this many elements (their records, 6 MB in 2D, outgrow the second-level caches).
constexpr std::int64_t kPlaceAheadFrom = std::int64_t{1} << 18;
}  // namespace

std::size_t NbsDetector::moved_bytes_per_element(int dim) {
  // Per element, from the layout below and in nbs_fast.cpp; a written line is counted twice (a
  // cached store first reads the line it writes).
  constexpr std::size_t id = sizeof(std::int32_t);
  constexpr std::size_t line = 64;
  const std::size_t record = static_cast<std::size_t>(dim + 1) * sizeof(double);
  const std::size_t lists = dim == 3 ? 2 : 1;                    // next arrays the bands compute: X (3D: and Y)
  const std::size_t first_lists = sizeof(double) + 2 * id;       // read the axis, write Y (3D: Z)
  const std::size_t place = record + 2 * (record + id + id);     // read the columns; write record, id and place
  const std::size_t gather = record + id;                        // read record and id in order
  const std::size_t retire = lists * 2 * id;                     // the values kept in list order
  const std::size_t scatter = id + lists * (line + 2 * id);      // by k: read the place, a random line, write X
  return first_lists + place + gather + retire + scatter;
}

void NbsDetector::order_and_pack(const Elements& e, int chunks) {
  const int axis = e.dim - 1;  // 2D: rows (y); 3D: layers (z)
  const int width = e.dim + 1;  // doubles per record
  const std::int64_t n = e.size();
  const auto lists = static_cast<std::int32_t>(grid_.n[axis]);
  const auto list_count = static_cast<std::size_t>(lists);
  std::int32_t* const heads = axis == 1 ? y_heads_.data() : z_heads_.data();
  std::int32_t* const next = axis == 1 ? y_next_.data() : z_next_.data();
  const double* const v = e.axis(axis).data();
  const double* const px = e.x.data();
  const double* const py = e.y.data();
  const double* const pz = e.dim == 3 ? e.z.data() : nullptr;
  const double* const pr = e.r.data();

  // Per chunk: counts[lists] (then where its elements of each list go; chunk 0's end as each list's
  // end, list_end()); for the chunks after the first also heads[lists] (its last element of each
  // list) and firsts[lists] (its first: the one whose next follows on from the chunks before).
  chunk_lists_.resize(list_count * static_cast<std::size_t>(3 * chunks - 2));
  auto counts = [&](int t) { return chunk_lists_.data() + static_cast<std::size_t>(t) * list_count; };
  auto chunk_heads = [&](int t) {
    return t == 0 ? heads : chunk_lists_.data() + list_count * static_cast<std::size_t>(chunks + 2 * (t - 1));
  };
  auto firsts = [&](int t) { return chunk_heads(t) + list_count; };
  auto chunk_begin = [&](int t) { return n * t / chunks; };

  // 1. The book's pushes, k ascending within each chunk: next[k] = heads[c]; heads[c] = k.
  const AxisCells cell_of(grid_, axis);
  // Prefetching where each record goes pays once the arrays outgrow the caches and only costs before.
  const bool prefetch = n >= kPlaceAheadFrom;
  auto push = [&](int t) {
    const AxisCells cell = cell_of;
    const double* const axis_v = v;
    std::int32_t* const list_next = next;
    std::int32_t* const count = counts(t);
    std::int32_t* const head = chunk_heads(t);
    std::fill(count, count + list_count, 0);
    const std::int64_t end = chunk_begin(t + 1);
    if (t == 0) {  // onto the book's heads, all -1 now
      for (std::int64_t k = 0; k < end; ++k) {
        const std::int32_t c = cell(axis_v[k]);
        list_next[k] = head[c];
        head[c] = static_cast<std::int32_t>(k);
        ++count[c];
      }
      return;
    }
    std::int32_t* const first = firsts(t);
    std::fill(head, head + list_count, -1);
    std::fill(first, first + list_count, -1);
    for (std::int64_t k = chunk_begin(t); k < end; ++k) {
      const std::int32_t c = cell(axis_v[k]);
      const std::int32_t h = head[c];
      if (h == -1) first[c] = static_cast<std::int32_t>(k);
      list_next[k] = h;
      head[c] = static_cast<std::int32_t>(k);
      ++count[c];
    }
  };
  // 3. Each chunk places its elements, k descending, at its place in each list's run; chunk 0 fills
  // each run's end, so its counts end as the lists' ends (list_end()).
  auto place = [&](int t) {
    const AxisCells cell = cell_of;
    const double* const axis_v = v;
    const double* const x = px;
    const double* const y = py;
    const double* const z = pz;
    const double* const r = pr;
    std::int32_t* const at = counts(t);
    std::int32_t* const order = order_.data();
    std::int32_t* const where = where_.data();
    double* const packed = packed_.data();
    const std::int64_t begin = chunk_begin(t);
    for (std::int64_t k = chunk_begin(t + 1) - 1; k >= begin; --k) {
      // The line the record of an element further on will go to: its list's place now is where
      // it goes or just before, so the write finds the line in cache (each stream's lines are
      // otherwise fetched one miss at a time).
      if (prefetch && k - kPlaceAhead >= begin) {
        const std::int32_t ahead = at[cell(axis_v[k - kPlaceAhead])];
        __builtin_prefetch(packed + static_cast<std::ptrdiff_t>(ahead) * width, 1, 3);
        __builtin_prefetch(order + ahead, 1, 3);
      }
      // The cell again, not kept from the pushes: a multiply is cheaper than writing and reading N integers.
      const std::int32_t pos = at[cell(axis_v[k])]++;
      order[pos] = static_cast<std::int32_t>(k);
      where[k] = pos;
      double* const rec = packed + static_cast<std::ptrdiff_t>(pos) * width;
      rec[0] = x[k];
      rec[1] = y[k];
      if (z) {
        rec[2] = z[k];
        rec[3] = r[k];
      } else {
        rec[2] = r[k];
      }
    }
  };

  order_.resize(static_cast<std::size_t>(n));
  where_.resize(static_cast<std::size_t>(n));
  packed_.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(width));
  if (chunks == 1) {
    push(0);
  } else {
    pool_->run(chunks, push);
  }
  // 2. Join the chunks' lists (the first element of a chunk in list c follows the chunks before's
  // last), and turn the counts into places: list c's run starts after the lists before it, and the
  // chunks fill it from the last (highest k) to the first.
  for (int t = 1; t < chunks; ++t) {
    const std::int32_t* const first = firsts(t);
    const std::int32_t* const head = chunk_heads(t);
    for (std::int32_t c = 0; c < lists; ++c) {
      if (first[c] == -1) continue;
      next[first[c]] = heads[c];
      heads[c] = head[c];
    }
  }
  std::int32_t start = 0;
  for (std::int32_t c = 0; c < lists; ++c) {
    for (int t = chunks - 1; t >= 0; --t) {
      std::int32_t* const count = counts(t);
      const std::int32_t m = count[c];
      count[c] = start;
      start += m;
    }
  }
  if (chunks == 1) {
    place(0);
  } else {
    pool_->run(chunks, place);
  }
}

}  // namespace nbscope
