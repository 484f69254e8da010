/* examples/detectors/nbs3d_reference.c: Munjiza-NBS in 3D as chapter 3 generalises it (book p.123),
 * the 3D counterpart of nbs_reference.c. Every element goes onto the z-list of its layer (heads C,
 * next Z); then, for each non-empty layer iz, the elements of layer iz go onto the y-lists of its
 * rows (heads B[0]) and those of layer iz-1 onto theirs (heads B[1]), with one next array Y; for
 * each non-empty row (iy, iz), met at the head of its y-list, the x-lists of the five rows its
 * contact mask reaches, (iy,iz), (iy-1,iz), (iy-1,iz-1), (iy,iz-1), (iy+1,iz-1) (heads A[0..4]), are
 * built with one next array X, each element of the row is checked against its cell (only the
 * elements after it), (ix-1,iy,iz) and the cells ix-1..ix+1 of the other four rows, and the heads
 * that were set are cleared: the x heads per row, the y heads per layer, the z heads at the end.
 * Same pairs, in the same order, and the same trace, as nbscope's built-in nbs on a 3D frame (open
 * grids: nbscope gives plugins no periodic frame), but for one thing the API cannot say: the
 * built-in's phases of a layer or row also name its cell (the layer iz), the plugin's their index alone.
 * Each line of the loops ends in a tag comment "@N": N is the 1-based pseudocode line it belongs to (the
 * trace's line), where a bug planted on that line should be located.
 *
 * Build: cc -std=c99 -O2 -shared -fPIC -I<nbscope>/include nbs3d_reference.c nbs3d_plugin.c -o nbs3d_reference.so
 * Run:   nbscope pairs --input assets/examples/pour3d/atoms.6000.dump --detector-lib ./nbs3d_reference.so */
#include "nbs3d_plugin.h"

NBS3D_PLUGIN_INFO("nbs3d-reference", "Munjiza-NBS 3D as the book writes it (a plugin: the examples' 3D reference)")

/* The rows whose x-lists the contact mask of row (iy, iz) reaches, as offsets (dy, dz); A[r] holds the
 * heads of row r, and its y-list is on B[0] (dz = 0) or B[1] (dz = -1). */
static const int32_t row_dy[5] = {0, -1, -1, 0, 1};
static const int32_t row_dz[5] = {0, 0, -1, -1, -1};

/* Checks k against every element of the x-list that starts at m; nonzero when the pair limit is reached.
 * The arrays and k's sphere are read once: add_pair is a call the compiler cannot see into, so it would
 * otherwise load them again through f after every pair. */
static inline int test_list(const nbscope_frame *f, const nbscope_output *out, const nbscope_trace *t, const int32_t *X,
                            int32_t k, int32_t m) {
  const double *x = f->x, *y = f->y, *z = f->z, *r = f->r; /* @12 */
  const double xk = x[k], yk = y[k], zk = z[k], rk = r[k]; /* @12 */
  for (; m != -1; m = X[m]) { /* @12 */
    const int contact = nbs3d_in_contact(xk - x[m], yk - y[m], zk - z[m], rk + r[m]); /* @12 */
    nbs3d_tested(t, k, m, contact); /* @12 */
    if (contact && out->add_pair(out->ctx, k, m) != 0) return 1; /* @12 */
  }
  return 0; /* @12 */
}

/* One non-empty row (iy, iz) of layer iz: the x-lists of the five rows its mask reaches, the contacts of
 * its elements, then clearing of the x heads that were set; nonzero when the pair limit is reached. */
