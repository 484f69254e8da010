/* examples/detectors/nbs_plugin.h: the plumbing the six example plugins share, so that the files
 * differ only where the algorithm does. Nothing here is the algorithm: the arrays a simulation keeps
 * between frames, the grid's integerisation and contact test exactly as nbscope computes them (so
 * that touching pairs and cell borders agree bit for bit), the trace calls, and the info block.
 *
 * Index: pseudocode lines | nbs_arrays (y_heads, Y, B[2][nx], X) | nbs_int | nbs_in_contact |
 * trace helpers | NBS_PLUGIN_INFO. */
#ifndef NBSCOPE_EXAMPLE_NBS_PLUGIN_H
#define NBSCOPE_EXAMPLE_NBS_PLUGIN_H

#include <stddef.h>

#include "nbscope/detector.h"

/* Asks the compiler to inline a function into each caller (the loops, into an untraced and a traced
 * copy); plain `inline` elsewhere. */
#if defined(__GNUC__)
#define NBS_INLINE __attribute__((always_inline)) inline
#else
#define NBS_INLINE inline
#endif

/* Pseudocode lines (the trace's `line`), the built-in nbs detector's wording. */
enum {
  NBS_LOOP_ALL = 0,
  NBS_PUSH_Y,
  NBS_LOOP_ROWS,
  NBS_PUSH_X0,
  NBS_PUSH_X1,
  NBS_LOOP_ROW,
  NBS_MASK_CELL,
  NBS_TEST_PAIR,
  NBS_CLEAR_X,
  NBS_CLEAR_Y,
  NBS_LINES
};

static const char *const nbs_pseudocode_2d[NBS_LINES] = {
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

/* Defines the version symbol, nbscope_detector_describe() and nbscope_release() of a 2D NBS plugin. */
#define NBS_PLUGIN_INFO(NAME, SUMMARY)                                                                           \
  NBSCOPE_DETECTOR_PLUGIN();                                                                                     \
  NBSCOPE_EXPORT const nbscope_detector_info *nbscope_detector_describe(void) {                                 \
    static const nbscope_detector_info info = {NBSCOPE_DETECTOR_API_VERSION, NAME, SUMMARY,                     \
                                               NBSCOPE_CAP_2D | NBSCOPE_CAP_TRACES | NBSCOPE_CAP_LISTS |        \
                                                   NBSCOPE_CAP_CELLS,                                            \
                                               nbs_pseudocode_2d, NBS_LINES, NULL, 0};                           \
    return &info;                                                                                                \
  }                                                                                                              \
  NBSCOPE_EXPORT void nbscope_release(void *state) { nbs_free((nbs_arrays *)state); }                          \
  NBSCOPE_EXPORT size_t nbscope_own_bytes(const void *state) { return nbs_bytes((const nbs_arrays *)state); }

/* The book's arrays, kept between frames: heads y_heads[ny] and B[2][nx] (B[1] at B + nx), next
 * arrays Y[N] and X[N]; every head is -1 between frames. Sizes are the current frame's. */
typedef struct nbs_arrays {
  int32_t *y_heads, *Y, *B, *X;
  int64_t n, nx, ny;            /* this frame's sizes */
  int64_t n_cap, nx_cap, ny_cap; /* allocated */
} nbs_arrays;

/* Frees the arrays (nbscope_release). */
void nbs_free(nbs_arrays *s);
/* Bytes of the book's arrays for this frame: ny + 2nx + 2N integers (nbscope_own_bytes). */
size_t nbs_bytes(const nbs_arrays *s);
/* The arrays for this frame (made on the first call, grown when N or the grid grows, every head -1);
 * NULL after out->fail when memory runs out. */
nbs_arrays *nbs_prepare(void **state, const nbscope_frame *f, const nbscope_output *out);
/* Every head back to -1 (after a run stopped at the pair limit). */
void nbs_reset_heads(nbs_arrays *s);
/* Int((v - origin) * inv_d) clamped into [0, n): nbscope's Grid::cell (eq. 3.76); pass the frame's inv_d,
 * so that the cells are nbscope's bit for bit. */
static inline int32_t nbs_int(double v, double origin, double inv_d, int64_t n) {
  const double c = (v - origin) * inv_d;
  if (!(c >= 0)) return 0;
  if (c >= (double)n) return (int32_t)(n - 1);
  return (int32_t)c;
}

/* The contact test of nbscope's core (in_contact) on dx = x_i - x_j, dy = y_i - y_j, rr = r_i + r_j, the
 * same expression: touching counts. */
static inline int nbs_in_contact(double dx, double dy, double rr) { return dx * dx + dy * dy <= rr * rr; }

/* Trace ids of the four arrays (-1 untraced). */
typedef struct nbs_ids {
  int y_heads, Y, B, X;
} nbs_ids;

/* Declares the four arrays when traced, as the built-in nbs names and shapes them. */
nbs_ids nbs_declare(const nbscope_trace *t, const nbs_arrays *s);

static inline void nbs_phase(const nbscope_trace *t, int32_t line, const char *label, int32_t index) {
  if (t != NULL) t->phase(t->ctx, line, label, index);
}
static inline void nbs_push(const nbscope_trace *t, int32_t line, const char *kind, int heads, int64_t list, int next,
                            int32_t k, int32_t ix, int32_t iy) {
  if (t != NULL) t->push(t->ctx, line, kind, heads, list, next, k, ix, iy, -1);
}
static inline void nbs_clear(const nbscope_trace *t, int32_t line, const char *kind, int heads, int64_t list) {
  if (t != NULL) t->clear(t->ctx, line, kind, heads, list);
}
static inline void nbs_visit(const nbscope_trace *t, int32_t k, int32_t ix, int32_t iy) {
  if (t != NULL) t->visit_cell(t->ctx, NBS_MASK_CELL, k, ix, iy, -1);
}
static inline void nbs_tested(const nbscope_trace *t, int32_t k, int32_t other, int contact) {
  if (t != NULL) t->test_pair(t->ctx, NBS_TEST_PAIR, k, other, contact);
}

#endif /* NBSCOPE_EXAMPLE_NBS_PLUGIN_H */
