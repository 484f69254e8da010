/* examples/detectors/nbs_plugin.c: the shared plumbing of nbs_plugin.h (arrays, trace declarations),
 * compiled into each example plugin. */
#include "nbs_plugin.h"

#include <stdlib.h>

/* Grows `*p` from `old` to `want` entries, new ones set to `fill`; 0 when out of memory. */
static int nbs_grow(int32_t **p, int64_t old, int64_t want, int32_t fill) {
  int32_t *q;
  int64_t k;
  if (want <= old) return 1;
  q = (int32_t *)realloc(*p, (size_t)want * sizeof(int32_t));
  if (q == NULL) return 0;
  for (k = old; k < want; ++k) q[k] = fill;
  *p = q;
  return 1;
}

void nbs_free(nbs_arrays *s) {
  if (s == NULL) return;
  free(s->y_heads);
  free(s->Y);
  free(s->B);
  free(s->X);
  free(s);
}

size_t nbs_bytes(const nbs_arrays *s) {
  return s == NULL ? 0 : (size_t)(s->ny + 2 * s->nx + 2 * s->n) * sizeof(int32_t);
}

/* The arrays for this frame (made on the first call, grown when N or the grid grows); NULL after
 * out->fail when memory runs out. */
nbs_arrays *nbs_prepare(void **state, const nbscope_frame *f, const nbscope_output *out) {
  nbs_arrays *s = (nbs_arrays *)*state;
  if (s == NULL) {
    s = (nbs_arrays *)calloc(1, sizeof *s);
    if (s == NULL) {
      out->fail(out->ctx, "out of memory");
      return NULL;
    }
    *state = s;
  }
  if (!nbs_grow(&s->y_heads, s->ny_cap, f->cells[1], -1) || !nbs_grow(&s->B, 2 * s->nx_cap, 2 * f->cells[0], -1) ||
      !nbs_grow(&s->Y, s->n_cap, f->n, 0) || !nbs_grow(&s->X, s->n_cap, f->n, 0)) {
    out->fail(out->ctx, "out of memory");
    return NULL;
  }
  if (f->cells[1] > s->ny_cap) s->ny_cap = f->cells[1];
  if (f->cells[0] > s->nx_cap) s->nx_cap = f->cells[0];
  if (f->n > s->n_cap) s->n_cap = f->n;
  s->n = f->n;
  s->nx = f->cells[0];
  s->ny = f->cells[1];
  return s;
}

/* Every head back to -1 (after a run stopped at the pair limit). */
void nbs_reset_heads(nbs_arrays *s) {
  int64_t k;
  for (k = 0; k < s->ny; ++k) s->y_heads[k] = -1;
  for (k = 0; k < 2 * s->nx; ++k) s->B[k] = -1;
}

/* Declares the four arrays when traced, as the built-in nbs names and shapes them. */
nbs_ids nbs_declare(const nbscope_trace *t, const nbs_arrays *s) {
  nbs_ids id = {-1, -1, -1, -1};
  int64_t shape[2];
  if (t == NULL) return id;
  shape[0] = s->ny;
  id.y_heads = t->declare_array(t->ctx, "y_heads", 1, shape, s->y_heads);
  shape[0] = s->n;
  id.Y = t->declare_array(t->ctx, "Y", 1, shape, s->Y);
  shape[0] = 2;
  shape[1] = s->nx;
  id.B = t->declare_array(t->ctx, "B", 2, shape, s->B);
  shape[0] = s->n;
  id.X = t->declare_array(t->ctx, "X", 1, shape, s->X);
  return id;
}

