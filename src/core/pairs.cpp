#include "core/pairs.hpp"

#include <algorithm>
#include <cassert>
#include <string>

#include "core/error.hpp"

namespace nbscope {

void throw_pair_limit(std::size_t limit) {
  throw Error("more than " + std::to_string(limit) + " contact pairs (the pair limit; too many elements overlap at one place)");
}

void PairCollector::overflow() const { throw_pair_limit(limit_); }

void BranchFreePairs::grow(std::size_t kept) {
  if (kept > limit_) {
    out_.resize(limit_);
    throw_pair_limit(limit_);
  }
  // Doubling, but never far past the limit: the tests beyond it only find that it is broken.
  out_.resize(std::max(kept + 1, std::min(2 * out_.size(), limit_ + 1)));
}

void BranchFreePairs::finish(std::size_t kept) {
  out_.resize(std::min(kept, limit_));
  if (kept > limit_) throw_pair_limit(limit_);
}

void sort_pairs(PairList& pairs) { std::sort(pairs.begin(), pairs.end()); }

void PairSorter::sort(PairList& pairs, std::size_t n) {
  if (pairs.size() < 64) {
    sort_pairs(pairs);
    return;
  }
  for (const Pair& p : pairs) {
    if (p.i < 0 || static_cast<std::size_t>(p.i) >= n) {
      sort_pairs(pairs);
      return;
    }
  }
  start_.assign(n + 1, 0);
  for (const Pair& p : pairs) ++start_[static_cast<std::size_t>(p.i) + 1];
  for (std::size_t k = 0; k < n; ++k) start_[k + 1] += start_[k];
  scratch_.resize(pairs.size());
  for (const Pair& p : pairs) scratch_[start_[static_cast<std::size_t>(p.i)]++] = p;
  // start_[i] is now the end of i's run (the start of i+1's).
  std::uint32_t from = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sort_run_by_j(scratch_.begin() + from, scratch_.begin() + start_[i]);
    from = start_[i];
  }
  pairs.swap(scratch_);
}

namespace {
void put_varint(std::vector<std::uint8_t>& out, std::uint32_t v) {
  while (v >= 0x80u) {
    out.push_back(static_cast<std::uint8_t>(v | 0x80u));
    v >>= 7;
  }
  out.push_back(static_cast<std::uint8_t>(v));
}
std::uint32_t get_varint(const std::uint8_t*& p) {
  std::uint32_t v = 0;
  for (int shift = 0;; shift += 7) {
    const std::uint8_t b = *p++;
    v |= static_cast<std::uint32_t>(b & 0x7fu) << shift;
    if ((b & 0x80u) == 0) return v;
  }
}
}  // namespace

PackedPairs PackedPairs::pack(const PairList& sorted) {
  PackedPairs out;
  out.count_ = sorted.size();
  out.bytes_.reserve(sorted.size() * 3);
  ElementId last_i = 0, last_j = 0;
  for (const Pair& p : sorted) {
    assert(p.i >= last_i && p.i < p.j && "PackedPairs::pack: pairs must be sorted with i < j");
    if (p.i != last_i) last_j = p.i;
    put_varint(out.bytes_, static_cast<std::uint32_t>(p.i - last_i));
    put_varint(out.bytes_, static_cast<std::uint32_t>(p.j - last_j));
    last_i = p.i;
    last_j = p.j;
  }
  out.bytes_.shrink_to_fit();
  return out;
}

void PackedPairs::unpack(PairList& out) const {
  out.resize(count_);
  const std::uint8_t* p = bytes_.data();
  ElementId i = 0, j = 0;
  for (std::size_t k = 0; k < count_; ++k) {
    const auto di = static_cast<ElementId>(get_varint(p));
    if (di != 0) j = i + di;
    i += di;
    j += static_cast<ElementId>(get_varint(p));
    out[k] = {i, j};
  }
}

PairList pairs_missing_from(const PairList& a, const PairList& b) {
  PairList out;
  for_each_missing(a, b, [&](const Pair& p) { out.push_back(p); });
  return out;
}

void sort_run_by_j(PairList::iterator first, PairList::iterator last) {
  if (last - first > 32) {
    std::sort(first, last);
    return;
  }
  for (auto it = first + (first != last ? 1 : 0); it < last; ++it) {
    const Pair p = *it;
    auto hole = it;
    for (; hole > first && (hole - 1)->j > p.j; --hole) *hole = *(hole - 1);
    *hole = p;
  }
}

}  // namespace nbscope
