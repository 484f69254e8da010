/* The smallest nbscope detector plugin: every pair tested, against the installed header only. */
#include <nbscope/detector.h>

NBSCOPE_DETECTOR_PLUGIN();

static const nbscope_detector_info info = {NBSCOPE_DETECTOR_API_VERSION, "install_brute",
                                           "brute force, built out of tree against an installed nbscope",
                                           NBSCOPE_CAP_2D | NBSCOPE_CAP_3D, NULL, 0, NULL, 0};

/* Not static and not NBSCOPE_EXPORT: nbscope_add_detector's hidden visibility keeps it inside the .so. */
int install_brute_touch(const nbscope_frame *f, int64_t i, int64_t j) {
  const double dx = f->x[i] - f->x[j], dy = f->y[i] - f->y[j];
  const double dz = f->dim == 3 ? f->z[i] - f->z[j] : 0.0;
  const double reach = f->r[i] + f->r[j];
  return dx * dx + dy * dy + dz * dz <= reach * reach;
}

NBSCOPE_EXPORT const nbscope_detector_info *nbscope_detector_describe(void) { return &info; }

NBSCOPE_EXPORT int nbscope_detect(void **state, const nbscope_frame *f, const nbscope_output *out,
                                  const nbscope_trace *trace) {
  (void)state;
  (void)trace;
  for (int64_t i = 0; i < f->n; ++i) {
    for (int64_t j = i + 1; j < f->n; ++j) {
      if (install_brute_touch(f, i, j) && out->add_pair(out->ctx, (int32_t)i, (int32_t)j) != 0) {
        out->fail(out->ctx, "too many pairs");
        return 1;
      }
    }
  }
  return 0;
}
