// `nbscope verify` through the binary: exit 0 for nbscope's own dumps, 1 with the planted entry
// named for a user's wrong pairs or arrays, 2 with the file and the JSON path for bad input.
//
// Index: helpers | --pairs | --arrays (right, wrong, base 1, a 1e6-element cycle) | the first broken
// contract | bad input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "support/paths.hpp"
#include "support/run_cli.hpp"

namespace nbscope {
namespace {

using nlohmann::json;
using testcli::run;
using testcli::scratch_dir;
using testcli::write_text;

const std::string kBookGrid = " --cell-size 1 --origin 0,0 --cells 10,10";

// `nbscope dump` of the nine elements on the book's grid, as JSON.
json nine_dump(const std::string& algorithm) {
  const auto r = run("dump --input " + testpaths::nine_csv() + " --algorithm " + algorithm + kBookGrid);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return json::parse(r.out);
}

// Writes `doc` into the test's scratch directory and runs verify --arrays on it.
testcli::Result verify_arrays(const std::string& test, const json& doc, const std::string& flags = "") {
  const std::string path = scratch_dir(test) + "/arrays.json";
  write_text(path, doc.dump(1));
  return run("verify --input " + testpaths::nine_csv() + " --arrays " + path + flags);
}

// ---- --pairs ----

TEST(VerifyCli, PairsRightExitZeroWithOneSummaryLine) {
  const std::string dir = scratch_dir("verify_pairs_right");
  write_text(dir + "/p.csv", "i,j\n1,0\n");  // the nine's one contact, given j,i
  const auto r = run("verify --input " + testpaths::nine_csv() + " --pairs " + dir + "/p.csv");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "nbscope verify: " + dir + "/p.csv: 1 pair given for 9 elements, the reference (brute) finds 1: 1 right, "
                   "0 missing, 0 extra, 0 duplicated, 0 with itself, 0 out of range: right\n");
}

TEST(VerifyCli, PairsWrongNameEachPairWithItsLineCellsAndGap) {
  const std::string dir = scratch_dir("verify_pairs_wrong");
  // Book numbering: the one contact is 1,2; given instead 2,4 (apart), 3,3, 1,10, and 2,4 twice.
  write_text(dir + "/p.csv", "2 4\n3 3\n1 10\n4,2\n");
  const auto r = run("verify --input " + testpaths::nine_csv() + " --pairs " + dir + "/p.csv --base 1" + kBookGrid);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.out.find(": WRONG\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nmissing 1,2: cells (5,7) and (5,7), distance - radii = -0.0418861 (in contact)\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nextra 2,4 (line 1): cells (5,7) and (5,7), distance - radii = 0.224264 (apart)\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nduplicated 2,4 (line 4, first on line 1)\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nwith itself 3,3 (line 2)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nout of range 1,10 (line 3): elements are 1..9"), std::string::npos) << r.out;
}

// ---- --arrays ----

TEST(VerifyCli, OwnDumpsOfEveryAlgorithmAreRightEvenWithExact) {
  for (const char* a : {"screen", "nbs", "tree", "sort"}) {
    const auto r = verify_arrays(std::string("verify_own_") + a, nine_dump(a), " --exact");
    EXPECT_EQ(r.exit_code, 0) << a << ": " << r.out << r.err;
    EXPECT_NE(r.out.find(std::string("the ") + a + " arrays of 9 elements are right"), std::string::npos) << r.out;
  }
}

TEST(VerifyCli, APlantedBugIsNamedFirstWithItsPathThenCounted) {
  json d = nine_dump("screen");
  d["next"][5] = 7;  // E[5] = 7: element 7 (cell (5,5)) hung on C[4][5]'s list
  d["heads"][5][5] = -1;
  const auto r = verify_arrays("verify_planted", d);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const std::string first = r.out.substr(0, r.out.find('\n'));
  EXPECT_EQ(first.substr(first.find("$.")), "$.next[5]: E[5] = 7, but element 7 lies in cell (5,5) and element 5 in cell (4,5)");
  EXPECT_NE(r.out.find("nbscope verify: 1 problem in the screen arrays of 9 elements (1 wrong list): WRONG"), std::string::npos) << r.out;
}

