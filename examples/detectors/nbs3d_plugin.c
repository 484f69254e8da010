/* examples/detectors/nbs3d_plugin.c: the plumbing of nbs3d_plugin.h (arrays, trace declarations),
 * compiled into the 3D NBS plugin. */
#include "nbs3d_plugin.h"

#include <stdlib.h>

/* Grows `*p` from `old` to `want` entries, new ones set to `fill`; 0 when out of memory. */
static int nbs3d_grow(int32_t **p, int64_t old, int64_t want, int32_t fill) {
  int32_t *q;
  int64_t k;
  if (want <= old) return 1;
  q = (int32_t *)realloc(*p, (size_t)want * sizeof(int32_t));
  if (q == NULL) return 0;
  for (k = old; k < want; ++k) q[k] = fill;
  *p = q;
  return 1;
}

void nbs3d_free(nbs3d_arrays *s) {
  if (s == NULL) return;
  free(s->C);
  free(s->Z);
  free(s->B);
  free(s->Y);
  free(s->A);
  free(s->X);
  free(s);
}

size_t nbs3d_bytes(const nbs3d_arrays *s) {
  return s == NULL ? 0 : (size_t)(s->nz + 2 * s->ny + 5 * s->nx + 3 * s->n) * sizeof(int32_t);
}

/* The arrays for this frame (made on the first call, grown when N or the grid grows); NULL after
 * out->fail when memory runs out. A head beyond this frame's grid stays -1 (every head is -1 between
 * frames), so a smaller grid reuses the arrays as they are; B[1] and A[r] start at ny and r*nx of
 * this frame, so the heads a frame uses are -1 whatever the last frame's sizes were. */
nbs3d_arrays *nbs3d_prepare(void **state, const nbscope_frame *f, const nbscope_output *out) {
  nbs3d_arrays *s = (nbs3d_arrays *)*state;
  if (s == NULL) {
    s = (nbs3d_arrays *)calloc(1, sizeof *s);
    if (s == NULL) {
      out->fail(out->ctx, "out of memory");
      return NULL;
    }
    *state = s;
  }
  if (!nbs3d_grow(&s->C, s->nz_cap, f->cells[2], -1) || !nbs3d_grow(&s->B, 2 * s->ny_cap, 2 * f->cells[1], -1) ||
      !nbs3d_grow(&s->A, 5 * s->nx_cap, 5 * f->cells[0], -1) || !nbs3d_grow(&s->Z, s->n_cap, f->n, 0) ||
      !nbs3d_grow(&s->Y, s->n_cap, f->n, 0) || !nbs3d_grow(&s->X, s->n_cap, f->n, 0)) {
    out->fail(out->ctx, "out of memory");
    return NULL;
  }
  if (f->cells[2] > s->nz_cap) s->nz_cap = f->cells[2];
  if (f->cells[1] > s->ny_cap) s->ny_cap = f->cells[1];
  if (f->cells[0] > s->nx_cap) s->nx_cap = f->cells[0];
  if (f->n > s->n_cap) s->n_cap = f->n;
  s->n = f->n;
  s->nx = f->cells[0];
  s->ny = f->cells[1];
  s->nz = f->cells[2];
  return s;
}

/* Every head back to -1 (after a run stopped at the pair limit). */
void nbs3d_reset_heads(nbs3d_arrays *s) {
  int64_t k;
  for (k = 0; k < s->nz; ++k) s->C[k] = -1;
  for (k = 0; k < 2 * s->ny; ++k) s->B[k] = -1;
  for (k = 0; k < 5 * s->nx; ++k) s->A[k] = -1;
}

/* Declares the six arrays when traced, as the built-in nbs names, shapes and orders them. */
nbs3d_ids nbs3d_declare(const nbscope_trace *t, const nbs3d_arrays *s) {
  nbs3d_ids id = {-1, -1, -1, -1, -1, -1};
  int64_t shape[2];
  if (t == NULL) return id;
  shape[0] = s->nz;
  id.C = t->declare_array(t->ctx, "C", 1, shape, s->C);
  shape[0] = s->n;
  id.Z = t->declare_array(t->ctx, "Z", 1, shape, s->Z);
  shape[0] = 2;
  shape[1] = s->ny;
  id.B = t->declare_array(t->ctx, "B", 2, shape, s->B);
  shape[0] = s->n;
  id.Y = t->declare_array(t->ctx, "Y", 1, shape, s->Y);
  shape[0] = 5;
  shape[1] = s->nx;
  id.A = t->declare_array(t->ctx, "A", 2, shape, s->A);
  shape[0] = s->n;
  id.X = t->declare_array(t->ctx, "X", 1, shape, s->X);
  return id;
}
