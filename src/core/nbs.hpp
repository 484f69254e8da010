// nbscope core: `nbs`, the Munjiza-NBS (No Binary Search) detector (book pp.102-123).
//
// 2D: every element is pushed onto the y-list of its row (heads y_heads[ny], next Y[N]); then for
// each non-empty row iy the x-lists of row iy (B[0][nx]) and of row iy-1 (B[1][nx]) are built with
// one next array X[N], every element of row iy is checked against the contact mask
// {(ix,iy) after it, (ix-1,iy), (ix-1..ix+1, iy-1)}, and only the heads that were set are cleared.
// Time O(N + ny), memory ny + 2nx + 2N integers whatever the density.
//
// 3D (p.123, nbs3d.cpp): every element onto the z-list of its layer (heads C[nz], next Z[N]); for
// each non-empty layer iz the y-lists of layers iz and iz-1 (heads B[2][ny], next Y[N]); for each
// non-empty row (iy,iz) the x-lists of the five rows the 3D contact mask reaches, (iy,iz),
// (iy-1,iz), (iy-1,iz-1), (iy,iz-1), (iy+1,iz-1) (heads A[5][nx], next X[N]); then the mask's 13
// neighbour cells and the own cell. Time O(N + nz), memory nz + 2ny + 5nx + 3N integers.
//
// Two paths compute the same arrays and the same pairs in the same order (tests/core/test_nbs_fast.cpp):
// - detect_traced() and detect_book() run the book's loops as written (nbs.cpp, nbs3d.cpp): every
//   list walk follows `next`, so with elements in random memory order each step is a cache miss;
// - detect() runs the fast path (nbs_order.cpp, nbs_fast.cpp): the book's first lists (2D y-lists,
//   3D z-lists) are pushed reading the columns in order, and one counting sort by those lists
//   writes each element's packed record (x, y, r; 3D x, y, z, r) into list order, so the rows
//   (layers) are then read in order, not by walking lists through memory. Each row's (layer's)
//   records are gathered into a buffer with their cells integerised once, the book's pushes and the
//   contact mask run on it in the book's order, and the buffer of the row (layer) below is reused
//   for the next one. The next arrays get each element's last value once, when its buffer is retired.
//   On DetectOptions::threads threads the pushes and the sort run on chunks of the elements and the
//   rows (layers) on bands, each band loading the row (layer) below it as its own; the arrays and
//   the pairs, in their order, are the serial loops' (tests/core/test_nbs_bands.cpp).
//   Extra memory: (D + 1) doubles and 1 integer per element, O(nx + ny) (3D: + nz) per band.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "core/detector.hpp"
#include "core/huge_pages.hpp"
#include "core/worker_pool.hpp"

namespace nbscope {

class NbsDetector final : public Detector {
 public:
  // The detector's loops as the book writes them; TraceEvent::line indexes this list.
  static const std::vector<const char*>& pseudocode_2d();
  // The same for the 3D detector (p.123).
  static const std::vector<const char*>& pseudocode_3d();

