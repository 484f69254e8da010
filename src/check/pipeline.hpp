// nbscope check: one frame's pipeline. Given a frame (physics/frame.hpp) it runs every lane
// (the selected detector, then the comparison ones, on the same elements with the same fault), then
// the cross-check (check/check.hpp), and returns one FrameResult (check/frame_result.hpp).
//
//   source elements -> [stale-positions: last frame's positions] -> each lane: detect, sort, grid,
//   cells (the detector's own when it has them, then the grid's kept for the cells check), output fault -> checker: F, G, T (Box2D's side, when the source has one), R, invariants
//   -> FrameResult (hash, lanes, sets)
//
// The pipeline is the one owner of the stale-positions fault's cache: the positions of the frame
// before, remembered when a frame is made from its predecessor, fetched (FrameInput::previous) only
// when a frame is detected without it (a past frame shown again).
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "check/check.hpp"
#include "check/faults.hpp"
#include "check/frame_result.hpp"
#include "check/recorded_lane.hpp"
#include "physics/frame.hpp"

namespace nbscope {

struct PipelineOptions {
  std::string algorithm = "nbs";    // registry name, or "recorded" (check/recorded_lane.hpp)
  Fault fault = Fault::None;
  bool checks = true;               // run the cross-check every frame
  std::int64_t brute_limit = 2000;  // R is brute force up to this many elements (CheckOptions)
};

// What the pipeline is told of one frame beside its source.
struct FrameInput {
  const Frame* source = nullptr;  // with its own pairs and their precision for a `recorded` lane
  bool first = false;             // no frame before it: stale positions are its own
  std::function<Elements()> previous;     // the frame before's elements, when not remembered
  std::string where;                      // "path: frame K: ", for errors
};

class Pipeline {
 public:
  // Throws Error for an unknown or 3D-only algorithm, or `recorded` with a fault it cannot take.
  explicit Pipeline(const PipelineOptions& options);
  ~Pipeline();
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  // ---- configuration (takes effect on the next run) ----
  // Switches lane 0's detector (its last report stays until then); Error, old kept, for an unknown
  // name or when `accept_recorded` (called when the name is `recorded`) throws.
  void set_algorithm(std::string_view name, const std::function<void()>& accept_recorded = {});
  // The comparison lanes (fresh reports); Error, old kept, as set_algorithm.
  void set_comparison_algorithms(const std::vector<std::string>& names, const std::function<void()>& accept_recorded = {});
  void set_fault(Fault fault) { options_.fault = fault; }
  void set_checks(bool on) { options_.checks = on; }
  // The grid options of the frames to come (the scene's or the recording's).
  void set_detect_options(const DetectOptions& options) { detect_options_ = options; }
  [[nodiscard]] const PipelineOptions& options() const { return options_; }
  [[nodiscard]] const DetectOptions& detect_options() const { return detect_options_; }
  [[nodiscard]] const std::vector<std::string>& comparison_algorithms() const { return comparison_names_; }
  // True when a lane checks a recording's own pairs.
  [[nodiscard]] bool has_recorded_lane() const;
  // Lane 0's detector (its name, own_bytes(), pseudocode()).
  [[nodiscard]] const Detector& detector() const { return *lanes_.front().detector; }
  // How R is chosen, in words.
  [[nodiscard]] std::string reference_policy() const { return checker_.reference_policy(); }

  // ---- one frame ----
  // Frame `frame` is to be detected with `previous` as the stale-positions fault's last positions.
  void remember_previous(std::int64_t frame, Elements previous);
  // The physics time of the frame to come (or of the current one, detected again: 0).
  void set_physics_ms(double ms);
  // Forgets every lane's report (a new run).
  void clear_reports();
  // Detects and checks `in.source`'s current frame with every lane. Throws Error ("where" + lane
  // name + what) when a detector refuses the frame.
  const FrameResult& run(const FrameInput& in);
  // The last run's result.
  [[nodiscard]] const FrameResult& result() const { return result_; }
  // Lane 0's traced run on what it was given this frame (`source` is the frame's, as at run()): the
  // frame's own detection when traces are recorded, else made on the first request (the detector
  // called once more, traced) and kept in the result until the next run.
  std::shared_ptr<const FrameTrace> trace(const Frame& source);
  // From the next run on, lane 0's detection records its trace (on one thread) and is the frame's
  // only call of the detector: what the window does while its lists overlay or stepper is open, so a
  // plugin is not called twice for one frame. Detects nothing now.
  void set_record_traces(bool on) { record_traces_ = on; }
  [[nodiscard]] bool record_traces() const { return record_traces_; }

 private:
  struct Lane {
    std::unique_ptr<Detector> detector;
    RecordedPairsDetector* recorded = nullptr;  // `detector` when it reads a recording's pairs
    std::vector<CellIndex> grid_cells;          // the grid's cells when the detector has its own (the cells check)
    explicit Lane(std::string_view algorithm);
  };
  // Runs `lane` on `input` into `out`; traced (into result_.trace) when `traced`.
  void detect(Lane& lane, LaneResult& out, const Elements& input, const std::string& where, bool traced);
  // What the detectors are given this frame.
  const Elements& detector_input(const Frame& source) const { return detected_on_source_ ? source.elements() : detected_on_; }

  PipelineOptions options_;
  bool record_traces_ = false;
  DetectOptions detect_options_;
  std::vector<Lane> lanes_;                      // parallel to result_.lanes
  std::vector<std::string> comparison_names_;
  FrameChecker checker_;
  FrameResult result_;
  Elements stale_;               // the elements of the frame before stale_for_ (stale-positions fault)
  std::int64_t stale_for_ = -1;  // the frame stale_ serves; another fetches its own when needed
  Elements detected_on_;         // what the detectors were given when not the source's elements
  bool detected_on_source_ = true;
};

}  // namespace nbscope
