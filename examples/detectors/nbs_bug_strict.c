/* examples/detectors/nbs_bug_strict.c: Munjiza-NBS 2D whose contact test is strict.
 * Otherwise nbs_reference.c, line for line; the bug is marked BUG.
 *
 * Two discs touch when the distance of their centres equals the sum of their radii; the book's
 * test (and nbscope's) counts them, `<=`. A strict `<` loses every exactly touching pair: a lattice
 * of equal discs, or the book's Fig. 3.15 elements 1 and 2 once they touch. nbscope: A==R (missing
 * from A), the Stepper at the test that answered apart.
 */
#include "nbs_plugin.h"

NBS_PLUGIN_INFO("nbs-bug-strict", "NBS 2D whose contact test is strict: touching discs are apart (an example bug)")

/* The contact test of two discs on dx = x_i - x_j, dy = y_i - y_j, rr = r_i + r_j. */
static int in_contact_strict(double dx, double dy, double rr) {
  return dx * dx + dy * dy < rr * rr; /* BUG: touching discs (distance == r_i + r_j) are taken as apart */
}

/* Checks k against every element of the x-list that starts at m; nonzero when the pair limit is reached.
 * The arrays and k's disc are read once: add_pair is a call the compiler cannot see into, so it would
 * otherwise load them again through f after every pair. */
static inline int test_list(const nbscope_frame *f, const nbscope_output *out, const nbscope_trace *t, const int32_t *X,
                     int32_t k, int32_t m) {
  const double *x = f->x, *y = f->y, *r = f->r;
  const double xk = x[k], yk = y[k], rk = r[k];
  for (; m != -1; m = X[m]) {
    const int contact = in_contact_strict(xk - x[m], yk - y[m], rk + r[m]);
    nbs_tested(t, k, m, contact);
    if (contact && out->add_pair(out->ctx, k, m) != 0) return 1;
  }
  return 0;
}

/* The loops, once: nbscope_detect below makes two copies of them, one for t == NULL. */
static NBS_INLINE int detect_frame(void **state, const nbscope_frame *f, const nbscope_output *out,
                                   const nbscope_trace *t) {
  nbs_arrays *s = nbs_prepare(state, f, out);
  nbs_ids id;
  const double *x, *y;
  double x_min, y_min, inv_d;
  int32_t n, nx, ny, k, ix, iy, jx, *yh, *Y, *B0, *B1, *X, *cells;
  if (s == NULL) return 1;
  n = (int32_t)f->n;
  nx = (int32_t)f->cells[0];
  ny = (int32_t)f->cells[1];
  x = f->x; /* the frame's fields in locals, loaded once (not again after every add_pair) */
  y = f->y;
  x_min = f->origin[0];
  y_min = f->origin[1];
  inv_d = f->inv_d; /* nbscope's 1/d: cells equal to its grid's, bit for bit */
  cells = out->cells;
  yh = s->y_heads;
  Y = s->Y;
  B0 = s->B;
  B1 = s->B + nx;
  X = s->X;
  id = nbs_declare(t, s);

  /* 1. y-lists: every element onto the list of its row. */
  nbs_phase(t, NBS_LOOP_ALL, "y-lists", -1);
  for (k = 0; k < n; ++k) {
    iy = nbs_int(y[k], y_min, inv_d, ny);
    cells[2 * k + 1] = iy;
    Y[k] = yh[iy];
    yh[iy] = k;
    nbs_push(t, NBS_PUSH_Y, "y-list", id.y_heads, iy, id.Y, k, -1, iy);
  }

  /* 2. rows: x-lists of row iy (B[0]) and iy-1 (B[1]), the contact mask, then clearing. */
  for (iy = 0; iy < ny; ++iy) {
    int below;
    if (yh[iy] == -1) continue;
    below = iy > 0 && yh[iy - 1] != -1;
    nbs_phase(t, NBS_LOOP_ROWS, "x-lists of row", iy);
    for (k = yh[iy]; k != -1; k = Y[k]) {
      ix = nbs_int(x[k], x_min, inv_d, nx);
      cells[2 * k] = ix;
      X[k] = B0[ix];
      B0[ix] = k;
      nbs_push(t, NBS_PUSH_X0, "x-list", id.B, ix, id.X, k, ix, iy);
    }
    if (below) {
      for (k = yh[iy - 1]; k != -1; k = Y[k]) {
        ix = nbs_int(x[k], x_min, inv_d, nx);
        X[k] = B1[ix];
        B1[ix] = k;
        nbs_push(t, NBS_PUSH_X1, "x-list", id.B, (int64_t)nx + ix, id.X, k, ix, iy - 1);
      }
    }

    nbs_phase(t, NBS_LOOP_ROW, "contacts of row", iy);
    for (k = yh[iy]; k != -1; k = Y[k]) {
      ix = nbs_int(x[k], x_min, inv_d, nx);
      nbs_visit(t, k, ix, iy);
      if (test_list(f, out, t, X, k, X[k])) goto full; /* own cell: only the elements after k */
      if (ix > 0) {
        nbs_visit(t, k, ix - 1, iy);
        if (test_list(f, out, t, X, k, B0[ix - 1])) goto full;
      }
      if (below) {
        const int32_t last = ix + 1 < nx ? ix + 1 : nx - 1; /* the bound once, as the book loops take it */
        for (jx = ix > 0 ? ix - 1 : 0; jx <= last; ++jx) {
          nbs_visit(t, k, jx, iy - 1);
          if (test_list(f, out, t, X, k, B1[jx])) goto full;
        }
      }
    }

    nbs_phase(t, NBS_CLEAR_X, "clear x-lists of row", iy);
    for (k = yh[iy]; k != -1; k = Y[k]) {
      ix = nbs_int(x[k], x_min, inv_d, nx);
      if (B0[ix] != -1) {
        B0[ix] = -1;
        nbs_clear(t, NBS_CLEAR_X, "x-list", id.B, ix);
      }
    }
    if (below) {
      for (k = yh[iy - 1]; k != -1; k = Y[k]) {
        ix = nbs_int(x[k], x_min, inv_d, nx);
        if (B1[ix] != -1) {
          B1[ix] = -1;
          nbs_clear(t, NBS_CLEAR_X, "x-list", id.B, (int64_t)nx + ix);
        }
      }
    }
  }

  /* 3. clear the y heads that were set. */
  nbs_phase(t, NBS_CLEAR_Y, "clear y-lists", -1);
  for (k = 0; k < n; ++k) {
    iy = nbs_int(y[k], y_min, inv_d, ny);
    if (yh[iy] != -1) {
      yh[iy] = -1;
      nbs_clear(t, NBS_CLEAR_Y, "y-list", id.y_heads, iy);
    }
  }
  return 0;

full:
  nbs_reset_heads(s);
  return 1;
}

/* Untraced frames run a copy of the loops in which t is a constant NULL, so every trace call and
 * its `t != NULL` test compile away (as C++ would with a template); traced frames run the other. */
NBSCOPE_EXPORT int nbscope_detect(void **state, const nbscope_frame *f, const nbscope_output *out,
                                  const nbscope_trace *t) {
  if (t == NULL) return detect_frame(state, f, out, NULL);
  return detect_frame(state, f, out, t);
}
