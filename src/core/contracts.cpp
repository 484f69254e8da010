// nbscope core: the list algorithms' contracts along a trace (contracts.hpp); each contract's name
// and rule are in contract_names.cpp.
//
// Index: Model (what the frame's lists hold so far, per heads array) | Checker: the events
// in order (pushes, clears, visits, tests), then the end of the frame (coverage, the mask) | the API.
#include "core/contracts.hpp"

#include "core/contract_checker.hpp"

#include <algorithm>
#include <cstdio>
#include <array>
#include <unordered_map>

namespace nbscope {

namespace contract_detail {

ContractChecker::ContractChecker(const FrameTrace& t, const ContractNames& names, bool complete)
    : complete_(complete), t_(t), e_(t.elements), g_(t.grid), dim_(t.elements.dim), n_(t.elements.size()), names_(names) {
  cells_.resize(static_cast<std::size_t>(n_));
  for (std::int64_t k = 0; k < n_; ++k) {
    Cell c{0, 0, -1};  // iz -1 in 2D
    for (int a = 0; a < dim_; ++a) c[static_cast<std::size_t>(a)] = g_.cell(e_.axis(a)[static_cast<Eigen::Index>(k)], a);
    cells_[static_cast<std::size_t>(k)] = c;
    members_[flat(c)].push_back(static_cast<std::int32_t>(k));
  }
  visits_.assign(static_cast<std::size_t>(n_), 0);
  last_visit_.assign(static_cast<std::size_t>(n_), kNone);
  first_level_.assign(static_cast<std::size_t>(n_), 0);
  on_cell_list_.assign(static_cast<std::size_t>(n_), false);
  reported_.reserve(t.pairs.size());
  for (const Pair& p : t.pairs) reported_.push_back(key(p.i, p.j));
  std::sort(reported_.begin(), reported_.end());
  for (std::int64_t k = n_; k-- > 0;) {
    const Cell& c = cells_[static_cast<std::size_t>(k)];
    row_member_[row_key(c)] = static_cast<std::int32_t>(k);  // the lowest k last
    if (row_count_[row_key(c)]++ == 0 && dim_ == 3) layer_rows_[c[2]].push_back(c[1]);
  }
  cell_listed_at_.assign(static_cast<std::size_t>(n_), kNone);
  const std::vector<TraceEvent>& ev = t.log.events();
  std::size_t phase = kNone;
  for (std::size_t at = 0; at < ev.size(); ++at) {
    // Lists keyed to a row but not a cell (2D's y-lists, 3D's y-lists of a layer): the book's, whose rows build cell lists.
    if (ev[at].op == TraceOp::Push && ev[at].cell[0] < 0 && ev[at].cell[1] >= 0) builds_cell_lists_ = true;
    if (ev[at].op == TraceOp::Phase) phases_.push_back(at), phase = at;
    if (ev[at].op == TraceOp::VisitCell && phase != kNone &&
        std::find(visit_lines_.begin(), visit_lines_.end(), ev[phase].line) == visit_lines_.end())
      visit_lines_.push_back(ev[phase].line);
    if (ev[at].op == TraceOp::Clear && ev[at].write_count > 0) {
      std::vector<std::uint8_t>& lines = clear_lines_[ev[at].writes[0].array];
      if (std::find(lines.begin(), lines.end(), ev[at].line) == lines.end()) lines.push_back(ev[at].line);
    }
  }
}

void ContractChecker::end_walk(std::size_t at) {
  if (!walk_) return;
  const Walk w = *walk_;
  walk_.reset();
  const auto members = members_.find(flat(w.cell));
  const auto list = cell_list_.find(flat(w.cell));
  if (members == members_.end() || list == cell_list_.end()) return;  // an empty cell: nothing to walk
  const Model& m = models_.at(list->second.heads);
  const auto slot = static_cast<std::size_t>(list->second.slot);
  const auto holds = static_cast<std::int64_t>(members->second.size());
  // The slot holds this cell's list only while its head was pushed for this cell (a slot is reused row by row).
  const std::int32_t head = m.head[slot];
  const std::int64_t listed = head >= 0 && m.member_cell[static_cast<std::size_t>(head)] == w.cell ? m.count[slot] : 0;
  const std::string text = "cell " + cell_text(w.cell) + " holds " + std::to_string(holds) + (holds == 1 ? " element" : " elements");
  subject_ = Pair{w.k, w.k};
  if (listed < holds) {
    // The list the mask walked was built short: located at its build's last push (the loop that stopped
    // early), or, built for this row not at all, at the last push of the loop that builds this row's lists.
    std::size_t due = listed > 0 ? m.last_push[slot] : w.visit;
    const auto row_push = last_row_push_.find(row_key(w.cell));
    const std::size_t row_start = row_starts_.empty() ? 0 : row_starts_.back().first;
    if (listed == 0 && row_push != last_row_push_.end() && row_push->second > row_start) due = row_push->second;
    breaks(Contract::ListComplete, due, text + ", but its list holds " + std::to_string(listed) + " when " + id(w.k) +
                                            "'s mask walks it (operation " + std::to_string(w.visit + 1) + "): the loop that builds it stops early");
  } else if (w.tested < holds) {
    breaks(Contract::WalkComplete, at, text + " on its list, but the walk for " + id(w.k) + " (operation " + std::to_string(w.visit + 1) + ") tests " +
                                           std::to_string(w.tested) + " of them and stops here");
  }
}

std::optional<BrokenContract> ContractChecker::run() {
  const std::vector<TraceEvent>& ev = t_.log.events();
  half_ = half_of_visits();
  if (dim_ == 3) {
    infer_phase_cells();
    for (const std::size_t p : phases_) {  // the lines of the layers' builds: a layer phase whose first operation pushes onto its y-lists
      const Cell pc = phase_cell(p);
      const bool build = pc[1] < 0 && pc[2] >= 0 && p + 1 < ev.size() && ev[p + 1].op == TraceOp::Push && ev[p + 1].cell[0] < 0 && ev[p + 1].cell[2] == pc[2];
      if (build && std::find(layer_build_lines_.begin(), layer_build_lines_.end(), ev[p].line) == layer_build_lines_.end())
        layer_build_lines_.push_back(ev[p].line);
    }
  }
  for (std::size_t at = 0; at < ev.size(); ++at) {  // on past a break: coverage needs every event
    const TraceEvent& e = ev[at];
    if (e.op != TraceOp::TestPair) end_walk(at);
    switch (e.op) {
      case TraceOp::Push: on_push(at, e); break;
      case TraceOp::Clear: on_clear(at, e); break;
      case TraceOp::VisitCell: on_visit(at, e); break;
      case TraceOp::TestPair: on_test(at, e); break;
      case TraceOp::Phase: on_phase(at, e); break;
      case TraceOp::Set: break;
    }
  }
  if (ev.empty()) return std::nullopt;
  close_phase(ev.size());
  // The end of the frame: what was never done is located where it was due, and competes with the
  // breaks found in order by its operation.
  end_walk(ev.empty() ? 0 : ev.size() - 1);
  check_tests();
  if (complete_) end_of_frame();
  return first_;
}

void ContractChecker::breaks(Contract c, std::size_t at, std::string text, std::vector<Pair> cost, std::int64_t cost_count) {
  if (first_ && first_->event <= at) return;
  BrokenContract b;
  b.contract = c;
  b.event = at;
  b.subject = !cost.empty() ? cost.front() : subject_;  // the pair it cost, else what the event names
  b.text = std::move(text);
  b.cost_count = std::max<std::int64_t>(cost_count, static_cast<std::int64_t>(cost.size()));
  if (cost.size() > kMaxCostListed) cost.resize(kMaxCostListed);
  b.cost = std::move(cost);
  first_ = std::move(b);
}

ContractChecker::Model& ContractChecker::model(int heads) {
  auto found = models_.find(heads);
  if (found != models_.end()) return found->second;
  Model m;
  m.level = models_.size();
  const std::vector<TracedArray>& arrays = t_.log.arrays();
  const std::size_t slots = heads >= 0 && static_cast<std::size_t>(heads) < arrays.size() ? arrays[static_cast<std::size_t>(heads)].initial.size() : 0;
  m.head.assign(slots, -1);
  m.build.assign(slots, 0);
  m.member_slot.assign(static_cast<std::size_t>(n_), -1);
  m.member_build.assign(static_cast<std::size_t>(n_), 0);
  m.member_cell.assign(static_cast<std::size_t>(n_), Cell{-1, -1, -1});
  m.member_at.assign(static_cast<std::size_t>(n_), 0);
  m.actual.assign(slots, -1);
  for (std::size_t slot = 0; slot < slots; ++slot) m.actual[slot] = initial_head(heads, static_cast<std::int64_t>(slot));
  m.last_push.assign(slots, kNone);
  m.count.assign(slots, 0);
  return models_.emplace(heads, std::move(m)).first->second;
}

void ContractChecker::on_phase(std::size_t at, const TraceEvent& e) {
  close_phase(at);
  std::int64_t row = -1;
  const Cell pc = phase_cell(at);
  // 3D: a layer's build ends at its first row phase, or at any other phase when it has no row (checked once).
  if (dim_ == 3 && layer_start_ != kNone && !layer_checked_ && at != layer_start_) {
    const std::int32_t layer = phase_cell(layer_start_)[2];
    if (pc[1] < 0 || pc[2] == layer) {
      layer_checked_ = true;
      check_layer_built(at, layer);
    }
  }
  if (dim_ == 3 && pc[1] < 0 && pc[2] >= 0) {
    // A layer's phase is a build when its line's phases push onto y-lists, and its own first push (if
    // any) is of its layer: one that names another layer is a trace that names the wrong one.
    const std::vector<TraceEvent>& ev = t_.log.events();
    const bool own = at + 1 >= ev.size() || ev[at + 1].op != TraceOp::Push || ev[at + 1].cell[2] == pc[2];
    const bool line = std::find(layer_build_lines_.begin(), layer_build_lines_.end(), e.line) != layer_build_lines_.end();
    layer_start_ = own && line ? at : kNone;
    layer_checked_ = false;
    layer_row_pushes_.clear();
    layer_last_push_.clear();
  }
  if (dim_ == 3 && pc[1] >= 0 && pc[2] >= 0) row = std::int64_t{pc[2]} * g_.n[1] + pc[1];
  else if (dim_ == 2 && e.index >= 0) row = e.index;
  if (row < 0) return;
  open_phase_ = at;
  if (row_starts_.empty() || row_starts_.back().second != row) {
    row_starts_.emplace_back(at, row);
    own_row_pushes_ = 0;
    own_row_last_push_ = kNone;
  } else if (builds_cell_lists_ && own_row_checked_at_ != row_starts_.back().first) {
    own_row_checked_at_ = row_starts_.back().first;
    check_own_row_built(at);
  }
}

void ContractChecker::on_push(std::size_t at, const TraceEvent& e) {
  const std::int32_t k = e.element;
  if (!in_range(k) || e.write_count < 2) return;
  subject_ = Pair{k, k};
  const ArrayWrite& nw = e.writes[0];
  const ArrayWrite& hw = e.writes[1];
  Model& m = model(hw.array);
  const auto slot = static_cast<std::size_t>(hw.index);
  if (slot >= m.head.size()) return;
  m.actual[slot] = hw.new_value;  // what the next frame finds, whatever the contracts say of it
  m.last_push[slot] = at;
  const Cell& own = cells_[static_cast<std::size_t>(k)];
  const std::string list = list_text(e, hw.array);
  if (m.level == 0 && first_level_[static_cast<std::size_t>(k)]++ > 0) {
    breaks(Contract::FirstLevelOnce, at, id(k) + " is pushed onto " + list + ", a second first-level list in this frame: every element goes onto one");
    return;
  }
  for (int a = 0; a < dim_; ++a) {
    if (e.cell[a] < g_.n[a]) continue;
    // A list keyed past the grid: a loop that ran a row (or a column) too far. Located at that row's
    // phase when one names it, else at the push.
    const Cell list_cell{e.cell[0], e.cell[1], e.cell[2]};
    std::int64_t row = dim_ == 3 ? std::int64_t{e.cell[2]} * g_.n[1] + e.cell[1] : e.cell[1];
    const bool phase = !row_starts_.empty() && row_starts_.back().second == row && phase_names(row_starts_.back().first, a, e.cell[a]);
    const bool layer = !phase && dim_ == 3 && layer_start_ != kNone && phase_names(layer_start_, a, e.cell[a]);  // a layer loop ran past the last
    breaks(Contract::ListCell, phase ? row_starts_.back().first : layer ? layer_start_ : at,
           id(k) + " is pushed onto " + list + ", the list of cell " + cell_text(list_cell) + ", outside the grid's " + grid_text() +
               " cells: a loop ran past the last row or column");
    return;
  }
  for (int a = 0; a < dim_; ++a) {
    const std::int32_t keyed = e.cell[a];
    if (keyed >= 0 && keyed != own[static_cast<std::size_t>(a)]) {
      Cell shown = own;
      for (int b = 0; b < dim_; ++b) if (e.cell[b] < 0) shown[static_cast<std::size_t>(b)] = -1;
      Cell list_cell{e.cell[0], e.cell[1], e.cell[2]};
      breaks(Contract::ListCell, at, id(k) + " lies in cell " + cell_text(own) + " but is pushed onto " + list + ", the list of cell " +
                                         cell_text(list_cell) + ": its cell was integerised wrongly, or the wrong head was taken");
      return;
    }
  }
  const bool full_key = std::all_of(e.cell, e.cell + dim_, [](std::int32_t c) { return c >= 0; });
  if (full_key && builds_cell_lists_ && half_ != 0 && !row_starts_.empty() && !row_reaches(row_starts_.back().second, row_key(own))) {
    const std::int64_t building = row_starts_.back().second;
    const Cell row_cell{0, static_cast<std::int32_t>(dim_ == 3 ? building % g_.n[1] : building), static_cast<std::int32_t>(dim_ == 3 ? building / g_.n[1] : -1)};
    breaks(Contract::CellList, at, id(k) + " (cell " + cell_text(own) + ") is pushed onto " + list + " while " + row_text(row_cell) +
                                       "'s lists are built, but its row is not one that row's mask reaches: the wrong row's list was taken");
    return;
  }
  if (full_key) on_cell_list_[static_cast<std::size_t>(k)] = true;
  const std::int32_t expected = m.head[slot];
  if (m.member_slot[static_cast<std::size_t>(k)] == static_cast<std::int64_t>(slot) && m.member_build[static_cast<std::size_t>(k)] == m.build[slot]) {
    breaks(Contract::ListTwice, at, id(k) + " is pushed onto " + list + " a second time in one build: the list now runs " + id(k) +
                                        " -> ... -> " + id(k) + ", a cycle");
    return;
  }
  if (hw.new_value != k) {
    breaks(Contract::ListLink, at, "the push of " + id(k) + " onto " + list + " left its head at " + std::to_string(hw.new_value) +
                                       ", not " + id(k) + ": the head was not written");
    return;
  }
  const Cell keyed{e.cell[0], e.cell[1], e.cell[2]};
  // The list was built for another cell: the clear that was due before its reuse is missing (traced
  // or done), whether the push then links to the old head or to -1.
  const bool reused = expected >= 0 && m.member_cell[static_cast<std::size_t>(expected)] != keyed;
  if (nw.new_value != expected && !(reused && nw.new_value == -1)) {
    const std::int32_t got = nw.new_value;
    std::string text = "the push of " + id(k) + " onto " + list + " links it to ";
    if (got == k) {
      text += "itself: the list " + id(k) + " -> " + id(k) + " is a cycle";
    } else if (got == -1) {
      text += "-1, where the list held " + id(expected) + ": the push cuts the list, and what it held is lost";
    } else if (!in_range(got)) {
      text += std::to_string(got) + ", which is no element (" + std::to_string(n_) + " elements)";
    } else if (m.member_slot[static_cast<std::size_t>(got)] == static_cast<std::int64_t>(slot) &&
               m.member_build[static_cast<std::size_t>(got)] == m.build[slot]) {
      text += id(got) + ", not to the head " + id(expected) + ": the elements pushed between them are cut out of the list";
    } else {
      const bool from_last_frame = initial_head(hw.array, hw.index) == got && m.build[slot] == 0;
      text += id(got) + ", which was not pushed onto it in this frame (" + (expected == -1 ? "the list was empty" : "its head was " + id(expected)) +
              "): the head was not cleared before reuse, so the list runs on into " +
              (from_last_frame ? "the last frame's list" : "an earlier list of this frame");
    }
    breaks(Contract::ListLink, at, text);
    return;
  }
  if (reused) {
    // The list was built for another cell and its clear is not in the trace: the break is the clear that was due.
    const std::string text = nw.new_value == -1
        ? "the push of " + id(k) + " onto " + list + " for cell " + cell_text(keyed) + " (operation " + std::to_string(at + 1) + ") finds it empty, but no clear of " +
              id(expected) + "'s list (cell " + cell_text(m.member_cell[static_cast<std::size_t>(expected)]) + ") was traced"
        : "the push of " + id(k) + " onto " + list + " for cell " + cell_text(keyed) + " (operation " + std::to_string(at + 1) + ") links it to " +
              id(expected) + ", pushed onto that list for cell " + cell_text(m.member_cell[static_cast<std::size_t>(expected)]) +
              ": the head was not cleared before the list was reused, so it runs on into a stale chain";
    breaks(Contract::ListLink, clear_was_due(hw.array, m.member_at[static_cast<std::size_t>(expected)], at),
           "this clearing leaves " + list + " set: " + text);
    return;
  }
  m.head[slot] = k;
  ++m.count[slot];
  if (layer_start_ != kNone && !full_key && e.cell[1] >= 0 && dim_ == 3 && e.cell[2] >= 0) {
    ++layer_row_pushes_[row_key(keyed)];
    layer_last_push_[keyed[2]] = at;
  }
  if (full_key) {
    cell_listed_at_[static_cast<std::size_t>(k)] = at;
    last_cell_push_ = at;
    cell_list_[flat(keyed)] = CellList{hw.array, static_cast<std::int64_t>(slot)};
    last_row_push_[row_key(keyed)] = at;
    if (!row_starts_.empty() && row_key(keyed) == row_starts_.back().second) ++own_row_pushes_, own_row_last_push_ = at;
  }
  m.member_cell[static_cast<std::size_t>(k)] = keyed;
  m.member_at[static_cast<std::size_t>(k)] = at;
  m.member_slot[static_cast<std::size_t>(k)] = static_cast<std::int64_t>(slot);
  m.member_build[static_cast<std::size_t>(k)] = m.build[slot];
  cell_pushes_.push_back({at, k, full_key});
}

void ContractChecker::on_clear(std::size_t at, const TraceEvent& e) {
  if (e.write_count < 1) return;
  const ArrayWrite& hw = e.writes[0];
  Model& m = model(hw.array);
  const auto slot = static_cast<std::size_t>(hw.index);
  if (slot >= m.head.size()) return;
  m.actual[slot] = hw.new_value;
  subject_ = Pair{-1, -1};
  if (hw.new_value != -1) {
    breaks(Contract::ClearWrites, at, "the clear of " + list_text(e, hw.array) + " left it at " + std::to_string(hw.new_value) + ", not -1");
    return;
  }
  m.head[slot] = -1;
  m.count[slot] = 0;
  ++m.build[slot];
}

void ContractChecker::on_visit(std::size_t at, const TraceEvent& e) {
  const std::int32_t k = e.element;
  if (!in_range(k)) return;
  subject_ = Pair{k, k};
  const Cell c{e.cell[0], e.cell[1], dim_ == 3 ? e.cell[2] : -1};
  visitor_ = k;
  visited_ = c;
  for (int a = 0; a < dim_; ++a) {
    if (c[static_cast<std::size_t>(a)] < 0 || c[static_cast<std::size_t>(a)] >= g_.n[a]) {
      breaks(Contract::MaskInGrid, at, "the mask of " + id(k) + " visits cell " + cell_text(c) + ", outside the grid's " + grid_text() +
                                           " cells: it reads a head past its array");
      return;
    }
  }
  const Cell& own = cells_[static_cast<std::size_t>(k)];
  Cell o{0, 0, 0};
  if (!offset_from(k, c, o)) {
    breaks(Contract::MaskNeighbours, at, "the mask of " + id(k) + " (cell " + cell_text(own) + ") visits cell " + cell_text(c) +
                                             ", which is not next to it: the mask reaches too far");
    return;
  }
  Cell mirror{};
  if (half_ != 0 && lean(o, dim_) == -half_ && !(neighbour(own, Cell{-o[0], -o[1], -o[2]}, mirror) && mirror == c)) {
    breaks(Contract::MaskHalf, at, "the mask of " + id(k) + " (cell " + cell_text(own) + ") visits cell " + cell_text(c) + ", its neighbour at " +
                                       offset_text(o) + ", outside the half mask every other visit keeps: the wrong row, layer or column was taken");
    return;
  }
  if (builds_cell_lists_ && half_ != 0 && !row_starts_.empty() && rows_checked_at_ != row_starts_.back().first) {
    rows_checked_at_ = row_starts_.back().first;
    check_rows_built(at, own);
  }
  if (o == Cell{0, 0, 0} && builds_cell_lists_ && !row_starts_.empty()) {
    const std::size_t row_start = row_starts_.back().first;
    const std::size_t listed = cell_listed_at_[static_cast<std::size_t>(k)];
    if (listed == kNone || listed < row_start) {
      // Due where this row's build stopped: after its last push, or at its first operation when it pushed nothing.
      const std::size_t due = last_cell_push_ != kNone && last_cell_push_ > row_start ? last_cell_push_ + 1 : row_start + 1;
      breaks(Contract::CellList, std::min(due, at), id(k) + " visits its own cell " + cell_text(own) + " (operation " + std::to_string(at + 1) +
                                                        "), but was not pushed onto that cell's list when its row's lists were built: the loop that builds them left it out");
      return;
    }
  }
  const int bit = offset_bit(o, dim_);
  last_visit_[static_cast<std::size_t>(k)] = at;  // a cell visited twice (offsets are distinct cells from 3 per axis): the wrong cell
  if (std::all_of(g_.n, g_.n + dim_, [](std::int64_t cells) { return cells >= 3; }) && (visits_[static_cast<std::size_t>(k)] >> bit & 1u) != 0) {
    breaks(Contract::MaskCell, at, "the mask of " + id(k) + " (cell " + cell_text(own) + ") visits cell " + cell_text(c) + " a second time: the visit names the wrong cell");
    return;
  }
  visits_[static_cast<std::size_t>(k)] |= 1u << bit;
  union_ |= 1u << bit;
  if (o != Cell{0, 0, 0}) walk_ = Walk{at, k, c, 0};  // own cell: only the elements after k are walked
}

void ContractChecker::on_test(std::size_t at, const TraceEvent& e) {
  const std::int32_t k = e.element, m = e.other;
  if (!in_range(k) || !in_range(m)) return;
  subject_ = Pair{std::min(k, m), std::max(k, m)};
  if (k == m) {
    breaks(Contract::TestSelf, at, id(k) + " is tested against itself: a walk reached its own entry (the own cell's walk starts at k, not after it)");
    return;
  }
  if (!models_.empty() && visitor_ == k) {
    const Cell& other = cells_[static_cast<std::size_t>(m)];
    bool same = true;
    for (int a = 0; a < dim_; ++a) same = same && other[static_cast<std::size_t>(a)] == visited_[static_cast<std::size_t>(a)];
    if (!same) {
      breaks(Contract::WalkCell, at, "the walk of cell " + cell_text(visited_) + "'s list, visited by " + id(k) + "'s mask, meets " + id(m) +
                                         ", which lies in cell " + cell_text(other) + ": the walk started at another cell's head, or the list holds a stale link");
      return;
    }
  }
  const bool truth = in_contact(e_, k, m, t_.touching);
  if (truth != e.contact) {
    const double gap = contact_gap(e_, k, m);
    breaks(Contract::TestAnswer, at, "the test of " + id(k) + " against " + id(m) + " answered " + (e.contact ? "contact" : "no contact") +
                                         " where the exact test says " + (truth ? "contact" : "apart") + " (gap " + number(gap) + ")",
           truth ? std::vector<Pair>{Pair{std::min(k, m), std::max(k, m)}} : std::vector<Pair>{});
    return;
  }
  tested_.emplace_back(key(k, m), at);
  if (walk_ && walk_->k == k) ++walk_->tested;  // once and reported: checked together at the end (sorted, not hashed)
}

void ContractChecker::check_tests() {
  const std::vector<TraceEvent>& ev = t_.log.events();
  std::vector<std::pair<std::int64_t, std::size_t>> by_pair = tested_;
  std::sort(by_pair.begin(), by_pair.end());
  for (std::size_t i = 1; i < by_pair.size(); ++i) {
    if (by_pair[i].first != by_pair[i - 1].first) continue;
    const std::size_t at = by_pair[i].second;
    if (first_ && first_->event <= at) continue;
    const std::int32_t k = ev[at].element, m = ev[at].other;
    subject_ = Pair{std::min(k, m), std::max(k, m)};
    breaks(Contract::TestOnce, at, id(k) + " and " + id(m) + " are tested a second time (first at operation " + std::to_string(by_pair[i - 1].second + 1) +
                                       "): a list holds an element twice, or a mask visits a cell twice");
  }
  for (const auto& [pair, at] : tested_) {  // in order: the first contact never reported
    if (first_ && first_->event <= at) break;
    if (!ev[at].contact || std::binary_search(reported_.begin(), reported_.end(), pair)) continue;
    const std::int32_t k = ev[at].element, m = ev[at].other;
    subject_ = Pair{std::min(k, m), std::max(k, m)};
    breaks(Contract::TestReported, at, "the test of " + id(k) + " against " + id(m) + " answered contact, but the pair was never reported (add_pair)",
           {subject_});
    break;
  }
}

std::string ContractChecker::number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", v);
  return buffer;
}

std::string ContractChecker::grid_text() const {
  std::string out = std::to_string(g_.n[0]) + " x " + std::to_string(g_.n[1]);
  if (dim_ == 3) out += " x " + std::to_string(g_.n[2]);
  return out;
}

}  // namespace contract_detail



