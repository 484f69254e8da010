/* nbscope detector plugin API, version 1 (C99; usable from C++ and, through ISO_C_BINDING, Fortran).
 *
 * A plugin is a shared library that nbscope loads with `--detector-lib PATH.so`. It then runs as a
 * detector like the built-in ones: every frame's checks, comparison lanes, the Timeline and
 * Violations, and, when it traces, the Stepper, Arrays and Pseudocode panels and the lists overlay.
 * docs/plugins.md is the guide; examples/detectors/ holds the book's NBS and five classic bugs.
 *
 * Index: exported symbols | the frame (input) | the output (pairs, cells) | the trace table | info.
 *
 * Exported symbols (the loader refuses a library that lacks a required one):
 *   const uint32_t nbscope_api_version;                                    required: NBSCOPE_DETECTOR_API_VERSION
 *   const nbscope_detector_info *nbscope_detector_describe(void);          required
 *   int  nbscope_detect(void **state, const nbscope_frame *frame,
 *                       const nbscope_output *out, const nbscope_trace *trace);   required
 *   void   nbscope_release(void *state);                                   optional: frees *state
 *   size_t nbscope_own_bytes(const void *state);                           optional: bytes of its arrays
 * NBSCOPE_DETECTOR_PLUGIN() defines nbscope_api_version.
 *
 * Threading: nbscope calls one library from one thread at a time. The state pointer is the plugin's
 * own (NULL on the first call); keep arrays in it between frames, as a simulation would.
 *
 * Isolated: each detector instance runs its calls in a process of its own (nbscope-plugin-host). A
 * crash or a call running past --detector-timeout in nbscope_detect is that frame's violation, located
 * after the last operation traced, and the next frame starts a new process (state NULL again); in the
 * library's constructors, describe, release or own_bytes (or with --detector-isolation none, where the
 * plugin runs in nbscope's process) it ends nbscope with one line naming the library and the call. A
 * breach of the rules below in a frame (a pair (k, k), out of range or given twice, a trace call
 * naming what does not exist, a cell not written) is that frame's violation (docs/diagnosis.md); a
 * trace call that breaks a rule, or a list that closes on itself, ends the call there (nbscope returns
 * from the trace callback straight to its own caller: memory the plugin allocated in that call is
 * lost). Texts
 * (fail() messages, names, labels, summary, pseudocode) are kept to their first 300 bytes.
 */
#ifndef NBSCOPE_DETECTOR_H
#define NBSCOPE_DETECTOR_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define NBSCOPE_DETECTOR_API_VERSION 1u

#if defined(_WIN32)
#define NBSCOPE_EXPORT __declspec(dllexport)
#else
#define NBSCOPE_EXPORT __attribute__((visibility("default")))
#endif

/* Defines the version symbol the loader checks before it calls anything. */
#define NBSCOPE_DETECTOR_PLUGIN() NBSCOPE_EXPORT const uint32_t nbscope_api_version = NBSCOPE_DETECTOR_API_VERSION

/* Capabilities (nbscope_detector_info.capabilities). */
#define NBSCOPE_CAP_2D 0x1u     /* handles 2D frames */
#define NBSCOPE_CAP_3D 0x2u     /* handles 3D frames */
#define NBSCOPE_CAP_TRACES 0x4u /* calls the trace table when it is given (Stepper, Arrays, Pseudocode) */
#define NBSCOPE_CAP_LISTS 0x8u  /* builds singly connected lists and traces their pushes (lists overlay) */
#define NBSCOPE_CAP_CELLS 0x10u /* fills nbscope_output.cells with its own integerisation (the cells check) */

/* One frame: the elements (bounding circles or spheres) and the grid nbscope uses. */
typedef struct nbscope_frame {
  int64_t frame;        /* frame number, for messages */
  int64_t n;            /* number of elements; element k is index k of each array */
  int32_t dim;          /* 2 or 3 */
  const double *x;      /* centres */
  const double *y;
  const double *z;      /* NULL in 2D */
  const double *r;      /* radii */
  double d;             /* cell size (the book's d: at least the largest diameter) */
  double origin[3];     /* lower corner of cell (0, 0, 0); origin[2] = 0 in 2D */
  int64_t cells[3];     /* nx, ny, nz (nz = 1 in 2D); cell (ix, iy, iz) = Int((x - origin) * inv_d) clamped into [0, n) */
  int64_t max_pairs;    /* add_pair refuses pairs beyond this many */
  double inv_d;         /* ix = Int((x - origin[0]) * inv_d), as nbscope integerises: 1/d, or a hair less where
                         * rounding could put two touching centres two cells apart */
} nbscope_frame;