TEST(VerifyCli, Base1NamesEverythingAsTheBookDoes) {
  json d = nine_dump("nbs");  // 0-based: shift every index to the book's numbering
  const auto shift = [](json& v) {
    if (v != -1) v = v.get<int>() + 1;
  };
  for (json& v : d["y_next"]) shift(v);
  for (json& v : d["y_heads"]) shift(v);
  for (json& row : d["rows"]) {
    row["iy"] = row["iy"].get<int>() + 1;
    for (json& p : row["x_heads"]) p[0] = p[0].get<int>() + 1, shift(p[1]);
    for (json& p : row["x_next"]) shift(p[0]), shift(p[1]);
  }
  d["base"] = 1;
  EXPECT_EQ(verify_arrays("verify_base1_ok", d, " --exact").exit_code, 0);
  d["y_next"][4] = 9;  // Y[5] = 9: y_heads[7] -> 9 -> 7 -> 5 -> 9
  const auto r = verify_arrays("verify_base1_cycle", d);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("$.y_next[4]: y_heads[7] -> 9 -> 7 -> 5 -> 9: a cycle (Y[5] = 9 leads back)"), std::string::npos) << r.out;
  // The flag agrees with the file, or is refused.
  EXPECT_EQ(verify_arrays("verify_base1_flag", d, " --base 0").exit_code, 2);
}

TEST(VerifyCli, EmptySparseNextArraysAreAVerdictNotACrash) {
  // A row's "x_next": [] and a 3D layer's "y_next": [] were a segfault (exit 139) in verify and gui.
  json d = nine_dump("nbs");
  d["rows"][0]["x_next"] = json::array();
  const auto r = verify_arrays("verify_empty_x_next", d);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.out.find("is not given in $.rows[0].x_next"), std::string::npos) << r.out;
#ifdef NBSCOPE_TEST_GUI  // gui --arrays exists in the GUI build only
  const std::string gui_dir = scratch_dir("verify_empty_x_next_gui");
  write_text(gui_dir + "/arrays.json", d.dump());
  const auto gui = run("gui --input " + testpaths::nine_csv() + " --arrays " + gui_dir + "/arrays.json --frames 1 --screenshot " +
                           gui_dir + "/x.png",
                       "env -u DISPLAY -u WAYLAND_DISPLAY");
  EXPECT_EQ(gui.exit_code, 1) << gui.err;
#endif

  const std::string dir = scratch_dir("verify_empty_y_next_3d");
  std::string csv = "x,y,z,r\n";
  for (int k = 0; k < 27; ++k) csv += std::to_string(k % 3) + "," + std::to_string(k / 3 % 3) + "," + std::to_string(k / 9) + ",0.4\n";
  write_text(dir + "/e.csv", csv);
  const auto dump = run("dump --input " + dir + "/e.csv --algorithm nbs");
  ASSERT_EQ(dump.exit_code, 0) << dump.err;
  json d3 = json::parse(dump.out);
  d3["layers"][0]["y_next"] = json::array();
  write_text(dir + "/a.json", d3.dump());
  const auto r3 = run("verify --input " + dir + "/e.csv --arrays " + dir + "/a.json");
  EXPECT_EQ(r3.exit_code, 1) << r3.err;
  EXPECT_NE(r3.out.find("is not given in $.layers[0].y_next"), std::string::npos) << r3.out;
  d3 = json::parse(dump.out);
  d3["layers"][0]["rows"][0]["x_next"] = json::array();
  write_text(dir + "/b.json", d3.dump());
  const auto rows3 = run("verify --input " + dir + "/e.csv --arrays " + dir + "/b.json");
  EXPECT_EQ(rows3.exit_code, 1) << rows3.err;
  EXPECT_NE(rows3.out.find("is not given in $.layers[0].rows[0].x_next"), std::string::npos) << rows3.out;
}

TEST(VerifyCli, APairsFileWithAByteOrderMarkIsReadLikeOneWithout) {
  const std::string dir = scratch_dir("verify_pairs_bom");
  write_text(dir + "/p.csv", "\xEF\xBB\xBFi,j\n1,0\n");
  const auto r = run("verify --input " + testpaths::nine_csv() + " --pairs " + dir + "/p.csv");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  write_text(dir + "/q.csv", "\xEF\xBB\xBF" "0,1\n");
  EXPECT_EQ(run("verify --input " + testpaths::nine_csv() + " --pairs " + dir + "/q.csv").exit_code, 0);
}

