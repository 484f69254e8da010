// nbscope core: scan_pairs (pair_scan.hpp).
#include "core/pair_scan.hpp"

#include <algorithm>
#include <bit>
#include <limits>
#include <utility>

namespace nbscope {

namespace {

bool valid_pair(Pair p, std::uint32_t n) {
  return (static_cast<std::uint32_t>(p.i) < n) & (static_cast<std::uint32_t>(p.j) < n) & (p.i != p.j);
}

// A valid ordered pair's key: i * n + j in 32 bits up to 65535 elements (at most 65534 * 65535 +
// 65533, below the free mark), else i:j in 64.
template <class Key>
Key key_of(Pair p, std::uint32_t n) {
  const auto i = static_cast<std::uint32_t>(p.i);
  const auto j = static_cast<std::uint32_t>(p.j);
  if constexpr (sizeof(Key) == 4) return i * n + j;
  else return std::uint64_t{i} << 32 | j;
}

// Fibonacci hashing (it spreads keys that share i): the top bits of key * 2^w / phi.
template <class Key>
std::size_t slot_of(Key key, int shift) {
  if constexpr (sizeof(Key) == 4) return static_cast<std::uint32_t>(key * 0x9E3779B1u) >> shift;
  else return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift);
}

// scan_pairs with keys of type Key, in a table of open addressing at most half full; false when the
// pairs collided past a budget of probes (the caller then sorts).
template <class Key>
bool scan_with(PairList& pairs, std::uint32_t n, std::vector<Key>& table, PairScan& out_scan) {
  constexpr Key kFree = std::numeric_limits<Key>::max();  // no valid pair's key
  const std::size_t count = pairs.size();
  std::size_t slots = 16;
  while (slots < 2 * count) slots <<= 1;
  const int shift = static_cast<int>(8 * sizeof(Key)) - std::countr_zero(slots);
  table.assign(slots, kFree);
  Key* const slot_keys = table.data();
  std::size_t budget = 8 * count;  // probes past the first; a half-full table needs about one per two pairs
  bool all_valid = true;
  std::int64_t repeat = -1;
  std::size_t k = 0;
  for (; k < count; ++k) {
    const Pair given = pairs[k];
    const bool valid = valid_pair(given, n);
    all_valid &= valid;
    const Pair ordered{std::min(given.i, given.j), std::max(given.i, given.j)};
    pairs[k] = valid ? ordered : given;  // a store, not a branch; a bad pair kept as given, for its message
    if (!valid) continue;
    const Key key = key_of<Key>(ordered, n);
    std::size_t slot = slot_of(key, shift);
    while (slot_keys[slot] != kFree && slot_keys[slot] != key) {
      if (budget-- == 0) return false;
      slot = (slot + 1) & (slots - 1);
    }
    if (slot_keys[slot] == key) {
      repeat = static_cast<std::int64_t>(k++);
      break;
    }
    slot_keys[slot] = key;
  }
  for (; k < count; ++k) {  // past the first repeat: only checked and ordered
    const Pair given = pairs[k];
    const bool valid = valid_pair(given, n);
    all_valid &= valid;
    if (valid) pairs[k] = Pair{std::min(given.i, given.j), std::max(given.i, given.j)};
  }
  out_scan = PairScan{all_valid, repeat, false};
  return true;
}

}  // namespace

PairScan scan_pairs(PairList& pairs, std::int64_t n, PairScanScratch& scratch) {
  PairScan scan;
  const auto un = static_cast<std::uint32_t>(std::clamp<std::int64_t>(n, 0, std::numeric_limits<std::int32_t>::max()));
  const bool fits = pairs.size() <= (std::size_t{1} << 28);  // else the table would not
  if (fits && (un <= 65535 ? scan_with(pairs, un, scratch.narrow, scan) : scan_with(pairs, un, scratch.wide, scan)))
    return scan;
  // Too many pairs, or pairs that collide: sort the valid ones instead (scan_with ordered those it reached).
  scan = PairScan{};
  scan.sorted = true;
  PairList valid_only;
  std::vector<std::size_t> at;  // the position of each valid pair
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const Pair given = pairs[k];
    if (!valid_pair(given, un)) {
      scan.all_valid = false;
      continue;
    }
    pairs[k] = Pair{std::min(given.i, given.j), std::max(given.i, given.j)};
    valid_only.push_back(pairs[k]);
    at.push_back(k);
  }
  const std::int64_t repeat = first_repeated_pair_sorted(valid_only);
  if (repeat >= 0) scan.first_repeat = static_cast<std::int64_t>(at[static_cast<std::size_t>(repeat)]);
  return scan;
}

std::int64_t first_repeated_pair_sorted(const PairList& pairs) {
  std::vector<std::pair<Pair, std::size_t>> sorted(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) sorted[k] = {pairs[k], k};
  std::sort(sorted.begin(), sorted.end());
  std::int64_t first = -1;  // the smallest position among the repeats
  for (std::size_t k = 1; k < sorted.size(); ++k) {
    const auto position = static_cast<std::int64_t>(sorted[k].second);
    if (sorted[k].first == sorted[k - 1].first && (first < 0 || position < first)) first = position;
  }
  return first;
}

}  // namespace nbscope
