// The .nbsrec format (io/recording.hpp): exact round trips of doubles, the header's grid, and every
// kind of bad input named by file and line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include "core/error.hpp"
#include "io/recording.hpp"

namespace nbscope {
namespace {

namespace fs = std::filesystem;

std::string temp_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("nbscope-recording-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

// Bit patterns, not values: -0.0 and 0.0 differ here, and so would any rounding.
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Doubles that stress a decimal round trip: random bits over many exponents, subnormals, the
// extremes of the supported magnitudes (core/elements.hpp).
Elements awkward_elements(std::uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  Elements e;
  e.dim = 2;
  auto any_double = [&] {
    for (;;) {
      const std::uint64_t bits = rng();
      double v;
      std::memcpy(&v, &bits, sizeof v);
      if (std::abs(v) <= kMaxCoordinate) return v;  // also refuses NaN and Inf
    }
  };
  for (int k = 0; k < n; ++k) {
    const double x = k == 0 ? std::numeric_limits<double>::denorm_min() : (k == 1 ? -0.0 : any_double());
    const double y = k == 2 ? kMaxCoordinate : std::ldexp(static_cast<double>(rng() >> 11), -40) - 1e3;
    double r = std::max(std::ldexp(static_cast<double>(rng() >> 11), -53), kMinRadius);
    if (k == 3) r = 0.1 + 0.2;  // 0.30000000000000004
    e.push_back(x, y, 0, r);
  }
  return e;
}

TEST(Recording, WriterThenReaderGivesBitIdenticalFramesAndGrid) {
  const std::string dir = temp_dir("roundtrip");
  const std::string path = dir + "/run.nbsrec";
  GridOptions grid;
  grid.cell_size = 1.0 / 3.0 * 7;  // not a short decimal
  grid.origin = std::array<double, 3>{-0.1, 1e-300, 0};
  grid.cells = std::array<std::int64_t, 3>{10, 12, 1};
  std::vector<Elements> frames;
  {
    RecordingWriter w(path, grid, "test\nsecond comment line");
    for (int f = 0; f < 4; ++f) {
      frames.push_back(awkward_elements(static_cast<std::uint64_t>(f) + 1, f == 2 ? 0 : 50 + f));
      w.write_frame(f * 3, f / 60.0, frames.back());
    }
    EXPECT_FALSE(fs::exists(path)) << "the file appears only at commit";
    w.commit();
  }
  ASSERT_TRUE(fs::exists(path));
  // A big cell_size in the header would refuse nothing here, but these radii are tiny anyway.
  const Recording rec = read_recording(path);
  ASSERT_TRUE(rec.grid.cell_size && rec.grid.origin && rec.grid.cells);
  EXPECT_TRUE(same_bits(*rec.grid.cell_size, *grid.cell_size));
  EXPECT_TRUE(same_bits((*rec.grid.origin)[0], -0.1));
  EXPECT_TRUE(same_bits((*rec.grid.origin)[1], 1e-300));
  EXPECT_EQ((*rec.grid.cells)[0], 10);
  EXPECT_EQ((*rec.grid.cells)[1], 12);
  ASSERT_EQ(rec.frames.size(), frames.size());
  for (std::size_t f = 0; f < frames.size(); ++f) {
    EXPECT_EQ(rec.frames[f].number, static_cast<std::int64_t>(f) * 3);
    EXPECT_TRUE(same_bits(rec.frames[f].time, static_cast<double>(f) / 60.0));
    const Elements& a = frames[f];
    const Elements& b = rec.frames[f].elements;
    ASSERT_EQ(a.size(), b.size()) << "frame " << f;
    for (Eigen::Index k = 0; k < a.size(); ++k) {
      ASSERT_TRUE(same_bits(a.x[k], b.x[k]) && same_bits(a.y[k], b.y[k]) && same_bits(a.r[k], b.r[k]))
          << "frame " << f << " element " << k << ": " << a.x[k] << " " << b.x[k];
    }
  }
  // --frames N reads the first N only.
  EXPECT_EQ(read_recording(path, 2).frames.size(), 2u);
  fs::remove_all(dir);
}

TEST(Recording, WriterDestroyedWithoutCommitLeavesNothing) {
  const std::string dir = temp_dir("abandon");
  {
    RecordingWriter w(dir + "/run.nbsrec", {}, "");
    w.write_frame(0, 0, awkward_elements(1, 10));
  }
  EXPECT_TRUE(fs::is_empty(dir)) << "neither the file nor its temporary may remain";
  EXPECT_THROW(RecordingWriter(dir + "/no/such/dir/run.nbsrec", {}, ""), Error);
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST(Recording, ParsesTheDocumentedExample) {
  const Recording rec = parse_recording(
      "# made by hand\n\nnbsrec 1\ncell_size 1\norigin 0,0\ncells 10,10\nframe 0 0.0\n0.5,0.5,0.5 # one\n1.4,0.5,0.5\n"
      "frame 1 0.0166667\r\n0.5,0.5,0.5\r\nframe 5 0.0166667\n",
      "ex.nbsrec");
  ASSERT_EQ(rec.frames.size(), 3u);
  EXPECT_EQ(rec.frames[0].elements.size(), 2);
  EXPECT_EQ(rec.frames[1].elements.size(), 1);
  EXPECT_EQ(rec.frames[2].elements.size(), 0) << "an empty frame is valid";
  EXPECT_EQ(rec.frames[2].number, 5);
  EXPECT_DOUBLE_EQ(rec.frames[0].elements.x[1], 1.4);
  EXPECT_EQ(*rec.grid.cell_size, 1.0);
}

// The message of parse_recording(text), or "" when it parses.
std::string error_of(const std::string& text) {
  try {
    parse_recording(text, "bad.nbsrec");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Recording, BadInputIsNamedByLine) {
  const std::string ok_head = "nbsrec 1\nframe 0 0\n";
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {"", "bad.nbsrec:1: empty file"},
      {"  \n\n", "bad.nbsrec:1: empty file"},
      {"# only a comment\n", "bad.nbsrec:1: only comments"},
      {"frame 0 0\n1,1,1\n", "bad.nbsrec:1: expected 'nbsrec 1'"},
      {"nbsrec 2\nframe 0 0\n", "bad.nbsrec:1: 'nbsrec 2': this nbscope reads version 1"},
      {"nbsrec 1\n", "bad.nbsrec:1: no frames"},
      {"nbsrec 1\ncell_size 1\n\n", "bad.nbsrec:3: no frames"},
      {ok_head + "frame 0 1\n", "bad.nbsrec:3: frame 0 after frame 0: frame numbers must increase"},
      {ok_head + "frame 2 1\nframe 1 2\n", "bad.nbsrec:4: frame 1 after frame 2"},
      {"nbsrec 1\nframe 0 0.5\nframe 1 0.25\n", "bad.nbsrec:3: frame 1: time 0.25 is before frame 0's 0.5"},
      {ok_head + "1,2,x\n", "bad.nbsrec:3: r: 'x' is not a number"},
      {ok_head + "1,1,1\n1,2\n", "bad.nbsrec:4: 2 columns; expected 3 (x,y,r)"},
      {ok_head + "nan,1,1\n", "bad.nbsrec:3: x: 'nan' is not a finite number"},
      {ok_head + "1,inf,1\n", "bad.nbsrec:3: y: 'inf' is not a finite number"},
      {ok_head + "1,1,0\n", "bad.nbsrec:3: r: radius must be > 0"},
      {ok_head + "1,1,-2\n", "bad.nbsrec:3: r: radius must be > 0"},
      {ok_head + "1,1,1,1\n", "bad.nbsrec:3: 4 columns (x,y,z,r) in a 2D recording: add 'dim 3' before the first frame"},
      {"nbsrec 1\n1,1,1\n", "bad.nbsrec:2: an element row before the first 'frame"},
      {ok_head + "cell_size 2\n", "bad.nbsrec:3: cell_size: header lines come before the first frame"},
      {"nbsrec 1\ncell_size 0\n", "bad.nbsrec:2: cell_size: must be > 0"},
      {"nbsrec 1\ncell_size 1\nframe 0 0\n1,1,0.6\n", "bad.nbsrec:4: r: diameter 1.2 is larger than the header's cell_size 1"},
      {"nbsrec 1\norigin 1\n", "bad.nbsrec:2: origin: '1' is not X,Y"},
      {"nbsrec 1\ncells 0,3\n", "bad.nbsrec:2: cells nx: 0 is out of range"},
      {"nbsrec 1\ncells 2.5,3\n", "bad.nbsrec:2: cells nx: '2.5' is not an integer"},
      {"nbsrec 1\nframe -1 0\n", "bad.nbsrec:2: frame number: -1 is out of range"},
      {"nbsrec 1\nframe 0\n", "bad.nbsrec:2: expected 'frame NUMBER TIME'"},
      {"nbsrec 1\nframe 0 nan\n", "bad.nbsrec:2: frame time: 'nan' is not a finite number"},
      {"nbsrec 1\nelements 3\n", "bad.nbsrec:2: unknown line 'elements 3'"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(c.text);
    EXPECT_EQ(message.rfind(c.expected, 0), 0u) << "input:\n" << c.text << "\ngot: " << message << "\nexpected: " << c.expected;
  }
}

// ---- pairs blocks: the simulation's own contact pairs of each frame -------------------------------

TEST(RecordingPairs, BlocksAreReadAsGivenAndZeroBased) {
  const Recording rec = parse_recording(
      "nbsrec 1\nframe 0 0\n0,0,1\n1,0,1\n2,0,1\npairs\n0,1\n2,1   # either order\n1,1\n0,1\n"
      "frame 1 0.1\n0,0,1\npairs\nframe 2 0.2\n0,0,1\n5,0,1\npairs # no contact\n",
      "p.nbsrec");
  ASSERT_TRUE(rec.has_pairs);
  EXPECT_EQ(rec.pair_base, 0);
  ASSERT_EQ(rec.frames.size(), 3u);
  EXPECT_EQ(rec.frames[0].elements.size(), 3);
  // Kept exactly as written: the order within a pair, i == j and a repeat are for the check to report.
  EXPECT_EQ(rec.frames[0].pairs, (PairList{{0, 1}, {2, 1}, {1, 1}, {0, 1}}));
  EXPECT_TRUE(rec.frames[1].pairs.empty()) << "an empty block is a frame without contacts";
  EXPECT_TRUE(rec.frames[2].pairs.empty());
  EXPECT_EQ(rec.frames[2].elements.size(), 2) << "rows before the block are the frame's elements";
}

TEST(RecordingPairs, BaseOneNumbersFromOne) {
  const Recording rec = parse_recording("nbsrec 1\nbase 1\nframe 4 0\n0,0,1\n1,0,1\n2,0,1\npairs\n1,2\n3,2\n", "f.nbsrec");
  ASSERT_TRUE(rec.has_pairs);
  EXPECT_EQ(rec.pair_base, 1);
  EXPECT_EQ(rec.frames[0].pairs, (PairList{{0, 1}, {2, 1}}));
  EXPECT_EQ(parse_recording("nbsrec 1\nbase 0\nframe 0 0\n0,0,1\npairs\n0,0\n", "z").frames[0].pairs, (PairList{{0, 0}}));
}

TEST(RecordingPairs, NoBlocksMeansNoPairs) {
  const Recording rec = parse_recording("nbsrec 1\nbase 1\nframe 0 0\n0,0,1\n1,0,1\nframe 1 0\n0,0,1\n", "n.nbsrec");
  EXPECT_FALSE(rec.has_pairs);
  for (const RecordedFrame& f : rec.frames) EXPECT_TRUE(f.pairs.empty());
}

TEST(RecordingPairs, FramesLimitStopsBeforeAFrameThatWouldBreakAllOrNone) {
  const std::string text = "nbsrec 1\nframe 0 0\n0,0,1\npairs\nframe 1 0\n0,0,1\npairs\nframe 2 0\n0,0,1\n";
  EXPECT_EQ(parse_recording(text, "m", 2).frames.size(), 2u) << "frame 2, not read, is not held against the rest";
  EXPECT_THROW(parse_recording(text, "m"), Error);
}

TEST(RecordingPairs, WriterRoundTripsPairsAndRefusesWhatTheReaderWould) {
  const std::string dir = temp_dir("pairs");
  const std::string path = dir + "/p.nbsrec";
  const Elements e = awkward_elements(5, 4);
  const PairList given{{3, 0}, {1, 1}, {0, 3}, {2, 3}};
  const PairList none;
  {
    RecordingWriter w(path, {}, "pairs");
    w.write_frame(0, 0, e, &given);
    w.write_frame(1, 0.5, e, &none);
    EXPECT_THROW(w.write_frame(2, 1, e), Error) << "a frame without pairs after one with";
    const PairList out_of_range{{0, 4}};
    EXPECT_THROW(w.write_frame(2, 1, e, &out_of_range), Error);
    w.commit();
  }
  const Recording rec = read_recording(path);
  ASSERT_TRUE(rec.has_pairs);
  ASSERT_EQ(rec.frames.size(), 2u);
  EXPECT_EQ(rec.frames[0].pairs, given);
  EXPECT_TRUE(rec.frames[1].pairs.empty());
  {
    RecordingWriter w(dir + "/q.nbsrec", {}, "");
    w.write_frame(0, 0, e);
    EXPECT_THROW(w.write_frame(1, 0, e, &given), Error) << "pairs after a frame without";
  }
  {
    RecordingWriter w(dir + "/one.nbsrec", {}, "", 2, 1);  // numbered from 1, as the file it came from
    w.write_frame(0, 0, e, &given);
    w.commit();
  }
  const Recording one = read_recording(dir + "/one.nbsrec");
  EXPECT_EQ(one.pair_base, 1);
  EXPECT_EQ(one.frames[0].pairs, given);
  std::ifstream in(dir + "/one.nbsrec");
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("\nbase 1\nframe 0 0\n"), std::string::npos);
  EXPECT_NE(text.str().find("\npairs\n4,1\n2,2\n1,4\n3,4\n"), std::string::npos) << text.str();
  EXPECT_THROW(RecordingWriter(dir + "/two.nbsrec", {}, "", 2, 2), Error);
  fs::remove_all(dir);
}

TEST(RecordingPairs, BadPairsInputIsNamedByLine) {
  const std::string nine = "0,0,1\n1,0,1\n2,0,1\n3,0,1\n4,0,1\n5,0,1\n6,0,1\n7,0,1\n8,0,1\n";
  const std::string two = "nbsrec 1\nframe 0 0\n0,0,1\n1,0,1\n";  // a frame of two elements, rows on lines 3-4
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {"nbsrec 1\npairs\nframe 0 0\n", "bad.nbsrec:2: a 'pairs' line before the first 'frame NUMBER TIME' line"},
      {two + "pairs\n0,1\npairs\n", "bad.nbsrec:7: a second 'pairs' line in frame 0 (one pairs block a frame)"},
      {two + "pairs 1\n", "bad.nbsrec:5: expected 'pairs' alone on its line, got 'pairs 1'"},
      {two + "pairs\n0,1\n2,0,1\n", "bad.nbsrec:7: an element row after frame 0's 'pairs' line (a frame's element rows come before its pairs)"},
      {two + "pairs\n1\n", "bad.nbsrec:6: pair row '1': expected i,j (two integers)"},
      {two + "pairs\n0,1,\n", "bad.nbsrec:6: an element row after frame 0's 'pairs' line"},
      {two + "pairs\n0,x\n", "bad.nbsrec:6: pair row '0,x': 'x' is not an integer"},
      {two + "pairs\n1.0,0\n", "bad.nbsrec:6: pair row '1.0,0': '1.0' is not an integer"},
      {two + "pairs\n,1\n", "bad.nbsrec:6: pair row ',1': '' is not an integer"},
      {two + "pairs\n0,2\n", "bad.nbsrec:6: pair 0,2: frame 0 has 2 elements (0..1)"},
      {two + "pairs\n-1,0\n", "bad.nbsrec:6: pair -1,0: frame 0 has 2 elements (0..1)"},
      {two + "pairs\n0,99999999999999999999\n", "bad.nbsrec:6: pair 0,99999999999999999999: frame 0 has 2 elements (0..1)"},
      {"nbsrec 1\nframe 0 0\npairs\n0,0\n", "bad.nbsrec:4: pair 0,0: frame 0 has 0 elements"},
      {"nbsrec 1\nbase 1\nframe 4 0\n" + nine + "pairs\n3,12\n", "bad.nbsrec:14: pair 3,12: frame 4 has 9 elements (1..9)"},
      {"nbsrec 1\nbase 1\nframe 4 0\n" + nine + "pairs\n0,1\n", "bad.nbsrec:14: pair 0,1: frame 4 has 9 elements (1..9)"},
      {"nbsrec 1\nbase 2\n", "bad.nbsrec:2: base: '2': pairs number elements from 0 ('base 0', the default) or 1 ('base 1')"},
      {"nbsrec 1\nbase\n", "bad.nbsrec:2: base: expected 'base 0|1'"},
      {two + "base 1\n", "bad.nbsrec:5: base: header lines come before the first frame"},
      {two + "1,0\n", "bad.nbsrec:5: 2 columns; expected 3 (x,y,r) (a pair i,j? pairs come after the frame's 'pairs' line)"},
      // All or none, named at the frame line that breaks it.
      {two + "pairs\n0,1\nframe 1 0\nframe 3 0\n0,0,1\npairs\n",
       "bad.nbsrec:7: frame 1 has no pairs block, but frame 0 has one: give every frame its pairs, or none"},
      {two + "pairs\n0,1\nframe 1 0\npairs\nframe 3 0\n0,0,1\n",
       "bad.nbsrec:9: frame 3 has no pairs block, but frame 0 has one: give every frame its pairs, or none"},
      {two + "frame 2 0\n0,0,1\npairs\n", "bad.nbsrec:5: frame 2 has a pairs block, but frame 0 has none: give every frame its pairs, or none"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(c.text);
    EXPECT_EQ(message.rfind(c.expected, 0), 0u) << "input:\n" << c.text << "\ngot: " << message << "\nexpected: " << c.expected;
  }
}

// ---- 3D recordings: `dim 3`, rows x,y,z,r, the grid's z ---------------------------------------

// The whole file at `path`.
std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

TEST(Recording3d, WriterThenReaderGivesBitIdenticalSpheresGridAndComment) {
  const std::string dir = temp_dir("roundtrip3d");
  GridOptions grid;
  grid.cell_size = 7.0 / 3.0;  // radii below 1: every diameter fits
  grid.origin = std::array<double, 3>{-0.1, 0.2, -1e-300};
  grid.cells = std::array<std::int64_t, 3>{4, 5, 6};
  std::vector<Elements> frames;
  {
    RecordingWriter w(dir + "/a.nbsrec", grid, "spheres\n made by hand", 3);
    for (int f = 0; f < 3; ++f) {
      Elements e = awkward_elements(static_cast<std::uint64_t>(f) + 7, f == 1 ? 0 : 40);
      e.dim = 3;
      const Elements zs = awkward_elements(static_cast<std::uint64_t>(f) + 70, static_cast<int>(e.size()));
      e.z = zs.x;  // z as awkward as x
      frames.push_back(e);
      w.write_frame(f, f * 0.5, e);
    }
    w.commit();
  }
  const Recording rec = read_recording(dir + "/a.nbsrec");
  EXPECT_EQ(rec.dim, 3);
  EXPECT_EQ(rec.comment, "spheres\n made by hand");
  ASSERT_TRUE(rec.grid.origin && rec.grid.cells);
  EXPECT_TRUE(same_bits((*rec.grid.origin)[2], -1e-300));
  EXPECT_EQ((*rec.grid.cells)[2], 6);
  ASSERT_EQ(rec.frames.size(), frames.size());
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const Elements& a = frames[f];
    const Elements& b = rec.frames[f].elements;
    EXPECT_EQ(b.dim, 3);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(b.z.size(), b.size());
    for (Eigen::Index k = 0; k < a.size(); ++k)
      ASSERT_TRUE(same_bits(a.x[k], b.x[k]) && same_bits(a.y[k], b.y[k]) && same_bits(a.z[k], b.z[k]) && same_bits(a.r[k], b.r[k]))
          << "frame " << f << " element " << k;
  }
  // Written again from what was read: the same bytes.
  {
    RecordingWriter w(dir + "/b.nbsrec", rec.grid, rec.comment, rec.dim);
    for (const RecordedFrame& f : rec.frames) w.write_frame(f.number, f.time, f.elements);
    w.commit();
  }
  EXPECT_EQ(file_text(dir + "/a.nbsrec"), file_text(dir + "/b.nbsrec"));
  fs::remove_all(dir);
}

TEST(Recording3d, HeaderCommentIsKeptAsItsFirstLinesUpToTheLimit) {
  std::string text = "#  two spaces\n#\nnbsrec 1 # not whole-line\n";
  const std::string long_line(1000, 'c');
  for (int k = 0; k < 80; ++k) text += "# " + std::to_string(k) + long_line + "\n";
  text += "# short\nframe 0 0\n# after the first frame\n";
  const Recording rec = parse_recording(text, "c.nbsrec");
  EXPECT_LE(rec.comment.size(), kMaxKeptComment);
  EXPECT_GT(rec.comment.size(), kMaxKeptComment - 2000);
  EXPECT_EQ(rec.comment.rfind(" two spaces\n\n0" + long_line + "\n1" + long_line + "\n", 0), 0u);
  EXPECT_EQ(rec.comment.find("short"), std::string::npos) << "no line after the first one left out";
  EXPECT_EQ(rec.comment.find("after"), std::string::npos);
}

TEST(Recording3d, TwoDimensionalFilesHaveNoDimLineAndTwoAxes) {
  const std::string dir = temp_dir("nodim");
  GridOptions grid;
  grid.cell_size = 1;
  grid.origin = std::array<double, 3>{0, 0, 0};
  grid.cells = std::array<std::int64_t, 3>{10, 10, 1};
  {
    RecordingWriter w(dir + "/a.nbsrec", grid, "c");
    Elements e;
    e.push_back(0.5, 0.5, 0, 0.5);
    w.write_frame(0, 0, e);
    w.commit();
  }
  EXPECT_EQ(file_text(dir + "/a.nbsrec"), "nbsrec 1\n# c\ncell_size 1\norigin 0,0\ncells 10,10\nframe 0 0\n0.5,0.5,0.5\n");
  fs::remove_all(dir);
}

TEST(Recording3d, DimMayFollowTheGridLinesAndDim2IsTheDefault) {
  const Recording rec = parse_recording("nbsrec 1\norigin 0,0,-1\ncells 2,2,3\ndim 3\nframe 0 0\n1,2,3,0.5\n1,2,4,0.25 # two\npairs\n0,1\n", "d.nbsrec");
  EXPECT_EQ(rec.dim, 3);
  ASSERT_EQ(rec.frames[0].elements.size(), 2);
  EXPECT_EQ(rec.frames[0].elements.dim, 3);
  EXPECT_EQ(rec.frames[0].elements.z[1], 4.0);
  EXPECT_EQ(rec.frames[0].elements.r[1], 0.25);
  EXPECT_EQ((*rec.grid.origin)[2], -1.0);
  EXPECT_EQ((*rec.grid.cells)[2], 3);
  EXPECT_EQ(rec.frames[0].pairs, (PairList{{0, 1}}));
  const Recording flat = parse_recording("nbsrec 1\ndim 2\nframe 0 0\n1,2,0.5\n", "f.nbsrec");
  EXPECT_EQ(flat.dim, 2);
  EXPECT_EQ(flat.frames[0].elements.dim, 2);
}

TEST(Recording3d, BadInputIsNamedByLine) {
  const std::string head3 = "nbsrec 1\ndim 3\nframe 0 0\n";
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {"nbsrec 1\nframe 0 0\n1,1,1,1\n", "bad.nbsrec:3: 4 columns (x,y,z,r) in a 2D recording: add 'dim 3' before the first frame"},
      {head3 + "1,1,1,1\n1,1,1\n", "bad.nbsrec:5: 3 columns (x,y,r) in a 3D recording ('dim 3' on line 2): rows are x,y,z,r"},
      {head3 + "1,1\n", "bad.nbsrec:4: 2 columns; expected 4 (x,y,z,r)"},
      {head3 + "1,1,1,1,1\n", "bad.nbsrec:4: 5 columns; expected 4 (x,y,z,r)"},
      {head3 + "1,1,1,0\n", "bad.nbsrec:4: r: radius must be > 0"},
      {head3 + "1,1,nan,1\n", "bad.nbsrec:4: z: 'nan' is not a finite number"},
      {"nbsrec 1\ndim 3\ndim 3\n", "bad.nbsrec:3: dim given twice (first on line 2)"},
      {"nbsrec 1\ndim 4\n", "bad.nbsrec:2: dim: '4': a recording is 2D ('dim 2', the default: rows x,y,r) or 3D ('dim 3': rows x,y,z,r)"},
      {"nbsrec 1\ndim\n", "bad.nbsrec:2: dim: expected 'dim 2|3'"},
      {"nbsrec 1\nframe 0 0\ndim 3\n", "bad.nbsrec:3: dim: header lines come before the first frame"},
      {"nbsrec 1\norigin 0,0,0\nframe 0 0\n", "bad.nbsrec:2: origin: 3 values (X,Y,Z) in a 2D recording: add 'dim 3' before the first frame"},
      {"nbsrec 1\ndim 3\ncells 2,2\nframe 0 0\n", "bad.nbsrec:3: cells: 2 values (NX,NY) in a 3D recording ('dim 3' on line 2): expected NX,NY,NZ"},
      {"nbsrec 1\norigin 1,2,3,4\n", "bad.nbsrec:2: origin: '1,2,3,4' is not X,Y (2D) or X,Y,Z (3D)"},
      {"nbsrec 1\ndim 3\ncells 2,2,0\n", "bad.nbsrec:3: cells nz: 0 is out of range"},
      {"nbsrec 1\ndim 3\ncell_size 1\nframe 0 0\n0,0,0,0.6\n", "bad.nbsrec:5: r: diameter 1.2 is larger than the header's cell_size 1"},
      {head3 + "0,0,0,1\npairs\n0,0,0,1\n", "bad.nbsrec:6: an element row after frame 0's 'pairs' line"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(c.text);
    EXPECT_EQ(message.rfind(c.expected, 0), 0u) << "input:\n" << c.text << "\ngot: " << message << "\nexpected: " << c.expected;
  }
}

TEST(Recording3d, WriterRefusesFramesTheHeaderDoesNotDescribe) {
  const std::string dir = temp_dir("refuse3d");
  Elements flat = awkward_elements(3, 5);
  Elements solid = flat;
  solid.dim = 3;
  solid.z = flat.x;
  {
    RecordingWriter w(dir + "/a.nbsrec", {}, "", 3);
    EXPECT_THROW(w.write_frame(0, 0, flat), Error) << "a 2D frame in a 3D recording";
    Elements periodic = solid;
    periodic.box.periodic[2] = true;
    periodic.box.hi[2] = 1;
    EXPECT_THROW(w.write_frame(0, 0, periodic), Error) << "the format has no periodic box";
  }
  {
    RecordingWriter w(dir + "/b.nbsrec", {}, "");
    EXPECT_THROW(w.write_frame(0, 0, solid), Error) << "a 3D frame in a 2D recording";
  }
  EXPECT_THROW(RecordingWriter(dir + "/c.nbsrec", {}, "", 4), Error);
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace nbscope