  [[nodiscard]] std::string_view name() const override { return "nbs"; }
  [[nodiscard]] bool supports_dim(int dim) const override { return dim == 2 || dim == 3; }
  // The fast path (see above): the book's arrays and pairs, faster.
  void detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) override;
  void detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                     TraceLog& out_trace) override;
  // The book's loops as written, untraced (what the trace compiles to when off; the reference of the fast path).
  void detect_book(const Elements& elements, const DetectOptions& options, PairList& out_pairs);
  // The book's arrays plus the fast path's scratch (order, row offsets, row buffers), in bytes.
  [[nodiscard]] std::size_t own_bytes() const override;
  // The book's arrays alone: 2D ny + 2nx + 2N integers, 3D nz + 2ny + 5nx + 3N (pp.102, 123).
  [[nodiscard]] std::size_t book_bytes() const;
  // Bytes the fast path moves to and from memory per element, from its layout (nbs_fast.cpp): the
  // columns read once in order, the packed records written and read, the next arrays written.
  [[nodiscard]] static std::size_t moved_bytes_per_element(int dim);
  // The bands (threads) the last fast detection ran on: 1 for the serial loops.
  [[nodiscard]] int last_bands() const { return last_bands_; }

  // The book's arrays after the last detection (heads are all -1 again; next arrays hold their last values).
  // 2D: y_heads[ny] and Y[N]; 3D: B[2][ny] (B[s][iy] at s*ny+iy) and Y[N].
  [[nodiscard]] const std::vector<std::int32_t>& y_heads() const { return y_heads_; }
  [[nodiscard]] const std::vector<std::int32_t>& y_next() const { return y_next_; }
  // 2D: B[2][nx] (B[s][ix] at s*nx+ix) and X[N]; 3D: A[5][nx] and X[N].
  [[nodiscard]] const std::vector<std::int32_t>& x_heads() const { return x_heads_; }
  [[nodiscard]] const std::vector<std::int32_t>& x_next() const { return x_next_; }
  // 3D: C[nz] and Z[N]; empty in 2D.
  [[nodiscard]] const std::vector<std::int32_t>& z_heads() const { return z_heads_; }
  [[nodiscard]] const std::vector<std::int32_t>& z_next() const { return z_next_; }
  [[nodiscard]] const Grid* last_grid() const override { return &grid_; }
  [[nodiscard]] const std::vector<const char*>& pseudocode(int dim) const override {
    return dim == 3 ? pseudocode_3d() : pseudocode_2d();
  }

 private:
  template <class Trace>
  void run_2d(const Elements& elements, const DetectOptions& options, PairList& out_pairs, Trace& trace);
  // Sizes the arrays for the current grid and N; every head is -1 afterwards.
  void prepare(std::int64_t n_elements);
  // Restores the all-heads-empty invariant after an interrupted run.
  void reset_heads();
  // 3D (nbs3d.cpp): sizes the 3D arrays; runs untraced when trace is nullptr.
  void prepare_3d(std::int64_t n_elements);
  void detect_3d(const Elements& elements, const DetectOptions& options, PairList& out_pairs, TraceLog* trace);
  template <class Trace>
  void run_3d(const Elements& elements, const DetectOptions& options, PairList& out_pairs, Trace& trace);

  // The fast path (nbs_fast.cpp: the bands of rows or layers; nbs_order.cpp: the first lists and
  // the packed records).
  struct Slot;
  struct Buffer;
  struct Band;
  void run_fast(const Elements& elements, const DetectOptions& options, PairList& out_pairs);
  // The book's first lists (2D: y-lists, y_heads_ and Y; 3D: z-lists, z_heads_ and Z) and a
  // counting sort of the elements by those lists, on `chunks` threads: packed_ holds their records
  // (x, y, r; 3D x, y, z, r) and order_ their ids, each list contiguous and in list order (descending
  // k, as pushing at the head leaves them); list c ends at list_end()[c].
  void order_and_pack(const Elements& elements, int chunks);
  // Where each row's (layer's) run ends in list order, after order_and_pack: chunk 0's counts.
  [[nodiscard]] const std::int32_t* list_end() const { return chunk_lists_.data(); }
  // Where list c's run starts (the end of list c - 1).
  [[nodiscard]] std::int32_t list_begin(std::int32_t c) const { return c == 0 ? 0 : list_end()[c - 1]; }
  // Detects the rows [first, last) (2D) into `out_pairs` with the band's own buffers and heads
  // (x_heads `b` = B[2][nx]); writes X only for those rows' elements.
  void rows_2d(Band& band, std::int32_t* b, std::int32_t first, std::int32_t last, const DetectOptions& options,
               PairList& out_pairs);
  // The same for the layers [first, last) (3D): `b` = B[2][ny], `a` = A[5][nx]; writes X and Y of
  // those layers' elements only.
  void layers_3d(Band& band, std::int32_t* b, std::int32_t* a, std::int32_t first, std::int32_t last,
                 const DetectOptions& options, PairList& out_pairs);
  // Copies the records [first, first + count) of packed_ and order_ into `out`, with ix (3D: and
  // iy) integerised once.
  template <int D>
  void gather(std::size_t first, std::size_t count, Slot* out) const;
  // X (3D: and Y) from the values the bands kept in list order: X[k] = x_sorted_[where_[k]], on
  // `chunks` threads by k, so each thread writes its own lines (bands writing X by id would share
  // every line between the cores).
  void scatter_next(int dim, int chunks);

  // One row's (3D: layer's) elements, gathered for the fast path; indices into it are local.
  struct Slot {
    // Not zeroed (a buffer is resized for every row); the fields a 3D regrouping copies before they
    // are written get a value, so no copy reads an indeterminate one.
    Slot() : xnext(-1), last_x(-1), run(0) {}
    double x, y, z, r;
    ElementId id;
    std::int32_t ix, iy;
    std::int32_t next;    // local next of the x-list (2D) or y-list (3D) it was pushed onto last
    std::int32_t xnext;   // 3D: local next of the x-list it was pushed onto last
    std::int32_t last_x;  // the book's X[id] as last written (global id, -1 ends)
    std::int32_t last_y;  // 3D: the book's Y[id] as last written
    std::int32_t run;     // 3D: at the head of a row, the number of its elements (contiguous from it)
    std::int32_t at;      // its place in list order (order_, x_sorted_)
  };
  struct Buffer {
    std::int32_t list = -1;  // the row (layer) it holds, -1 for none
    bool owned = true;       // false: the row (layer) below a band, loaded for its lists; another band writes its X (Y)
    std::vector<Slot> slots;
    // Holds no row (layer) again.
    void empty() {
      slots.clear();
      list = -1;
      owned = true;
    }
  };
  // What one band's thread works with, kept between detections so that nothing is reallocated.
  struct Band {
    Buffer buffers[2];               // the row (layer) being processed and the one below
    std::vector<Slot> spare;         // 3D: a layer regrouped row by row, then swapped into its buffer
    std::vector<std::int32_t> heads;  // bands after the first: their own B[2] (2D 2nx, 3D 2ny), all -1 between runs
    std::vector<std::int32_t> rows;   // bands after the first, 3D: their own A[5][nx], all -1 between runs
    PairList pairs;                   // bands after the first: their pairs, appended to the first's in band order
  };

  Grid grid_;
  int last_bands_ = 1;
  std::vector<std::int32_t, HugePageAllocator<std::int32_t>> order_;  // fast path: N element ids grouped by row (layer), in list order
  std::vector<double, HugePageAllocator<double>> packed_;  // fast path: their records, D + 1 doubles each, in the same order
  std::vector<std::int32_t, HugePageAllocator<std::int32_t>> where_;  // fast path: each element's place in that order
  std::vector<std::int32_t, HugePageAllocator<std::int32_t>> x_sorted_;  // fast path: X values by place, for scatter_next
  std::vector<std::int32_t, HugePageAllocator<std::int32_t>> y_sorted_;  // fast path, 3D: Y values by place
  std::vector<std::int32_t> chunk_lists_;  // fast path: each chunk's counts (chunk 0's: the lists' ends), heads and firsts per list
  std::vector<Band> bands_;             // fast path: one per band (the first serves the serial path)
  std::unique_ptr<WorkerPool> pool_;    // fast path: the threads of bands after the first, started on first need
  std::vector<std::int32_t> y_heads_;  // 2D: ny heads of the row lists; 3D: B[2][ny] (B[s][iy] at s*ny+iy)
  std::vector<std::int32_t> y_next_;   // Y[N]
  std::vector<std::int32_t> x_heads_;  // 2D: B[2][nx] (B[s][ix] at s*nx+ix); 3D: A[5][nx] (A[r][ix] at r*nx+ix)
  std::vector<std::int32_t> x_next_;   // X[N]
  std::vector<std::int32_t> z_heads_;  // 3D: C[nz], heads of the layer lists; empty in 2D
  std::vector<std::int32_t> z_next_;   // 3D: Z[N]; empty in 2D
};

}  // namespace nbscope
