// nbscope core: one frame's traced detection, the single record that the lists overlay and the
// stepper both show — the elements the detector ran on, its grid, the book operations it performed
// and its pseudocode. The frame loop (app) makes one per frame on request; render and ui only read it.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/detector.hpp"
#include "core/elements.hpp"
#include "core/grid.hpp"
#include "core/trace.hpp"

namespace nbscope {

// Most elements whose detection is recorded: ~30 events of ~90 bytes each per element.
inline constexpr std::int64_t kMaxTracedElements = 50'000;
// Most pair tests of brute force recorded (one event each; brute keeps no arrays, only tests).
inline constexpr std::int64_t kMaxTracedBruteTests = 2'000'000;

// One frame's traced detection. `refusal` says why `log` holds no operations ("" when it does).
struct FrameTrace {
  std::uint64_t serial = 0;        // distinct for every trace made in this process (a cache key)
  std::int64_t frame = -1;         // the frame it was recorded on
  std::string algorithm;           // the detector's registry name
  Elements elements;               // the detector's input (stale positions under that fault)
  Grid grid;                       // the frame's grid: the detector's own, else fitted to the elements
  bool detector_grid = false;      // true when `grid` is the detector's own (nbs, screen, tree, sort)
  TraceLog log;                    // every book operation, in order
  PairList pairs;                  // the traced run's pairs, unsorted (before any fault)
  std::vector<const char*> pseudocode;  // TraceEvent::line indexes it
  std::string refusal;             // why nothing was recorded, in words for the panels
  bool detected = false;           // the detector ran (`pairs` is its answer), recorded or not
  Touching touching = Touching::inclusive;  // the contact convention it detected under
  std::optional<Misbehaviour> misbehaviour;  // the detection's first misbehaviour (a plugin's), if any
};

// An empty trace of frame `frame` by `algorithm` with a fresh serial, for a caller to fill `refusal`.
[[nodiscard]] FrameTrace refused_trace(std::int64_t frame, std::string_view algorithm);

// Runs `detector` traced on `elements` (frame `frame`, whose grid is `frame_grid`) unless the
// recording would not fit in memory or the detector records nothing; never throws for those: the
// result's `refusal` says why. Throws Error when the detection itself fails.
[[nodiscard]] std::shared_ptr<const FrameTrace> trace_frame(Detector& detector, const Elements& elements,
                                                            const DetectOptions& options, std::int64_t frame,
                                                            const Grid& frame_grid);

}  // namespace nbscope
