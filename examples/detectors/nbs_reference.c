/* examples/detectors/nbs_reference.c: Munjiza-NBS in 2D as chapter 3 writes it (book pp.102-104),
 * the reference the five bug plugins beside it are copies of. Every element goes onto the y-list of
 * its row; then, for each non-empty row iy, the x-lists of row iy (heads B[0]) and of row iy-1
 * (heads B[1]) are built with one next array X, each element of row iy is checked against its cell
 * (only the elements after it) and the half mask (ix-1,iy), (ix-1,iy-1), (ix,iy-1), (ix+1,iy-1),
 * and the heads that were set are cleared. Same pairs, in the same order, as nbscope's built-in nbs.
 * Each line of the loops ends in a tag comment "@N": N is the 1-based pseudocode line it belongs to (the
 * trace's line), where scripts/mutants.py expects a bug planted on that line to be located.
 *
 * Build: cc -std=c99 -O2 -shared -fPIC -I<nbscope>/include nbs_reference.c -o nbs_reference.so
 * Run:   nbscope headless --scene assets/scenes/pile.json --detector-lib ./nbs_reference.so */
#include "nbs_plugin.h"

NBS_PLUGIN_INFO("nbs-reference", "Munjiza-NBS 2D as the book writes it (a plugin: the reference of the examples)")

/* Checks k against every element of the x-list that starts at m; nonzero when the pair limit is reached.
 * The arrays and k's disc are read once: add_pair is a call the compiler cannot see into, so it would
 * otherwise load them again through f after every pair. */
static inline int test_list(const nbscope_frame *f, const nbscope_output *out, const nbscope_trace *t, const int32_t *X,
                     int32_t k, int32_t m) {
  const double *x = f->x, *y = f->y, *r = f->r; /* @8 */
  const double xk = x[k], yk = y[k], rk = r[k]; /* @8 */
  for (; m != -1; m = X[m]) { /* @8 */
    const int contact = nbs_in_contact(xk - x[m], yk - y[m], rk + r[m]); /* @8 */
    nbs_tested(t, k, m, contact); /* @8 */
    if (contact && out->add_pair(out->ctx, k, m) != 0) return 1; /* @8 */
  }
  return 0; /* @8 */
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
  nbs_phase(t, NBS_LOOP_ALL, "y-lists", -1); /* @1 */
  for (k = 0; k < n; ++k) { /* @1 */
    iy = nbs_int(y[k], y_min, inv_d, ny); /* @2 */
    cells[2 * k + 1] = iy; /* @2 */
    Y[k] = yh[iy]; /* @2 */
    yh[iy] = k; /* @2 */
    nbs_push(t, NBS_PUSH_Y, "y-list", id.y_heads, iy, id.Y, k, -1, iy); /* @2 */
  }

  /* 2. rows: x-lists of row iy (B[0]) and iy-1 (B[1]), the contact mask, then clearing. */
  for (iy = 0; iy < ny; ++iy) { /* @3 */
    int below; /* @3 */
    if (yh[iy] == -1) continue; /* @3 */
    below = iy > 0 && yh[iy - 1] != -1; /* @3 */
    nbs_phase(t, NBS_LOOP_ROWS, "x-lists of row", iy); /* @3 */
    for (k = yh[iy]; k != -1; k = Y[k]) { /* @4 */
      ix = nbs_int(x[k], x_min, inv_d, nx); /* @4 */
      cells[2 * k] = ix; /* @4 */
      X[k] = B0[ix]; /* @4 */
      B0[ix] = k; /* @4 */
      nbs_push(t, NBS_PUSH_X0, "x-list", id.B, ix, id.X, k, ix, iy); /* @4 */
    }
    if (below) { /* @5 */
      for (k = yh[iy - 1]; k != -1; k = Y[k]) { /* @5 */
        ix = nbs_int(x[k], x_min, inv_d, nx); /* @5 */
        X[k] = B1[ix]; /* @5 */
        B1[ix] = k; /* @5 */
        nbs_push(t, NBS_PUSH_X1, "x-list", id.B, (int64_t)nx + ix, id.X, k, ix, iy - 1); /* @5 */
      }
    }

    nbs_phase(t, NBS_LOOP_ROW, "contacts of row", iy); /* @6 */
    for (k = yh[iy]; k != -1; k = Y[k]) { /* @6 */
      ix = nbs_int(x[k], x_min, inv_d, nx); /* @7 */
      nbs_visit(t, k, ix, iy); /* @7 */
      if (test_list(f, out, t, X, k, X[k])) goto full; /* own cell: only the elements after k */ /* @8 */
      if (ix > 0) { /* @7 */
        nbs_visit(t, k, ix - 1, iy); /* @7 */
        if (test_list(f, out, t, X, k, B0[ix - 1])) goto full; /* @8 */
      }
      if (below) { /* @7 */
        const int32_t last = ix + 1 < nx ? ix + 1 : nx - 1; /* the bound once, as the book loops take it */ /* @7 */
        for (jx = ix > 0 ? ix - 1 : 0; jx <= last; ++jx) { /* @7 */
          nbs_visit(t, k, jx, iy - 1); /* @7 */
          if (test_list(f, out, t, X, k, B1[jx])) goto full; /* @8 */
        }
      }
    }

    nbs_phase(t, NBS_CLEAR_X, "clear x-lists of row", iy); /* @9 */
    for (k = yh[iy]; k != -1; k = Y[k]) { /* @9 */
      ix = nbs_int(x[k], x_min, inv_d, nx); /* @9 */
      if (B0[ix] != -1) { /* @9 */
        B0[ix] = -1; /* @9 */
        nbs_clear(t, NBS_CLEAR_X, "x-list", id.B, ix); /* @9 */
      }
    }
    if (below) { /* @9 */
      for (k = yh[iy - 1]; k != -1; k = Y[k]) { /* @9 */
        ix = nbs_int(x[k], x_min, inv_d, nx); /* @9 */
        if (B1[ix] != -1) { /* @9 */
          B1[ix] = -1; /* @9 */
          nbs_clear(t, NBS_CLEAR_X, "x-list", id.B, (int64_t)nx + ix); /* @9 */
        }
      }
    }
  }

  /* 3. clear the y heads that were set. */
  nbs_phase(t, NBS_CLEAR_Y, "clear y-lists", -1); /* @10 */
  for (k = 0; k < n; ++k) { /* @10 */
    iy = nbs_int(y[k], y_min, inv_d, ny); /* @10 */
    if (yh[iy] != -1) { /* @10 */
      yh[iy] = -1; /* @10 */
      nbs_clear(t, NBS_CLEAR_Y, "y-list", id.y_heads, iy); /* @10 */
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
