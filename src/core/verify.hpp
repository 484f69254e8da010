// nbscope core: checking someone else's arrays against what the book requires (`nbscope verify
// --arrays`). The user's heads and next arrays, read by io/arrays_json.hpp into plain families of
// lists, are walked once each — O(N + heads) in all, so a cycle or an index out of range is found,
// never followed — and every element is held to one list, the list of its own cell.
//
// Index: UserList, ListFamily, SortArrays, UserArrays (what was given) | ProblemKind, Problem,
// WalkedList, ArraysVerdict (what was found) | verify_arrays | the contract a problem breaks |
// names in the book's terms.
#pragma once
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/array_schema.hpp"
#include "core/contracts.hpp"
#include "core/elements.hpp"
#include "core/grid.hpp"
#include "core/pairs.hpp"

namespace nbscope::verify {

// An index the file gives as 0 where it counts from 1 ("base": 1): neither an element nor -1.
inline constexpr std::int32_t kZeroInBase1 = std::numeric_limits<std::int32_t>::min();

// One list: where its head sits and the cell its elements must lie in. 32 bytes: a million-element
// file has about as many lists (its JSON path is written by list_where() only for a message).
struct UserList {
  std::int64_t slot = 0;                  // flat index into the family's heads (its name: heads_name[...])
  std::int32_t head = -1;                 // the first element, -1 for an empty list
  std::array<std::int32_t, 3> cell{-1, -1, -1};  // the cell its elements lie in; -1: an axis it does not fix
  std::int32_t entry = 0;                 // the index of its entry in the file's heads array (HeadsForm Pairs, Leaves)
};

// How the file gives a family's heads, for the JSON path of a list's head value (core/array_schema.hpp).
using HeadsForm = array_schema::HeadsForm;

// One family of lists sharing a next array: C + E (screen), HEAD + E (tree), y_heads + Y (nbs), the
// x-lists of one NBS row (x_heads + X), ...
struct ListFamily {
  std::string heads_name;                 // as the book and the dump name it: "C", "HEAD", "y_heads", "x_heads", "z_heads"
  std::string next_name;                  // "E", "Y", "X", "Z"
  std::vector<std::int64_t> heads_shape;  // to name a slot by its indices: C[ix][iy]
  std::vector<UserList> lists;            // in the file's order (the walk's and the report's order)
  std::string heads_path;                 // JSON path of the heads array ("$.heads", "$.rows[2].x_heads", "$.leaves")
  HeadsForm heads_form = HeadsForm::Dense;
  // The next array: dense (N entries, `next[k]`), or sparse as the file gives an NBS row's
  // ([k, next[k]] pairs, k possibly out of range; none at all is legal). `sparse` says which: an
  // empty `next_pairs` is still a sparse family whose entries are all not given. A dense array
  // shorter than N (the reader refuses one) gives no entry past its end.
  bool sparse = false;
  std::vector<std::int32_t> next;
  std::vector<std::array<std::int32_t, 2>> next_pairs;
  std::string next_path;                  // JSON path of the next array ("$.next", "$.rows[2].x_next"), for messages
  // Which elements must be on these lists: those whose cell matches `scope` on every axis it fixes
  // (-1: any), e.g. the elements of row iy for that row's x-lists; all elements when nothing is fixed.
  std::array<std::int32_t, 3> scope{-1, -1, -1};
  // The book's order within a list (--exact): true when ids rise from the head (NBS 2D x-lists are
  // pushed while walking a y-list that runs from the highest id down), false when they fall (pushed
  // at the head in element order).
  bool ascending = false;
};

// The sort algorithm's arrays: no lists, a permutation and each element's integerised cell.
struct SortArrays {
  std::vector<std::array<std::int32_t, 3>> keys;      // keys[p]: the cell of sorted position p
  std::vector<std::int32_t> order;                    // order[p]: the element at sorted position p
  std::array<std::vector<std::int32_t>, 3> cell_of;   // ix, iy (iz): each element's integerised coordinate
};

// Everything the file gave, indices already shifted to 0-based.
struct UserArrays {
  std::string algorithm;     // screen, nbs, tree, sort
  int dim = 2;
  int base = 0;              // the file's numbering (0 or 1): messages use it
  std::vector<ListFamily> families;  // in the file's order
  std::optional<SortArrays> sort;
};

// ---- what was found ----

enum class ProblemKind : std::uint8_t {
  OutOfRange,  // an index that names no element (nor -1), or a slot outside the grid
  Cycle,       // a list that comes back to one of its own elements
  TwoLists,    // an element reached a second time: on two lists, or twice in a permutation
  NotListed,   // an element on no list of its family (dropped)
  WrongList,   // an element on the list of another cell (or another row)
  NotGiven,    // a list runs into an element whose next entry the file does not give
  WrongOrder,  // --exact: a list not in the book's order (or sort ties not by element id)
  WrongCell,   // sort: an element's ix/iy/key not its cell, or keys not sorted
};
// "out of range", "cycle", ... for reports and tests.
const char* problem_kind_name(ProblemKind kind);

// One problem, in the book's terms, with what to draw in red.
struct Problem {
  ProblemKind kind = ProblemKind::OutOfRange;
  std::string text;                       // e.g. "E[7] = 5, but element 5 lies in cell (2,7) and element 7 in cell (3,7)"
  std::string where;                      // JSON path of the value at fault
  std::vector<ElementId> elements;        // the elements at fault (misplaced, dropped, repeated)
  // The wrong link: from element `first` (-1: from the list's head) to element `second`.
  std::optional<std::pair<ElementId, ElementId>> link;
  int family = -1;                        // index into UserArrays::families, or -1 (sort)
  int list = -1;                          // index into that family's lists, or -1
  // The contract of docs/diagnosis.md the lists break here (contract_broken_by); none for a problem
  // of the file's form, of the order, or of sort's arrays.
  std::optional<Contract> contract{};
};

// One list as its links were followed, for drawing: the elements reached, head first.
struct WalkedList {
  int family = 0;
  int list = 0;
  std::vector<ElementId> chain;
  bool cut = false;  // the walk stopped at a problem (cycle, out of range, an element seen before)
};

struct ArraysVerdict {
  std::vector<Problem> problems;  // the first kMaxKeptProblems, in the order found
  std::int64_t problem_count = 0; // all of them
  std::int64_t other_order_lists = 0;  // lists right but not in the book's order (counted without --exact)
  std::vector<WalkedList> lists;  // every non-empty list walked
};
// Problems kept with their text; beyond, only counted (a file with a million wrong entries).
inline constexpr std::size_t kMaxKeptProblems = 10'000;

// How close (in cells, relative to the coordinate's cell index) a centre may lie to a cell
// boundary and still be taken on either side: the user's code may round the other way there.
inline constexpr double kBoundaryTolerance = 1e-9;

// Holds `user` to the book: every index in range, every list ends, every element of a family on
// exactly one of its lists and that list the one of its own cell under `grid` (an element within
// rounding of a cell boundary may be on either side's list), sort's permutation and keys; with
// `exact`, also the book's order in every list. O(N + heads + entries given).
ArraysVerdict verify_arrays(const Elements& elements, const Grid& grid, const UserArrays& user, bool exact);

// ---- the contract a problem breaks (docs/verify.md "The first broken contract") ----

// The contract broken by a problem of `kind` found walking `family`'s lists: list-cell (on the list
// of another cell or row), cycle, list-link (a head or link naming no element), first-level-once
// (a first-level family: on no list, or on two) or cell-list (a family of a row or layer: on no list),
// list-cell (on two lists of a row or layer: one is not its cell's). None for order and not given.
// The final arrays hold no operation, so the rules of clears, masks, walks and tests never apply.
[[nodiscard]] std::optional<Contract> contract_broken_by(ProblemKind kind, const ListFamily& family);

// The index into `verdict.problems` of the first problem that breaks a contract, in the order found
// (the first-level lists before each row's, as the book builds them; list by list from its head).
[[nodiscard]] std::optional<std::size_t> first_contract_problem(const ArraysVerdict& verdict);

// ---- pairs (`nbscope verify --pairs`) ----

// One pair as the user's file gives it: indices already shifted to 0-based, either order, and the
// file's line for messages.
struct GivenPair {
  std::int64_t i = 0, j = 0;
  std::int64_t line = 0;
};

// The user's pairs held against the reference: each class in the order of the file (missing: by i, j).
struct PairsVerdict {
  PairList missing;                               // in R, not given
  std::vector<GivenPair> extra;                   // given, not in R
  std::vector<std::pair<GivenPair, std::int64_t>> duplicates;  // given again; the line of its first
  std::vector<GivenPair> self;                    // i == j
  std::vector<GivenPair> out_of_range;            // an index that names no element
  std::int64_t right = 0;                         // distinct given pairs that are in R
  [[nodiscard]] bool ok() const {
    return missing.empty() && extra.empty() && duplicates.empty() && self.empty() && out_of_range.empty();
  }
};

// Compares `given` (as read) with the sorted reference pairs `reference` of `n` elements. O(P log P).
PairsVerdict compare_pairs(std::int64_t n, const std::vector<GivenPair>& given, const PairList& reference);

// ---- names in the book's terms (base 0 or 1 added to every index) ----

// "C[4][6]" for slot 46 of a 10x10 family, "y_heads[3]", "HEAD[7]".
std::string slot_name(const ListFamily& family, std::int64_t slot, int base);
// "(4,6)" or "(4,6,2)": a cell, printed with `base`.
std::string cell_name(const std::array<std::int32_t, 3>& cell, int dim, int base);
// "row 3: ", "layer 2: ", "row 3 of layer 2: " for a family with a scope, else "".
std::string scope_prefix(const ListFamily& family, int base);
// An index as the file wrote it: "-1", kZeroInBase1 as "0", else value + base.
std::string file_index(std::int64_t value, int base);
// The JSON path of list `l`'s head value in `family`: "$.rows[2].x_heads[0][1]".
std::string list_where(const ListFamily& family, const UserList& l);

}  // namespace nbscope::verify
