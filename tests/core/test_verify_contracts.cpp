// `nbscope verify --arrays`: the contract of docs/diagnosis.md each problem of a user's final lists
// breaks (core/verify.hpp contract_broken_by), on planted arrays of every level, and the first one.
//
// Index: the mapping, kind by kind | screen (first level) | nbs rows and 3D layers (lower levels) |
// problems of the file's form, order and sort: none | the first broken contract.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/verify.hpp"
#include "support/generators.hpp"
#include "support/verify_check.hpp"

namespace nbscope {
namespace {

using namespace testverify;
using nlohmann::json;
using verify::ProblemKind;

// The contract of the first problem of `kind` whose text holds `text` (fails the test when none does).
std::optional<Contract> contract_of(const Checked& c, ProblemKind kind, const std::string& text) {
  for (const verify::Problem& p : c.verdict.problems)
    if (p.kind == kind && p.text.find(text) != std::string::npos) return p.contract;
  ADD_FAILURE() << "no " << verify::problem_kind_name(kind) << " problem with \"" << text << "\" in:\n" << c.all();
  return std::nullopt;
}

// ---- the mapping ----

TEST(VerifyContracts, EachKindMapsByTheContractsOwnDefinitionAtEachLevel) {
  verify::ListFamily first_level;  // screen's C, NBS's y-lists, 3D z-lists: no row or layer fixed
  verify::ListFamily row;          // one row's x-lists
  row.scope = {-1, 6, -1};
  verify::ListFamily layer;        // one 3D layer's y-lists
  layer.scope = {-1, -1, 2};
  using verify::contract_broken_by;
  for (const auto* f : {&first_level, &row, &layer}) {
    EXPECT_EQ(contract_broken_by(ProblemKind::WrongList, *f), Contract::ListCell);
    EXPECT_EQ(contract_broken_by(ProblemKind::Cycle, *f), Contract::Cycle);
    EXPECT_EQ(contract_broken_by(ProblemKind::OutOfRange, *f), Contract::ListLink);
    EXPECT_EQ(contract_broken_by(ProblemKind::WrongOrder, *f), std::nullopt);
    EXPECT_EQ(contract_broken_by(ProblemKind::NotGiven, *f), std::nullopt);
    EXPECT_EQ(contract_broken_by(ProblemKind::WrongCell, *f), std::nullopt);
  }
  EXPECT_EQ(contract_broken_by(ProblemKind::NotListed, first_level), Contract::FirstLevelOnce);
  EXPECT_EQ(contract_broken_by(ProblemKind::TwoLists, first_level), Contract::FirstLevelOnce);
  EXPECT_EQ(contract_broken_by(ProblemKind::NotListed, row), Contract::CellList);
  EXPECT_EQ(contract_broken_by(ProblemKind::NotListed, layer), Contract::CellList);
  EXPECT_EQ(contract_broken_by(ProblemKind::TwoLists, row), Contract::ListCell);
  EXPECT_EQ(contract_broken_by(ProblemKind::TwoLists, layer), Contract::ListCell);
}

// ---- screen: one level, Fig. 3.20 0-based (C[4][6] -> 3 -> 1 -> 0, C[4][5] -> 5, C[5][5] -> 7, C[1][6] -> 8 -> 6 -> 4 -> 2) ----

class ScreenContracts : public ::testing::Test {
 protected:
  Elements e = testdata::book_nine();
  json d = own_dump(e, "screen", testdata::book_grid());
};

TEST_F(ScreenContracts, AnElementOnAnotherCellsListBreaksListCell) {
  d["next"][5] = 7;
  d["heads"][5][5] = -1;
  EXPECT_EQ(contract_of(check(e, d), ProblemKind::WrongList, "E[5] = 7"), Contract::ListCell);
}

TEST_F(ScreenContracts, AnElementOnNoListOrOnTwoBreaksFirstLevelOnce) {
  d["next"][6] = 2;  // 4 skipped
  EXPECT_EQ(contract_of(check(e, d), ProblemKind::NotListed, "element 4 is on no list"), Contract::FirstLevelOnce);
  d = own_dump(e, "screen", testdata::book_grid());
  d["next"][7] = 0;  // 0 on C[5][5]'s list as well as C[4][6]'s
  EXPECT_EQ(contract_of(check(e, d), ProblemKind::TwoLists, "element 0 is already on C[4][6]'s list"), Contract::FirstLevelOnce);
}

TEST_F(ScreenContracts, AListClosingOnItselfBreaksCycleAndWhatItCutOffFirstLevelOnce) {
  d["next"][1] = 3;  // C[4][6] -> 3 -> 1 -> 3
  const Checked c = check(e, d);
  EXPECT_EQ(contract_of(c, ProblemKind::Cycle, "a cycle"), Contract::Cycle);
  EXPECT_EQ(contract_of(c, ProblemKind::NotListed, "after the cut"), Contract::FirstLevelOnce);
  EXPECT_EQ(verify::first_contract_problem(c.verdict), 0u);  // the cause, found first
}

TEST_F(ScreenContracts, AHeadOrALinkNamingNoElementBreaksListLink) {
  d["next"][8] = 9;
  EXPECT_EQ(contract_of(check(e, d), ProblemKind::OutOfRange, "E[8] = 9"), Contract::ListLink);
  d = own_dump(e, "screen", testdata::book_grid());
  d["heads"][4][6] = 42;  // a head never written or never cleared
  EXPECT_EQ(contract_of(check(e, d), ProblemKind::OutOfRange, "C[4][6] = 42"), Contract::ListLink);
}

TEST_F(ScreenContracts, ANextEntryNoWalkReachesBreaksNone) {
  d["heads"][5][5] = -1;  // 7 on no list: that is first-level-once; its next entry is read by no walk
  d["next"][7] = 99;
  const Checked c = check(e, d);
  EXPECT_EQ(contract_of(c, ProblemKind::NotListed, "element 7 is on no list"), Contract::FirstLevelOnce);
  EXPECT_EQ(contract_of(c, ProblemKind::OutOfRange, "E[7] = 99"), std::nullopt);
}

// ---- nbs: y-lists, each row's x-lists (row 6: x_heads [[1, 2], [4, 0]]), 3D layers' y-lists ----

class NbsContracts : public ::testing::Test {
 protected:
  Elements e = testdata::book_nine();
  json d = own_dump(e, "nbs", testdata::book_grid());
  json& row(int iy) {
    for (json& r : d["rows"])
      if (r["iy"] == iy) return r;
    throw Error("no row");
  }
};

TEST_F(NbsContracts, AnElementOnAnotherRowsYListBreaksListCell) {
  d["y_next"][7] = -1;  // 5 (row 5) on row 6's y-list
  d["y_next"][0] = 5;
  d["y_next"][5] = -1;
  EXPECT_EQ(contract_of(check(e, d), ProblemKind::WrongList, "Y[0] = 5"), Contract::ListCell);
}

TEST_F(NbsContracts, AnXListMissingAnElementOfItsRowBreaksCellList) {
  for (json& p : row(6)["x_next"])
    if (p[0] == 6) p[1] = -1;  // x_heads[1] -> 2 -> 4 -> 6: 8 left out
  EXPECT_EQ(contract_of(check(e, d), ProblemKind::NotListed, "element 8 is on no list"), Contract::CellList);
}

TEST_F(NbsContracts, AnElementOnTwoXListsOfItsRowBreaksListCell) {
  for (json& p : row(6)["x_next"])
    if (p[0] == 3) p[1] = 2;  // x_heads[4] -> 0 -> 1 -> 3 -> 2, and 2 heads x_heads[1] too
  EXPECT_EQ(contract_of(check(e, d), ProblemKind::TwoLists, "element 2 is already on"), Contract::ListCell);
}

TEST_F(NbsContracts, AnXListRunningPastTheEntriesGivenBreaksNone) {
  json kept = json::array();
  for (json& p : row(6)["x_next"])
    if (p[0] != 1) kept.push_back(p);
  row(6)["x_next"] = kept;
  EXPECT_EQ(contract_of(check(e, d), ProblemKind::NotGiven, "X[1] is not given"), std::nullopt);
}

TEST(VerifyContracts3d, ALayersYListMissingAnElementBreaksCellList) {
  // Three elements in cells (0,0,0), (0,0,0) and (2,0,0); one in (0,2,1). Layer 0's y-list 0 -> 1 -> 2.
  Elements e;
  e.dim = 3;
  for (const auto& [x, y, z, r] : {std::array{0.5, 0.5, 0.5, 0.3}, std::array{0.6, 0.6, 0.6, 0.01}, std::array{2.5, 0.5, 0.5, 0.3},
                                   std::array{0.5, 2.5, 1.5, 0.3}})
    e.push_back(x, y, z, r);
  GridOptions g;
  g.cell_size = 1;
  g.origin = std::array<double, 3>{0, 0, 0};
  g.cells = std::array<std::int64_t, 3>{3, 3, 3};
  json d = own_dump(e, "nbs", g);
  ASSERT_EQ(d["layers"][0]["y_next"], json::parse("[[0, 1], [1, 2], [2, -1]]"));
  d["layers"][0]["y_next"][1][1] = -1;  // 2 never reaches a y-list of its layer, so never its cell's x-list
  EXPECT_EQ(contract_of(check(e, d), ProblemKind::NotListed, "element 2 is on no list"), Contract::CellList);
}

// ---- none: the file's form, sort ----

TEST_F(NbsContracts, TwoHeadsForOneCellBreakNone) {
  row(6)["x_heads"] = json::array({json::array({1, 2}), json::array({1, 0})});
  EXPECT_EQ(contract_of(check(e, d), ProblemKind::TwoLists, "are both the list of cell"), std::nullopt);
}

TEST(VerifyContractsSort, SortsArraysBreakNoListContract) {
  const Elements e = testdata::book_nine();
  json d = own_dump(e, "sort", testdata::book_grid());
  d["order"][1] = d["order"][0];  // an element twice in the permutation, another never
  const Checked c = check(e, d);
  ASSERT_GT(c.verdict.problem_count, 0);
  for (const verify::Problem& p : c.verdict.problems) EXPECT_EQ(p.contract, std::nullopt) << p.text;
  EXPECT_EQ(verify::first_contract_problem(c.verdict), std::nullopt);
}

// ---- the first broken contract ----

TEST_F(ScreenContracts, TheFirstBrokenContractIsTheFirstProblemThatBreaksOne) {
  d["heads"][4][6] = 0;  // C[4][6] -> 0 -> 1 -> 3: not the book's order (no contract), found first
  d["next"][0] = 1;
  d["next"][1] = 3;
  d["next"][3] = -1;
  d["heads"][5][5] = -1;  // 7 on no list: first-level-once, found after the walks
  const Checked c = check(e, d, true);
  ASSERT_EQ(c.verdict.problems.size(), 2u) << c.all();
  EXPECT_EQ(c.first().kind, ProblemKind::WrongOrder);
  EXPECT_EQ(verify::first_contract_problem(c.verdict), 1u);
  EXPECT_EQ(c.verdict.problems[1].contract, Contract::FirstLevelOnce);
}

}  // namespace
}  // namespace nbscope