TEST(VerifyCli, AMillionElementFileWithACycleIsRefusedAfterOneWalk) {
  // One row of a million elements, every y-list link to the element before, the first back to the last.
  const std::string dir = scratch_dir("verify_million_cycle");
  const int n = 1'000'000;
  std::string csv = "x,y,r\n", next;
  csv.reserve(static_cast<std::size_t>(n) * 14);
  for (int k = 0; k < n; ++k) csv += std::to_string(k % 1000) + ",0.5,0.5\n";
  next.reserve(static_cast<std::size_t>(n) * 8);
  for (int k = 0; k < n; ++k) next += (k ? "," : "") + std::to_string(k == 0 ? n - 1 : k - 1);
  write_text(dir + "/e.csv", csv);
  write_text(dir + "/a.json", "{\"algorithm\": \"nbs\", \"cell_size\": 1000, \"origin\": [0, 0], \"y_heads\": [" +
                                  std::to_string(n - 1) + "], \"y_next\": [" + next + "]}");
  const auto r = run("verify --input " + dir + "/e.csv --arrays " + dir + "/a.json");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.out.find("$.y_next[0]: y_heads[0] -> 999999 -> 999998 -> 999997 -> ... (999994 more) -> 2 -> 1 -> 0 -> 999999: a cycle"),
            std::string::npos) << r.out.substr(0, 300);
  EXPECT_NE(r.out.find("1 problem in the nbs arrays of 1000000 elements (1 cycle)"), std::string::npos) << r.out.substr(0, 600);
}

// ---- the first broken contract (docs/verify.md): verify leads with it, as headless does ----

// verify --arrays on a bundled planted-bug file (assets/examples/NAME), its output whole.
testcli::Result verify_example(const std::string& name) {
  return run("verify --input " + testpaths::nine_csv() + " --arrays " + std::string(NBSCOPE_SOURCE_DIR) + "/assets/examples/" + name);
}

TEST(VerifyCliContract, TheBundledPlantedBugsLeadWithTheContractTheyBreak) {
  const std::string dir = std::string(NBSCOPE_SOURCE_DIR) + "/assets/examples/";
  auto r = verify_example("nine_screen_bug.json");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.out, "nbscope verify: " + dir + "nine_screen_bug.json: contract list-cell broken: $.next[5]: E[5] = 3, but element 3 "
                   "lies in cell (4,6) and element 5 in cell (4,5)\n"
                   "nbscope verify: 1 problem in the screen arrays of 9 elements (1 wrong list): WRONG\n");
  r = verify_example("nine_screen_bug_book.json");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.out, "nbscope verify: " + dir + "nine_screen_bug_book.json: contract list-cell broken: $.next[5]: E[6] = 4, but "
                   "element 4 lies in cell (5,7) and element 6 in cell (5,6)\n"
                   "nbscope verify: 1 problem in the screen arrays of 9 elements (1 wrong list): WRONG\n");
  r = verify_example("nine_nbs_bug_base1.json");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.out, "nbscope verify: " + dir + "nine_nbs_bug_base1.json: contract cycle broken: $.y_next[6]: y_heads[7] -> 9 -> 7 -> 9: "
                   "a cycle (Y[7] = 9 leads back)\n"
                   "  $.y_next: y_heads[7]: 5 elements after the cut, 1, 2, 3, 4 and 5, are on no list\n"
                   "nbscope verify: 2 problems in the nbs arrays of 9 elements (1 cycle, 1 dropped): WRONG\n");
}

// The first line of verify --arrays on `doc`, from its contract on ("contract NAME broken: ...").
std::string lead_contract(const std::string& test, const json& doc, const std::string& flags = "") {
  const auto r = verify_arrays(test, doc, flags);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const std::string first = r.out.substr(0, r.out.find('\n'));
  const std::size_t at = first.find("contract ");
  return at == std::string::npos ? "(no contract) " + first : first.substr(at);
}

TEST(VerifyCliContract, EachMappedContractLeadsOnArraysThatBreakIt) {
  json d = nine_dump("screen");  // 0-based Fig. 3.20: C[4][6] -> 3 -> 1 -> 0, C[1][6] -> 8 -> 6 -> 4 -> 2
  d["next"][6] = 2;               // 4 skipped
  EXPECT_EQ(lead_contract("verify_contract_first_level", d),
            "contract first-level-once broken: $.next: element 4 is on no list, but lies in cell (1,6): C[1][6] misses it");
  d = nine_dump("screen");
  d["next"][1] = 3;
  EXPECT_EQ(lead_contract("verify_contract_cycle", d), "contract cycle broken: $.next[1]: C[4][6] -> 3 -> 1 -> 3: a cycle (E[1] = 3 leads back)");
  d = nine_dump("screen");
  d["next"][8] = 9;
  EXPECT_EQ(lead_contract("verify_contract_link", d), "contract list-link broken: $.next[8]: E[8] = 9, but elements are 0..8, and -1 ends a list");
  d = nine_dump("screen");
  d["next"][7] = 0;
  EXPECT_EQ(lead_contract("verify_contract_twice", d),
            "contract first-level-once broken: $.next[7]: E[7] = 0, but element 0 is already on C[4][6]'s list (an element is on one list only)");
  d = nine_dump("nbs");  // row 6's x-lists: x_heads[1] -> 2 -> 4 -> 6 -> 8, x_heads[4] -> 0 -> 1 -> 3
  for (json& row : d["rows"])
    if (row["iy"] == 6)
      for (json& p : row["x_next"])
        if (p[0] == 6) p[1] = -1;  // 8 left out of its cell's x-list
  EXPECT_EQ(lead_contract("verify_contract_cell_list", d),
            "contract cell-list broken: $.rows[1].x_next: row 6: element 8 is on no list, but lies in cell (1,6): x_heads[1] misses it");
}

