// TEMPORARY (removed when the core helper's branch merges): the contact rule's functions, so the
// command line builds before core has them.
#pragma once
#include <cmath>

#include "core/pairs.hpp"

namespace nbscope {

inline double tmp_axis_delta(const Elements& e, const Eigen::ArrayXd& c, int a, ElementId i, ElementId j) {
  double d = c[i] - c[j];
  if (e.box.periodic[a]) {
    const double l = e.box.length(a);
    if (d > l / 2) d -= l;
    if (d < -l / 2) d += l;
  }
  return d;
}
inline bool in_contact(const Elements& e, ElementId i, ElementId j, Touching t) {
  const double dx = tmp_axis_delta(e, e.x, 0, i, j), dy = tmp_axis_delta(e, e.y, 1, i, j);
  const double dz = e.dim == 3 ? tmp_axis_delta(e, e.z, 2, i, j) : 0.0;
  const double rr = e.r[i] + e.r[j];
  const double d2 = dx * dx + dy * dy + dz * dz;
  return t == Touching::strict ? d2 < rr * rr : d2 <= rr * rr;
}
inline double contact_gap(const Elements& e, ElementId i, ElementId j) {
  const double dx = tmp_axis_delta(e, e.x, 0, i, j), dy = tmp_axis_delta(e, e.y, 1, i, j);
  const double dz = e.dim == 3 ? tmp_axis_delta(e, e.z, 2, i, j) : 0.0;
  return std::sqrt(dx * dx + dy * dy + dz * dz) - (e.r[i] + e.r[j]);
}
inline void wrap_into_box(Elements& e) {
  for (int a = 0; a < e.dim; ++a) {
    if (!e.box.periodic[a]) continue;
    Eigen::ArrayXd& c = a == 0 ? e.x : a == 1 ? e.y : e.z;
    const double lo = e.box.lo[a], l = e.box.length(a);
    for (Eigen::Index k = 0; k < c.size(); ++k) {
      double v = c[k] - l * std::floor((c[k] - lo) / l);
      if (v >= e.box.hi[a]) v = lo;
      c[k] = v;
    }
  }
}

}  // namespace nbscope
