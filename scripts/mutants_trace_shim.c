/* scripts/mutants_trace_shim.c: the trace of one frame of a plugin, written by the plugin's own side, for
 * the mutation benchmark (scripts/mutants.py). nbscope's CLI gives a frame's located operation but not
 * its whole trace, so mutants.py builds a mutant (and the unmodified reference) a second time with this
 * file and -Dnbscope_detect=nbscope_mutant_detect_inner: this nbscope_detect passes every call through,
 * and on the frame $NBSCOPE_MUTANT_TRACE_FRAME it puts a table of its own between the plugin and
 * nbscope's, which writes each trace call to $NBSCOPE_MUTANT_TRACE (one line an operation, flushed as it
 * goes, so a crash or a cycle that nbscope cuts short keeps what came before) and then forwards it.
 * A push line carries the values it wrote (next[k] and heads[list] as they stand after the call), a
 * clear and a set the entry they wrote; "?" where the index is outside the declared array.
 * Lines: "call FRAME" at each call of that frame, "declare ID NAME SHAPE", then one per operation:
 *   phase LINE LABEL INDEX | push LINE KIND HEADS LIST NEXT K IX IY IZ next=V head=V |
 *   clear LINE KIND HEADS LIST head=V | visit LINE K IX IY IZ | test LINE K OTHER CONTACT |
 *   set LINE LABEL ARRAY INDEX K value=V
 * Nothing here changes what nbscope sees: the calls reach it as the plugin made them. */
#include <stdio.h>
#include <stdlib.h>

#include "nbscope/detector.h"

#undef nbscope_detect /* -Dnbscope_detect=nbscope_mutant_detect_inner renames the plugin's, not this one */

int nbscope_mutant_detect_inner(void **state, const nbscope_frame *f, const nbscope_output *out,
                                const nbscope_trace *t);

#define SHIM_ARRAYS 64
static struct {
  const int32_t *data;
  int64_t size;
} shim_arrays[SHIM_ARRAYS];
static FILE *shim_log;
static const nbscope_trace *shim_real;

static const char *shim_text(const char *s) { return s == NULL ? "(null)" : s; }

/* Labels may hold spaces: written with '_' instead, so that a line splits on spaces. */
static void shim_word(const char *s) {
  const char *p;
  for (p = shim_text(s); *p != '\0'; ++p) fputc(*p == ' ' ? '_' : *p, shim_log);
}

static void shim_value(const char *name, int32_t array, int64_t index) {
  if (array >= 0 && array < SHIM_ARRAYS && shim_arrays[array].data != NULL && index >= 0 &&
      index < shim_arrays[array].size)
    fprintf(shim_log, " %s=%d", name, (int)shim_arrays[array].data[index]);
  else
    fprintf(shim_log, " %s=?", name);
}

static void shim_end(void) {
  fputc('\n', shim_log);
  fflush(shim_log);
}

static int shim_declare(void *ctx, const char *name, int32_t rank, const int64_t *shape, const int32_t *data) {
  int id = shim_real->declare_array(shim_real->ctx, name, rank, shape, data);
  int64_t size = 1;
  int32_t a;
  (void)ctx;
  for (a = 0; a < rank && shape != NULL; ++a) size *= shape[a];
  if (id >= 0 && id < SHIM_ARRAYS) {
    shim_arrays[id].data = data;
    shim_arrays[id].size = size;
  }
  fprintf(shim_log, "declare %d ", id);
  shim_word(name);
  fprintf(shim_log, " %lld", (long long)size);
  shim_end();
  return id;
}

static void shim_phase(void *ctx, int32_t line, const char *label, int32_t index) {
  (void)ctx;
  fprintf(shim_log, "phase %d ", (int)line);
  shim_word(label);
  fprintf(shim_log, " %d", (int)index);
  shim_end();
  shim_real->phase(shim_real->ctx, line, label, index);
}

static void shim_push(void *ctx, int32_t line, const char *kind, int32_t heads, int64_t list, int32_t next, int32_t k,
                      int32_t ix, int32_t iy, int32_t iz) {
  (void)ctx;
  fprintf(shim_log, "push %d ", (int)line);
  shim_word(kind);
  fprintf(shim_log, " %d %lld %d %d %d %d %d", (int)heads, (long long)list, (int)next, (int)k, (int)ix, (int)iy,
          (int)iz);
  shim_value("next", next, k);
  shim_value("head", heads, list);
  shim_end();
  shim_real->push(shim_real->ctx, line, kind, heads, list, next, k, ix, iy, iz);
}

static void shim_clear(void *ctx, int32_t line, const char *kind, int32_t heads, int64_t list) {
  (void)ctx;
  fprintf(shim_log, "clear %d ", (int)line);
  shim_word(kind);
  fprintf(shim_log, " %d %lld", (int)heads, (long long)list);
  shim_value("head", heads, list);
  shim_end();
  shim_real->clear(shim_real->ctx, line, kind, heads, list);
}

static void shim_visit(void *ctx, int32_t line, int32_t k, int32_t ix, int32_t iy, int32_t iz) {
  (void)ctx;
  fprintf(shim_log, "visit %d %d %d %d %d", (int)line, (int)k, (int)ix, (int)iy, (int)iz);
  shim_end();
  shim_real->visit_cell(shim_real->ctx, line, k, ix, iy, iz);
}

static void shim_test(void *ctx, int32_t line, int32_t k, int32_t other, int32_t contact) {
  (void)ctx;
  fprintf(shim_log, "test %d %d %d %d", (int)line, (int)k, (int)other, contact != 0);
  shim_end();
  shim_real->test_pair(shim_real->ctx, line, k, other, contact);
}

static void shim_set(void *ctx, int32_t line, const char *label, int32_t array, int64_t index, int32_t k) {
  (void)ctx;
  fprintf(shim_log, "set %d ", (int)line);
  shim_word(label);
  fprintf(shim_log, " %d %lld %d", (int)array, (long long)index, (int)k);
  shim_value("value", array, index);
  shim_end();
  shim_real->set(shim_real->ctx, line, label, array, index, k);
}

NBSCOPE_EXPORT int nbscope_detect(void **state, const nbscope_frame *f, const nbscope_output *out,
                                  const nbscope_trace *t) {
  static nbscope_trace table;
  const char *path = getenv("NBSCOPE_MUTANT_TRACE");
  const char *frame = getenv("NBSCOPE_MUTANT_TRACE_FRAME");
  int k;
  if (t == NULL || path == NULL || frame == NULL || f->frame != atoll(frame))
    return nbscope_mutant_detect_inner(state, f, out, t);
  if (shim_log == NULL) shim_log = fopen(path, "w");
  if (shim_log == NULL) return nbscope_mutant_detect_inner(state, f, out, t);
  for (k = 0; k < SHIM_ARRAYS; ++k) shim_arrays[k].data = NULL;
  fprintf(shim_log, "call %lld", (long long)f->frame);
  shim_end();
  shim_real = t;
  table.ctx = NULL;
  table.declare_array = shim_declare;
  table.phase = shim_phase;
  table.push = shim_push;
  table.clear = shim_clear;
  table.visit_cell = shim_visit;
  table.test_pair = shim_test;
  table.set = shim_set;
  return nbscope_mutant_detect_inner(state, f, out, &table);
}
