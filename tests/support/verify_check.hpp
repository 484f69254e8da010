// Helpers of the verify tests (tests/core/test_verify*.cpp): nbscope's own arrays as JSON, and a user's
// arrays read back through the arrays reader and held to the book.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "core/verify.hpp"
#include "io/arrays_json.hpp"
#include "support/own_dump.hpp"

namespace nbscope::testverify {

using nlohmann::json;
using verify::ProblemKind;

// nbscope's own arrays of `e` as `nbscope dump` writes them (the grid keys pin it, as a user's would).
inline json own_dump(const Elements& e, const std::string& algorithm, const GridOptions& grid = {}) {
  return json::parse(testdump::own_dump_text(e, algorithm, grid));
}

struct Checked {
  verify::ArraysVerdict verdict;
  [[nodiscard]] const verify::Problem& first() const { return verdict.problems.at(0); }
  [[nodiscard]] bool has(ProblemKind kind, const std::string& text) const {
    for (const auto& p : verdict.problems)
      if (p.kind == kind && p.text.find(text) != std::string::npos) return true;
    return false;
  }
  [[nodiscard]] std::string all() const {
    std::string s;
    for (const auto& p : verdict.problems) s += std::string(verify::problem_kind_name(p.kind)) + ": " + p.text + "\n";
    return s;
  }
};

// The arrays in `doc` read back as a user's file and held to the book on the grid the file pins.
inline Checked check(const Elements& e, const json& doc, bool exact = false) {
  const ArraysJson file = parse_arrays_json(doc.dump(), "arrays.json");
  GridOptions g = file.grid;
  const Grid grid = make_grid(e, g);
  const verify::UserArrays user = file.arrays(*file.algorithm, grid, e.size(), file.base.value_or(0));
  return Checked{verify::verify_arrays(e, grid, user, exact)};
}

}  // namespace nbscope::testverify