static NBS3D_INLINE int detect_row(const nbscope_frame *f, const nbscope_output *out, const nbscope_trace *t,
                                   const nbs3d_ids *id, nbs3d_arrays *s, int32_t iy, int32_t iz, int below) {
  const double *x = f->x;
  const double x_min = f->origin[0], inv_d = f->inv_d;
  const int32_t nx = (int32_t)s->nx, ny = (int32_t)s->ny;
  const int32_t *B = s->B, *Y = s->Y;
  int32_t *X = s->X;
  int32_t *A[5];     /* A[r]: the x heads of row r (at s->A + r*nx) */
  int32_t row_y[5];  /* the five rows' iy, -1 past an open edge */
  int32_t row_z[5];  /* and their iz: iz or iz-1 */
  int32_t source[5]; /* the first element of each of the five rows' y-lists, -1 for none */
  int32_t r, k, ix, jx, last;

  for (r = 0; r < 5; ++r) { /* @9 */
    A[r] = s->A + (int64_t)r * nx; /* @9 */
    row_y[r] = iy + row_dy[r] >= 0 && iy + row_dy[r] < ny ? iy + row_dy[r] : -1; /* @9 */
    row_z[r] = iz + row_dz[r]; /* @9 */
    source[r] = row_y[r] >= 0 && (row_dz[r] == 0 || below) ? B[(row_dz[r] == 0 ? 0 : ny) + row_y[r]] : -1; /* @9 */
  }
  nbs3d_phase(t, NBS3D_LOOP_ROWS, "x-lists of row", iy); /* @8 */
  for (r = 0; r < 5; ++r) { /* @9 */
    for (k = source[r]; k != -1; k = Y[k]) { /* @9 */
      ix = nbs3d_int(x[k], x_min, inv_d, nx); /* @9 */
      X[k] = A[r][ix]; /* @9 */
      A[r][ix] = k; /* @9 */
      nbs3d_push(t, NBS3D_PUSH_X, "x-list", id->A, (int64_t)r * nx + ix, id->X, k, ix, row_y[r], row_z[r]); /* @9 */
    }
  }

  nbs3d_phase(t, NBS3D_LOOP_ROW, "contacts of row", iy); /* @10 */
  for (k = source[0]; k != -1; k = Y[k]) { /* @10 */
    ix = nbs3d_int(x[k], x_min, inv_d, nx); /* @11 */
    nbs3d_visit(t, k, ix, iy, iz); /* @11 */
    if (test_list(f, out, t, X, k, X[k])) return 1; /* own cell: only the elements after k */ /* @12 */
    if (ix > 0) { /* @11 */
      nbs3d_visit(t, k, ix - 1, iy, iz); /* @11 */
      if (test_list(f, out, t, X, k, A[0][ix - 1])) return 1; /* @12 */
    }
    last = ix + 1 < nx ? ix + 1 : nx - 1; /* the bound once, as the book loops take it */ /* @11 */
    for (r = 1; r < 5; ++r) { /* @11 */
      if (source[r] == -1) continue; /* @11 */
      for (jx = ix > 0 ? ix - 1 : 0; jx <= last; ++jx) { /* @11 */
        nbs3d_visit(t, k, jx, row_y[r], row_z[r]); /* @11 */
        if (test_list(f, out, t, X, k, A[r][jx])) return 1; /* @12 */
      }
    }
  }

  nbs3d_phase(t, NBS3D_CLEAR_X, "clear x-lists of row", iy); /* @13 */
  for (r = 0; r < 5; ++r) { /* @13 */
    for (k = source[r]; k != -1; k = Y[k]) { /* @13 */
      ix = nbs3d_int(x[k], x_min, inv_d, nx); /* @13 */
      if (A[r][ix] != -1) { /* @13 */
        A[r][ix] = -1; /* @13 */
        nbs3d_clear(t, NBS3D_CLEAR_X, "x-list", id->A, (int64_t)r * nx + ix); /* @13 */
      }
    }
  }
  return 0;
}

