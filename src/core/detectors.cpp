#include "core/detectors.hpp"

#include "core/brute.hpp"
#include "core/nbs.hpp"

namespace nbscope {

std::vector<DetectorInfo> builtin_detectors() {
  std::vector<DetectorInfo> d;
  d.push_back({"brute", "direct checking of all N(N-1)/2 pairs (the reference)", true, true,
               [] { return std::make_unique<BruteDetector>(); }});
  d.push_back({"nbs", "Munjiza-NBS: y-lists, then x-lists of each row and the row below; O(N) time and memory",
               true, false, [] { return std::make_unique<NbsDetector>(); }});
  return d;
}

}  // namespace nbscope
