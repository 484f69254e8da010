// nbscope_gen: writes one generated layout as ELEMENTS.csv (for CLI tests and scripts).
// usage: nbscope_gen LAYOUT N DIM SEED OUT.csv
#include <cstdio>
#include <cstdlib>
#include <string>

#include "support/generators.hpp"

int main(int argc, char** argv) {
  using namespace nbscope::testdata;
  if (argc != 6) {
    std::fprintf(stderr, "usage: nbscope_gen LAYOUT N DIM SEED OUT.csv\n");
    return 2;
  }
  const std::string name = argv[1];
  for (Layout layout : all_layouts()) {
    if (layout_name(layout) != name) continue;
    const int dim = std::atoi(argv[3]);
    const auto e = make_layout(layout, std::atoll(argv[2]), dim, std::strtoull(argv[4], nullptr, 10));
    std::FILE* f = std::fopen(argv[5], "w");
    if (!f) return 2;
    std::fputs(dim == 3 ? "x,y,z,r\n" : "x,y,r\n", f);
    for (Eigen::Index i = 0; i < e.size(); ++i) {
      if (dim == 3)
        std::fprintf(f, "%.17g,%.17g,%.17g,%.17g\n", e.x[i], e.y[i], e.z[i], e.r[i]);
      else
        std::fprintf(f, "%.17g,%.17g,%.17g\n", e.x[i], e.y[i], e.r[i]);
    }
    return std::fclose(f) == 0 ? 0 : 2;
  }
  std::fprintf(stderr, "nbscope_gen: unknown layout %s\n", name.c_str());
  return 2;
}
