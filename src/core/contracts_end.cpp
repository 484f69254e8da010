// nbscope core: the contracts a frame breaks by what it never does (contract_checker.hpp): an element
// never pushed, a row never processed, a neighbour no mask relates, a mask cell one element skips.
// Each is located where the missing work was due.
#include <algorithm>

#include "core/contract_checker.hpp"

namespace nbscope::contract_detail {

// --- the end of the frame
// Where a row that was never processed was due: the start of the first processed row after it
// (2D rows go up; 3D's order is the layer lists', so its first later key), else the last row's start.
std::size_t ContractChecker::row_due(std::int64_t row) const {
  if (dim_ == 3) return row_due_3d(row);
  for (const auto& [at, key] : row_starts_)
    if (key > row) return at;
  // No row after it was processed: the last row's start (the loop over the rows, which stopped there);
  // no row processed at all: the first phase after the first-level lists' pushes began, where the loop
  // went on past every row.
  if (!row_starts_.empty()) return row_starts_.back().first;
  const std::vector<TraceEvent>& ev = t_.log.events();
  const std::size_t after = cell_pushes_.empty() ? 0 : cell_pushes_.front().at;
  for (auto p = std::upper_bound(phases_.begin(), phases_.end(), after); p != phases_.end(); ++p)
    if (ev[*p].index < 0) return *p;
  return ev.size() - 1;
}

// 3D: the book walks a layer's rows in the order its z-list loop meets their heads, the row whose lowest
// element is highest first. Due at the first processed row of the layer that comes after it so, else
// where the layer's rows end (its next phase that is no row's), else, a layer never begun, where the
// loop went on to the next layer or past the last.
std::size_t ContractChecker::row_due_3d(std::int64_t row) const {
  const std::vector<TraceEvent>& ev = t_.log.events();
  const std::int64_t layer = row / g_.n[1];
  const auto lowest = [&](std::int64_t r) { const auto f = row_member_.find(r); return f == row_member_.end() ? -1 : f->second; };
  for (const auto& [at, key] : row_starts_)
    if (key / g_.n[1] == layer && lowest(key) < lowest(row)) return at;
  std::size_t last_of_layer = kNone;  // the layer's last row phase, or the layer's own first
  for (const std::size_t p : phases_) {
    const Cell e = phase_cell(p);
    if (e[2] != layer) continue;
    const bool row_phase = e[1] >= 0;
    if (row_phase || last_of_layer == kNone) last_of_layer = p;  // with no row begun: the layer's first phase
  }
  const std::size_t first_push = cell_pushes_.empty() ? 0 : cell_pushes_.front().at;
  for (const std::size_t p : phases_) {
    const Cell e = phase_cell(p);
    if (last_of_layer != kNone ? p <= last_of_layer || (e[2] == layer && e[1] >= 0)
                               : p <= first_push || (e[2] >= 0 ? e[2] < layer : ev[p].index >= 0))
      continue;
    return p;
  }
  return row_starts_.empty() ? ev.size() - 1 : row_starts_.back().first;
}

std::string ContractChecker::row_text(const Cell& c) const {
  if (dim_ == 3) return "row " + std::to_string(names_.book_numbering ? c[1] + 1 : c[1]) + " of layer " + std::to_string(names_.book_numbering ? c[2] + 1 : c[2]);
  return "row " + std::to_string(names_.book_numbering ? c[1] + 1 : c[1]);
}

// Contacts of element k with the elements of cell `c` (the cost of a skipped cell).
void ContractChecker::cost_of_cell(std::int32_t k, const Cell& c, std::vector<Pair>& cost, std::int64_t& count) const {
  auto found = members_.find(flat(c));
  if (found == members_.end()) return;
  for (const std::int32_t m : found->second) {
    if (m == k || !in_contact(e_, k, m, t_.touching)) continue;
    ++count;
    if (cost.size() < kMaxCostListed) cost.push_back(Pair{std::min(k, m), std::max(k, m)});
  }
}

void ContractChecker::end_of_frame() {
  const std::size_t end = t_.log.events().size() - 1;
  if (!models_.empty()) {
    coverage(end);
    heads_cleared(end);
  }
  if (union_ != 0) mask(end);
}

void ContractChecker::heads_cleared(std::size_t end) {
  // A detector that clears no head (the tree rebuilds its leaves' lists) keeps no lists between frames.
  if (clear_lines_.empty()) return;
  const std::vector<TracedArray>& arrays = t_.log.arrays();
  for (const auto& [heads, m] : models_) {
    for (std::size_t slot = 0; slot < m.actual.size(); ++slot) {
      if (m.last_push[slot] == kNone || m.actual[slot] == -1) continue;
      // Due at the clearing of this array after the slot's last push (the loop that left it set), else the end.
      const std::optional<std::size_t> due = clear_due(heads, m.last_push[slot], end + 1);
      const std::size_t at = due ? *due : end;
      if (first_ && first_->event <= at) continue;
      const std::string name = static_cast<std::size_t>(heads) < arrays.size() ? arrays[static_cast<std::size_t>(heads)].name : "?";
      const std::int32_t held = m.actual[slot];
      subject_ = in_range(held) ? Pair{held, held} : Pair{-1, -1};
      breaks(Contract::HeadsCleared, at, name + "[" + std::to_string(slot) + "] still holds " + (in_range(held) ? id(held) : std::to_string(held)) +
                                         " when the frame ends: " + (due ? "this clearing leaves it set" : "no clearing resets it") +
                                         ", so the next frame's first push onto it links into this frame's list");
    }
  }
}

void ContractChecker::coverage(std::size_t end) {
  // Every element onto one first-level list: located at the loop that should have pushed it.
  std::size_t first_level_start = kNone;
  const std::vector<TraceEvent>& ev = t_.log.events();
  for (std::size_t at = 0; at < ev.size(); ++at) {
    if (ev[at].op != TraceOp::Push) continue;
    first_level_start = at;
    for (std::size_t back = at; back-- > 0;) {
      if (ev[back].op == TraceOp::Phase) {
        first_level_start = back;
        break;
      }
    }
    break;
  }
  for (std::int64_t k = 0; k < n_ && first_level_start != kNone; ++k) {
    if (first_level_[static_cast<std::size_t>(k)] == 0) {
      subject_ = Pair{static_cast<ElementId>(k), static_cast<ElementId>(k)};
      breaks(Contract::FirstLevelOnce, first_level_start, id(k) + " is never pushed onto a first-level list: the loop over all elements leaves it out");
      break;
    }
  }
  // Rows and cell lists: an element of a row that nobody of it visits from is a row not processed.
  const bool has_cell_lists = std::any_of(cell_pushes_.begin(), cell_pushes_.end(), [](const CellPush& p) { return p.full; });
  std::unordered_map<std::int64_t, bool> row_visited;
  for (std::int64_t k = 0; k < n_; ++k)
    if (last_visit_[static_cast<std::size_t>(k)] != kNone) row_visited[row_key(cells_[static_cast<std::size_t>(k)])] = true;
  // A detector that visits no cell at all while its phases run its loops has processed no row.
  const bool visits = union_ != 0 || !phases_.empty();
  bool cell_list_checked = false;
  for (std::int64_t k = 0; k < n_; ++k) {
    const Cell& c = cells_[static_cast<std::size_t>(k)];
    const std::int64_t row = row_key(c);
    const bool listed = !has_cell_lists || on_cell_list_[static_cast<std::size_t>(k)];
    if (visits && !row_visited[row]) {
      row_visited[row] = true;  // each row once; the earliest due is the break
      std::vector<Pair> cost;
      std::int64_t count = 0;
      for (std::int64_t m = 0; m < n_; ++m)
        if (row_key(cells_[static_cast<std::size_t>(m)]) == row && m > k && in_contact(e_, static_cast<ElementId>(k), static_cast<ElementId>(m), t_.touching)) {
          ++count;
          if (cost.size() < kMaxCostListed) cost.push_back(Pair{static_cast<ElementId>(k), static_cast<ElementId>(m)});
        }
      subject_ = Pair{static_cast<ElementId>(k), static_cast<ElementId>(k)};
      breaks(Contract::RowProcessed, row_due(row), row_text(c) + " holds elements (" + id(k) + " in cell " + cell_text(c) +
                                                       ") but is never processed: its cell lists are not built and no element of it visits a cell",
             std::move(cost), count);
      continue;
    }
    if (!listed && !cell_list_checked) {
      cell_list_checked = true;
      std::size_t due = end;
      for (auto p = cell_pushes_.rbegin(); p != cell_pushes_.rend(); ++p)
        if (p->full && row_key(cells_[static_cast<std::size_t>(p->k)]) == row) {
          due = p->at;
          break;
        }
      subject_ = Pair{static_cast<ElementId>(k), static_cast<ElementId>(k)};
      breaks(Contract::CellList, due, id(k) + " is never pushed onto the list of its cell " + cell_text(c) + ", while " + row_text(c) +
                                          "'s lists were built: the loop that builds them leaves it out");
    }
  }
}

void ContractChecker::mask(std::size_t end) {
  (void)end;
  const int offsets = dim_ == 3 ? 27 : 9;
  // The book's half mask when the visits keep one (so a bug's wrong visits do not redefine it), else
  // what the masks of all elements visit.
  const std::uint32_t bits = mask_bits();
  // Offsets related by neither direction: no mask relates those neighbouring cells. The direction
  // due is the one the mask's other offsets lean to (the book's half masks look down a row or layer).
  for (int bit = 0; bit < offsets; ++bit) {
    const Cell o = offset_of_bit(bit, dim_);
    const Cell opposite{-o[0], -o[1], -o[2]};
    const int back = offset_bit(opposite, dim_);
    if (bit == back) continue;
    // An offset of the book's half that no mask visits; with no half, one visited in neither direction.
    if (half_ != 0 ? lean(o, dim_) != half_ || (union_ >> bit & 1u) != 0
                   : (union_ >> bit & 1u) != 0 || (union_ >> back & 1u) != 0 || back < bit)
      continue;
    const Cell due = half_ != 0 || leans_to(o) ? o : opposite;
    for (std::int64_t k = 0; k < n_; ++k) {
      const std::size_t last = last_visit_[static_cast<std::size_t>(k)];
      Cell c{};
      if (last == kNone || (first_ && first_->event <= last)) continue;
      if (!neighbour(cells_[static_cast<std::size_t>(k)], due, c) || !members_.count(flat(c))) continue;
      std::vector<Pair> cost;
      std::int64_t count = 0;
      cost_of_cell(static_cast<std::int32_t>(k), c, cost, count);
      subject_ = Pair{static_cast<ElementId>(k), static_cast<ElementId>(k)};
      breaks(Contract::MaskRelates, last,
             "no element's mask visits its neighbour at " + offset_text(due) + " nor at " + offset_text(Cell{-due[0], -due[1], -due[2]}) +
                 ": the mask of " + id(k) + " (cell " + cell_text(cells_[static_cast<std::size_t>(k)]) + ") ends without cell " + cell_text(c) +
                 ", which holds elements, and no mask relates the two cells",
             std::move(cost), count);
    }
  }
  // Each element: the offsets the masks visit, where the cell exists and holds elements.
  for (std::int64_t k = 0; k < n_; ++k) {
    const std::size_t last = last_visit_[static_cast<std::size_t>(k)];
    if (last == kNone) continue;
    if (first_ && first_->event <= last) continue;
    for (int bit = 0; bit < offsets; ++bit) {
      if (((bits & union_) >> bit & 1u) == 0 || (visits_[static_cast<std::size_t>(k)] >> bit & 1u) != 0) continue;
      Cell c{};
      const Cell o = offset_of_bit(bit, dim_);
      if (!neighbour(cells_[static_cast<std::size_t>(k)], o, c) || !members_.count(flat(c))) continue;
      std::vector<Pair> cost;
      std::int64_t count = 0;
      cost_of_cell(static_cast<std::int32_t>(k), c, cost, count);
      subject_ = Pair{static_cast<ElementId>(k), static_cast<ElementId>(k)};
      breaks(Contract::MaskCell, last, "the mask of " + id(k) + " (cell " + cell_text(cells_[static_cast<std::size_t>(k)]) + ") never visits cell " +
                                           cell_text(c) + ", its neighbour at " + offset_text(o) + ", which holds elements and is in the contact mask",
             std::move(cost), count);
      break;
    }
  }
}

// True when offset `o` leans the way the mask's visited offsets do: on its last nonzero axis, the
// sign most visited offsets have there.
bool ContractChecker::leans_to(const Cell& o) const {
  int axis = -1;
  for (int a = 0; a < dim_; ++a)
    if (o[static_cast<std::size_t>(a)] != 0) axis = a;
  if (axis < 0) return true;
  int score = 0;
  for (int bit = 0; bit < (dim_ == 3 ? 27 : 9); ++bit) {
    if ((union_ >> bit & 1u) == 0) continue;
    score += offset_of_bit(bit, dim_)[static_cast<std::size_t>(axis)];
  }
  return score == 0 || (score > 0) == (o[static_cast<std::size_t>(axis)] > 0);
}

std::string ContractChecker::offset_text(const Cell& o) const {
  std::string out = "(";
  for (int a = 0; a < dim_; ++a) {
    const std::int32_t v = o[static_cast<std::size_t>(a)];
    out += (a > 0 ? "," : "") + std::string(v > 0 ? "+1" : v < 0 ? "-1" : "0");
  }
  return out + ")";
}

bool ContractChecker::neighbour(const Cell& c, const Cell& o, Cell& out) const {
  out = Cell{-1, -1, -1};
  for (int a = 0; a < dim_; ++a) {
    const std::int32_t v = g_.neighbour(c[static_cast<std::size_t>(a)], o[static_cast<std::size_t>(a)], a);
    if (v < 0) return false;
    out[static_cast<std::size_t>(a)] = v;
  }
  return true;
}

}  // namespace nbscope::contract_detail
