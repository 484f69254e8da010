// `nbscope verify --arrays`: which contract of docs/diagnosis.md each problem of the final lists
// breaks, and the first one, for the line verify leads with (docs/verify.md "The first broken contract").
#include <algorithm>

#include "core/verify.hpp"

namespace nbscope::verify {

namespace {

// A family that holds every element (no row or layer fixed): the book's first level (screening's
// cell lists, the tree's leaves, NBS's y-lists, 3D z-lists), as the trace's contracts count levels.
bool first_level(const ListFamily& family) {
  return std::all_of(family.scope.begin(), family.scope.end(), [](std::int32_t c) { return c < 0; });
}

}  // namespace

std::optional<Contract> contract_broken_by(ProblemKind kind, const ListFamily& family) {
  switch (kind) {
    case ProblemKind::WrongList: return Contract::ListCell;
    // An element pushed twice onto one build of a list (list-twice) is seen here only as the cycle it made.
    case ProblemKind::Cycle: return Contract::Cycle;
    // A head or a link that is no element: no push links to that (a head never written or never cleared).
    case ProblemKind::OutOfRange: return Contract::ListLink;
    // On two lists of one family: two first-level lists, or two cells' lists of a row (one is not its own).
    case ProblemKind::TwoLists: return first_level(family) ? Contract::FirstLevelOnce : Contract::ListCell;
    // On no list: the loop over all elements left it out, or its row's (layer's) lists were built
    // without it, so it never reaches the list of its cell.
    case ProblemKind::NotListed: return first_level(family) ? Contract::FirstLevelOnce : Contract::CellList;
    // The book's order is no contract; an entry the file leaves out is the file's, not the lists'.
    case ProblemKind::WrongOrder:
    case ProblemKind::NotGiven:
    case ProblemKind::WrongCell: return std::nullopt;
  }
  return std::nullopt;
}

std::optional<std::size_t> first_contract_problem(const ArraysVerdict& verdict) {
  for (std::size_t i = 0; i < verdict.problems.size(); ++i)
    if (verdict.problems[i].contract) return i;
  return std::nullopt;
}

}  // namespace nbscope::verify
