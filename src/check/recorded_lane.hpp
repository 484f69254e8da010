// nbscope check: `recorded`, the contact pairs a recording carries (a frame's `pairs` block,
// io/recording.hpp) as a lane beside the detectors' (check/pipeline.hpp), so that `nbscope replay` checks a
// simulation's own pairs with A==R exactly as it checks nbscope's, and the window's picker,
// Timeline and Violations panel work on them.
//
// Not in core's registry: it is no contact-detection algorithm (`pairs`, `dump`, `scaling`, the
// benchmarks and scenes have nothing for it). The pipeline makes it by name (make_lane_detector),
// with its capabilities declared (recorded_info: no trace, no lists), and gives it each frame's
// pairs (set_pairs).
#pragma once
#include <memory>
#include <string_view>

#include "check/faults.hpp"
#include "core/detector.hpp"

namespace nbscope {

// Returns the pairs of the recorded frame it is given: normalised to i < j (i == j and repeats are
// kept, for the check to report as the user's bugs); the lane sorts them as it sorts any detector's.
class RecordedPairsDetector final : public Detector {
 public:
  // "recorded".
  [[nodiscard]] std::string_view name() const override { return kRecordedAlgorithm; }
  // A .nbsrec is 2D; a dump's frames may be 3D.
  [[nodiscard]] bool supports_dim(int dim) const override { return dim == 2 || dim == 3; }
  // The frame's pairs the next detect() returns, as recorded (they must outlive that call); null: none.
  void set_pairs(const PairList* pairs) { pairs_ = pairs; }
  // The current frame's pairs (the elements are not looked at); Error without a frame that has a
  // pairs block, or past options.max_pairs.
  void detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) override;
  // As detect(); nothing is recorded (no book operations: the pairs were read, not detected).
  void detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs, TraceLog& out_trace) override;
  // No arrays of its own.
  [[nodiscard]] std::size_t own_bytes() const override { return 0; }

 private:
  const PairList* pairs_ = nullptr;
};

// What `recorded` can do, in the registry's terms: 2D and 3D, no trace, no lists.
[[nodiscard]] const DetectorInfo& recorded_info();
// recorded_info() for "recorded", else the registry's entry (Error for an unknown name).
[[nodiscard]] const DetectorInfo& algorithm_info(std::string_view name);
// A lane's detector: RecordedPairsDetector for "recorded", else the registry's (of either dimension:
// a frame it does not handle is refused when it comes); Error for an unknown name.
[[nodiscard]] std::unique_ptr<Detector> make_lane_detector(std::string_view name);
// Error when `fault` cannot act on recorded pairs: the faults that emulate a detector's bug in its
// input or cells (stale-positions, drop-mask-cell, off-by-one-cell) and Box2D's (drop-box2d-contact).
// None and drop-pair, which drops one of the pairs themselves, pass.
void check_recorded_fault(Fault fault);
// Why the stepper and the lists overlay have nothing to show for `recorded`, in words.
[[nodiscard]] const char* recorded_trace_refusal();

}  // namespace nbscope
