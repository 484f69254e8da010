/* examples/detectors/nbs3d_plugin.h: the plumbing of the 3D NBS plugin (nbs3d_reference.c), as
 * nbs_plugin.h is the 2D plugins': nothing here is the algorithm. The arrays a simulation keeps
 * between frames, the grid's integerisation and contact test exactly as nbscope computes them (so
 * that touching pairs and cell borders agree bit for bit), the trace calls, and the info block.
 * Standalone (it does not include nbs_plugin.h), so that the 2D plugins' header can change freely.
 *
 * Index: pseudocode lines | nbs3d_arrays (C, Z, B[2][ny], Y, A[5][nx], X) | nbs3d_int |
 * nbs3d_in_contact | trace helpers | NBS3D_PLUGIN_INFO. */
#ifndef NBSCOPE_EXAMPLE_NBS3D_PLUGIN_H
#define NBSCOPE_EXAMPLE_NBS3D_PLUGIN_H

#include <stddef.h>

#include "nbscope/detector.h"

/* Asks the compiler to inline a function into each caller (the loops, into an untraced and a traced
 * copy); plain `inline` elsewhere. */
#if defined(__GNUC__)
#define NBS3D_INLINE __attribute__((always_inline)) inline
#else
#define NBS3D_INLINE inline
#endif

/* Pseudocode lines (the trace's `line`), the built-in nbs detector's 3D wording (src/core/nbs3d.cpp).
 * NBS3D_LOOP_Z and NBS3D_LOOP_Z_BELOW are loops no trace call names (their pushes name the line
 * below each), as in the built-in. */
enum {
  NBS3D_LOOP_ALL = 0,
  NBS3D_PUSH_Z,
  NBS3D_LOOP_LAYERS,
  NBS3D_LOOP_Z,
  NBS3D_PUSH_Y0,
  NBS3D_LOOP_Z_BELOW,
  NBS3D_PUSH_Y1,
  NBS3D_LOOP_ROWS,
  NBS3D_PUSH_X,
  NBS3D_LOOP_ROW,
  NBS3D_MASK_CELL,
  NBS3D_TEST_PAIR,
  NBS3D_CLEAR_X,
  NBS3D_CLEAR_Y,
  NBS3D_CLEAR_Z,
  NBS3D_LINES
};

static const char *const nbs3d_pseudocode_3d[NBS3D_LINES] = {
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

/* Defines the version symbol, nbscope_detector_describe(), nbscope_release() and nbscope_own_bytes()
 * of a 3D-only NBS plugin: no NBSCOPE_CAP_2D, and no NBSCOPE_CAP_CELLS (the API's cells output is 2D). */
#define NBS3D_PLUGIN_INFO(NAME, SUMMARY)                                                                         \
  NBSCOPE_DETECTOR_PLUGIN();                                                                                     \
  NBSCOPE_EXPORT const nbscope_detector_info *nbscope_detector_describe(void) {                                 \
    static const nbscope_detector_info info = {NBSCOPE_DETECTOR_API_VERSION, NAME, SUMMARY,                     \
                                               NBSCOPE_CAP_3D | NBSCOPE_CAP_TRACES | NBSCOPE_CAP_LISTS,         \
                                               NULL, 0, nbs3d_pseudocode_3d, NBS3D_LINES};                       \
    return &info;                                                                                                \
  }                                                                                                              \
  NBSCOPE_EXPORT void nbscope_release(void *state) { nbs3d_free((nbs3d_arrays *)state); }                      \
  NBSCOPE_EXPORT size_t nbscope_own_bytes(const void *state) { return nbs3d_bytes((const nbs3d_arrays *)state); }

/* The book's arrays (p.123), kept between frames: z-list heads C[nz] and next Z[N]; y-list heads
 * B[2][ny] (B[0] the rows of layer iz, B[1] those of layer iz-1, at B + ny) and next Y[N]; x-list
 * heads A[5][nx] (A[r] the cells of the r-th row the contact mask reaches, at A + r*nx) and next
 * X[N]. Every head is -1 between frames. Sizes are the current frame's. */
typedef struct nbs3d_arrays {
  int32_t *C, *Z, *B, *Y, *A, *X;
  int64_t n, nx, ny, nz;                 /* this frame's sizes */
  int64_t n_cap, nx_cap, ny_cap, nz_cap; /* allocated */
} nbs3d_arrays;

/* Frees the arrays (nbscope_release). */
void nbs3d_free(nbs3d_arrays *s);
/* Bytes of the book's arrays for this frame: nz + 2ny + 5nx + 3N integers (nbscope_own_bytes), as the
 * built-in counts its own. */
size_t nbs3d_bytes(const nbs3d_arrays *s);
/* The arrays for this frame (made on the first call, grown when N or the grid grows, every head -1);
 * NULL after out->fail when memory runs out. */
nbs3d_arrays *nbs3d_prepare(void **state, const nbscope_frame *f, const nbscope_output *out);
/* Every head back to -1 (after a run stopped at the pair limit). */
void nbs3d_reset_heads(nbs3d_arrays *s);

/* Int((v - origin) * inv_d) clamped into [0, n): nbscope's Grid::cell (eq. 3.76), the same expression as
 * nbs_int of nbs_plugin.h; pass the frame's inv_d, so that the cells are nbscope's bit for bit. */
static inline int32_t nbs3d_int(double v, double origin, double inv_d, int64_t n) {
  const double c = (v - origin) * inv_d;
  if (!(c >= 0)) return 0;
  if (c >= (double)n) return (int32_t)(n - 1);
  return (int32_t)c;
}

/* The contact test of nbscope's core (in_contact) on dx = x_i - x_j, dy, dz likewise, rr = r_i + r_j, the
 * same expression: touching counts. */
static inline int nbs3d_in_contact(double dx, double dy, double dz, double rr) {
  return dx * dx + dy * dy + dz * dz <= rr * rr;
}

/* Trace ids of the six arrays (-1 untraced). */
typedef struct nbs3d_ids {
  int C, Z, B, Y, A, X;
} nbs3d_ids;

/* Declares the six arrays when traced, as the built-in nbs names, shapes and orders them. */
nbs3d_ids nbs3d_declare(const nbscope_trace *t, const nbs3d_arrays *s);

static inline void nbs3d_phase(const nbscope_trace *t, int32_t line, const char *label, int32_t index) {
  if (t != NULL) t->phase(t->ctx, line, label, index);
}
static inline void nbs3d_push(const nbscope_trace *t, int32_t line, const char *kind, int heads, int64_t list, int next,
                              int32_t k, int32_t ix, int32_t iy, int32_t iz) {
  if (t != NULL) t->push(t->ctx, line, kind, heads, list, next, k, ix, iy, iz);
}
static inline void nbs3d_clear(const nbscope_trace *t, int32_t line, const char *kind, int heads, int64_t list) {
  if (t != NULL) t->clear(t->ctx, line, kind, heads, list);
}
static inline void nbs3d_visit(const nbscope_trace *t, int32_t k, int32_t ix, int32_t iy, int32_t iz) {
  if (t != NULL) t->visit_cell(t->ctx, NBS3D_MASK_CELL, k, ix, iy, iz);
}
static inline void nbs3d_tested(const nbscope_trace *t, int32_t k, int32_t other, int contact) {
  if (t != NULL) t->test_pair(t->ctx, NBS3D_TEST_PAIR, k, other, contact);
}

#endif /* NBSCOPE_EXAMPLE_NBS3D_PLUGIN_H */
