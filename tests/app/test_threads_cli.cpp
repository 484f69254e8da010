// --threads N on every command that detects: its refusals (one line, exit 2), and `pairs` on one and
// two threads on a set large enough to be cut into bands (2D and 3D): the same output, which is
// also sort's (an independent detector).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>

#include "core/threads.hpp"
#include "support/run_cli.hpp"

namespace nbscope {
namespace {

using testcli::read_text;
using testcli::run;
using testcli::scratch_dir;
using testcli::write_text;

// "nbscope: error: --threads: ..." alone on stderr, exit 2.
void expect_refused(const std::string& args) {
  const auto r = run(args);
  EXPECT_EQ(r.exit_code, 2) << args;
  EXPECT_EQ(r.err.rfind("nbscope: error: --threads: ", 0), 0u) << args << ": " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.out, "") << args;
}

TEST(ThreadsCli, AnythingButAWholeNumberFromOneToTheMostIsRefused) {
  for (const char* bad : {"0", "-1", "two", "65", "''", "2.5"}) expect_refused(std::string("pairs --threads ") + bad + " --input x.csv");
  // Every other command that detects takes it through the same parser, before any other work.
  for (const char* command : {"headless", "replay x.nbsrec", "verify", "scaling --n 100"})
    expect_refused(std::string(command) + " --threads " + std::to_string(kMaxThreads + 1));
#ifdef NBSCOPE_TEST_GUI  // without the window, gui refuses itself first (NBSCOPE_GUI=OFF, the ASan build)
  expect_refused("gui --frames 1 --threads " + std::to_string(kMaxThreads + 1));
#endif
  // dump's arrays are its traced run, the book's serial loops: no threads to choose.
  const auto dump = run("dump --threads 2");
  EXPECT_EQ(dump.exit_code, 2);
  EXPECT_EQ(dump.err.rfind("nbscope: error: dump: --threads is not an option of dump", 0), 0u) << dump.err;
}

// `n` elements (x,y,r or x,y,z,r) of radius 0.3..0.5 at about one contact each, at random.
std::string random_elements(int n, int dim) {
  std::mt19937 rng(7);
  const double side = dim == 2 ? std::sqrt(n * 1.6) : std::cbrt(n * 1.4);
  std::uniform_real_distribution<double> at(0.0, side), radius(0.3, 0.5);
  std::string text = dim == 2 ? "x,y,r\n" : "x,y,z,r\n";
  char line[128];
  for (int k = 0; k < n; ++k) {
    const double x = at(rng), y = at(rng), z = at(rng), r = radius(rng);
    if (dim == 2) std::snprintf(line, sizeof line, "%.6f,%.6f,%.4f\n", x, y, r);
    else std::snprintf(line, sizeof line, "%.6f,%.6f,%.6f,%.4f\n", x, y, z, r);
    text += line;
  }
  return text;
}

TEST(ThreadsCli, PairsAreTheSameOnOneAndTwoThreadsAndSortsToo) {
  const std::string dir = scratch_dir("threads_pairs");
  // Two bands' worth at the least: below 2 * kMinBandElements the detection would stay on one thread.
  const int n = static_cast<int>(2 * kMinBandElements + 4000);
  for (int dim : {2, 3}) {
    SCOPED_TRACE(dim);
    const std::string input = dir + "/e" + std::to_string(dim) + ".csv";
    write_text(input, random_elements(n, dim));
    const auto one = run("pairs --input '" + input + "' --threads 1");
    const auto two = run("pairs --input '" + input + "' --threads 2");
    const auto sort = run("pairs --input '" + input + "' --algorithm sort --threads 2");
    ASSERT_EQ(one.exit_code, 0) << one.err;
    ASSERT_EQ(two.exit_code, 0) << two.err;
    ASSERT_EQ(sort.exit_code, 0) << sort.err;
    EXPECT_GT(std::count(one.out.begin(), one.out.end(), '\n'), n / 4) << "too few contacts to mean anything";
    EXPECT_EQ(two.out, one.out);
    EXPECT_EQ(sort.out, one.out);
  }
}

TEST(ThreadsCli, AHeadlessRunOnTwoThreadsHolds) {
  const std::string scene = std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/book-fig-3-15.json";
  const auto r = run("headless --scene '" + scene + "' --frames 3 --threads 2 --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

}  // namespace
}  // namespace nbscope
