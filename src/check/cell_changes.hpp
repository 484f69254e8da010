// nbscope check: which element changed cell at which step of the frames shown, kept by the frame
// loop as it publishes each frame, so that a view draws the cell-change flashes of any frame when
// it draws, without having followed each step (app/frame_loop.hpp: FrameLoop::cell_changes).
//
// Steps count the frames shown one after another: a step forwards, or a neighbouring kept frame
// shown. A new source, or a jump to a frame that is no neighbour, starts the count again with no
// change known. Rows of a dump's frames follow their atom ids, so that an atom that is lost or
// inserted does not mark every row after it.
#pragma once
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "core/cells.hpp"
#include "core/elements.hpp"

namespace nbscope {

// The row in `after` of the atom at `row` in `before` (two frames' atom ids, a dump's ascending):
// -1 when it is gone, or `row` is none.
[[nodiscard]] ElementId row_of_atom(const std::vector<std::int64_t>& before, const std::vector<std::int64_t>& after, ElementId row);

class CellChanges {
 public:
  // changed_at() of an element whose cell did not change since the count started.
  static constexpr std::uint64_t kNever = std::numeric_limits<std::uint64_t>::max();
  using Ids = std::shared_ptr<const std::vector<std::int64_t>>;

  // A new source, or a jump: frame `frame`'s cells, step 0, no change known.
  void start(std::int64_t frame, const std::vector<CellIndex>& cells, Ids ids);
  // The frame shown next (`frame` with its `cells` and atom `ids`): one step after a neighbour
  // (|frame - last| <= 1, or `forwards` for a step through kept frames), marking every element
  // whose cell differs; anything else starts again.
  void show(std::int64_t frame, const std::vector<CellIndex>& cells, Ids ids, bool forwards);
  // Steps since the count started.
  [[nodiscard]] std::uint64_t steps() const { return steps_; }
  // The step at which element k's cell last changed (kNever: not since the start, or no such row).
  [[nodiscard]] std::uint64_t changed_at(ElementId k) const {
    return k >= 0 && static_cast<std::size_t>(k) < changed_at_.size() ? changed_at_[static_cast<std::size_t>(k)] : kNever;
  }
  // 1 at the step element k's cell changed, times `decay` for each step since; 0 without a change.
  [[nodiscard]] float flash(ElementId k, float decay) const;
  // Rows of the frame last shown.
  [[nodiscard]] std::size_t size() const { return changed_at_.size(); }

 private:
  std::int64_t frame_ = 0;
  std::uint64_t steps_ = 0;
  std::vector<CellIndex> cells_;
  std::vector<std::uint64_t> changed_at_;
  Ids ids_;
};

}  // namespace nbscope
