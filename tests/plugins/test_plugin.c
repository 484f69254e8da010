/* nbscope's test detector plugin: brute force (every pair), traced, reporting its cells. Compiled
 * into one library per PLUGIN_* switch (tests/plugins/CMakeLists.txt), each breaking the plugin API
 * (include/nbscope/detector.h) in one way that the loader or the adapter must catch and name:
 *   PLUGIN_GOOD       well-formed and right             PLUGIN_DROP_PAIR   well-formed, drops a pair a frame
 *   PLUGIN_NO_DETECT  no nbscope_detect symbol          PLUGIN_NO_VERSION  no nbscope_api_version symbol
 *   PLUGIN_VERSION_2  built for API version 2           PLUGIN_BAD_NAME    a name outside [a-z0-9_-]
 *   PLUGIN_PAIR_RANGE a pair (0, n)                     PLUGIN_SELF_PAIR   a pair (0, 0)
 *   PLUGIN_PAIR_TWICE the pair (0, 1) twice             PLUGIN_UNDECLARED  a trace call on array 7
 *   PLUGIN_INDEX_SHAPE a trace set past its array       PLUGIN_CRASH       writes through NULL on frame 3
 *   PLUGIN_HANG       never returns on frame 2        PLUGIN_DESCRIBE_CRASH  crashes when asked what it is
 *   PLUGIN_LOAD_CRASH a constructor crashes (dlopen)  PLUGIN_LOAD_HANG   a constructor never returns
 *   PLUGIN_DESCRIBE_HANG never says what it is        PLUGIN_RELEASE_CRASH / _HANG   in nbscope_release
 *   PLUGIN_OWN_BYTES_CRASH / _HANG in nbscope_own_bytes  PLUGIN_LONG_FAIL  fails on frame 0 with 1 MB of text
 *   PLUGIN_NULL_ARRAY_NAME declares an array named NULL  PLUGIN_ONCE_PER_FRAME  refuses a frame given twice in a row
 *   PLUGIN_HEAP_SMASH frees a block twice on frame 1 (the heap it shares with its process corrupted)
 * PLUGIN_NAME is the detector's registry name. */
#include <nbscope/detector.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef PLUGIN_NAME
#define PLUGIN_NAME "test-good"
#endif

#if defined(PLUGIN_VERSION_2)
NBSCOPE_EXPORT const uint32_t nbscope_api_version = 2;
#elif !defined(PLUGIN_NO_VERSION)
NBSCOPE_DETECTOR_PLUGIN();
#endif

/* Spins until the watchdog ends the process (unused by most variants). */
__attribute__((unused)) static void hang(void) {
  volatile int forever = 1;
  while (forever) {
  }
}

/* Writes through NULL: SIGSEGV. */
__attribute__((unused)) static void crash(void) { *(volatile int *)NULL = 1; }

#if defined(PLUGIN_LOAD_CRASH)
__attribute__((constructor)) static void crash_at_load(void) { crash(); }
#elif defined(PLUGIN_LOAD_HANG)
__attribute__((constructor)) static void hang_at_load(void) { hang(); }
#endif

static const char *const pseudocode_lines[] = {
    "Integerise every element: ix = Int((x - origin) / d), iy = Int((y - origin) / d)",
    "Loop over all discrete elements i, and for each over all discrete elements j > i",
    "  check i against j: in contact when |c_i - c_j| <= r_i + r_j",
};

static const nbscope_detector_info info = {
    NBSCOPE_DETECTOR_API_VERSION,
#if defined(PLUGIN_BAD_NAME)
    "Test Plugin!",
#else
    PLUGIN_NAME,
#endif
    "the test plugin: brute force, traced, with its cells",
    NBSCOPE_CAP_2D | NBSCOPE_CAP_3D | NBSCOPE_CAP_TRACES | NBSCOPE_CAP_CELLS,
    pseudocode_lines,
    3,
    pseudocode_lines,
    3,
};

NBSCOPE_EXPORT const nbscope_detector_info *nbscope_detector_describe(void) {
#if defined(PLUGIN_DESCRIBE_CRASH)
  crash();
#elif defined(PLUGIN_DESCRIBE_HANG)
  hang();
#endif
  return &info;
}

/* The plugin's own arrays, kept between frames as a simulation would. */
typedef struct state {
  int32_t *cell; /* n x dim integerised coordinates */
  int64_t capacity;
  int64_t calls;      /* nbscope_detect calls so far */
  int64_t last_frame; /* the frame of the last call */
} state;

static int32_t integerise(double v, double origin, double d, int64_t n) {
  const double c = (v - origin) / d;
  if (!(c >= 0)) return 0;
  if (c >= (double)n) return (int32_t)(n - 1);
  return (int32_t)c;
}

static int in_contact(const nbscope_frame *f, int64_t i, int64_t j) {
  const double dx = f->x[i] - f->x[j], dy = f->y[i] - f->y[j];
  const double dz = f->dim == 3 ? f->z[i] - f->z[j] : 0.0;
  const double rr = f->r[i] + f->r[j];
  return dx * dx + dy * dy + dz * dz <= rr * rr;
}

