// nbscope check: a violation followed to the operation of the detector's trace that decided it
// (core/locate.hpp), in words: the sentence the window's Stepper and Violations panel show, the
// headless summary line ends with, and the report's "located" object holds.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>

#include "check/report.hpp"
#include "core/contracts.hpp"
#include "core/elements.hpp"
#include "core/grid.hpp"
#include "core/locate.hpp"
#include "core/trace.hpp"

namespace nbscope {

// Where a violation was decided, and what that means: the frame's first broken contract when its
// trace has one (the diagnosis), with the pair's own finding as the detail under it.
struct Diagnosis {
  PairLocation at;               // the pair's finding (core/locate.hpp); at.event its operation, 0-based
  std::optional<BrokenContract> contract;  // the frame's first broken contract (core/contracts.hpp)
  std::optional<std::size_t> event;        // the operation to show: the contract's, else the pair's
  std::size_t operations = 0;    // the trace's length
  std::string kind;              // that operation's kind (trace_op_name), "" without one
  int line = -1;                 // its pseudocode line (0-based), -1 without one
  std::string pseudocode;        // that line's text ("" without one)
  std::string text;              // "operation 81 of 14929: k=79 ... : the contact mask leaves it out ..."
};

// Locates violation `v` in `events`, one traced detection of `elements` on `grid` by `algorithm`
// with `pseudocode` lines, and says what it means; `id` names an element (a row: its book number,
// atom id, or the row itself), cells are numbered from 0, or from 1 with `book_numbering`.
[[nodiscard]] Diagnosis diagnose(const Violation& v, std::span<const TraceEvent> events, const Grid& grid, const Elements& elements,
                                 const std::string& algorithm, std::span<const char* const> pseudocode,
                                 const std::function<std::string(std::int64_t)>& id, bool book_numbering = false);

// How a diagnosis names element `row` whose atom id is `atom` (a dump's): "9 (row 8)" where they
// differ, else the one number.
[[nodiscard]] std::string element_label(std::int64_t atom, std::int64_t row);

// diagnose() of `v` in `trace`, led by the trace's first broken contract when it has one: the text
// says the contract, its operation and the pairs it cost, then the pair's finding as "Detail: ...".
[[nodiscard]] Diagnosis diagnose_frame(const Violation& v, const FrameTrace& trace,
                                       const std::function<std::string(std::int64_t)>& id, bool book_numbering = false);

}  // namespace nbscope
