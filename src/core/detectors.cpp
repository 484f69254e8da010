#include "core/detectors.hpp"

#include "core/brute.hpp"
#include "core/nbs.hpp"
#include "core/screen.hpp"
#include "core/sort.hpp"
#include "core/tree.hpp"

namespace nbscope {

std::vector<DetectorInfo> builtin_detectors() {
  // In the order of the book's chapter 3.
  std::vector<DetectorInfo> d;
  d.push_back({"brute", "direct checking of all N(N-1)/2 pairs (the reference)", true, true,
               [] { return std::make_unique<BruteDetector>(); }});
  d.push_back({"tree", "binary tree of cells, HEAD + next array E at each leaf, neighbour leaves searched (p.85)",
               true, true, [] { return std::make_unique<TreeDetector>(); }});
  d.push_back({"sort", "direct mapping onto cells, then sorting by cell; RAM 3N (2D) / 4N (3D) (pp.87, 102)", true,
               true, [] { return std::make_unique<SortDetector>(); }});
  d.push_back({"screen", "screen array C[nx][ny] of list heads + next array E[N]; memory grows with the grid (p.91)",
               true, true, [] { return std::make_unique<ScreenDetector>(); }});
  d.push_back({"nbs", "Munjiza-NBS: y-lists (3D: z-lists first), then x-lists row by row; O(N) time and memory",
               true, true, [] { return std::make_unique<NbsDetector>(); }});
  return d;
}

}  // namespace nbscope
