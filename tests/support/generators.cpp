#include "support/generators.hpp"

#include "core/brute.hpp"

namespace nbscope::testdata {

PairList brute_pairs(const Elements& elements) {
  BruteDetector brute;
  PairList out;
  brute.detect(elements, DetectOptions{}, out);
  sort_pairs(out);
  return out;
}

Elements book_nine() {
  const double x[] = {4.75, 4.90, 1.85, 4.60, 1.30, 4.50, 1.60, 5.20, 1.20};
  const double y[] = {6.45, 6.50, 6.45, 6.80, 6.85, 5.55, 6.60, 5.40, 6.55};
  Elements e;
  for (int k = 0; k < 9; ++k) e.push_back(x[k], y[k], 0, 0.1);
  return e;
}

GridOptions book_grid() {
  GridOptions o;
  o.cell_size = 1.0;
  o.origin = std::array<double, 3>{0, 0, 0};
  o.cells = std::array<std::int64_t, 3>{10, 10, 1};
  return o;
}

}  // namespace nbscope::testdata
