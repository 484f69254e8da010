// `nbscope scaling` end to end (a small range, as CI runs it): one CSV row per (detector, layout,
// N), the table on stdout, bad flags as one line and exit 2; `nbscope headless --scaling`'s bad
// input (a bad CSV names its line, no screenshot, plan flags without `run`).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>
#include <tuple>

#include "support/run_cli.hpp"

namespace nbscope {
namespace {

using testcli::read_text;
using testcli::run;
using testcli::scratch_dir;
using testcli::write_text;

const std::string kHeader = "algorithm,layout,n,ns_per_element,bytes_per_element,pairs,repeats,threads";

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, kHeader);
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::istringstream f(line);
    std::string field;
    while (std::getline(f, field, ',')) fields.push_back(field);
    rows.push_back(fields);
  }
  return rows;
}

TEST(ScalingCli, OneRowPerDetectorThreadsLayoutAndSize) {
  const std::string dir = scratch_dir("scaling_cli");
  const auto r = run("scaling --algorithm nbs,sort --layout loose,dense --n 1000..4000 --points-per-decade 1 --threads 2 --output '" + dir + "/x.csv'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = csv_rows(read_text(dir + "/x.csv"));
  std::set<std::tuple<std::string, std::string, std::string, std::string>> got;
  for (const auto& row : rows) {
    ASSERT_EQ(row.size(), 8u);
    EXPECT_TRUE(got.emplace(row[0], row[7], row[1], row[2]).second) << row[0] << " " << row[1] << " " << row[2] << " twice";
  }
  // --n 1000..4000 at 1 point a decade: 1000 and the end, 4000; nbs on 1 and 2 threads, sort on 1.
  std::set<std::tuple<std::string, std::string, std::string, std::string>> expected;
  for (const auto& [a, t] : {std::pair{"nbs", "1"}, std::pair{"nbs", "2"}, std::pair{"sort", "1"}})
    for (const char* l : {"loose", "dense"})
      for (const char* n : {"1000", "4000"}) expected.emplace(a, t, l, n);
  EXPECT_EQ(got, expected);
  EXPECT_NE(r.out.find("threads"), std::string::npos) << r.out;  // the table's column
  // The table on stdout: a header line and one line per row.
  std::istringstream out(r.out);
  std::string line;
  std::size_t lines = 0;
  while (std::getline(out, line)) ++lines;
  EXPECT_EQ(lines, rows.size() + 1) << r.out;

  // --threads 1: one series of nbs.
  const auto one = run("scaling --algorithm nbs --n 100 --threads 1 --quiet --output '" + dir + "/one.csv'");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const auto one_rows = csv_rows(read_text(dir + "/one.csv"));
  ASSERT_EQ(one_rows.size(), 1u);
  EXPECT_EQ(one_rows[0][7], "1");
}

// --touching, as on every command that detects (README): on the `touching` layout (a 10 x 10 lattice
// of unit spacing and radius 0.5) the 180 lattice neighbours touch exactly, so strict finds none.
TEST(ScalingCli, TouchingStrictTimesTheStrictContactTest) {
  const std::string dir = scratch_dir("scaling_cli_touching");
  for (const auto& [touching, pairs] : {std::pair{"inclusive", "180"}, std::pair{"strict", "0"}}) {
    const std::string csv = dir + "/" + touching + ".csv";
    const auto r = run("scaling --algorithm nbs,brute --layout touching --n 100 --threads 1 --quiet --touching " + std::string(touching) +
                       " --output '" + csv + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto rows = csv_rows(read_text(csv));
    ASSERT_EQ(rows.size(), 2u);
    for (const auto& row : rows) EXPECT_EQ(row[5], pairs) << touching << ": " << row[0];
  }
}

TEST(ScalingCli, BruteIsSkippedAboveItsCapAndSaysSo) {
  const std::string dir = scratch_dir("scaling_cli_brute");
  const auto r = run("scaling --algorithm brute,nbs --n 1e4..2e4 --points-per-decade 1 --threads 1 --quiet --output '" + dir + "/b.csv'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::set<std::string> brute_sizes;
  for (const auto& row : csv_rows(read_text(dir + "/b.csv")))
    if (row[0] == "brute") brute_sizes.insert(row[2]);
  EXPECT_EQ(brute_sizes, (std::set<std::string>{"10000"}));
  EXPECT_NE(r.out.find("note: brute loose N=20000: skipped"), std::string::npos) << r.out;
}

TEST(ScalingCli, BadFlagsAreOneLineAndExit2) {
  const std::string dir = scratch_dir("scaling_cli_bad");
  const std::pair<std::string, std::string> cases[] = {
      {"--algorithm nosuch", "nbscope: error: --algorithm: unknown algorithm 'nosuch'"},
      {"--algorithm nbs,nbs", "nbscope: error: --algorithm: 'nbs' named twice"},
      {"--layout one_point", "nbscope: error: --layout: 'one_point' is not one of loose, dense"},
      {"--n 4000..1000", "nbscope: error: --n: '4000..1000' goes down"},
      {"--n 1000..lots", "nbscope: error: --n: '1000..lots' is not MIN..MAX"},
      {"--n 0..10", "nbscope: error: --n: '0..10' is not MIN..MAX"},
      {"--points-per-decade 0", "nbscope: error: --points-per-decade: '0' is not a whole number from 1 to 20"},
      {"--report r.json", "nbscope: error: scaling: --report is not an option of scaling"},
      {"--output '" + dir + "/no/such/dir/x.csv'", "nbscope: error: " + dir + "/no/such/dir/x.csv: cannot write"},
  };
  for (const auto& [flags, message] : cases) {
    const auto r = run("scaling " + std::string(flags.rfind("--n ", 0) == 0 ? "" : "--n 100 ") + flags);
    EXPECT_EQ(r.exit_code, 2) << flags;
    EXPECT_EQ(r.err.rfind(message, 0), 0u) << flags << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

#ifdef NBSCOPE_TEST_GUI
TEST(ScalingCli, HeadlessRefusesABadCsvByItsLine) {
  const std::string dir = scratch_dir("scaling_headless_bad");
  write_text(dir + "/bad.csv", kHeader + "\nnbs,loose,1000,20,8,90,10,1\nnbs,loose,2000,20,8,90,10\n");
  const std::string scene = "--scene '" + std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/book-fig-3-15.json' --frames 1 ";
  auto r = run("headless " + scene + "--scaling '" + dir + "/bad.csv' --screenshot '" + dir + "/s.png'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("nbscope: error: " + dir + "/bad.csv:3: 7 columns", 0), 0u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/s.png"));
  r = run("headless " + scene + "--scaling '" + dir + "/bad.csv'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "nbscope: error: --scaling: needs --screenshot (headless draws nothing without one)\n");
  r = run("headless " + scene + "--scaling '" + dir + "/bad.csv' --layout dense --screenshot '" + dir + "/s.png'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "nbscope: error: --layout: only with --scaling run\n");
}

TEST(ScalingCli, HeadlessRunsAPlanBeforeTheScreenshot) {
  const std::string dir = scratch_dir("scaling_headless_run");
  const std::string scene = "--scene '" + std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/book-fig-3-15.json' --frames 1 ";
  const auto r = run("headless " + scene + "--scaling run --algorithm nbs,sort --n 100..300 --no-timings --quiet --screenshot '" +
                     dir + "/s.png'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/s.png"));
}
#endif

}  // namespace
}  // namespace nbscope
