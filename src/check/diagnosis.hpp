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
#include "core/elements.hpp"
#include "core/grid.hpp"
#include "core/locate.hpp"
#include "core/trace.hpp"

namespace nbscope {

// Where a violation was decided, and what that means.
struct Diagnosis {
  PairLocation at;               // the finding (core/locate.hpp); at.event the operation, 0-based
  std::size_t operations = 0;    // the trace's length
  std::string kind;              // the operation's kind (trace_op_name), "" without one
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

}  // namespace nbscope
