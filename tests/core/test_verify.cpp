// `nbscope verify`'s checks (core/verify.hpp) and readers (io/arrays_json.hpp, io/given_pairs.hpp):
// nbscope's own arrays, as `nbscope dump` writes them, pass on every layout, algorithm and
// dimension; each planted bug is found and named by the entry it was planted in.
//
// Index: helpers (dump, plant, check) | own arrays pass | planted bugs: screen, nbs 2D, nbs 3D, tree,
// sort | base 1 | a million-element cycle. Pairs and the readers' bad input: test_verify_input.cpp.
#include <gtest/gtest.h>

#include <functional>
#include <nlohmann/json.hpp>

#include "core/detector.hpp"
#include "core/error.hpp"
#include "core/verify.hpp"
#include "io/arrays_json.hpp"
#include "io/dump_json.hpp"
#include "io/given_pairs.hpp"
#include "support/generators.hpp"
#include "support/verify_check.hpp"

namespace nbscope {
namespace {

using namespace testverify;
using nlohmann::json;
using verify::ProblemKind;

// ---- own arrays pass ----

// Under the sanitizers (~7x slower) the largest set is 90 elements: the same lists, shorter.
#ifdef NBSCOPE_SANITIZED_BUILD
constexpr std::int64_t kOwnArraysLargest = 90;
#else
constexpr std::int64_t kOwnArraysLargest = 250;
#endif

TEST(VerifyArrays, OwnArraysPassOnEveryLayoutAlgorithmAndDimension) {
  for (int dim : {2, 3}) {
    for (const Layout layout : testdata::all_layouts()) {
      for (std::int64_t n : {std::int64_t{0}, std::int64_t{1}, std::int64_t{2}, std::int64_t{17}, kOwnArraysLargest}) {
        const Elements e = make_layout(layout, n, dim, 7 + static_cast<std::uint64_t>(n));
        for (const char* a : {"screen", "nbs", "tree", "sort"}) {
          SCOPED_TRACE(std::string(a) + " " + std::to_string(dim) + "D " + layout_name(layout) + " n=" + std::to_string(n));
          const Checked c = check(e, own_dump(e, a), true);
          EXPECT_EQ(c.verdict.problem_count, 0) << c.all();
          EXPECT_EQ(c.verdict.other_order_lists, 0);
        }
      }
    }
  }
}

TEST(VerifyArrays, BookNineOnItsGridPassesAndWalksEveryList) {
  const Elements e = testdata::book_nine();
  const Checked c = check(e, own_dump(e, "screen", testdata::book_grid()), true);
  EXPECT_EQ(c.verdict.problem_count, 0) << c.all();
  std::size_t reached = 0;
  for (const auto& l : c.verdict.lists) reached += l.chain.size();
  EXPECT_EQ(c.verdict.lists.size(), 4u);  // Fig. 3.20: four non-empty cells
  EXPECT_EQ(reached, 9u);
}

// ---- planted bugs: screen (Fig. 3.20, 0-based: C[4][6] -> 3 -> 1 -> 0, C[4][5] -> 5, C[5][5] -> 7, C[1][6] -> 8 -> 6 -> 4 -> 2) ----

class ScreenBugs : public ::testing::Test {
 protected:
  Elements e = testdata::book_nine();
  json d = own_dump(e, "screen", testdata::book_grid());
};

TEST_F(ScreenBugs, AWrongHeadIsNamedWithBothCells) {
  d["heads"][4][5] = 3;  // element 3 (cell (4,6)) made the head of C[4][5], whose 5 it hides
  d["next"][3] = 5;
  d["heads"][4][6] = 1;
  const Checked c = check(e, d);
  EXPECT_EQ(c.first().kind, ProblemKind::WrongList);
  EXPECT_EQ(c.first().text, "C[4][5] = 3, but element 3 lies in cell (4,6), not in cell (4,5)");
  EXPECT_EQ(c.first().where, "$.heads[4][5]");
  EXPECT_EQ(c.first().link, (std::pair<ElementId, ElementId>{-1, 3}));
  EXPECT_EQ(c.verdict.problem_count, 1);
}

TEST_F(ScreenBugs, AnElementInTheNeighbouringCellsListIsNamedByTheLinkToIt) {
  d["next"][5] = 7;  // C[4][5] -> 5 -> 7, and 7 (cell (5,5)) taken off its own list
  d["heads"][5][5] = -1;
  const Checked c = check(e, d);
  EXPECT_EQ(c.first().text, "E[5] = 7, but element 7 lies in cell (5,5) and element 5 in cell (4,5)");
  EXPECT_EQ(c.first().where, "$.next[5]");
  EXPECT_EQ(c.first().link, (std::pair<ElementId, ElementId>{5, 7}));
}

TEST_F(ScreenBugs, ADroppedElementIsNamedWithTheListThatMissesIt) {
  d["next"][6] = 2;  // C[1][6] -> 8 -> 6 -> 2: 4 skipped
  const Checked c = check(e, d);
  EXPECT_EQ(c.first().kind, ProblemKind::NotListed);
  EXPECT_EQ(c.first().text, "element 4 is on no list, but lies in cell (1,6): C[1][6] misses it");
  EXPECT_EQ(c.first().elements, std::vector<ElementId>{4});
  EXPECT_EQ(c.verdict.problem_count, 1);
}

TEST_F(ScreenBugs, ADuplicatedElementIsNamedWhereItIsReachedAgain) {
  d["next"][7] = 0;  // C[5][5] -> 7 -> 0, but 0 is on C[4][6]'s list already
  const Checked c = check(e, d);
  EXPECT_TRUE(c.has(ProblemKind::TwoLists, "E[7] = 0, but element 0 is already on C[4][6]'s list")) << c.all();
}

TEST_F(ScreenBugs, ACycleIsFoundNotFollowed) {
  d["next"][1] = 3;  // C[4][6] -> 3 -> 1 -> 3
  const Checked c = check(e, d);
  EXPECT_EQ(c.first().kind, ProblemKind::Cycle);
  EXPECT_EQ(c.first().text, "C[4][6] -> 3 -> 1 -> 3: a cycle (E[1] = 3 leads back)");
  EXPECT_EQ(c.first().where, "$.next[1]");
  // 0, behind the cycle, is named once as cut off C[4][6], not as a dropped element of its own.
  EXPECT_TRUE(c.has(ProblemKind::NotListed, "C[4][6]: 1 element after the cut, 0, is on no list")) << c.all();
  EXPECT_EQ(c.verdict.problem_count, 2);
}

TEST_F(ScreenBugs, ElementsCutOffAListByARepeatAreNamed) {
  d["next"][3] = 8;  // C[4][6] -> 3 -> 8, but 8 heads C[1][6], walked before it: 1 and 0 are cut off
  const Checked c = check(e, d);
  EXPECT_TRUE(c.has(ProblemKind::TwoLists, "E[3] = 8, but element 8 is already on C[1][6]'s list")) << c.all();
  EXPECT_TRUE(c.has(ProblemKind::NotListed, "C[4][6]: 2 elements after the cut, 0 and 1, are on no list")) << c.all();
  EXPECT_EQ(c.verdict.problem_count, 2) << c.all();
  for (const verify::Problem& p : c.verdict.problems)
    if (p.kind == ProblemKind::NotListed) { EXPECT_EQ(p.elements, (std::vector<ElementId>{0, 1})); }
}

TEST_F(ScreenBugs, AnIndexOutOfRangeIsNamed) {
  d["next"][8] = 9;  // nine elements: 0..8
  const Checked c = check(e, d);
  EXPECT_EQ(c.first().kind, ProblemKind::OutOfRange);
  EXPECT_EQ(c.first().text, "E[8] = 9, but elements are 0..8, and -1 ends a list");
  d["next"][8] = 6;
  d["next"][3] = -7;  // a negative index other than -1
  EXPECT_TRUE(check(e, d).has(ProblemKind::OutOfRange, "E[3] = -7"));
}

TEST_F(ScreenBugs, AnotherValidOrderPassesAndFailsOnlyWithExact) {
  d["heads"][4][6] = 0;  // C[4][6] -> 0 -> 1 -> 3: the same elements, ids rising
  d["next"][0] = 1;
  d["next"][1] = 3;
  d["next"][3] = -1;
  const Checked loose = check(e, d, false);
  EXPECT_EQ(loose.verdict.problem_count, 0) << loose.all();
  EXPECT_EQ(loose.verdict.other_order_lists, 1);
  const Checked exact = check(e, d, true);
  EXPECT_EQ(exact.first().kind, ProblemKind::WrongOrder);
  EXPECT_NE(exact.first().text.find("C[4][6] -> ... -> 0 -> 1: 1 follows 0"), std::string::npos) << exact.first().text;
}

// ---- nbs 2D ----

class NbsBugs : public ::testing::Test {
 protected:
  Elements e = testdata::book_nine();
  json d = own_dump(e, "nbs", testdata::book_grid());
  // Row iy's object in "rows".
  json& row(int iy) {
    for (json& r : d["rows"])
      if (r["iy"] == iy) return r;
    throw Error("no row");
  }
};

TEST_F(NbsBugs, AYListCycleIsNamedAsTheBookWouldDrawIt) {
  d["y_next"][4] = 8;  // y_heads[6] -> 8 -> 6 -> 4 -> 8
  const Checked c = check(e, d);
  EXPECT_EQ(c.first().kind, ProblemKind::Cycle);
  EXPECT_EQ(c.first().text, "y_heads[6] -> 8 -> 6 -> 4 -> 8: a cycle (Y[4] = 8 leads back)");
}

TEST_F(NbsBugs, AnElementOnTheWrongRowsYListIsNamed) {
  // 5 (row 5) pushed on row 6's y-list instead: y_heads[5] -> 7, y_heads[6] -> 8 -> ... -> 5
  d["y_next"][7] = -1;
  d["y_next"][0] = 5;
  d["y_next"][5] = -1;
  const Checked c = check(e, d);
  EXPECT_TRUE(c.has(ProblemKind::WrongList, "Y[0] = 5, but element 5 lies in row 5 and element 0 in row 6")) << c.all();
}

TEST_F(NbsBugs, AnXListOfARowHoldingAnotherCellsElementIsNamedWithTheRow) {
  json& r = row(6);  // x_heads [[1, 2], [4, 0]]: move 2 (column 1) onto column 4's list
  r["x_heads"] = json::array({json::array({1, 4}), json::array({4, 2})});
  for (json& p : r["x_next"])
    if (p[0] == 2) p[1] = 0;
  const Checked c = check(e, d);
  EXPECT_EQ(c.first().kind, ProblemKind::WrongList);
  EXPECT_EQ(c.first().text, "row 6: x_heads[4] = 2, but element 2 lies in cell (1,6), not in cell (4,6)");
}

TEST_F(NbsBugs, AnXListRunningIntoAnElementWithoutAnEntryIsNamed) {
  json& r = row(6);
  json kept = json::array();
  for (json& p : r["x_next"])
    if (p[0] != 1) kept.push_back(p);  // X[1] not given
  r["x_next"] = kept;
  const Checked c = check(e, d);
  EXPECT_EQ(c.first().kind, ProblemKind::NotGiven);
  EXPECT_NE(c.first().text.find("X[1] is not given in $.rows[1].x_next"), std::string::npos) << c.first().text;
}

TEST_F(NbsBugs, XListsInAnotherOrderFailOnlyWithExact) {
  json& r = row(6);  // x_heads[4] -> 0 -> 1 -> 3 (the book: ascending) reversed
  r["x_heads"] = json::array({json::array({1, 2}), json::array({4, 3})});
  r["x_next"] = json::array({json::array({2, 4}), json::array({4, 6}), json::array({6, 8}), json::array({8, -1}),
                             json::array({3, 1}), json::array({1, 0}), json::array({0, -1})});
  EXPECT_EQ(check(e, d, false).verdict.problem_count, 0) << check(e, d, false).all();
  EXPECT_TRUE(check(e, d, true).has(ProblemKind::WrongOrder, "row 6: x_heads[4] -> ... -> 3 -> 1"));
}

// ---- nbs 3D, tree, sort ----

TEST(VerifyArrays3d, AZListCycleAndAWrongLayerYListAreNamed) {
  const Elements e = make_layout(Layout::Loose, 60, 3, 3);
  json d = own_dump(e, "nbs");
  // A cycle: the last element of the first non-empty z-list pointed back at its head.
  for (std::size_t iz = 0; iz < d["z_heads"].size(); ++iz) {
    const int head = d["z_heads"][iz];
    if (head == -1) continue;
    int k = head;
    while (d["z_next"][k] != -1) k = d["z_next"][k];
    if (k == head) continue;  // a list of one: try the next
    d["z_next"][k] = head;
    const Checked c = check(e, d);
    EXPECT_EQ(c.first().kind, ProblemKind::Cycle);
    EXPECT_NE(c.first().text.find("z_heads[" + std::to_string(iz) + "] -> " + std::to_string(head)), std::string::npos);
    EXPECT_NE(c.first().text.find("(Z[" + std::to_string(k) + "] = " + std::to_string(head) + " leads back)"), std::string::npos);
    return;
  }
  FAIL() << "no z-list of two elements";
}

TEST(VerifyArraysTree, AnElementOnAnotherLeafsListIsNamed) {
  const Elements e = testdata::book_nine();
  json d = own_dump(e, "tree", testdata::book_grid());
  // Swap the heads of two leaves: every element then sits on another cell's list.
  json& leaves = d["leaves"];
  ASSERT_GE(leaves.size(), 2u);
  std::swap(leaves[0]["head"], leaves[1]["head"]);
  const Checked c = check(e, d);
  EXPECT_EQ(c.first().kind, ProblemKind::WrongList);
  EXPECT_EQ(c.first().where, "$.leaves[0].head");
  EXPECT_NE(c.first().text.find("HEAD[" + std::to_string(leaves[0]["node"].get<int>()) + "] = "), std::string::npos);
}

TEST(VerifyArraysSort, AWrongCellARepeatedElementAndUnsortedKeysAreNamed) {
  const Elements e = testdata::book_nine();
  const json good = own_dump(e, "sort", testdata::book_grid());
  json d = good;
  d["iy"][4] = 5;  // element 4 lies in row 6
  EXPECT_EQ(check(e, d).first().text, "iy[4] = 5, but element 4 lies in cell (1,6)");
  d = good;
  d["order"][1] = d["order"][0];
  const Checked c = check(e, d);
  EXPECT_TRUE(c.has(ProblemKind::TwoLists, "order[1] = " + std::to_string(good["order"][0].get<int>()))) << c.all();
  EXPECT_TRUE(c.has(ProblemKind::NotListed, "element " + std::to_string(good["order"][1].get<int>()) + " is not in order"));
  d = good;
  std::swap(d["keys"][0], d["keys"][8]);
  std::swap(d["order"][0], d["order"][8]);
  EXPECT_TRUE(check(e, d).has(ProblemKind::WrongCell, "not sorted (ix first)"));
  d = good;  // ties out of id order: C[1][6]'s four at positions 0..3
  std::swap(d["order"][0], d["order"][1]);
  EXPECT_EQ(check(e, d, false).verdict.problem_count, 0);
  EXPECT_TRUE(check(e, d, true).has(ProblemKind::WrongOrder, "the book's ties go by element id"));
}

// ---- every planted bug in every list-based algorithm's arrays, 2D and 3D ----

// The parsed arrays of nbscope's own run, and a list of at least two elements to plant bugs in.
struct Planting {
  Elements e;
  Grid grid;
  verify::UserArrays user;
  int family = -1, list = -1;
  std::vector<ElementId> chain;  // that list's elements, head first
};

Planting planting(const std::string& algorithm, int dim) {
  Planting p;
  p.e = make_layout(Layout::Dense, 300, dim, 11);
  const ArraysJson file = parse_arrays_json(own_dump(p.e, algorithm).dump(), "arrays.json");
  p.grid = make_grid(p.e, file.grid);
  p.user = file.arrays(algorithm, p.grid, p.e.size(), 0);
  for (std::size_t f = 0; f < p.user.families.size() && p.family < 0; ++f) {
    const verify::ListFamily& fam = p.user.families[f];
    if (fam.sparse) continue;  // a dense next array, to plant by index
    for (std::size_t l = 0; l < fam.lists.size(); ++l) {
      std::vector<ElementId> chain;
      for (std::int32_t k = fam.lists[l].head; k != -1; k = fam.next[static_cast<std::size_t>(k)]) chain.push_back(k);
      if (chain.size() >= 3) {
        p.family = static_cast<int>(f);
        p.list = static_cast<int>(l);
        p.chain = chain;
        break;
      }
    }
  }
  return p;
}

TEST(VerifyArraysPlanted, EveryBugInEveryListAlgorithmIsNamedByTheEntryPlanted) {
  for (const char* algorithm : {"screen", "nbs", "tree"}) {
    for (int dim : {2, 3}) {
      SCOPED_TRACE(std::string(algorithm) + " " + std::to_string(dim) + "D");
      const Planting base = planting(algorithm, dim);
      ASSERT_GE(base.family, 0) << "no list of three elements";
      const auto fi = static_cast<std::size_t>(base.family);
      const auto li = static_cast<std::size_t>(base.list);
      const verify::ListFamily& fam = base.user.families[fi];
      const std::string head = verify::slot_name(fam, fam.lists[li].slot, 0);
      const auto next_of = [&](ElementId k) { return fam.next_name + "[" + std::to_string(k) + "]"; };
      const ElementId a = base.chain[0], b = base.chain[1], c = base.chain[2], last = base.chain.back();
      const auto run = [&](const std::function<void(verify::ListFamily&)>& plant, bool exact = false) {
        verify::UserArrays u = base.user;
        plant(u.families[fi]);
        const Checked checked{verify::verify_arrays(base.e, base.grid, u, exact)};
        EXPECT_GT(checked.verdict.problem_count, 0);
        return checked;
      };
      // Another list's element at this list's head: wrong list, named by the head.
      ElementId stranger = -1;
      for (std::size_t l = 0; l < fam.lists.size() && stranger < 0; ++l)
        if (l != li && fam.lists[l].cell != fam.lists[li].cell) stranger = fam.lists[l].head;
      ASSERT_GE(stranger, 0);
      Checked r = run([&](verify::ListFamily& f) { f.lists[li].head = stranger; });
      // (Reached already when its own list comes first in the file: then "already on", named by the head too.)
      EXPECT_TRUE(r.has(ProblemKind::WrongList, head + " = " + std::to_string(stranger) + ", but element ") ||
                  r.has(ProblemKind::TwoLists, head + " = " + std::to_string(stranger) + ", but element "))
          << r.all();
      // The head's successor skipped: dropped, named with the list that misses it.
      r = run([&](verify::ListFamily& f) { f.next[static_cast<std::size_t>(a)] = c; });
      EXPECT_TRUE(r.has(ProblemKind::NotListed, "element " + std::to_string(b) + " is on no list")) << r.all();
      // The list's last element linked on to another list's head: that element reached twice.
      r = run([&](verify::ListFamily& f) { f.next[static_cast<std::size_t>(last)] = stranger; });
      EXPECT_TRUE(r.has(ProblemKind::WrongList, next_of(last) + " = " + std::to_string(stranger)) ||
                  r.has(ProblemKind::TwoLists, next_of(last) + " = " + std::to_string(stranger)) ||
                  r.has(ProblemKind::TwoLists, "= " + std::to_string(stranger) + ", but element " + std::to_string(stranger) + " is already on"))
          << r.all();
      // The last element linked back to the head: a cycle, named by the link that closes it.
      r = run([&](verify::ListFamily& f) { f.next[static_cast<std::size_t>(last)] = a; });
      EXPECT_TRUE(r.has(ProblemKind::Cycle, "(" + next_of(last) + " = " + std::to_string(a) + " leads back)")) << r.all();
      // An index past the last element.
      const auto n = static_cast<std::int32_t>(base.e.size());
      r = run([&](verify::ListFamily& f) { f.next[static_cast<std::size_t>(b)] = n; });
      EXPECT_TRUE(r.has(ProblemKind::OutOfRange, next_of(b) + " = " + std::to_string(n) + ", but elements are 0..")) << r.all();
      // The first two swapped: right, but not the book's order (only --exact says so).
      const auto swap_two = [&](verify::ListFamily& f) {
        f.lists[li].head = b;
        f.next[static_cast<std::size_t>(b)] = a;
        f.next[static_cast<std::size_t>(a)] = c;
      };
      verify::UserArrays swapped = base.user;
      swap_two(swapped.families[fi]);
      const verify::ArraysVerdict loose = verify::verify_arrays(base.e, base.grid, swapped, false);
      EXPECT_EQ(loose.problem_count, 0);
      EXPECT_EQ(loose.other_order_lists, 1);
      r = run(swap_two, true);
      EXPECT_TRUE(r.has(ProblemKind::WrongOrder, head + " -> ... -> " + std::to_string(b) + " -> " + std::to_string(a))) << r.all();
    }
  }
}

// ---- sparse next arrays given empty (a row's "x_next": [], a layer's "y_next": []) ----

TEST(VerifyArraysSparse, AnEmptySparseNextArrayLeavesEveryListEntryNotGiven) {
  // Was a segfault: an empty next_pairs was taken for a dense next array and indexed.
  for (int dim : {2, 3}) {
    SCOPED_TRACE(std::to_string(dim) + "D");
    const Elements e = make_layout(Layout::Dense, 60, dim, 5);
    json d = own_dump(e, "nbs");
    json& holder = dim == 2 ? d["rows"][0] : d["layers"][0];
    const char* next_key = dim == 2 ? "x_next" : "y_next";
    ASSERT_FALSE(holder[next_key].empty());
    holder[next_key] = json::array();
    const Checked c = check(e, d);
    EXPECT_TRUE(c.has(ProblemKind::NotGiven, std::string(dim == 2 ? "X[" : "Y[") + "")) << c.all();
    EXPECT_EQ(c.first().kind, ProblemKind::NotGiven) << c.all();
    if (dim == 3) {  // a layer's rows too
      json r = own_dump(e, "nbs");
      ASSERT_FALSE(r["layers"][0]["rows"].empty());
      r["layers"][0]["rows"][0]["x_next"] = json::array();
      EXPECT_TRUE(check(e, r).has(ProblemKind::NotGiven, "X[")) << check(e, r).all();
    }
  }
  // Built by hand, no reader: a sparse family with heads and no next entries at all.
  const Elements e = testdata::book_nine();
  const Grid grid = make_grid(e, testdata::book_grid());
  verify::UserArrays u;
  u.algorithm = "nbs";
  verify::ListFamily f;
  f.sparse = true;
  f.heads_name = "x_heads";
  f.next_name = "X";
  f.heads_shape = {grid.n[0]};
  f.scope = {-1, 6, -1};
  f.lists.push_back({4, 3, {4, -1, -1}, 0});
  f.heads_path = "$.rows[0].x_heads";
  f.heads_form = verify::HeadsForm::Pairs;
  f.next_path = "$.rows[0].x_next";
  u.families.push_back(std::move(f));
  const verify::ArraysVerdict v = verify::verify_arrays(e, grid, u, false);
  ASSERT_GE(v.problem_count, 1);
  EXPECT_EQ(v.problems[0].text, "row 6: x_heads[4] -> 3, but X[3] is not given in $.rows[0].x_next");
}

TEST(VerifyArraysSparse, ADenseNextArrayShorterThanNGivesNoEntryPastItsEnd) {
  const Elements e = testdata::book_nine();
  const Grid grid = make_grid(e, testdata::book_grid());
  verify::UserArrays u;
  u.algorithm = "screen";
  verify::ListFamily f;
  f.heads_name = "C";
  f.next_name = "E";
  f.heads_shape = {grid.n[0], grid.n[1]};
  f.lists.push_back({46, 3, {4, 6, -1}, 0});
  f.heads_path = "$.heads";
  f.heads_form = verify::HeadsForm::Cells;
  f.next_path = "$.next";
  u.families.push_back(std::move(f));
  const verify::ArraysVerdict v = verify::verify_arrays(e, grid, u, false);
  ASSERT_GE(v.problem_count, 1);
  EXPECT_EQ(v.problems[0].kind, ProblemKind::NotGiven);
}

// ---- base 1: the book's numbering ----

TEST(VerifyArraysBase1, TheBooksArraysReadAsPrintedAndProblemsNamedAsTheBookDoes) {
  // Fig. 3.20 as the book prints it (1-based, -1 the end): C[5][7] = 4, C[5][6] = 6, C[6][6] = 8, C[2][7] = 9,
  // E = -1 1 -1 2 3 -1 5 -1 7.
  const Elements e = testdata::book_nine();
  json d = {{"algorithm", "screen"}, {"base", 1}, {"cell_size", 1}, {"origin", {0, 0}}, {"nx", 10}, {"ny", 10}};
  json heads = json::array();
  for (int ix = 1; ix <= 10; ++ix) {
    json col = json::array();
    for (int iy = 1; iy <= 10; ++iy) col.push_back(-1);
    heads.push_back(col);
  }
  heads[4][6] = 4;
  heads[4][5] = 6;
  heads[5][5] = 8;
  heads[1][6] = 9;
  d["heads"] = heads;
  d["next"] = {-1, 1, -1, 2, 3, -1, 5, -1, 7};
  EXPECT_EQ(check(e, d, true).verdict.problem_count, 0) << check(e, d).all();
  d["next"][7] = 5;  // E[8] = 5 (book numbering): 5 is on C[2][7]'s list already
  const Checked c = check(e, d);
  EXPECT_EQ(c.first().text, "E[8] = 5, but element 5 is already on C[2][7]'s list (an element is on one list only)");
  d["next"][7] = 0;  // 0 is no element when counting from 1
  EXPECT_EQ(check(e, d).first().text, "E[8] = 0, but elements are 1..9, and -1 ends a list");
}

// ---- a million elements on one list that closes on itself ----

TEST(VerifyArraysScale, AMillionElementCycleIsFoundInOneWalk) {
  const std::int64_t n = 1'000'000;
  Elements e;
  e.resize(n);
  for (std::int64_t k = 0; k < n; ++k) {
    e.x[k] = static_cast<double>(k % 1000);
    e.y[k] = 0.5;
    e.r[k] = 0.5;
  }
  GridOptions g;
  g.cell_size = 1000;
  g.origin = std::array<double, 3>{0, 0, 0};
  const Grid grid = make_grid(e, g);
  verify::UserArrays u;
  u.algorithm = "nbs";
  verify::ListFamily f;
  f.heads_name = "y_heads";
  f.next_name = "Y";
  f.heads_shape = {grid.n[1]};
  f.lists.push_back({0, static_cast<std::int32_t>(n - 1), {-1, 0, -1}, 0});
  f.heads_path = "$.y_heads";
  f.next.resize(static_cast<std::size_t>(n));
  for (std::int64_t k = 1; k < n; ++k) f.next[static_cast<std::size_t>(k)] = static_cast<std::int32_t>(k - 1);
  f.next[0] = static_cast<std::int32_t>(n - 1);  // the last link closes the list on its head
  f.next_path = "$.y_next";
  u.families.push_back(std::move(f));
  const verify::ArraysVerdict v = verify::verify_arrays(e, grid, u, true);
  ASSERT_EQ(v.problem_count, 1);
  EXPECT_EQ(v.problems[0].kind, ProblemKind::Cycle);
  EXPECT_EQ(v.problems[0].text, "y_heads[0] -> 999999 -> 999998 -> 999997 -> ... (999994 more) -> 2 -> 1 -> 0 -> 999999: a cycle "
                                "(Y[0] = 999999 leads back)");
}

}  // namespace
}  // namespace nbscope
