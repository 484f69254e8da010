// Traces to plant breaks in (tests of first_broken_contract): one traced detection as trace_frame
// would make it, a log recorded again event by event through an edit, and the contract it breaks.
#pragma once
#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/contracts.hpp"
#include "core/detector.hpp"
#include "core/layouts.hpp"
#include "support/generators.hpp"

namespace nbscope::testdata {

// One traced detection, as trace_frame would make it.
inline FrameTrace traced(const std::string& algorithm, Layout layout, std::int64_t n, int dim, std::uint64_t seed) {
  FrameTrace t;
  t.algorithm = algorithm;
  t.elements = testdata::make_layout(layout, n, dim, seed);
  auto d = make_detector(algorithm);
  d->detect_traced(t.elements, DetectOptions{}, t.pairs, t.log);
  t.grid = d->last_grid() != nullptr ? *d->last_grid() : make_grid(t.elements, GridOptions{});
  return t;
}

// An edit of one event: return false to drop it; may change it.
using Edit = std::function<bool(std::size_t at, TraceEvent& e)>;

// `log` recorded again through TraceLog's public calls, each event through `edit`; `initial`
// may change the arrays' contents before the first event.
inline TraceLog rerecorded(const TraceLog& log, const Edit& edit,
                    const std::function<void(std::size_t array, std::vector<std::int32_t>&)>& initial = {}) {
  TraceLog out;
  for (std::size_t a = 0; a < log.arrays().size(); ++a) {
    std::vector<std::int32_t> contents = log.arrays()[a].initial;
    if (initial) initial(a, contents);
    out.declare_array(log.arrays()[a].name, log.arrays()[a].shape, contents);
  }
  for (std::size_t at = 0; at < log.events().size(); ++at) {
    TraceEvent e = log.events()[at];
    if (!edit(at, e)) continue;
    switch (e.op) {
      case TraceOp::Phase: out.phase(e.line, e.label, e.index, e.cell[0], e.cell[1], e.cell[2]); break;
      case TraceOp::Push:
        out.push_written(e.line, e.label, e.writes[1].array, e.writes[1].index, e.writes[0].array, e.element, e.writes[1].old_value,
                         e.writes[0].old_value, e.writes[1].new_value, e.writes[0].new_value, e.cell[0], e.cell[1], e.cell[2]);
        break;
      case TraceOp::Clear:
        out.clear_written(e.line, e.label, e.writes[0].array, e.writes[0].index, e.writes[0].old_value, e.writes[0].new_value);
        break;
      case TraceOp::VisitCell: out.visit_cell(e.line, e.element, e.cell[0], e.cell[1], e.cell[2]); break;
      case TraceOp::TestPair: out.test_pair(e.line, e.element, e.other, e.contact); break;
      case TraceOp::Set:
        out.set(e.line, e.label, e.writes[0].array, e.writes[0].index, e.writes[0].old_value, e.writes[0].new_value, e.element);
        break;
    }
  }
  return out;
}

// The index of the first event of `log` that `pick` accepts.
inline std::size_t first_event(const TraceLog& log, const std::function<bool(const TraceEvent&)>& pick) {
  for (std::size_t at = 0; at < log.events().size(); ++at)
    if (pick(log.events()[at])) return at;
  ADD_FAILURE() << "no such event";
  return 0;
}

// `log` without the events `drop` picks; `removed` counts them.
inline TraceLog without(const TraceLog& log, const std::function<bool(std::size_t at, const TraceEvent& e)>& drop, std::size_t& removed) {
  removed = 0;
  return rerecorded(log, [&](std::size_t at, TraceEvent& e) {
    const bool gone = drop(at, e);
    removed += gone ? 1 : 0;
    return !gone;
  });
}

// The first broken contract of `t` with its log replaced by `log`; it must be one.
inline BrokenContract broken_with(FrameTrace& t, TraceLog log) {
  t.log = std::move(log);
  const std::optional<BrokenContract> b = first_broken_contract(t);
  if (!b) {
    ADD_FAILURE() << "no contract broken";
    return {};
  }
  return *b;
}

}  // namespace nbscope::testdata
