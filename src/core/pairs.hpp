// nbscope core: contact pairs, the contact test, and a bounded pair collector.
#pragma once
#include <algorithm>
#include <compare>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/elements.hpp"

namespace nbscope {

// Which pairs at exactly zero gap are contacts: `inclusive` (|c_i - c_j| <= r_i + r_j, nbscope's
// default) or `strict` (<, as LAMMPS and LIGGGHTS test rsq < radsum*radsum). --touching on every command.
enum class Touching : std::uint8_t { inclusive, strict };

// A contact between elements i < j.
struct Pair {
  ElementId i = 0;
  ElementId j = 0;
  friend auto operator<=>(const Pair&, const Pair&) = default;
};
using PairList = std::vector<Pair>;

// Most pairs one detection may produce by default (8 bytes each: 400 MB). A pile of N elements
// at one point has N(N-1)/2 contacts, so this allows one of ~10,000 elements; past it detection
// stops with an Error instead of exhausting memory. Override with DetectOptions::max_pairs.
inline constexpr std::size_t kDefaultMaxPairs = 50'000'000;

// The name --touching takes: "inclusive" or "strict".
[[nodiscard]] const char* touching_name(Touching touching);

// The contact rule on squared distances, without a branch on its data (the detectors' hot loops):
// strict d2 < rr2; inclusive also d2 == rr2.
[[nodiscard]] inline bool touches(double d2, double rr2, bool inclusive) {
  return (d2 < rr2) | (inclusive & (d2 == rr2));
}

// The difference c_i - c_j along axis a, by the minimum image when the frame is periodic along a
// (centres in [lo, hi), so one period at most is added or taken away).
[[nodiscard]] inline double axis_delta(const Elements& e, int a, double d) {
  if (!e.box.periodic[a]) return d;
  const double period = e.box.length(a);
  if (d > 0.5 * period) return d - period;
  if (d < -0.5 * period) return d + period;
  return d;
}

// Squared centre distance of i and j, by the minimum image on the frame's periodic axes.
[[nodiscard]] inline double centre_distance2(const Elements& e, ElementId i, ElementId j) {
  double dx = e.x[i] - e.x[j];
  double dy = e.y[i] - e.y[j];
  double dz = e.dim == 3 ? e.z[i] - e.z[j] : 0.0;
  if (e.box.any()) [[unlikely]] {
    dx = axis_delta(e, 0, dx);
    dy = axis_delta(e, 1, dy);
    if (e.dim == 3) dz = axis_delta(e, 2, dz);
  }
  return dx * dx + dy * dy + dz * dz;
}

// Contact as in docs/architecture.md: |c_i - c_j| <= r_i + r_j (inclusive) or < (strict), in double,
// by the minimum image on periodic axes. Exact to rounding for elements within the supported
// magnitudes (elements.hpp), where no square over- or underflows.
[[nodiscard]] inline bool in_contact(const Elements& e, ElementId i, ElementId j, Touching touching) {
  const double rr = e.r[i] + e.r[j];
  return touches(centre_distance2(e, i, j), rr * rr, touching == Touching::inclusive);
}

// Minimum-image |c_i - c_j| - (r_i + r_j): negative for an overlap; for messages.
[[nodiscard]] double contact_gap(const Elements& e, ElementId i, ElementId j);
// Each element's largest overlap r_i + r_j - |c_i - c_j| (minimum image) over its pairs in `pairs`
// that overlap; 0 for an element with none (--color-by overlap, --export-vtk's `overlap`).
[[nodiscard]] std::vector<double> element_overlaps(const Elements& e, const PairList& pairs);

// Moves every centre into [lo, hi) on the frame's periodic axes (within its dimension): a centre
// exactly at hi goes to lo, one far outside by whole periods. Open axes are left alone.
void wrap_into_box(Elements& e);

// "x, y" for the frame's periodic axes within its dimension; empty when it has none.
[[nodiscard]] std::string periodic_axes(const Elements& e);

// Throws Error("<detector>: the frame is periodic in x, y; only nbs and brute find contacts across
// a periodic boundary") when the frame has a periodic axis: the detectors that cannot wrap.
void refuse_periodic(const Elements& e, std::string_view detector);

// Throws Error when a periodic axis has no positive finite period or a centre outside [lo, hi):
// the minimum image needs both.
void check_periodic_box(const Elements& e, std::string_view detector);

// Appends pairs in (min, max) order and refuses to grow past a limit.
class PairCollector {
 public:
  // Collects into `out` (cleared), throwing Error once more than `limit` pairs arrive.
  PairCollector(PairList& out, std::size_t limit) : out_(out), limit_(limit) { out_.clear(); }
  // Records the contact {a, b}; a != b.
  void add(ElementId a, ElementId b) {
    if (out_.size() >= limit_) overflow();
    out_.push_back(a < b ? Pair{a, b} : Pair{b, a});
  }
  [[nodiscard]] std::size_t size() const { return out_.size(); }