/* Where the plugin puts its answer. */
typedef struct nbscope_output {
  void *ctx;
  /* Reports contact {i, j} (0 <= i, j < n, i != j, each pair once, either order). Returns 0, or
   * nonzero when the pair limit is reached (stop and return nonzero from nbscope_detect). */
  int (*add_pair)(void *ctx, int32_t i, int32_t j);
  /* n * dim integers: cells[k * dim + a] is element k's integerised coordinate on axis a, as the
   * plugin computed it. Prefilled with -1; NULL unless the plugin declares NBSCOPE_CAP_CELLS. */
  int32_t *cells;
  /* Says why nbscope_detect failed (copied: its first 300 bytes); call before returning nonzero. */
  void (*fail)(void *ctx, const char *message);
} nbscope_output;

/* The trace table: NULL when the frame is not traced (then make no call). A plugin declaring
 * NBSCOPE_CAP_TRACES | NBSCOPE_CAP_LISTS gets it on every checked frame too (its walks are checked,
 * nothing is recorded), so trace the same way whenever it is given. Each call describes
 * writes the plugin has just made (call after the write), so nbscope reads the new values from the
 * declared arrays and keeps the old ones itself. `line` indexes the plugin's pseudocode lines. */
typedef struct nbscope_trace {
  void *ctx;
  /* Declares a heads or next array (its contents now are "before the first event"); returns its id
   * (>= 0). `name` is required (not NULL, not empty; its first 300 bytes are kept). `data` must stay
   * valid and in place until nbscope_detect returns. Shape is row-major. */
  int (*declare_array)(void *ctx, const char *name, int32_t rank, const int64_t *shape, const int32_t *data);
  /* A phase begins ("y-lists", "x-lists of row", ...); index: the row, layer or leaf, or -1. */
  void (*phase)(void *ctx, int32_t line, const char *label, int32_t index);
  /* Element k was pushed onto list `list` of array `heads`, linked through array `next`
   * (next[k] = heads[list]; heads[list] = k); (ix, iy, iz) is the list's cell (-1: not keyed on that axis). */
  void (*push)(void *ctx, int32_t line, const char *kind, int32_t heads, int64_t list, int32_t next, int32_t k,
               int32_t ix, int32_t iy, int32_t iz);
  /* Head `list` of array `heads` was reset to -1. */
  void (*clear)(void *ctx, int32_t line, const char *kind, int32_t heads, int64_t list);
  /* Cell (ix, iy, iz) is visited under the contact mask of element k (iz = -1 in 2D). The tests of k
   * that follow, until its next visit, walk that cell's list: with NBSCOPE_CAP_LISTS nbscope checks
   * that each element they name lies in that cell (a stale or wrong list is a `cells` violation). */
  void (*visit_cell)(void *ctx, int32_t line, int32_t k, int32_t ix, int32_t iy, int32_t iz);
  /* Pair (k, other) was tested; contact is the answer (nonzero: in contact). */
  void (*test_pair)(void *ctx, int32_t line, int32_t k, int32_t other, int32_t contact);
  /* Entry `index` of array `array` was set, on behalf of element k (-1: none); label says what it is. */
  void (*set)(void *ctx, int32_t line, const char *label, int32_t array, int64_t index, int32_t k);
} nbscope_trace;

/* What the plugin is. Strings and arrays must live as long as the library is loaded. */
typedef struct nbscope_detector_info {
  uint32_t api_version;              /* NBSCOPE_DETECTOR_API_VERSION */
  const char *name;                  /* registry name: [a-z0-9_-]+, not a built-in's */
  const char *summary;               /* one line for `nbscope algorithms` */
  uint32_t capabilities;             /* NBSCOPE_CAP_* */
  const char *const *pseudocode_2d;  /* the loops in the book's wording, one line each (trace `line` indexes it) */
  int32_t pseudocode_2d_lines;
  const char *const *pseudocode_3d;
  int32_t pseudocode_3d_lines;
} nbscope_detector_info;

typedef const nbscope_detector_info *(*nbscope_describe_fn)(void);
typedef int (*nbscope_detect_fn)(void **state, const nbscope_frame *frame, const nbscope_output *out,
                                 const nbscope_trace *trace);
typedef void (*nbscope_release_fn)(void *state);
typedef size_t (*nbscope_own_bytes_fn)(const void *state);

#ifdef __cplusplus
}
#endif

#endif /* NBSCOPE_DETECTOR_H */
