// ELEMENTS.csv parsing and PAIRS.csv writing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "core/error.hpp"
#include "io/csv.hpp"
#include "io/input_file.hpp"

namespace nbscope {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_elements_csv(text, "in.csv");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ElementsCsv, Reads2DWithHeaderCommentsAndBlankLines) {
  const Elements e = parse_elements_csv("# a comment\nx,y,r\n\n1, 2, 0.5  # trailing\n-3e2,4.25,1\n", "in.csv");
  EXPECT_EQ(e.dim, 2);
  ASSERT_EQ(e.size(), 2);
  EXPECT_DOUBLE_EQ(e.x[1], -300);
  EXPECT_DOUBLE_EQ(e.y[0], 2);
  EXPECT_DOUBLE_EQ(e.r[1], 1);
}

TEST(ElementsCsv, Reads3D) {
  const Elements e = parse_elements_csv("1,2,3,0.5\n4,5,6,0.25", "in.csv");
  EXPECT_EQ(e.dim, 3);
  ASSERT_EQ(e.size(), 2);
  EXPECT_DOUBLE_EQ(e.z[1], 6);
  EXPECT_DOUBLE_EQ(e.r[1], 0.25);
}

TEST(ElementsCsv, SkipsAByteOrderMarkAndCarriageReturns) {
  const Elements e = parse_elements_csv("\xEF\xBB\xBFx,y,r\r\n1,2,0.5\r\n3,4,1\r\n", "in.csv");
  ASSERT_EQ(e.size(), 2);
  EXPECT_DOUBLE_EQ(e.x[1], 3);
  EXPECT_DOUBLE_EQ(e.r[1], 1);
  EXPECT_EQ(error_of("\xEF\xBB\xBF\n"), "in.csv:1: empty file (expected rows of x,y,r or x,y,z,r)");
}

TEST(ElementsCsv, HeaderOnlyIsAValidEmptySet) {
  EXPECT_EQ(parse_elements_csv("x,y,r\n", "in.csv").size(), 0);
  EXPECT_EQ(parse_elements_csv("# nothing here\n", "in.csv").size(), 0);
}

TEST(ElementsCsv, EveryBadRowNamesFileLineAndWhat) {
  EXPECT_EQ(error_of(""), "in.csv:1: empty file (expected rows of x,y,r or x,y,z,r)");
  EXPECT_EQ(error_of("1,2\n"), "in.csv:1: 2 columns; expected 3 (x,y,r) or 4 (x,y,z,r)");
  EXPECT_EQ(error_of("1\n"), "in.csv:1: 1 column; expected 3 (x,y,r) or 4 (x,y,z,r)");
  EXPECT_EQ(error_of("1,2,3\n1,2,3,4,5\n"), "in.csv:2: 5 columns; expected 3 (x,y,r) or 4 (x,y,z,r)");
  EXPECT_EQ(error_of("x,y,r\n1,abc,1\n"), "in.csv:2: y: 'abc' is not a number");
  EXPECT_EQ(error_of("1,2,1\n\n1,nan,1\n"), "in.csv:3: y: 'nan' is not a finite number");
  EXPECT_EQ(error_of("inf,2,1\n"), "in.csv:1: x: 'inf' is not a finite number");
  EXPECT_EQ(error_of("1,2,1e999\n"), "in.csv:1: r: '1e999' is not a finite number");
  EXPECT_EQ(error_of("1,2,0\n"), "in.csv:1: r: radius must be > 0, got 0");
  EXPECT_EQ(error_of("1,2,-1\n"), "in.csv:1: r: radius must be > 0, got -1");
  EXPECT_EQ(error_of("1,2,3\n1,2,3,4\n"), "in.csv:2: 4 columns, but the first row had 3");
  EXPECT_EQ(error_of("1,,3\n"), "in.csv:1: column 2 (y) is empty");
  EXPECT_EQ(error_of("0,0,0.5,\n"), "in.csv:1: column 4 (r) is empty (a trailing comma?)");
  EXPECT_EQ(error_of("x,y,z,r\n1,2,3\n"), "in.csv:2: 3 columns, but the header on line 1 has 4");
  EXPECT_EQ(error_of("1e101,0,1\n"), "in.csv:1: x: 1e101 is outside the supported coordinates -1e100 to 1e100");
  EXPECT_EQ(error_of("0,0,1e-101\n"), "in.csv:1: r: 1e-101 is outside the supported radii 1e-100 to 1e100");
  EXPECT_EQ(error_of("0,0,1e-309\n"), "in.csv:1: r: 1e-309 is outside the supported radii 1e-100 to 1e100");
  EXPECT_EQ(error_of("1,2,3x\n"), "in.csv:1: r: '3x' is not a number");
}

TEST(ElementsCsv, MissingFileIsAnError) {
  EXPECT_THROW(read_elements_csv("/nonexistent/dir/e.csv"), Error);
}

TEST(PairsCsv, WritesHeaderAndPairsAndLeavesNoTemporary) {
  const auto dir = std::filesystem::temp_directory_path() / ("nbscope_csv_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "p.csv").string();
  write_pairs_csv(path, {{0, 1}, {2, 5}});
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(ss.str(), "i,j\n0,1\n2,5\n");
  int files = 0;
  for ([[maybe_unused]] const auto& f : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
  std::filesystem::remove_all(dir);
}

TEST(PairsCsv, UnwritablePathThrowsAndCreatesNothing) {
  EXPECT_THROW(write_pairs_csv("/nonexistent/dir/p.csv", {{0, 1}}), Error);
  EXPECT_FALSE(std::filesystem::exists("/nonexistent/dir/p.csv"));
}

// ---- reading input files --------------------------------------------------------------------

std::string read_error(const std::string& path, std::size_t max_bytes) {
  try {
    read_input_file(path, "elements file", max_bytes);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(InputFile, ReadsAFileWholeUpToItsLimit) {
  const auto path = (std::filesystem::temp_directory_path() / ("nbscope-input-" + std::to_string(::getpid()))).string();
  std::ofstream(path) << "0,0,1\n";
  EXPECT_EQ(read_input_file(path, "elements file", 6), "0,0,1\n");
  EXPECT_EQ(read_error(path, 5), path + ": larger than 5 bytes, the limit for an elements file");
  std::filesystem::remove(path);
}

TEST(InputFile, AnEndlessDeviceOfZerosStopsAtItsFirstByteInsteadOfFillingMemory) {
  // (An endless pipe of text stops at the size limit: tests/io/test_hostile_input.cpp.)
  EXPECT_EQ(read_error("/dev/zero", std::size_t{4} << 20),
            "/dev/zero:1: a NUL byte (byte 0): an elements file is text, this is binary data (or UTF-16 text: save it as UTF-8)");
}

TEST(InputFile, MissingEmptyPathAndDirectoryAreNamed) {
  EXPECT_EQ(read_error("/nonexistent/x.csv", 100), "/nonexistent/x.csv: cannot open the elements file (no such file or not readable)");
  EXPECT_EQ(read_error("", 100), "elements file path is empty");
  EXPECT_EQ(read_error("/tmp", 100), "/tmp: is a directory, not an elements file");
}

}  // namespace
}  // namespace nbscope