 private:
  [[noreturn]] void overflow() const;
  PairList& out_;
  std::size_t limit_;
};

// Throws the Error of a detection past its pair limit.
[[noreturn]] void throw_pair_limit(std::size_t limit);

// PairCollector for hot loops whose contact tests are unpredictable: the caller writes every pair
// it tests at out[kept] and advances `kept` only on contact (offer_pair), so no branch depends on
// the test and `kept` stays in a register; when kept reaches capacity(), it asks reserve() for room.
class BranchFreePairs {
 public:
  // Collects into `out` (cleared), throwing Error once more than `limit` pairs are kept.
  BranchFreePairs(PairList& out, std::size_t limit) : out_(out), limit_(limit) {
    out_.clear();
    out_.resize(std::max<std::size_t>(out_.capacity(), 1024));
  }
  BranchFreePairs(const BranchFreePairs&) = delete;
  BranchFreePairs& operator=(const BranchFreePairs&) = delete;
  // The array to write pairs into, and how many fit.
  [[nodiscard]] Pair* data() { return out_.data(); }
  [[nodiscard]] std::size_t capacity() const { return out_.size(); }
  // Room for more pairs after the `kept` kept so far (throws past the limit); then data() and capacity() again.
  void grow(std::size_t kept);
  // Leaves exactly the `kept` pairs in `out`; throws past the limit.
  void finish(std::size_t kept);

 private:
  PairList& out_;
  std::size_t limit_;
};

// The place pairs are written to: out[kept], with room up to `capacity`.
struct PairCursor {
  Pair* out;
  std::size_t kept;
  std::size_t capacity;
  BranchFreePairs* owner;
};

// Writes {a, b} in (min, max) order at the cursor and keeps it when `contact` (BranchFreePairs).
inline void offer_pair(PairCursor& c, bool contact, ElementId a, ElementId b) {
  if (c.kept == c.capacity) [[unlikely]] {
    c.owner->grow(c.kept);
    c.out = c.owner->data();
    c.capacity = c.owner->capacity();
  }
  c.out[c.kept] = a < b ? Pair{a, b} : Pair{b, a};
  c.kept += contact ? 1 : 0;
}

// A sorted pair list packed as variable-length deltas (the gap to the previous i, then the gap to the
// previous j of the same i, or to i): 2-4 bytes a pair instead of 8, for what the frame history keeps.
class PackedPairs {
 public:
  // Packs `sorted` (i < j, sorted, no duplicates).
  [[nodiscard]] static PackedPairs pack(const PairList& sorted);
  // The pairs again, sorted, into `out`.
  void unpack(PairList& out) const;
  // Number of pairs, and the bytes they take.
  [[nodiscard]] std::size_t size() const { return count_; }
  [[nodiscard]] std::size_t bytes() const { return bytes_.capacity(); }

 private:
  std::vector<std::uint8_t> bytes_;
  std::size_t count_ = 0;
};

// Sorts pairs into (i, j) order; detectors emit them in their own order.
void sort_pairs(PairList& pairs);
// Sorts [first, last), pairs of one i, by j: insertion for the usual handful, std::sort beyond.
void sort_run_by_j(PairList::iterator first, PairList::iterator last);
// Calls f(p) for every pair p in `a` and not in `b`, in order; both must be sorted. No list is built.
template <class F>
void for_each_missing(const PairList& a, const PairList& b, F&& f) {
  auto j = b.begin();
  for (auto i = a.begin(); i != a.end();) {
    if (j == b.end() || *i < *j) {
      f(*i++);
    } else {
      if (!(*j < *i)) ++i;
      ++j;
    }
  }
}
// Pairs in `a` and not in `b`; both must be sorted.
PairList pairs_missing_from(const PairList& a, const PairList& b);

// Sorts pairs into (i, j) order as sort_pairs() does, in time linear in pairs + elements: a counting
// sort by i, then each i's few j in place. Keeps its buffers between calls (the check's sets of
// every frame).
class PairSorter {
 public:
  // Sorts `pairs` of elements 0..n-1 (any pair outside that range: falls back to sort_pairs()).
  void sort(PairList& pairs, std::size_t n);

 private:
  std::vector<std::uint32_t> start_;
  PairList scratch_;
};

}  // namespace nbscope
