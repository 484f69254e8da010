// 3D recordings through the binary: `replay --dump` of LIGGGHTS's 3D pour and a hand-written 3D
// .nbsrec recorded with `replay --record` (rows read back here with strtod, independently of src/io),
// recorded again to the same bytes; the faults and the headless debugging loop (--stop-at-violation,
// --violation, --back) on a 3D recording; a 3D report's cells; bad 3D input exits 2 with one line.
//
// Index: helpers | round trips | faults and the debugging loop | bad input.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <utility>

#include "support/generators.hpp"
#include "support/run_cli.hpp"
#include "support/x_display.hpp"

namespace nbscope {
namespace {

namespace fs = std::filesystem;
using testcli::read_text;
using testcli::run;
using testcli::scratch_dir;
using testcli::write_text;

const std::string kPour = std::string(NBSCOPE_SOURCE_DIR) + "/assets/examples/pour3d/atoms.*.dump";

// ---- helpers: what docs/formats.md says, read with nothing but strtod ----------------------------

struct Row {
  double v[4] = {0, 0, 0, 0};
};
struct TestFrame {
  long long number = 0;
  std::vector<Row> rows;
};

// The frames of a .nbsrec text whose rows are x,y,z,r (4 fields each, or the test fails).
std::vector<TestFrame> frames_of(const std::string& text) {
  std::vector<TestFrame> frames;
  std::istringstream in(text);
  std::string line;
  bool in_pairs = false;
  while (std::getline(in, line)) {
    if (line.rfind("frame ", 0) == 0) {
      frames.push_back({std::atoll(line.c_str() + 6), {}});
      in_pairs = false;
    } else if (line == "pairs") {
      in_pairs = true;
    } else if (!frames.empty() && !in_pairs && !line.empty() && line[0] != '#') {
      EXPECT_EQ(std::count(line.begin(), line.end(), ','), 3) << line;
      Row r;
      const char* p = line.c_str();
      char* end = nullptr;
      for (double& v : r.v) {
        v = std::strtod(p, &end);
        p = end + 1;
      }
      frames.back().rows.push_back(r);
    }
  }
  return frames;
}

// The frames of a LAMMPS dump text (`ITEM: ATOMS id type x y z radius`), rows as written.
std::vector<TestFrame> dump_frames(const std::string& text) {
  std::vector<TestFrame> frames;
  std::istringstream in(text);
  std::string line;
  bool atoms = false, timestep = false;
  while (std::getline(in, line)) {
    if (line.rfind("ITEM:", 0) == 0) {
      timestep = line == "ITEM: TIMESTEP";
      atoms = line.rfind("ITEM: ATOMS", 0) == 0;
    } else if (timestep) {
      frames.push_back({std::atoll(line.c_str()), {}});
      timestep = false;
    } else if (atoms) {
      double f[6];
      std::istringstream fields(line);
      for (double& v : f) fields >> v;
      frames.back().rows.push_back(Row{{f[2], f[3], f[4], f[5]}});
    }
  }
  return frames;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::size_t lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

// ---- round trips -------------------------------------------------------------------------------

// The pour's two frames recorded once (replay --dump --record), shared by the tests below.
class Pour : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(scratch_dir("replay3d_pour_" + std::to_string(::getpid())));
    const auto r = run("replay --headless --quiet --dump '" + kPour + "' --record '" + rec() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static std::string rec() { return *dir_ + "/pour.nbsrec"; }
  static std::string* dir_;
};
std::string* Pour::dir_ = nullptr;

TEST_F(Pour, DumpIsRecordedAsSpheresExactlyAndRecordedAgainToTheSameBytes) {
  const std::string text = read_text(rec());
  EXPECT_EQ(text.rfind("nbsrec 1\n", 0), 0u);
  EXPECT_NE(text.find("\ndim 3\nframe 6000 "), std::string::npos) << text.substr(0, 300);
  std::string dumps;
  for (const char* step : {"6000", "7500"})
    dumps += read_text(std::string(NBSCOPE_SOURCE_DIR) + "/assets/examples/pour3d/atoms." + step + ".dump");
  const std::vector<TestFrame> want = dump_frames(dumps), got = frames_of(text);
  ASSERT_EQ(got.size(), 2u);
  ASSERT_EQ(want.size(), 2u);
  for (std::size_t f = 0; f < 2; ++f) {
    EXPECT_EQ(got[f].number, want[f].number);
    ASSERT_EQ(got[f].rows.size(), 1000u);
    ASSERT_EQ(got[f].rows.size(), want[f].rows.size());
    for (std::size_t k = 0; k < want[f].rows.size(); ++k)
      for (int c = 0; c < 4; ++c)
        ASSERT_TRUE(same_bits(got[f].rows[k].v[c], want[f].rows[k].v[c])) << "frame " << f << " row " << k << " column " << c;
  }
  const std::string again = *dir_ + "/again.nbsrec";
  const auto r = run("replay '" + rec() + "' --headless --quiet --record '" + again + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("2 frames, 1000 elements: A==R held in every frame"), std::string::npos) << r.out;
  EXPECT_TRUE(read_text(again) == text) << "recorded again, a recording is the same file";
}

TEST(Replay3d, HandWrittenSpheresWithPairsRoundTripByteForByte) {
  const std::string dir = scratch_dir("replay3d_hand");
  const Elements e = make_layout(Layout::Loose, 1500, 3, 11);
  const PairList pairs = testdata::brute_pairs(e);
  ASSERT_GT(pairs.size(), 10u);
  std::string text = "# spheres by hand\nnbsrec 1\ndim 3\nbase 1\nframe 0 0.5\n";  // pairs numbered from 1
  char buf[128];
  for (Eigen::Index k = 0; k < e.size(); ++k) {
    std::snprintf(buf, sizeof buf, "%.17g, %.17g, %.17g, %.17g\n", e.x[k], e.y[k], e.z[k], e.r[k]);
    text += buf;
  }
  text += "pairs\n";
  for (const Pair& p : pairs) text += std::to_string(p.j + 1) + "," + std::to_string(p.i + 1) + "\n";  // either order
  write_text(dir + "/hand.nbsrec", text);
  // Its pairs are right: `recorded` (the default when the frames carry pairs) passes.
  const auto first = run("replay '" + dir + "/hand.nbsrec' --headless --quiet --record '" + dir + "/one.nbsrec'");
  ASSERT_EQ(first.exit_code, 0) << first.out << first.err;
  EXPECT_EQ(first.out.rfind("replay: hand, recorded, 1 frame, 1500 elements: A==R held", 0), 0u) << first.out;
  const std::string one = read_text(dir + "/one.nbsrec");
  EXPECT_EQ(one.rfind("nbsrec 1\n# spheres by hand\ndim 3\nbase 1\nframe 0 0.5\n", 0), 0u) << one.substr(0, 200);
  const std::vector<TestFrame> got = frames_of(one);
  ASSERT_EQ(got.size(), 1u);
  ASSERT_EQ(got[0].rows.size(), 1500u);
  for (Eigen::Index k = 0; k < e.size(); ++k) {
    const Row& r = got[0].rows[static_cast<std::size_t>(k)];
    ASSERT_TRUE(same_bits(r.v[0], e.x[k]) && same_bits(r.v[1], e.y[k]) && same_bits(r.v[2], e.z[k]) && same_bits(r.v[3], e.r[k])) << k;
  }
  EXPECT_NE(one.find("\npairs\n" + std::to_string(pairs[0].j + 1) + "," + std::to_string(pairs[0].i + 1) + "\n"), std::string::npos)
      << "the pairs block is kept as given, numbered from 1";
  const auto second = run("replay '" + dir + "/one.nbsrec' --headless --quiet --record '" + dir + "/two.nbsrec'");
  ASSERT_EQ(second.exit_code, 0) << second.out << second.err;
  EXPECT_TRUE(read_text(dir + "/two.nbsrec") == one);
  // And every 3D detector finds the same pairs on it.
  const auto all = run("replay '" + dir + "/one.nbsrec' --headless --quiet --algorithm nbs,sort,screen,tree,brute,recorded");
  EXPECT_EQ(all.exit_code, 0) << all.out << all.err;
  fs::remove_all(dir);
}

// ---- faults and the debugging loop ---------------------------------------------------------------

TEST_F(Pour, EveryRecordedFrameFaultActsInThreeDimensions) {
  for (const std::string fault : {"drop-pair", "drop-mask-cell", "off-by-one-cell", "stale-positions"}) {
    const auto r = run("replay '" + rec() + "' --headless --quiet --inject-fault " + fault);
    EXPECT_EQ(r.exit_code, 1) << fault << ": " << r.out << r.err;
    EXPECT_NE(r.out.find(", fault " + fault + ", 2 frames, 1000 elements: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("missing from A (in R)"), std::string::npos) << fault << ": " << r.out;
  }
  const auto box2d = run("replay '" + rec() + "' --headless --inject-fault drop-box2d-contact");
  EXPECT_EQ(box2d.exit_code, 2);
  EXPECT_EQ(box2d.err.rfind("nbscope: error: --inject-fault drop-box2d-contact: recorded frames have no Box2D contact list", 0), 0u) << box2d.err;
}

TEST_F(Pour, StopAtViolationViolationAndBackTravelThroughTheSpheres) {
  const auto stop = run("replay '" + rec() + "' --headless --quiet --inject-fault drop-pair --stop-at-violation");
  EXPECT_EQ(stop.exit_code, 1) << stop.err;
  EXPECT_NE(stop.out.find(", 1 frame, 1000 elements:"), std::string::npos) << stop.out;
  EXPECT_NE(stop.out.find("; stopped at the first violation, frame 6000: A==R ("), std::string::npos) << stop.out;
  // Each frame drops one pair: the second listed violation is frame 7500's.
  const auto second = run("replay '" + rec() + "' --headless --quiet --inject-fault drop-pair --violation 2");
  EXPECT_EQ(second.exit_code, 1) << second.err;
  EXPECT_NE(second.out.find("; went to violation 2, frame 7500: A==R ("), std::string::npos) << second.out;
  const auto back = run("replay '" + rec() + "' --headless --quiet --back 1");
  EXPECT_EQ(back.exit_code, 0) << back.err;
  EXPECT_NE(back.out.find("; went back 1 frame to frame 6000: "), std::string::npos) << back.out;
  const auto far = run("replay '" + rec() + "' --headless --quiet --back 2");
  EXPECT_EQ(far.exit_code, 2);
  EXPECT_EQ(far.err, "nbscope: error: --back: 2 goes before the first recorded frame (2 frames replayed: at most 1 back)\n");
}

// A dump's frames are read when they are shown (io/dump_frames.hpp): with no memory for past frames,
// a frame gone back to (or the one before, for stale-positions) is read again from its file and
// finds exactly what a run that kept it finds.
TEST_F(Pour, AFrameNotKeptIsReadAgainFromTheDump) {
  for (const std::string travel : {"--back 1", "--inject-fault drop-pair --violation 2", "--inject-fault drop-pair --stop-at-violation",
                                   "--inject-fault stale-positions"}) {
    const std::string args = "replay --dump '" + kPour + "' --headless --quiet " + travel;
    const auto kept = run(args + " --history-mb 256");
    const auto read_again = run(args + " --history-mb 0");
    EXPECT_EQ(kept.exit_code, travel == "--back 1" ? 0 : 1) << travel << ": " << kept.err;
    EXPECT_EQ(read_again.exit_code, kept.exit_code) << travel << ": " << read_again.err;
    const std::regex ms("[0-9]+\\.[0-9]{3}");  // the timings differ from run to run
    EXPECT_EQ(std::regex_replace(read_again.out, ms, "#"), std::regex_replace(kept.out, ms, "#")) << travel;
  }
}

TEST_F(Pour, ReportNamesTheCellsOfAThreeDimensionalViolation) {
  const std::string report = *dir_ + "/mask.json";
  const auto r = run("replay '" + rec() + "' --headless --quiet --inject-fault drop-mask-cell --report '" + report + "'");
  ASSERT_EQ(r.exit_code, 1) << r.err;
  const auto j = nlohmann::json::parse(read_text(report));
  const auto& v = j.at("runs").at(0).at("frames").at(0).at("violations").at(0);
  ASSERT_EQ(v.at("cells").size(), 2u);
  for (const auto& cell : v.at("cells")) EXPECT_EQ(cell.size(), 3u) << "(ix, iy, iz): " << v.dump();
  // Every pair the fault dropped lies in cells (ix, iy, iz) and (ix-1, iy-1, iz): the one mask cell of the same layer.
  std::size_t seen = 0;
  for (const auto& frame : j.at("runs").at(0).at("frames"))
    for (const auto& violation : frame.at("violations")) {
      const auto& c = violation.at("cells");
      const int dx = c[1][0].get<int>() - c[0][0].get<int>(), dy = c[1][1].get<int>() - c[0][1].get<int>();
      EXPECT_TRUE(dx == dy && (dx == 1 || dx == -1)) << violation.dump();
      EXPECT_EQ(c[0][2], c[1][2]) << "same layer: " << violation.dump();
      ++seen;
    }
  EXPECT_GT(seen, 10u);
}

// ---- bad input ---------------------------------------------------------------------------------

TEST(Replay3d, BadThreeDimensionalInputExits2WithOneLine) {
  struct Case {
    const char* name;
    std::string text;
    std::string expected;  // after "nbscope: error: <file>:"
  };
  const Case cases[] = {
      {"row4_in_2d", "nbsrec 1\nframe 0 0\n0,0,1\n1,1,1,1\n", "4: 4 columns (x,y,z,r) in a 2D recording: add 'dim 3' before the first frame"},
      {"row3_in_3d", "nbsrec 1\ndim 3\nframe 0 0\n0,0,0,1\n1,1,1\n", "5: 3 columns (x,y,r) in a 3D recording ('dim 3' on line 2): rows are x,y,z,r"},
      {"dim_twice", "nbsrec 1\ndim 3\n# again\ndim 3\nframe 0 0\n", "4: dim given twice (first on line 2)"},
      {"dim_4", "nbsrec 1\ndim 4\nframe 0 0\n", "2: dim: '4': a recording is 2D ('dim 2', the default: rows x,y,r) or 3D ('dim 3': rows x,y,z,r)"},
      {"dim_after_frame", "nbsrec 1\nframe 0 0\n0,0,1\ndim 3\n0,0,0,1\n", "4: dim: header lines come before the first frame"},
      {"origin_2d_in_3d", "nbsrec 1\ndim 3\norigin 0,0\nframe 0 0\n", "3: origin: 2 values (X,Y) in a 3D recording ('dim 3' on line 2): expected X,Y,Z"},
  };
  for (const Case& c : cases) {
    const std::string dir = scratch_dir(std::string("replay3d_bad_") + c.name);
    const std::string file = dir + "/in.nbsrec";
    write_text(file, c.text);
    const auto r = run("replay '" + file + "' --headless --record '" + dir + "/out.nbsrec'");
    EXPECT_EQ(r.exit_code, 2) << c.name;
    EXPECT_EQ(r.out, "") << c.name;
    EXPECT_EQ(lines(r.err), 1u) << c.name << ": " << r.err;
    const std::string prefix = "nbscope: error: " + file + ":" + c.expected;
    EXPECT_EQ(r.err.rfind(prefix, 0), 0u) << c.name << ":\n got: " << r.err << " want: " << prefix;
    EXPECT_FALSE(fs::exists(dir + "/out.nbsrec")) << c.name;
  }
}

TEST(Replay3d, PeriodicDumpIsNotRecordedWithoutItsBox) {
  const std::string dir = scratch_dir("replay3d_periodic");
  write_text(dir + "/p.dump",
             "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\n"
             "ITEM: ATOMS id type x y z radius\n1 1 0.05 0.5 0.5 0.1\n2 1 0.95 0.5 0.5 0.1\n");
  const auto r = run("replay --headless --dump '" + dir + "/p.dump' --record '" + dir + "/out.nbsrec'");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_EQ(r.err.rfind("nbscope: error: recording: frame 0 is periodic", 0), 0u) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out.nbsrec"));
  // Checked without --record, the same frame passes (the periodic pair by its minimum image).
  EXPECT_EQ(run("replay --headless --quiet --dump '" + dir + "/p.dump'").exit_code, 0);
}

TEST(Replay3d, OutputsNeverOverwriteADumpTheGlobNames) {
  const std::string dir = scratch_dir("replay3d_own_dump");
  const std::string src = std::string(NBSCOPE_SOURCE_DIR) + "/assets/examples/pour3d/";
  for (const char* step : {"6000", "7500"}) fs::copy_file(src + "atoms." + step + ".dump", dir + "/atoms." + step + ".dump");
  const std::string before = read_text(dir + "/atoms.7500.dump");
  for (const char* flag : {"--record", "--report"}) {
    const auto r = run("replay --headless --quiet --dump '" + dir + "/atoms.*.dump' " + flag + " '" + dir + "/atoms.7500.dump'");
    EXPECT_EQ(r.exit_code, 2) << flag << ": " << r.out;
    EXPECT_EQ(r.err, "nbscope: error: " + dir + "/atoms.7500.dump: cannot write: it is also the --dump\n") << flag;
    EXPECT_TRUE(read_text(dir + "/atoms.7500.dump") == before) << flag;
  }
  fs::remove_all(dir);
}

#ifdef NBSCOPE_TEST_GUI
// With a display, replay opens the window, which records nothing and travels with its own panels:
// --record, --back and --violation are refused there, one line, before any window opens.
TEST_F(Pour, TheWindowRefusesTheHeadlessOnlyFlags) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::pair<const char*, const char*> cases[] = {
      {"--record x.nbsrec", "--record: needs --headless (the window writes no recording)"},
      {"--back 1", "--back: needs --headless (the window travels with its Timeline and Violations panel)"},
      {"--violation 1", "--violation: needs --headless (the window travels with its Timeline and Violations panel)"}};
  for (const auto& [flags, message] : cases) {
    const auto r = run("replay '" + rec() + "' " + flags, testcli::on_display());
    EXPECT_EQ(r.exit_code, 2) << flags;
    EXPECT_EQ(r.err, std::string("nbscope: error: ") + message + "\n") << flags;
  }
}
#endif

}  // namespace
}  // namespace nbscope
