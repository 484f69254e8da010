// `nbscope dump` through the binary: the book's Fig. 3.20, every algorithm's arrays checked against
// cells computed here from the CSV's coordinates, the screen limit, and every bad input.
//
// Index: helpers (run + parse, cells from the dump's grid) | Fig. 3.20 | lists cover every element
// in its own cell (and the checker's fault test) | screen limit vs nbs | bad input.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>

#include "support/paths.hpp"
#include "support/run_cli.hpp"

namespace nbscope {
namespace {

using nlohmann::json;
using testcli::run;
using testcli::scratch_dir;
using testcli::write_text;


json dump(const std::string& args) {
  const auto r = run("dump " + args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  return json::parse(r.out);
}

struct Point {
  double c[3] = {0, 0, 0};
};

// Random elements written as CSV; returns their centres.
std::vector<Point> write_random(const std::string& path, int n, int dim, double side, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, side);
  std::ostringstream csv;
  csv.precision(17);
  csv << (dim == 3 ? "x,y,z,r\n" : "x,y,r\n");
  std::vector<Point> out;
  for (int i = 0; i < n; ++i) {
    Point p;
    for (int a = 0; a < dim; ++a) {
      p.c[a] = u(rng);
      csv << p.c[a] << ",";
    }
    csv << 0.3 + 0.2 * u(rng) / side << "\n";
    out.push_back(p);
  }
  write_text(path, csv.str());
  return out;
}

// The cell of a centre on axis a, from the grid the dump reports: Int((v - origin)/d), clamped.
int cell(const json& d, const Point& p, int a) {
  const char* n[3] = {"nx", "ny", "nz"};
  const double c = std::floor((p.c[a] - d["origin"][a].get<double>()) / d["cell_size"].get<double>());
  return static_cast<int>(std::clamp(c, 0.0, d[n[a]].get<double>() - 1));
}

std::vector<int> walk(int head, const json& next) {
  std::vector<int> out;
  for (int k = head; k != -1 && out.size() <= next.size(); k = next[k].get<int>()) out.push_back(k);
  return out;
}

// Walks a sparse [[k, next]] list from head.
std::vector<int> walk_pairs(int head, const json& pairs) {
  std::map<int, int> next;
  for (const json& p : pairs) next[p[0].get<int>()] = p[1].get<int>();
  std::vector<int> out;
  for (int k = head; k != -1 && out.size() <= pairs.size() && next.count(k); k = next[k]) out.push_back(k);
  return out;
}

// ---------------------------------------------------------------------------------------------

// Fig. 3.20: C[5][7] = 4, C[5][6] = 6, C[6][6] = 8, C[2][7] = 9 and E = -1 1 -1 2 3 -1 5 -1 7 (1-based).
TEST(Dump, ScreenGivesFig3_20OnTheBooksTenByTenGrid) {
  const json d = dump("--input '" + testpaths::nine_csv() + "' --algorithm screen --cell-size 1 --origin 0,0 --cells 10,10");
  EXPECT_EQ(d["algorithm"], "screen");
  EXPECT_EQ(d["nx"], 10);
  EXPECT_EQ(d["ny"], 10);
  EXPECT_EQ(d["cell_size"], 1.0);
  EXPECT_EQ(d["origin"], json::array({0.0, 0.0}));
  const json& c = d["heads"];
  ASSERT_EQ(c.size(), 10u);
  EXPECT_EQ(c[5 - 1][7 - 1], 4 - 1);
  EXPECT_EQ(c[5 - 1][6 - 1], 6 - 1);
  EXPECT_EQ(c[6 - 1][6 - 1], 8 - 1);
  EXPECT_EQ(c[2 - 1][7 - 1], 9 - 1);
  int empty = 0;
  for (const json& column : c) {
    ASSERT_EQ(column.size(), 10u);
    for (const json& h : column) empty += h == -1;
  }
  EXPECT_EQ(empty, 96);
  EXPECT_EQ(d["next"], json::array({-1, 0, -1, 1, 2, -1, 4, -1, 6}));
  EXPECT_EQ(d["bytes"]["C"], 400);
  EXPECT_EQ(d["bytes"]["E"], 36);
  EXPECT_EQ(d["own_bytes"], 436);
  EXPECT_EQ(d["pairs"], 1);
}

TEST(Dump, WithoutPinnedCellsTheGridJustCoversTheCentres) {
  const json d = dump("--input '" + testpaths::nine_csv() + "' --algorithm screen --cell-size 1 --origin 0,0");
  EXPECT_EQ(d["nx"], 6);  // Int(5.2) + 1
  EXPECT_EQ(d["ny"], 7);  // Int(6.85) + 1
  EXPECT_EQ(d["heads"][1][6], 8);
  EXPECT_EQ(d["next"], json::array({-1, 0, -1, 1, 2, -1, 4, -1, 6}));
}

// ---------------------------------------------------------------------------------------------
// Every element in exactly one list, the list of its own cell (cells computed here).

::testing::AssertionResult lists_cover_elements(const json& d, const std::vector<Point>& pts) {
  const std::string algo = d["algorithm"];
  const int dim = d["dim"];
  std::map<int, int> seen;  // element -> times seen
  std::string bad;
  auto in_cell = [&](int k, int ix, int iy, int iz) {
    ++seen[k];
    if (cell(d, pts[k], 0) != ix || (iy >= 0 && cell(d, pts[k], 1) != iy) || (iz >= 0 && cell(d, pts[k], 2) != iz))
      bad = "element " + std::to_string(k) + " is listed in the wrong cell";
  };
  if (algo == "screen") {
    for (std::size_t ix = 0; ix < d["heads"].size(); ++ix)
      for (std::size_t iy = 0; iy < d["heads"][ix].size(); ++iy) {
        const json& h = d["heads"][ix][iy];
        if (dim == 2) {
          for (int k : walk(h, d["next"])) in_cell(k, int(ix), int(iy), -1);
        } else {
          for (std::size_t iz = 0; iz < h.size(); ++iz)
            for (int k : walk(h[iz], d["next"])) in_cell(k, int(ix), int(iy), int(iz));
        }
      }
  } else if (algo == "tree") {
    for (const json& leaf : d["leaves"])
      for (int k : walk(leaf["head"], d["next"]))
        in_cell(k, leaf["cell"][0], leaf["cell"][1], dim == 3 ? leaf["cell"][2].get<int>() : -1);
  } else if (algo == "sort") {
    for (std::size_t p = 0; p < d["order"].size(); ++p) {
      const json& key = d["keys"][p];
      in_cell(d["order"][p], key[0], key[1], dim == 3 ? key[2].get<int>() : -1);
      if (p > 0 && !(d["keys"][p - 1] <= key)) bad = "keys not sorted at " + std::to_string(p);
    }
  } else if (algo == "nbs" && dim == 2) {
    std::map<int, int> rows_seen;
    for (std::size_t iy = 0; iy < d["y_heads"].size(); ++iy)
      for (int k : walk(d["y_heads"][iy], d["y_next"])) {
        ++rows_seen[k];
        if (cell(d, pts[k], 1) != int(iy)) bad = "element " + std::to_string(k) + " in the wrong y-list";
      }
    if (rows_seen.size() != pts.size()) bad = "the y-lists miss elements";
    for (const json& row : d["rows"])
      for (const json& h : row["x_heads"]) for (int k : walk_pairs(h[1], row["x_next"])) in_cell(k, h[0], row["iy"], -1);
  } else if (algo == "nbs") {
    for (std::size_t iz = 0; iz < d["z_heads"].size(); ++iz)
      for (int k : walk(d["z_heads"][iz], d["z_next"]))
        if (cell(d, pts[k], 2) != int(iz)) bad = "element " + std::to_string(k) + " in the wrong z-list";
    for (const json& layer : d["layers"]) {
      for (const json& h : layer["y_heads"])
        for (int k : walk_pairs(h[1], layer["y_next"]))
          if (cell(d, pts[k], 1) != h[0].get<int>() || cell(d, pts[k], 2) != layer["iz"].get<int>()) bad = "wrong y-list";
      for (const json& row : layer["rows"])
        for (const json& h : row["x_heads"])
          for (int k : walk_pairs(h[1], row["x_next"])) in_cell(k, h[0], row["iy"], layer["iz"]);
    }
  }
  if (!bad.empty()) return ::testing::AssertionFailure() << algo << ": " << bad;
  for (std::size_t k = 0; k < pts.size(); ++k)
    if (seen[int(k)] != 1) return ::testing::AssertionFailure() << algo << ": element " << k << " listed " << seen[int(k)] << " times";
  long long sum = 0;
  for (const auto& [name, bytes] : d["bytes"].items()) sum += bytes.get<long long>();
  if (sum != d["own_bytes"].get<long long>()) return ::testing::AssertionFailure() << algo << ": bytes do not add up to own_bytes";
  return ::testing::AssertionSuccess();
}

TEST(Dump, EveryAlgorithmListsEveryElementOnceInItsOwnCell) {
  const std::string dir = scratch_dir("dump_cover");
  for (int dim : {2, 3}) {
    const std::string in = dir + "/in" + std::to_string(dim) + ".csv";
    const auto pts = write_random(in, 300, dim, dim == 2 ? 20.0 : 7.0, 5 + dim);
    for (const char* algo : {"screen", "tree", "sort", "nbs"}) {
      const json d = dump("--input '" + in + "' --algorithm " + algo);
      EXPECT_EQ(d["dim"], dim);
      EXPECT_EQ(d["elements"], 300);
      EXPECT_TRUE(lists_cover_elements(d, pts)) << dim << "D";
    }
  }
}

TEST(Dump, TheCoverCheckCatchesAMovedAndALostElement) {
  const std::string dir = scratch_dir("dump_cover_fault");
  const auto pts = write_random(dir + "/in.csv", 200, 2, 15.0, 3);
  for (const char* algo : {"screen", "nbs"}) {
    json d = dump("--input '" + dir + "/in.csv' --algorithm " + algo);
    ASSERT_TRUE(lists_cover_elements(d, pts));
    json& next = std::string(algo) == "screen" ? d["next"] : d["y_next"];
    // Cut one list short: its tail elements vanish.
    for (std::size_t k = 0; k < next.size(); ++k) {
      if (next[k] != -1) {
        next[k] = -1;
        break;
      }
    }
    EXPECT_FALSE(lists_cover_elements(d, pts)) << algo;
  }
  json d = dump("--input '" + dir + "/in.csv' --algorithm tree");
  d["leaves"][0]["cell"][0] = d["leaves"][0]["cell"][0].get<int>() + 1;  // a leaf in the wrong place
  EXPECT_FALSE(lists_cover_elements(d, pts));
}

// ---------------------------------------------------------------------------------------------

TEST(Dump, ScreenRefusesASparseWorldThatNbsHandles) {
  const std::string dir = scratch_dir("dump_sparse");
  write_text(dir + "/sparse.csv", "x,y,r\n0,0,0.5\n10000,10000,0.5\n0.5,0.5,0.5\n");  // 10001 x 10001 cells
  for (const std::string cmd : {"dump", "pairs"}) {
    const auto r = run(cmd + " --input '" + dir + "/sparse.csv' --algorithm screen");
    EXPECT_EQ(r.exit_code, 2) << cmd;
    EXPECT_TRUE(r.out.empty()) << cmd;
    EXPECT_EQ(r.err.rfind("nbscope: error: " + dir + "/sparse.csv: screen: the screen array C[nx][ny] would need 10001 x 10001 = 100020001 cells", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("use --algorithm nbs"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const auto ok = run("pairs --input '" + dir + "/sparse.csv' --algorithm nbs");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(ok.out, "i,j\n0,2\n");
  // The book's ny + 2nx + 2N integers, (10001 + 20002 + 6) * 4 bytes, and the fast path's scratch
  // (nbs.hpp): the rows' counts and ends (ny integers), the order, each element's place and X in
  // list order (3N integers), the records (3N doubles) and two row buffers of at most N 64-byte slots.
  const std::size_t at = ok.err.find(" bytes of own arrays");
  ASSERT_NE(at, std::string::npos) << ok.err;
  const std::size_t from = ok.err.rfind(", ", at) + 2;
  const long bytes = std::stol(ok.err.substr(from, at - from));
  EXPECT_GE(bytes, 120036) << ok.err;
  EXPECT_LE(bytes, 120036 + 4 * 10001 + 4 * 3 * 3 + 8 * 3 * 3 + 2 * 3 * 64) << ok.err;
  // dump runs the book's loops, which need nothing beside the book's arrays.
  const json d = dump("--input '" + dir + "/sparse.csv' --algorithm nbs");
  EXPECT_EQ(d["own_bytes"], 120036);
}

// ---------------------------------------------------------------------------------------------
// Memory: dump's peak grows by the arrays it shows, not by a log of the run or a document of the dump.

// Peak resident memory, in KB, of `nbscope ARGS` with stdout to `out` (waited for with wait4).
long peak_rss_kb(const std::vector<std::string>& args, const std::string& out, int* exit_code) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 1);
    std::vector<char*> argv{const_cast<char*>(testcli::binary().c_str())};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    std::_Exit(127);
  }
  int status = 0;
  struct rusage ru {};
  ::wait4(pid, &status, 0, &ru);
  *exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return ru.ru_maxrss;
}

TEST(Dump, PeakMemoryIsTheArraysNotALogOfTheRunOrADocument) {
#ifdef NBSCOPE_SANITIZED_BUILD
  GTEST_SKIP() << "the sanitizers' shadow memory and quarantine make RSS meaningless";
#endif
  const std::string dir = scratch_dir("dump_memory");
  const int n = 200'000;
  write_random(dir + "/in.csv", n, 2, 600, 11);
  int code = -1;
  const long kb = peak_rss_kb({"dump", "--input", dir + "/in.csv", "--algorithm", "nbs"}, dir + "/out.json", &code);
  ASSERT_EQ(code, 0);
  // Its arrays and each row's lists are some 100 bytes an element; the log of the run took 440 and a
  // document of the dump some 500 more (190 MB here).
  EXPECT_LT(kb * 1024, 40'000'000 + 250L * n) << kb << " KB for " << n << " elements";
  EXPECT_EQ(json::parse(testcli::read_text(dir + "/out.json"))["elements"], n);
}

struct BadDump {
  const char* name;
  const char* args;     // after "dump --input IN"
  const char* message;  // expected after "nbscope: error: "
};

void PrintTo(const BadDump& c, std::ostream* os) { *os << c.name; }

class DumpBadInput : public ::testing::TestWithParam<BadDump> {};

TEST_P(DumpBadInput, ExitsTwoWithOneLine) {
  const BadDump& c = GetParam();
  const std::string dir = scratch_dir(std::string("dump_bad_") + c.name);
  write_text(dir + "/in.csv", "x,y,r\n1,2,0.5\n2,2,0.5\n");
  write_text(dir + "/in3.csv", "x,y,z,r\n1,2,3,0.5\n");
  std::string args = c.args;
  if (const auto p = args.find("IN3"); p != std::string::npos) args.replace(p, 3, "'" + dir + "/in3.csv'");
  const auto r = run("dump " + (args.rfind("--input", 0) == 0 ? args : "--input '" + dir + "/in.csv' " + args));
  EXPECT_EQ(r.exit_code, 2);
  std::string expected = std::string("nbscope: error: ") + c.message + "\n";
  if (const auto p = expected.find("IN:"); p != std::string::npos) expected.replace(p, 2, dir + "/in.csv");
  if (const auto p = expected.find("ALGOS"); p != std::string::npos) {
    EXPECT_EQ(r.err.substr(0, p), expected.substr(0, p));  // the list grows with the registry
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  } else {
    EXPECT_EQ(r.err, expected);
  }
  EXPECT_TRUE(r.out.empty());
}

const BadDump kBadDumps[] = {
    {"no_algorithm", "", "dump: --algorithm NAME is required (one of: brute, tree, sort, screen, nbs, ALGOS)"},
    {"unknown_algorithm", "--algorithm quick", "unknown algorithm 'quick' (known: brute, tree, sort, screen, nbs, ALGOS)"},
    {"bad_format", "--algorithm nbs --format xml", "dump: --format: 'xml' is not a known format (json)"},
    {"bad_cells", "--algorithm nbs --cells 10,0", "--cells: '10,0' is not NX,NY or NX,NY,NZ of whole numbers >= 1"},
    {"fractional_cells", "--algorithm nbs --cells 10,2.5", "--cells: '10,2.5' is not NX,NY or NX,NY,NZ of whole numbers >= 1"},
    {"cells_3d_for_2d", "--algorithm nbs --cells 10,10,10", "--cells: '10,10,10' has 3 counts, the elements are 2D"},
    {"origin_2d_for_3d", "--input IN3 --algorithm nbs --origin 0,0", "--origin: '0,0' has 2 coordinates, the elements are 3D"},
    {"small_cell", "--algorithm screen --cell-size 0.5",
     "IN: cell size 0.5 is smaller than the largest diameter 1 (contacts could span more than one cell)"},
    {"unknown_flag", "--algorithm nbs --verbose", "dump: --verbose is not an option of dump (see nbscope --help)"},
};

INSTANTIATE_TEST_SUITE_P(Dump, DumpBadInput, ::testing::ValuesIn(kBadDumps), [](const auto& info) { return info.param.name; });

TEST(Dump, MissingInputFileAndFlag) {
  auto r = run("dump --algorithm nbs");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "nbscope: error: dump: --input ELEMENTS.csv is required\n");
  r = run("dump --algorithm nbs --input /nonexistent/x.csv");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("nbscope: error: /nonexistent/x.csv:", 0), 0u) << r.err;
}

}  // namespace
}  // namespace nbscope
