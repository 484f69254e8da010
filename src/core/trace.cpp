#include "core/trace.hpp"

#include <algorithm>
#include <cassert>

namespace nbscope {

const char* trace_op_name(TraceOp op) {
  // No exhaustive switch: detectors may add operations, and they are all just "writes" here.
  if (op == TraceOp::Phase) return "phase";
  if (op == TraceOp::Push) return "push";
  if (op == TraceOp::Clear) return "clear";
  if (op == TraceOp::VisitCell) return "visit-cell";
  if (op == TraceOp::TestPair) return "test-pair";
  return "write";
}

void TraceLog::reset() {
  events_.clear();
  arrays_.clear();
  live_.clear();
}

int TraceLog::declare_array(std::string name, std::vector<std::int64_t> shape, std::span<const std::int32_t> initial) {
  arrays_.push_back(TracedArray{std::move(name), std::move(shape), {initial.begin(), initial.end()}});
  live_.push_back(initial);
  return static_cast<int>(arrays_.size()) - 1;
}

void TraceLog::phase(std::uint8_t line, const char* label, std::int32_t index) { phase(line, label, index, -1, -1, -1); }

void TraceLog::phase(std::uint8_t line, const char* label, std::int32_t index, std::int32_t ix, std::int32_t iy,
                     std::int32_t iz) {
  TraceEvent e;
  e.op = TraceOp::Phase;
  e.line = line;
  e.label = label;
  e.index = index;
  e.cell[0] = ix;
  e.cell[1] = iy;
  e.cell[2] = iz;
  record(e);  // whole: a consumer sees the event as it will be kept
}

void TraceLog::push(std::uint8_t line, const char* kind, int heads, std::int64_t list_index, int next, ElementId k,
                    std::int32_t old_head, std::int32_t old_next, std::int32_t ix, std::int32_t iy, std::int32_t iz) {
  push_written(line, kind, heads, list_index, next, k, old_head, old_next, k, old_head, ix, iy, iz);
}

void TraceLog::push_written(std::uint8_t line, const char* kind, int heads, std::int64_t list_index, int next,
                            ElementId k, std::int32_t old_head, std::int32_t old_next, std::int32_t new_head,
                            std::int32_t new_next, std::int32_t ix, std::int32_t iy, std::int32_t iz) {
  TraceEvent e;
  e.op = TraceOp::Push;
  e.line = line;
  e.label = kind;
  e.element = k;
  e.index = static_cast<std::int32_t>(list_index);
  e.cell[0] = ix;
  e.cell[1] = iy;
  e.cell[2] = iz;
  e.write_count = 2;
  e.writes[0] = ArrayWrite{next, old_next, new_next, k};
  e.writes[1] = ArrayWrite{heads, old_head, new_head, list_index};
  record(e);
}

void TraceLog::clear(std::uint8_t line, const char* kind, int heads, std::int64_t list_index, std::int32_t old_head) {
  clear_written(line, kind, heads, list_index, old_head, -1);
}

void TraceLog::clear_written(std::uint8_t line, const char* kind, int heads, std::int64_t list_index,
                             std::int32_t old_head, std::int32_t new_head) {
  TraceEvent e;
  e.op = TraceOp::Clear;
  e.line = line;
  e.label = kind;
  e.index = static_cast<std::int32_t>(list_index);
  e.write_count = 1;
  e.writes[0] = ArrayWrite{heads, old_head, new_head, list_index};
  record(e);
}

void TraceLog::visit_cell(std::uint8_t line, ElementId k, std::int32_t ix, std::int32_t iy, std::int32_t iz) {
  if (!keep_tests_) return;
  TraceEvent e;
  e.op = TraceOp::VisitCell;
  e.line = line;
  e.element = k;
  e.cell[0] = ix;
  e.cell[1] = iy;
  e.cell[2] = iz;
  record(e);
}

void TraceLog::test_pair(std::uint8_t line, ElementId k, ElementId other, bool contact) {
  if (!keep_tests_) return;
  TraceEvent e;
  e.op = TraceOp::TestPair;
  e.line = line;
  e.element = k;
  e.other = other;
  e.contact = contact;
  record(e);
}

void TraceLog::set(std::uint8_t line, const char* label, int array, std::int64_t index, std::int32_t old_value,
                   std::int32_t new_value, ElementId k) {
  TraceEvent e;
  e.op = TraceOp::Set;
  e.line = line;
  e.label = label;
  e.element = k;
  e.index = static_cast<std::int32_t>(index);
  e.write_count = 1;
  e.writes[0] = ArrayWrite{array, old_value, new_value, index};
  record(e);
}

void TraceLog::record(const TraceEvent& e) {
  if (probe_) {
    std::vector<std::vector<std::int32_t>> live;
    live.reserve(live_.size());
    for (const auto& a : live_) live.emplace_back(a.begin(), a.end());
    probe_(events_.size(), e, live);
  }
  if (consumer_) {
    consumer_(e);
    return;
  }
  events_.push_back(e);
}

void TraceLog::append(std::span<const TraceEvent> events) {
  if (probe_ || consumer_) {
    for (const TraceEvent& e : events) record(e);
    return;
  }
  events_.insert(events_.end(), events.begin(), events.end());
}

void TraceLog::apply(const TraceEvent& e, std::vector<std::vector<std::int32_t>>& state) {
  for (int w = 0; w < e.write_count; ++w) {
    const ArrayWrite& a = e.writes[w];
    assert(a.array >= 0 && static_cast<std::size_t>(a.array) < state.size() && "trace write to an undeclared array");
    state[a.array][a.index] = a.new_value;
  }
}

void TraceLog::undo(const TraceEvent& e, std::vector<std::vector<std::int32_t>>& state) {
  for (int w = e.write_count - 1; w >= 0; --w) {
    const ArrayWrite& a = e.writes[w];
    assert(a.array >= 0 && static_cast<std::size_t>(a.array) < state.size() && "trace write to an undeclared array");
    state[a.array][a.index] = a.old_value;
  }
}

std::vector<std::vector<std::int32_t>> TraceLog::state_after(std::size_t count) const {
  std::vector<std::vector<std::int32_t>> state;
  state.reserve(arrays_.size());
  for (const TracedArray& a : arrays_) state.push_back(a.initial);
  count = std::min(count, events_.size());
  for (std::size_t i = 0; i < count; ++i) apply(events_[i], state);
  return state;
}

int TraceLog::array_id(std::string_view name) const {
  for (std::size_t a = 0; a < arrays_.size(); ++a)
    if (arrays_[a].name == name) return static_cast<int>(a);
  return -1;
}

}  // namespace nbscope