BrokenContract api_rule_break(const Misbehaviour& m) {
  BrokenContract b;
  b.contract = m.cycle ? Contract::Cycle : Contract::ApiRule;
  b.event = m.operations > 0 ? m.operations - 1 : 0;
  b.after = m.operations > 0 && !m.cycle;  // a cycle is the push or test that closed it: recorded
  b.text = m.text;
  b.subject = m.subject;
  return b;
}

std::optional<BrokenContract> first_broken_contract(const FrameTrace& trace, const ContractNames& names) {
  std::optional<BrokenContract> found;
  if (!trace.log.events().empty() && trace.elements.size() > 0) {
    // A call stopped at a misbehaviour left a trace without its end: what it never did is not known.
    const bool complete = !trace.misbehaviour || !trace.misbehaviour->cut;
    found = contract_detail::ContractChecker(trace, names, complete).run();
  }
  if (trace.misbehaviour) {
    BrokenContract api = api_rule_break(*trace.misbehaviour);
    // A cell not written was found where the element went onto a list keyed on that axis: located there.
    const Misbehaviour& m = *trace.misbehaviour;
    const std::vector<TraceEvent>& ev = trace.log.events();
    for (std::size_t at = 0; m.cell_element >= 0 && at < ev.size(); ++at) {
      if (ev[at].op != TraceOp::Push || ev[at].element != m.cell_element || ev[at].cell[m.cell_axis] < 0) continue;
      api.event = at;
      api.after = false;
      api.text += ", though this push keys it to its cell on that axis: the cell was found, and never written to out->cells";
      break;
    }
    // At one operation the call nbscope stopped there says it best (a cycle names its list).
    const bool tie = found && api.event == found->event && (!api.after || trace.misbehaviour->cut);
    if (!found || api.event < found->event || tie) found = api;
    else if (trace.misbehaviour->cut) found->text += " (then, at operation " + std::to_string(api.event + 1) + ": " + api.text + ")";
  }
  return found;
}

}  // namespace nbscope