TEST(VerifyCliContract, AProblemThatBreaksNoContractIsListedAfterTheOneThatDoes) {
  json d = nine_dump("screen");
  d["heads"][4][6] = 0;  // C[4][6] -> 0 -> 1 -> 3: not the book's order, found first (--exact)
  d["next"][0] = 1;
  d["next"][1] = 3;
  d["next"][3] = -1;
  d["heads"][5][5] = -1;  // 7 on no list
  const auto r = verify_arrays("verify_contract_after_order", d, " --exact");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const std::string first = r.out.substr(0, r.out.find('\n'));
  EXPECT_NE(first.find(": contract first-level-once broken: $.next: element 7 is on no list"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\n  $.next[0]: C[4][6] -> ... -> 0 -> 1: 1 follows 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2 problems in the screen arrays of 9 elements (1 dropped, 1 order): WRONG"), std::string::npos) << r.out;
  // Order alone breaks no contract: the first problem leads, named by no contract.
  d["heads"][5][5] = 7;
  EXPECT_EQ(lead_contract("verify_contract_order_only", d, " --exact").rfind("(no contract) ", 0), 0u);
}

TEST(VerifyCliContract, PairsNameNoContract) {
  const std::string dir = scratch_dir("verify_contract_pairs");
  write_text(dir + "/p.csv", "2 4\n");  // apart; the contact 1,2 missing
  const auto r = run("verify --input " + testpaths::nine_csv() + " --pairs " + dir + "/p.csv --base 1");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.out.find("broken"), std::string::npos) << r.out;
}

// ---- bad input: exit 2, one line naming the file and the JSON path ----

TEST(VerifyCli, BadInputNamesTheFileAndTheJsonPath) {
  const json good = nine_dump("screen");
  struct Case {
    std::string name;
    json doc;
    std::string flags;
    std::string message;  // after "nbscope: error: " and the file's path
  };
  json wrong_length = good, nested = good, dim = good, count = good, grid = good, small = good;
  wrong_length["heads"][3].erase(0);
  nested["heads"][2][2] = json::array({-1});
  dim["dim"] = 3;  // 3D arrays (said so, without the 2D origin that would contradict it first)
  dim.erase("origin");
  count["elements"] = 10;
  grid["cell_size"] = 0.1;  // smaller than the largest diameter, 0.2
  small["nx"] = 4;          // elements lie up to x = 5.2
  small["heads"] = json::array({good["heads"][0], good["heads"][1], good["heads"][2], good["heads"][3]});
  const std::vector<Case> cases{
      {"length", wrong_length, "", ": $.heads[3]: 9 entries, but ny is 10"},
      {"nested", nested, "", ": $.heads[2][2]: an array, but a number is expected (arrays of another dimension?)"},
      {"dim", dim, "", ": $.dim: 3D arrays, but " + testpaths::nine_csv() + " holds 2D elements"},
      {"count", count, "", ": $.elements: 10, but " + testpaths::nine_csv() + " has 9 elements"},
      {"cellsize", grid, "", ": the grid does not fit the elements: "},
      {"outside", small, "", ": the grid does not hold the elements: element 0 has x = 4.75, outside the 4 cells"},
      {"scene", json{{"name", "x"}, {"bodies", json::array()}}, "", ": $: a scene or a report, not arrays"},
      {"flag", good, " --cell-size 2", ""},
      {"algorithm", good, " --algorithm nbs", ""},
  };
  for (const Case& c : cases) {
    const auto r = verify_arrays("verify_bad_" + c.name, c.doc, c.flags);
    EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.out;
    EXPECT_TRUE(r.out.empty()) << c.name << ": " << r.out;
    EXPECT_EQ(r.err.rfind("nbscope: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    if (!c.message.empty()) {
      EXPECT_NE(r.err.find("arrays.json" + c.message), std::string::npos) << c.name << ": " << r.err;
    }
  }
  EXPECT_EQ(run("verify --input " + testpaths::nine_csv()).exit_code, 2);
  EXPECT_EQ(run("verify --input " + testpaths::nine_csv() + " --pairs a --arrays b").exit_code, 2);
}

}  // namespace
}  // namespace nbscope
