#include "check/cell_changes.hpp"

#include <algorithm>
#include <cmath>

namespace nbscope {

ElementId row_of_atom(const std::vector<std::int64_t>& before, const std::vector<std::int64_t>& after, ElementId row) {
  if (row < 0 || static_cast<std::size_t>(row) >= before.size()) return -1;
  const std::int64_t id = before[static_cast<std::size_t>(row)];
  if (static_cast<std::size_t>(row) < after.size() && after[static_cast<std::size_t>(row)] == id) return row;
  const auto sorted = std::lower_bound(after.begin(), after.end(), id);  // a dump's ids ascend (io/recording.hpp)
  const auto it = sorted != after.end() && *sorted == id ? sorted : std::find(after.begin(), after.end(), id);
  return it == after.end() ? -1 : static_cast<ElementId>(it - after.begin());
}

void CellChanges::start(std::int64_t frame, const std::vector<CellIndex>& cells, Ids ids) {
  frame_ = frame;
  steps_ = 0;
  cells_ = cells;
  changed_at_.assign(cells.size(), kNever);
  ids_ = std::move(ids);
}

void CellChanges::show(std::int64_t frame, const std::vector<CellIndex>& cells, Ids ids, bool forwards) {
  if (!forwards && std::llabs(frame - frame_) > 1) return start(frame, cells, std::move(ids));
  if (ids_ && ids && ids_ != ids && *ids_ != *ids) {
    // Another frame of a dump: the cells and changes before move to their atoms' new rows.
    std::vector<CellIndex> moved_cells(ids->size(), CellIndex{-1, -1, -1});
    std::vector<std::uint64_t> moved_at(ids->size(), kNever);
    std::vector<bool> known(ids->size(), false);
    for (std::size_t k = 0; k < ids_->size() && k < cells_.size(); ++k) {
      const ElementId row = row_of_atom(*ids_, *ids, static_cast<ElementId>(k));
      if (row < 0) continue;
      moved_cells[static_cast<std::size_t>(row)] = cells_[k];
      moved_at[static_cast<std::size_t>(row)] = changed_at_[k];
      known[static_cast<std::size_t>(row)] = true;
    }
    for (std::size_t k = 0; k < known.size() && k < cells.size(); ++k)
      if (!known[k]) moved_cells[k] = cells[k];  // an atom inserted: no change
    cells_ = std::move(moved_cells);
    changed_at_ = std::move(moved_at);
  }
  ++steps_;
  changed_at_.resize(cells.size(), kNever);
  for (std::size_t k = 0; k < cells.size(); ++k)
    if (k < cells_.size() && !(cells[k] == cells_[k])) changed_at_[k] = steps_;
  cells_ = cells;
  frame_ = frame;
  ids_ = std::move(ids);
}

float CellChanges::flash(ElementId k, float decay) const {
  const std::uint64_t at = changed_at(k);
  if (at == kNever) return 0.0f;
  return std::pow(decay, static_cast<float>(steps_ - at));
}

}  // namespace nbscope
