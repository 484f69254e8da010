// nbscope core: the checks of a pair list that nbscope did not make itself (a plugin's), in one pass:
// every pair in range and not an element with itself, put as i < j, and the first repeat found.
#pragma once
#include <cstdint>
#include <vector>

#include "core/pairs.hpp"

namespace nbscope {

// What scan_pairs found: whether every pair names two different elements of [0, n), and the index of
// the first valid pair that repeats an earlier one (-1: none).
struct PairScan {
  bool all_valid = true;
  std::int64_t first_repeat = -1;
  bool sorted = false;  // the hash table gave up (pairs that collide, or too many): found by sorting
};

// Memory scan_pairs reuses between calls (its contents mean nothing between them): the hash table of
// the pairs seen, in 32-bit keys up to 65535 elements and 64-bit ones past that.
struct PairScanScratch {
  std::vector<std::uint32_t> narrow;
  std::vector<std::uint64_t> wide;
};

// Checks `pairs` in place: a pair outside [0, n) or of an element with itself is kept as given (and
// all_valid is false), every other is put as i < j and looked up in, then added to, a hash table of
// those before it. One pass, O(pairs) expected; pairs that collide past a budget of probes, or more
// than 2^28 of them, are sorted instead, O(pairs log pairs) whatever they are.
PairScan scan_pairs(PairList& pairs, std::int64_t n, PairScanScratch& scratch);
// The index of the first pair equal to one before it, by sorting a copy (-1: none). The reference
// scan_pairs is tested against, and its fallback.
std::int64_t first_repeated_pair_sorted(const PairList& pairs);

}  // namespace nbscope
