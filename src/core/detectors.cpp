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
  d.push_back({.name = "brute",
               .summary = "direct checking of all N(N-1)/2 pairs (the reference)",
               .dim2 = true, .dim3 = true, .traces = true, .has_lists = false, .periodic = true,
               .make = [] { return std::make_unique<BruteDetector>(); }});
  d.push_back({.name = "tree",
               .summary = "binary tree of cells, HEAD + next array E at each leaf, neighbour leaves searched (p.85)",
               .dim2 = true, .dim3 = true, .traces = true, .has_lists = true,
               .make = [] { return std::make_unique<TreeDetector>(); }});
  d.push_back({.name = "sort",
               .summary = "direct mapping onto cells, then sorting by cell; RAM 3N (2D) / 4N (3D) (pp.87, 102)",
               .dim2 = true, .dim3 = true, .traces = true, .has_lists = false,
               .make = [] { return std::make_unique<SortDetector>(); }});
  d.push_back({.name = "screen",
               .summary = "screen array C[nx][ny] of list heads + next array E[N]; memory grows with the grid (p.91)",
               .dim2 = true, .dim3 = true, .traces = true, .has_lists = true,
               .make = [] { return std::make_unique<ScreenDetector>(); }});
  d.push_back({.name = "nbs",
               .summary = "Munjiza-NBS: y-lists (3D: z-lists first), then x-lists row by row; O(N) time and memory",
               .dim2 = true, .dim3 = true, .traces = true, .has_lists = true, .periodic = true,
               .uses_threads = true, .make = [] { return std::make_unique<NbsDetector>(); }});
  return d;
}

}  // namespace nbscope
