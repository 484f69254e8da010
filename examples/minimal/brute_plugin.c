/* The smallest nbscope detector plugin: brute force, every pair tested once (docs/plugins.md).
 * Build: cc -std=c99 -O2 -shared -fPIC -I<prefix>/include brute_plugin.c -o brute_plugin.so
 * Run:   nbscope headless --scene default.json --detector-lib ./brute_plugin.so --algorithm my_brute */
#include <nbscope/detector.h>

NBSCOPE_DETECTOR_PLUGIN();

NBSCOPE_EXPORT const nbscope_detector_info *nbscope_detector_describe(void) {
  static const nbscope_detector_info info = {
      NBSCOPE_DETECTOR_API_VERSION, "my_brute", "every pair tested once (a first plugin)",
      NBSCOPE_CAP_2D | NBSCOPE_CAP_3D, 0, 0, 0, 0};
  return &info;
}

NBSCOPE_EXPORT int nbscope_detect(void **state, const nbscope_frame *f, const nbscope_output *out,
                                  const nbscope_trace *trace) {
  (void)state;
  (void)trace; /* not traced: the capabilities do not say NBSCOPE_CAP_TRACES */
  for (int32_t i = 0; i < f->n; ++i) {
    for (int32_t j = i + 1; j < f->n; ++j) {
      const double dx = f->x[i] - f->x[j], dy = f->y[i] - f->y[j];
      const double dz = f->dim == 3 ? f->z[i] - f->z[j] : 0.0, reach = f->r[i] + f->r[j];
      if (dx * dx + dy * dy + dz * dz <= reach * reach && out->add_pair(out->ctx, i, j) != 0) return 1;
    }
  }
  return 0;
}
