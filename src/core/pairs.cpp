#include "core/pairs.hpp"

#include <algorithm>
#include <iterator>
#include <string>

#include "core/error.hpp"

namespace nbscope {

void PairCollector::overflow() const {
  throw Error("more than " + std::to_string(limit_) +
              " contact pairs (the pair limit; too many elements overlap at one place)");
}

void sort_pairs(PairList& pairs) { std::sort(pairs.begin(), pairs.end()); }

PairList pairs_missing_from(const PairList& a, const PairList& b) {
  PairList out;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

}  // namespace nbscope
