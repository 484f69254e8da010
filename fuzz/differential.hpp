// nbscope fuzz targets: every registered detector against brute force on one element set, shared by
// the detectors target (decoded sets) and the recording target (recorded frames).
//
// A detector may refuse a set only where the contract says it does: the grid cannot be made
// (make_grid throws: cell size below the largest diameter, too many cells), the screen array would
// be too large, an element beyond box2d's float range, or more pairs than options.max_pairs — and
// the pair limit must refuse exactly when brute force finds more pairs than it.
#pragma once
#include <bit>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/brute.hpp"
#include "core/detector.hpp"
#include "core/error.hpp"
#include "core/grid.hpp"
#include "core/nbs.hpp"
#include "fuzz_check.hpp"

namespace nbscope::fuzz {

// Grids larger than this are skipped: the detectors' arrays grow with the grid's sides (screen's
// with its area), and filling 2^24 heads under the sanitizers takes 0.1 s an input, which would
// starve the search of everything else. Those sizes are the unit tests' and the limits' business.
inline constexpr std::int64_t kFuzzMaxSides = std::int64_t{1} << 12;  // nx + ny (+ nz)
inline constexpr std::int64_t kFuzzMaxCells = std::int64_t{1} << 16;  // nx * ny (* nz)

// One instance of every registered detector for `dim`, kept across the sets of one input (as a
// simulation keeps them across frames, so stale state from the set before is exercised too).
struct DetectorSet {
  std::vector<std::unique_ptr<Detector>> detectors;
  explicit DetectorSet(int dim) {
    for (const DetectorInfo& info : detector_infos())
      if ((dim == 2 && info.dim2) || (dim == 3 && info.dim3)) detectors.push_back(info.make());
  }
};

// "(i,j)" for messages.
inline std::string pair_text(const Pair& p) { return "(" + std::to_string(p.i) + "," + std::to_string(p.j) + ")"; }

// Most elements a set given to require_every_detector_equals_brute() may have.
inline constexpr std::int64_t kFuzzMaxElements = 64;

// A pair set of at most kFuzzMaxElements elements as a bit matrix: row i holds bit j for pair (i, j).
// Comparing bit matrices instead of sorted lists keeps the check linear in the pairs (a set of 64
// elements at one point has 2016 pairs, for every detector and path).
struct PairBits {
  std::uint64_t row[kFuzzMaxElements] = {};
  friend bool operator==(const PairBits&, const PairBits&) = default;
};

// Aborts unless `got` is `ref` as a set, each pair once with i < j, ids below `n`.
inline void require_same_pairs(const PairBits& ref, const PairList& got, std::int64_t n, const std::string& who) {
  PairBits bits;
  // Messages are built only on failure: this runs for every pair of every detector of every input.
  for (const Pair& p : got) {
    if (!(p.i < p.j) || p.i < 0 || p.j >= n) fuzz_fail(who + ": pair " + pair_text(p) + " is not i < j < N");
    std::uint64_t& word = bits.row[p.i];
    const std::uint64_t bit = std::uint64_t{1} << p.j;
    if (word & bit) fuzz_fail(who + ": pair " + pair_text(p) + " twice");
    word |= bit;
  }
  if (bits == ref) return;
  std::size_t ref_count = 0;
  for (const std::uint64_t w : ref.row) ref_count += static_cast<std::size_t>(std::popcount(w));
  std::string what = who + ": " + std::to_string(got.size()) + " pairs, brute force finds " + std::to_string(ref_count);
  for (ElementId i = 0; i < n; ++i) {
    const std::uint64_t missing = ref.row[i] & ~bits.row[i], extra = bits.row[i] & ~ref.row[i];
    if (missing != 0) what += "; missing " + pair_text({i, static_cast<ElementId>(std::countr_zero(missing))});
    if (extra != 0) what += "; extra " + pair_text({i, static_cast<ElementId>(std::countr_zero(extra))});
  }
  fuzz_fail(what);
}

// True when `message` is a refusal the contract documents for `name` on a grid make_grid accepts.
inline bool documented_refusal(std::string_view name, const std::string& message) {
  if (name == "screen" && message.starts_with("screen: the screen array")) return true;
  if (name == "box2d" && message.find("beyond Box2D's float range") != std::string::npos) return true;
  return false;
}

// Runs every detector of `set` on `e` (untraced, traced, and nbs's book path) and aborts on any
// difference from brute force or any refusal the contract does not allow. Skips grids past
// kFuzzMaxSides / kFuzzMaxCells.
inline void require_every_detector_equals_brute(DetectorSet& set, const Elements& e, const DetectOptions& options) {
  if (e.size() > kFuzzMaxElements) fuzz_fail("require_every_detector_equals_brute: more than 64 elements");
  PairBits ref;
  std::size_t ref_count = 0;
  {
    BruteDetector brute;
    DetectOptions unlimited = options;
    unlimited.max_pairs = kDefaultMaxPairs;
    PairList pairs;
    brute.detect(e, unlimited, pairs);  // at most 64*63/2 pairs here: never refused
    for (const Pair& p : pairs) ref.row[p.i] |= std::uint64_t{1} << p.j;
    ref_count = pairs.size();
  }
  const bool over_limit = ref_count > options.max_pairs;
  std::string grid_error;
  try {
    const Grid grid = make_grid(e, options.grid);
    const std::int64_t sides = grid.n[0] + grid.n[1] + grid.n[2];
    const double cells = static_cast<double>(grid.n[0]) * static_cast<double>(grid.n[1]) * static_cast<double>(grid.n[2]);
    if (sides > kFuzzMaxSides || cells > static_cast<double>(kFuzzMaxCells)) return;
  } catch (const Error& error) {
    grid_error = error.what();
  }
  PairList got;
  TraceLog trace;
  for (auto& detector : set.detectors) {
    const std::string name(detector->name());
    for (int path = 0; path < 3; ++path) {
      auto* nbs = dynamic_cast<NbsDetector*>(detector.get());
      if (path == 2 && nbs == nullptr) continue;
      const std::string who = name + (path == 0 ? "" : path == 1 ? " (traced)" : " (book path)");  // short: SSO
      try {
        if (path == 0) detector->detect(e, options, got);
        if (path == 1) detector->detect_traced(e, options, got, trace);
        if (path == 2) nbs->detect_book(e, options, got);
      } catch (const Error& error) {
        const std::string message = error.what();
        if (!grid_error.empty() && message == grid_error) continue;  // the grid refused, as documented
        if (over_limit && message.starts_with("more than ")) continue;
        if (documented_refusal(name, message)) continue;
        fuzz_fail(who + " refused a set: " + message + (grid_error.empty() ? "" : " (make_grid: " + grid_error + ")") +
                  (over_limit ? " (over the pair limit)" : ""));
      }
      if (over_limit)
        fuzz_fail(who + ": " + std::to_string(got.size()) + " pairs past the pair limit " +
                  std::to_string(options.max_pairs) + " without an error");
      if (!grid_error.empty() && detector->last_grid() != nullptr)
        fuzz_fail(who + ": detected on a grid make_grid refuses: " + grid_error);
      if (planted_fault() == "drop-pair" && name == "nbs" && !got.empty()) got.pop_back();
      require_same_pairs(ref, got, e.size(), who);
    }
  }
}

}  // namespace nbscope::fuzz
