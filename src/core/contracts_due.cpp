// nbscope core: where the book's loops say work was due (contract_checker.hpp): which row or layer a
// plugin's phase works on, the half mask the visits keep, the rows a row's build must reach, a row
// phase that did nothing, and the clearing where a missing clear was due.
#include <algorithm>
#include <vector>

#include "core/contract_checker.hpp"

namespace nbscope::contract_detail {

void ContractChecker::infer_phase_cells() {
  const std::vector<TraceEvent>& ev = t_.log.events();
  // A plugin's phase names only its index: a row's (iy) or a layer's (iz). Which, and the row's layer,
  // is read off the first operation of its segment; phases of the same line are of the same kind.
  std::unordered_map<std::uint8_t, bool> line_is_row;
  std::unordered_map<std::size_t, std::int32_t> row_layer;
  std::unordered_map<int, bool> array_is_row;  // per heads array: its pushes key a whole cell (a row's lists) or a row of a layer
  for (const TraceEvent& e : ev)
    if (e.op == TraceOp::Push && e.write_count > 1 && e.cell[1] >= 0) array_is_row.emplace(e.writes[1].array, e.cell[0] >= 0);
  for (std::size_t i = 0; i < phases_.size(); ++i) {
    const TraceEvent& e = ev[phases_[i]];
    if (e.cell[0] >= 0 || e.cell[1] >= 0 || e.cell[2] >= 0 || e.index < 0) continue;
    const std::size_t q = phases_[i] + 1;
    if (q >= ev.size() || ev[q].op == TraceOp::Phase) continue;
    const TraceEvent& first = ev[q];
    const bool keyed_row = (first.op == TraceOp::VisitCell || (first.op == TraceOp::Push && first.cell[0] >= 0)) && first.cell[1] == e.index;
    if (keyed_row) {
      line_is_row[e.line] = true;
      row_layer[phases_[i]] = first.cell[2];
    } else if (first.op == TraceOp::Push && first.cell[0] < 0 && first.cell[1] >= 0 && first.cell[2] == e.index) {
      line_is_row.emplace(e.line, false);
    } else if (first.op == TraceOp::Clear && first.write_count > 0) {  // a clearing: of the lists of a row, or of a layer
      const auto kind = array_is_row.find(first.writes[0].array);
      if (kind != array_is_row.end()) line_is_row.emplace(e.line, kind->second);
    }
  }
  // A line no segment resolves (a row's build that pushed nothing anywhere): a row's when its phase is
  // followed at once by a row phase of the same index.
  for (std::size_t i = 0; i + 1 < phases_.size(); ++i) {
    const TraceEvent& e = ev[phases_[i]];
    const TraceEvent& next = ev[phases_[i + 1]];
    const auto next_kind = line_is_row.find(next.line);
    if (phases_[i] + 1 == phases_[i + 1] && e.index >= 0 && next.index == e.index && next_kind != line_is_row.end() && next_kind->second)
      line_is_row.emplace(e.line, true);
  }
  std::int32_t layer = -1, row = -1;
  for (const std::size_t p : phases_) {
    const TraceEvent& e = ev[p];
    Cell c{e.cell[0], e.cell[1], e.cell[2]};
    auto kind = line_is_row.find(e.line);
    // A line never resolved (a row's contacts that visit nothing anywhere): the row's phase when it follows that row's.
    if (kind == line_is_row.end() && e.index >= 0 && e.index == row) kind = line_is_row.emplace(e.line, true).first;
    if (c == Cell{-1, -1, -1} && e.index >= 0 && kind != line_is_row.end()) {
      row = kind->second ? e.index : -1;
      const auto known = row_layer.find(p);
      if (!kind->second) layer = e.index;
      c = kind->second ? Cell{-1, e.index, known != row_layer.end() ? known->second : layer} : Cell{-1, -1, e.index};
    }
    phase_cells_.emplace(p, c);
  }
}

std::optional<std::size_t> ContractChecker::clear_due(int heads, std::size_t pushed, std::size_t before) const {
  const auto found = clear_lines_.find(heads);
  if (found == clear_lines_.end()) return std::nullopt;
  const std::vector<TraceEvent>& ev = t_.log.events();
  for (auto p = std::upper_bound(phases_.begin(), phases_.end(), pushed); p != phases_.end() && *p < before; ++p)
    if (std::find(found->second.begin(), found->second.end(), ev[*p].line) != found->second.end()) return *p;
  return std::nullopt;
}

std::size_t ContractChecker::clear_was_due(int heads, std::size_t pushed, std::size_t at) const {
  const std::vector<TraceEvent>& ev = t_.log.events();
  std::optional<std::size_t> phase = clear_due(heads, pushed, at);
  if (!phase) {  // no clear of this array is traced: the phase before the reusing push's own
    const auto after = std::upper_bound(phases_.begin(), phases_.end(), at);
    if (after - phases_.begin() >= 2 && *(after - 2) > pushed) phase = *(after - 2);
  }
  if (!phase) return at;
  for (std::size_t e = *phase + 1; e < at && ev[e].op != TraceOp::Phase; ++e)
    if (ev[e].op == TraceOp::Clear && ev[e].write_count > 0 && ev[e].writes[0].array == heads) return *phase;
  return *phase + 1;  // the clearing cleared nothing of it: due at its first clear
}

void ContractChecker::close_phase(std::size_t at) {
  const std::size_t phase = open_phase_;
  open_phase_ = kNone;
  if (phase == kNone || !complete_ || at != phase + 1) return;  // the segment did something
  const TraceEvent& e = t_.log.events()[phase];
  // Which lines visit is read off the trace; where no phase visits at all, every row phase must do something.
  if (!visit_lines_.empty() && std::find(visit_lines_.begin(), visit_lines_.end(), e.line) == visit_lines_.end()) return;
  const Cell pc = phase_cell(phase);
  if (dim_ == 3 && (pc[1] < 0 || pc[2] < 0)) return;
  const std::int64_t row = dim_ == 3 ? std::int64_t{pc[2]} * g_.n[1] + pc[1] : e.index;
  const auto held = row_member_.find(row);
  if (held == row_member_.end()) return;
  const std::int32_t k = held->second;
  subject_ = Pair{k, k};
  // The row's phases before it that did nothing too (its lists built from nothing): due at the first.
  std::size_t due = phase + 1;
  for (auto p = std::lower_bound(phases_.begin(), phases_.end(), phase); p != phases_.begin(); --p) {
    const std::size_t before = *(p - 1);
    if (before + 1 != *p || phase_cell(before) != phase_cell(phase) || (dim_ == 2 && t_.log.events()[before].index != e.index)) break;
    due = before + 1;
  }
  const std::string phase_name = e.label[0] != '\0' ? std::string(e.label) : std::string("its phase");
  breaks(Contract::RowProcessed, std::min(due, t_.log.events().size() - 1),
         row_text(cells_[static_cast<std::size_t>(k)]) + " holds elements (" + id(k) + " in cell " + cell_text(cells_[static_cast<std::size_t>(k)]) +
             ") but its phase '" + phase_name + "' (operation " + std::to_string(phase + 1) + ") does nothing: no element of it visits a cell");
}

void ContractChecker::check_rows_built(std::size_t at, const Cell& own) {
  const std::size_t row_start = row_starts_.back().first;
  const auto phase = std::upper_bound(phases_.begin(), phases_.end(), at);
  const std::size_t due = phase == phases_.begin() ? at : *(phase - 1);  // the contacts' phase: where the build ended
  const int offsets = dim_ == 3 ? 27 : 9;
  for (int bit = 0; bit < offsets; ++bit) {
    const Cell o = offset_of_bit(bit, dim_);
    if (o[0] != 0 || (lean(o, dim_) != half_ && o != Cell{0, 0, 0})) continue;  // each row the half mask reaches, once
    Cell c = own;
    bool inside = true;
    for (int a = 1; a < dim_; ++a) {
      c[static_cast<std::size_t>(a)] = g_.neighbour(own[static_cast<std::size_t>(a)], o[static_cast<std::size_t>(a)], a);
      inside = inside && c[static_cast<std::size_t>(a)] >= 0;
    }
    const std::int64_t row = row_key(c);
    if (!inside || o == Cell{0, 0, 0} || !row_member_.count(row)) continue;  // the own row: cell-list at its own visit
    const auto pushed = last_row_push_.find(row);
    if (pushed != last_row_push_.end() && pushed->second > row_start) continue;
    const std::int32_t m = row_member_.at(row);
    breaks(Contract::ListComplete, due, row_text(cells_[static_cast<std::size_t>(m)]) + " holds elements (" + id(m) + " in cell " +
                                           cell_text(cells_[static_cast<std::size_t>(m)]) + "), which " + row_text(own) + "'s mask reaches, but " +
                                           row_text(own) + "'s build (operation " + std::to_string(row_start + 1) + ") put none of them on a cell list");
    return;
  }
}

void ContractChecker::check_layer_built(std::size_t at, std::int32_t layer) {
  if (!builds_cell_lists_ || half_ == 0) return;
  const auto rows = layer_rows_.find(layer);
  if (rows == layer_rows_.end()) return;
  std::size_t due = kNone;
  std::int64_t short_row = -1;
  const auto pushed_of = [this](std::int64_t row) {
    const auto p = layer_row_pushes_.find(row);
    return p == layer_row_pushes_.end() ? std::int64_t{0} : p->second;
  };
  // The loop over a layer stopped after its last push; one that never pushed was due where the build's pushes ended.
  const auto build_end = std::max_element(layer_last_push_.begin(), layer_last_push_.end(),
                                          [](const auto& a, const auto& b) { return a.second < b.second; });
  for (const std::int32_t iy : rows->second)
    for (std::int32_t dz = -1; dz <= 1; ++dz)
      for (std::int32_t dy = -1; dy <= 1; ++dy) {
        const Cell o{0, dy, dz};
        if (o != Cell{0, 0, 0} && lean(o, dim_) != half_) continue;  // the rows the half mask reaches
        const std::int32_t ry = g_.neighbour(iy, dy, 1), rz = g_.neighbour(layer, dz, 2);
        if (ry < 0 || rz < 0) continue;
        const std::int64_t row = std::int64_t{rz} * g_.n[1] + ry;
        const auto holds = row_count_.find(row);
        if (holds == row_count_.end() || pushed_of(row) >= holds->second) continue;
        const auto last = layer_last_push_.find(rz);
        const std::size_t row_due = last != layer_last_push_.end() ? last->second + 1
                                    : build_end != layer_last_push_.end() ? build_end->second + 1 : at;
        if (std::min(row_due, at) < due) due = std::min(row_due, at), short_row = row;
      }
  if (short_row < 0) return;
  const std::int32_t m = row_member_.at(short_row);
  const Cell& c = cells_[static_cast<std::size_t>(m)];
  subject_ = Pair{m, m};
  breaks(Contract::ListComplete, due,
         row_text(c) + " holds " + std::to_string(row_count_.at(short_row)) + (row_count_.at(short_row) == 1 ? " element (" : " elements (") + id(m) + " in cell " + cell_text(c) + "), which the mask of layer " +
             std::to_string(names_.book_numbering ? layer + 1 : layer) + " reaches, but that layer's build (operation " + std::to_string(layer_start_ + 1) + ") pushed " +
             std::to_string(pushed_of(short_row)) + " of them onto its y-lists when it ended (operation " + std::to_string(at + 1) +
             "): the loop over layer " + std::to_string(names_.book_numbering ? c[2] + 1 : c[2]) + "'s list stops early or never runs");
}

void ContractChecker::check_own_row_built(std::size_t at) {
  const auto [row_start, row] = row_starts_.back();
  // Only a row begun by its build: a phase that says it visits or clears begins no build (a phase naming the wrong row).
  const std::uint8_t line = t_.log.events()[row_start].line;
  if (std::find(visit_lines_.begin(), visit_lines_.end(), line) != visit_lines_.end()) return;
  for (const auto& [heads, lines] : clear_lines_)
    if (std::find(lines.begin(), lines.end(), line) != lines.end()) return;
  const auto holds = row_count_.find(row);
  if (holds == row_count_.end() || own_row_pushes_ >= holds->second) return;
  const std::int32_t m = row_member_.at(row);
  const Cell& c = cells_[static_cast<std::size_t>(m)];
  subject_ = Pair{m, m};
  // Its own row's elements first, as the book builds them: due after the last of them, or at the build's start.
  const std::size_t due = own_row_last_push_ != kNone ? own_row_last_push_ + 1 : row_start + 1;
  breaks(Contract::ListComplete, std::min(due, at),
         row_text(c) + " holds " + std::to_string(holds->second) + (holds->second == 1 ? " element" : " elements") + " (" + id(m) + " in cell " + cell_text(c) +
             "), but its build (operation " + std::to_string(row_start + 1) + ") put " + std::to_string(own_row_pushes_) +
             " of them on cell lists before its next phase (operation " + std::to_string(at + 1) + "): the loop over its own y-list stops early or never runs");
}

bool ContractChecker::row_reaches(std::int64_t building, std::int64_t row) const {
  const std::int64_t ny = g_.n[1];
  const std::int32_t by = static_cast<std::int32_t>(dim_ == 3 ? building % ny : building), ry = static_cast<std::int32_t>(dim_ == 3 ? row % ny : row);
  const std::int32_t bz = static_cast<std::int32_t>(dim_ == 3 ? building / ny : 0), rz = static_cast<std::int32_t>(dim_ == 3 ? row / ny : 0);
  for (std::int32_t dz = dim_ == 3 ? -1 : 0; dz <= (dim_ == 3 ? 1 : 0); ++dz)
    for (std::int32_t dy = -1; dy <= 1; ++dy) {
      const Cell o{0, dy, dz};
      if (o != Cell{0, 0, 0} && lean(o, dim_) != half_) continue;
      if (g_.neighbour(by, dy, 1) == ry && (dim_ != 3 || g_.neighbour(bz, dz, 2) == rz)) return true;
    }
  return false;
}

bool ContractChecker::offset_from(std::int32_t k, const Cell& c, Cell& o) const {
  const Cell& own = cells_[static_cast<std::size_t>(k)];
  o = Cell{0, 0, 0};
  for (int a = 0; a < dim_; ++a) {
    std::int32_t d = c[static_cast<std::size_t>(a)] - own[static_cast<std::size_t>(a)];
    const auto last = static_cast<std::int32_t>(g_.n[a] - 1);
    if (g_.periodic[a] && last >= 2 && (d == last || d == -last)) d = d > 0 ? -1 : 1;
    if (d < -1 || d > 1) return false;
    o[static_cast<std::size_t>(a)] = d;
  }
  return true;
}

int ContractChecker::half_of_visits() const {
  std::vector<int> leans;  // each visit's lean, in order
  for (const TraceEvent& e : t_.log.events()) {
    Cell o{};
    if (e.op != TraceOp::VisitCell || !in_range(e.element)) continue;
    if (!offset_from(e.element, Cell{e.cell[0], e.cell[1], dim_ == 3 ? e.cell[2] : -1}, o)) continue;
    if (const int l = lean(o, dim_); l != 0) leans.push_back(l);
  }
  // Visits the other way are a bug's while they are fewer than half; as many both ways is a full mask.
  const auto half_of = [&leans](std::size_t count) {
    std::int64_t down = 0, up = 0;
    for (std::size_t k = 0; k < count; ++k) (leans[k] < 0 ? down : up) += 1;
    if (down > 0 && up * 2 < down) return -1;
    if (up > 0 && down * 2 < up) return 1;
    return 0;
  };
  if (const int whole = half_of(leans.size()); whole != 0) return whole;
  // A bug late in the frame (lists a wrong clear left stale, walked by every later element) can make
  // as many wrong visits as right ones: the first quarter, before it, still keeps the half. A full
  // mask's first quarter leans both ways as its whole does.
  return leans.size() >= 64 ? half_of(leans.size() / 4) : 0;
}

std::uint32_t ContractChecker::mask_bits() const {
  if (half_ == 0) return union_;
  const int offsets = dim_ == 3 ? 27 : 9;
  std::uint32_t bits = union_ & (1u << offset_bit(Cell{0, 0, 0}, dim_));
  for (int bit = 0; bit < offsets; ++bit)
    if (lean(offset_of_bit(bit, dim_), dim_) == half_) bits |= 1u << bit;
  return bits;
}

}  // namespace nbscope::contract_detail