/* The loops, once: nbscope_detect below makes two copies of them, one for t == NULL. */
static NBS3D_INLINE int detect_frame(void **state, const nbscope_frame *f, const nbscope_output *out,
                                     const nbscope_trace *t) {
  nbs3d_arrays *s = nbs3d_prepare(state, f, out);
  nbs3d_ids id;
  const double *y, *z;
  double y_min, z_min, inv_d;
  int32_t n, ny, nz, k, iy, iz, *C, *Z, *B0, *B1, *Y;
  if (s == NULL) return 1;
  n = (int32_t)f->n;
  ny = (int32_t)f->cells[1];
  nz = (int32_t)f->cells[2];
  y = f->y; /* the frame's fields in locals, loaded once (not again after every add_pair) */
  z = f->z;
  y_min = f->origin[1];
  z_min = f->origin[2];
  inv_d = f->inv_d; /* nbscope's 1/d: cells equal to its grid's, bit for bit */
  C = s->C;
  Z = s->Z;
  B0 = s->B;
  B1 = s->B + ny;
  Y = s->Y;
  id = nbs3d_declare(t, s);

  /* 1. z-lists: every element onto the list of its layer. */
  nbs3d_phase(t, NBS3D_LOOP_ALL, "z-lists", -1); /* @1 */
  for (k = 0; k < n; ++k) { /* @1 */
    iz = nbs3d_int(z[k], z_min, inv_d, nz); /* @2 */
    Z[k] = C[iz]; /* @2 */
    C[iz] = k; /* @2 */
    nbs3d_push(t, NBS3D_PUSH_Z, "z-list", id.C, iz, id.Z, k, -1, -1, iz); /* @2 */
  }

  /* 2. layers: y-lists of layer iz (B[0]) and iz-1 (B[1]), every non-empty row of layer iz, clearing. */
  for (iz = 0; iz < nz; ++iz) { /* @3 */
    int below; /* @3 */
    if (C[iz] == -1) continue; /* @3 */
    below = iz > 0 && C[iz - 1] != -1; /* @3 */
    nbs3d_phase(t, NBS3D_LOOP_LAYERS, "y-lists of layer", iz); /* @3 */
    for (k = C[iz]; k != -1; k = Z[k]) { /* @4 */
      iy = nbs3d_int(y[k], y_min, inv_d, ny); /* @5 */
      Y[k] = B0[iy]; /* @5 */
      B0[iy] = k; /* @5 */
      nbs3d_push(t, NBS3D_PUSH_Y0, "y-list", id.B, iy, id.Y, k, -1, iy, iz); /* @5 */
    }
    if (below) { /* @6 */
      for (k = C[iz - 1]; k != -1; k = Z[k]) { /* @6 */
        iy = nbs3d_int(y[k], y_min, inv_d, ny); /* @7 */
        Y[k] = B1[iy]; /* @7 */
        B1[iy] = k; /* @7 */
        nbs3d_push(t, NBS3D_PUSH_Y1, "y-list", id.B, (int64_t)ny + iy, id.Y, k, -1, iy, iz - 1); /* @7 */
      }
    }

    /* Each non-empty row once: when the loop meets the element at its head (O(N), never O(ny nz)). */
    for (k = C[iz]; k != -1; k = Z[k]) { /* @8 */
      iy = nbs3d_int(y[k], y_min, inv_d, ny); /* @8 */
      if (B0[iy] == k && detect_row(f, out, t, &id, s, iy, iz, below)) goto full; /* @8 */
    }

    nbs3d_phase(t, NBS3D_CLEAR_Y, "clear y-lists of layer", iz); /* @14 */
    for (k = C[iz]; k != -1; k = Z[k]) { /* @14 */
      iy = nbs3d_int(y[k], y_min, inv_d, ny); /* @14 */
      if (B0[iy] != -1) { /* @14 */
        B0[iy] = -1; /* @14 */
        nbs3d_clear(t, NBS3D_CLEAR_Y, "y-list", id.B, iy); /* @14 */
      }
    }
    if (below) { /* @14 */
      for (k = C[iz - 1]; k != -1; k = Z[k]) { /* @14 */
        iy = nbs3d_int(y[k], y_min, inv_d, ny); /* @14 */
        if (B1[iy] != -1) { /* @14 */
          B1[iy] = -1; /* @14 */
          nbs3d_clear(t, NBS3D_CLEAR_Y, "y-list", id.B, (int64_t)ny + iy); /* @14 */
        }
      }
    }
  }

  /* 3. clear the z heads that were set. */
  nbs3d_phase(t, NBS3D_CLEAR_Z, "clear z-lists", -1); /* @15 */
  for (k = 0; k < n; ++k) { /* @15 */
    iz = nbs3d_int(z[k], z_min, inv_d, nz); /* @15 */
    if (C[iz] != -1) { /* @15 */
      C[iz] = -1; /* @15 */
      nbs3d_clear(t, NBS3D_CLEAR_Z, "z-list", id.C, iz); /* @15 */
    }
  }
  return 0;

full:
  nbs3d_reset_heads(s);
  return 1;
}

/* Untraced frames run a copy of the loops in which t is a constant NULL, so every trace call and
 * its `t != NULL` test compile away (as C++ would with a template); traced frames run the other. */
NBSCOPE_EXPORT int nbscope_detect(void **state, const nbscope_frame *f, const nbscope_output *out,
                                  const nbscope_trace *t) {
  if (t == NULL) return detect_frame(state, f, out, NULL);
  return detect_frame(state, f, out, t);
}