/* Fills the cell array (traced: one set per entry) and the output's cells. */
static void integerise_all(state *s, const nbscope_frame *f, const nbscope_output *out, const nbscope_trace *t, int id) {
  int64_t k;
  int a;
  const double *axis[3];
  axis[0] = f->x;
  axis[1] = f->y;
  axis[2] = f->z;
  for (k = 0; k < f->n; ++k) {
    for (a = 0; a < f->dim; ++a) {
      const int64_t entry = k * f->dim + a;
      s->cell[entry] = integerise(axis[a][k], f->origin[a], f->d, f->cells[a]);
      if (out->cells != NULL) out->cells[entry] = s->cell[entry];
      if (t != NULL) t->set(t->ctx, 0, "cell", id, entry, (int32_t)k);
    }
  }
#if defined(PLUGIN_INDEX_SHAPE)
  if (t != NULL) t->set(t->ctx, 0, "cell", id, f->n * f->dim + 5, 0);
#endif
#if defined(PLUGIN_UNDECLARED)
  if (t != NULL) t->set(t->ctx, 0, "cell", 7, 0, 0);
#endif
}

#if defined(PLUGIN_NO_DETECT)
#define DETECT_SYMBOL nbscope_detect_misspelt /* the required symbol is absent */
#else
#define DETECT_SYMBOL nbscope_detect
#endif

NBSCOPE_EXPORT int DETECT_SYMBOL(void **state_pointer, const nbscope_frame *f, const nbscope_output *out,
                                  const nbscope_trace *t) {
  state *s = (state *)*state_pointer;
  int64_t i, j;
  int id = -1, dropped = 0;
  if (s == NULL) {
    s = (state *)calloc(1, sizeof *s);
    if (s == NULL) return 1;
    *state_pointer = s;
  }
  if (s->capacity < f->n * f->dim) {
    int32_t *grown = (int32_t *)realloc(s->cell, (size_t)(f->n * f->dim + 1) * sizeof *grown);
    if (grown == NULL) {
      out->fail(out->ctx, "out of memory");
      return 1;
    }
    s->cell = grown;
    s->capacity = f->n * f->dim;
  }
#if defined(PLUGIN_ONCE_PER_FRAME)
  /* Each call's frame appended to the file NBSCOPE_TEST_CALLS names (a test reads it), and a frame
   * given twice in a row refused, as a stateful detector would suffer it (nbscope must not). */
  {
    const char *log = getenv("NBSCOPE_TEST_CALLS");
    FILE *calls = log != NULL ? fopen(log, "a") : NULL;
    if (calls != NULL) {
      fprintf(calls, "%lld\n", (long long)f->frame);
      fclose(calls);
    }
  }
  if (s->calls > 0 && f->frame == s->last_frame) {
    out->fail(out->ctx, "called twice for this frame");
    return 1;
  }
#endif
  s->calls += 1;
  s->last_frame = f->frame;
#if defined(PLUGIN_CRASH)
  if (f->frame == 3) crash();
#endif
#if defined(PLUGIN_HANG)
  if (f->frame == 2) hang();
#endif
#if defined(PLUGIN_HEAP_SMASH)
  if (f->frame == 1) {
    void *volatile block = malloc(32);
    free(block);
    free(block); /* glibc aborts ("double free detected"); a sanitizer's allocator reports it */
  }
#endif
#if defined(PLUGIN_LONG_FAIL)
  if (f->frame == 0) {
    const size_t length = (size_t)1 << 20;
    char *message = (char *)malloc(length + 1);
    if (message == NULL) return 1;
    memset(message, 'x', length);
    message[length] = '\0';
    out->fail(out->ctx, message); /* copied: freed right after */
    free(message);
    return 1;
  }
#endif
  for (i = 0; i < f->n * f->dim; ++i) s->cell[i] = -1;
  if (t != NULL) {
    int64_t shape[2];
    shape[0] = f->n;
    shape[1] = f->dim;
#if defined(PLUGIN_NULL_ARRAY_NAME)
    id = t->declare_array(t->ctx, NULL, 2, shape, s->cell);
#else
    id = t->declare_array(t->ctx, "cell", 2, shape, s->cell);
#endif
    t->phase(t->ctx, 0, "cells", -1);
  }
  integerise_all(s, f, out, t, id);
#if defined(PLUGIN_PAIR_RANGE)
  if (out->add_pair(out->ctx, 0, (int32_t)f->n)) return 1;
#endif
#if defined(PLUGIN_SELF_PAIR)
  if (out->add_pair(out->ctx, 0, 0)) return 1;
#endif
#if defined(PLUGIN_PAIR_TWICE)
  if (f->n >= 2 && (out->add_pair(out->ctx, 0, 1) || out->add_pair(out->ctx, 1, 0))) return 1;
#endif
  if (t != NULL) t->phase(t->ctx, 1, "all pairs", -1);
  for (i = 0; i < f->n; ++i) {
    for (j = i + 1; j < f->n; ++j) {
      const int contact = in_contact(f, i, j);
      if (t != NULL) t->test_pair(t->ctx, 2, (int32_t)i, (int32_t)j, contact);
      if (!contact) continue;
#if defined(PLUGIN_DROP_PAIR)
      if (!dropped) {
        dropped = 1;
        continue;
      }
#endif
      if (out->add_pair(out->ctx, (int32_t)i, (int32_t)j)) return 1;
    }
  }
  (void)dropped;
  return 0;
}

NBSCOPE_EXPORT void nbscope_release(void *state_pointer) {
  state *s = (state *)state_pointer;
#if defined(PLUGIN_RELEASE_CRASH)
  crash();
#elif defined(PLUGIN_RELEASE_HANG)
  hang();
#endif
  if (s == NULL) return;
  free(s->cell);
  free(s);
}

NBSCOPE_EXPORT size_t nbscope_own_bytes(const void *state_pointer) {
  const state *s = (const state *)state_pointer;
#if defined(PLUGIN_OWN_BYTES_CRASH)
  crash();
#elif defined(PLUGIN_OWN_BYTES_HANG)
  hang();
#endif
  return s == NULL ? 0 : (size_t)s->capacity * sizeof(int32_t);
}
