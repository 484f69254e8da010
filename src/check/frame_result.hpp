// nbscope check: everything one frame's pipeline (check/pipeline.hpp) found, as one value: the
// elements' hash, each lane's pairs, grid, cells and report (counts, timings, violations), the
// check's sets and, when asked, the selected lane's trace. The views and the tests read a frame here.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "check/report.hpp"
#include "core/frame_trace.hpp"
#include "core/grid.hpp"
#include "core/pairs.hpp"
#include "physics/atom_columns.hpp"

namespace nbscope {

// One detector's view of the frame.
struct LaneResult {
  std::string algorithm;          // the registry name (or "recorded")
  PairList pairs;                 // A, after any injected fault, sorted, i < j
  Grid grid;                      // the detector's own grid, or one fitted with the scene's cell size
  std::vector<CellIndex> cells;   // the detector's cell of every element (shifted by off-by-one-cell)
  FrameReport report;             // counts, timings, violations (report.checked false when checks are off)
};

struct FrameResult {
  std::int64_t frame = 0;
  double time = 0;
  std::uint64_t hash = 0;         // hash_elements() of the frame's elements
  // The atom ids of the elements' rows as the frame carries them (a dump's), or null: rows name them.
  std::shared_ptr<const std::vector<std::int64_t>> ids;
  // The frame's other per-atom columns (Frame::columns: a dump's type, vx, ...), or null.
  std::shared_ptr<const AtomColumns> columns;
  // Lane 0 is the selected detector, then the comparison ones in the order given.
  std::vector<LaneResult> lanes = std::vector<LaneResult>(1);
  // The check's sets, sorted (empty when checks are off): R of lane 0, F (Box2D's contact list),
  // T (shapes touching now), G (tight-AABB pairs).
  PairList reference, box2d, touching, tight_aabb;
  // Lane 0's traced run on the elements it was given (faults not applied), made on the first request
  // (Pipeline::trace); null until then. Its `refusal` says why it holds no operations.
  std::shared_ptr<const FrameTrace> trace;

  // The selected lane and its report.
  [[nodiscard]] const LaneResult& selected() const { return lanes.front(); }
  [[nodiscard]] const FrameReport& report() const { return lanes.front().report; }
};

}  // namespace nbscope
