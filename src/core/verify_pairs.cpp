// `nbscope verify --pairs`: the user's pairs against the reference's, each wrong one with its line.
#include <algorithm>

#include "core/verify.hpp"

namespace nbscope::verify {

PairsVerdict compare_pairs(std::int64_t n, const std::vector<GivenPair>& given, const PairList& reference) {
  PairsVerdict out;
  // Distinct valid pairs (i < j) with the line that gave each first.
  std::vector<std::pair<Pair, std::int64_t>> valid;
  valid.reserve(given.size());
  for (const GivenPair& g : given) {
    if (g.i < 0 || g.j < 0 || g.i >= n || g.j >= n) {
      out.out_of_range.push_back(g);
    } else if (g.i == g.j) {
      out.self.push_back(g);
    } else {
      const auto a = static_cast<ElementId>(std::min(g.i, g.j)), b = static_cast<ElementId>(std::max(g.i, g.j));
      valid.push_back({Pair{a, b}, g.line});
    }
  }
  // Stable: among equal pairs the first line stays first.
  std::stable_sort(valid.begin(), valid.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
  PairList distinct;
  std::size_t run = 0;  // where the run of the current distinct pair starts in `valid`
  for (std::size_t k = 0; k < valid.size(); ++k) {
    const auto& [p, line] = valid[k];
    if (!distinct.empty() && distinct.back() == p) {
      out.duplicates.push_back({GivenPair{p.i, p.j, line}, valid[run].second});
      continue;
    }
    run = k;
    distinct.push_back(p);
  }
  for_each_missing(reference, distinct, [&](const Pair& p) { out.missing.push_back(p); });
  for_each_missing(distinct, reference, [&](const Pair& p) {
    // The line that gave it first: the start of its run in `valid`.
    const auto it = std::lower_bound(valid.begin(), valid.end(), p, [](const auto& v, const Pair& q) { return v.first < q; });
    out.extra.push_back(GivenPair{p.i, p.j, it->second});
  });
  out.right = static_cast<std::int64_t>(distinct.size() - out.extra.size());
  // Reports follow the file: by line.
  const auto by_line = [](const GivenPair& a, const GivenPair& b) { return a.line < b.line; };
  std::sort(out.extra.begin(), out.extra.end(), by_line);
  std::sort(out.duplicates.begin(), out.duplicates.end(), [](const auto& a, const auto& b) { return a.first.line < b.first.line; });
  return out;
}

}  // namespace nbscope::verify
