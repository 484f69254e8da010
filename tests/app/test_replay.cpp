// `nbscope headless --record` and `nbscope replay` end to end: a recorded run replays to the very
// pairs brute force finds on the recorded elements (parsed here independently of src/io), every
// algorithm passes on the same frames, faults that need no Box2D are caught, the Box2D invariants are
// reported as not checked, and bad recordings or output paths exit 2 with one line and no files.
//
// Index: helpers (an independent .nbsrec reader) | record + replay | faults | bad input | outputs.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/paths.hpp"
#include "support/generators.hpp"
#include "support/run_cli.hpp"
#include "support/x_display.hpp"

namespace nbscope {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testcli::read_text;
using testcli::run;
using testcli::scratch_dir;
using testcli::write_text;

using testpaths::scene;

// ---- helpers: the format as docs/formats.md documents it, read with nothing but strtod -------

struct TestFrame {
  long long number = 0;
  Elements elements;
};

std::vector<TestFrame> frames_of(const std::string& text, std::string* header = nullptr) {
  std::vector<TestFrame> frames;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("frame ", 0) == 0) {
      frames.push_back({std::atoll(line.c_str() + 6), {}});
      frames.back().elements.dim = 2;
    } else if (!line.empty() && line[0] != '#' && !frames.empty()) {
      char* end = nullptr;
      const double x = std::strtod(line.c_str(), &end);
      const double y = std::strtod(end + 1, &end);
      const double r = std::strtod(end + 1, &end);
      frames.back().elements.push_back(x, y, 0, r);
    } else if (frames.empty() && header != nullptr) {
      *header += line + "\n";
    }
  }
  return frames;
}

// Names of the files in `dir`, sorted.
std::vector<std::string> files_in(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::size_t lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

// ---- record + replay ---------------------------------------------------------------------------

// One recorded run shared by the tests below (60 steps of default.json: frames 0..60).
class Recorded : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One directory per process: ctest runs these tests in parallel processes.
    dir_ = new std::string(scratch_dir("replay_recorded_" + std::to_string(::getpid())));
    const auto r = run("headless --scene '" + scene("default") + "' --frames 60 --record '" + rec() + "' --report '" + *dir_ + "/headless.json'");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static std::string rec() { return *dir_ + "/run.nbsrec"; }
  static std::string* dir_;
};
std::string* Recorded::dir_ = nullptr;

TEST_F(Recorded, ReplayFindsBrutePairsOfEveryRecordedFrameAsTheRecordedRunDid) {
  const std::string text = read_text(rec());
  ASSERT_EQ(text.rfind("nbsrec 1\n", 0), 0u) << text.substr(0, 100);
  const std::vector<TestFrame> frames = frames_of(text);
  ASSERT_EQ(frames.size(), 61u) << "frame 0 (the initial poses) and the 60 steps";
  const auto r = run("replay '" + rec() + "' --headless --report '" + *dir_ + "/replay.json'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(lines(r.out), 1u);
  EXPECT_NE(r.out.find("replay: run, nbs, 61 frames"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("A==R held in every frame"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("A-in-F, T-in-A, AABB-in-cells not checked (recorded frames have no Box2D world)"), std::string::npos) << r.out;

  const json recorded = json::parse(read_text(*dir_ + "/headless.json"));
  const json replayed = json::parse(read_text(*dir_ + "/replay.json"));
  EXPECT_EQ(replayed["source"], "recording");
  EXPECT_EQ(replayed["passed"], true);
  EXPECT_EQ(replayed["not_checked"]["invariants"], json({"A-in-F", "T-in-A", "AABB-in-cells"}));
  const json& hf = recorded["runs"][0]["frames"];
  const json& rf = replayed["runs"][0]["frames"];
  ASSERT_EQ(hf.size(), 61u) << "headless counts frame 0 as replay does: one numbering";
  ASSERT_EQ(rf.size(), 61u);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const PairList brute = testdata::brute_pairs(frames[k].elements);
    ASSERT_EQ(frames[k].number, static_cast<long long>(k));
    EXPECT_EQ(rf[k]["frame"], k);
    EXPECT_EQ(rf[k]["pairs"]["A"], brute.size()) << "frame " << k;
    EXPECT_EQ(rf[k]["elements"], frames[k].elements.size());
    EXPECT_EQ(rf[k]["held"]["A==R"], true);
    for (const char* inv : {"A-in-F", "T-in-A", "AABB-in-cells"}) EXPECT_TRUE(rf[k]["held"][inv].is_null()) << inv << " is not checked, not passed";
    EXPECT_EQ(hf[k]["frame"], k);
    EXPECT_EQ(hf[k]["pairs"]["A"], brute.size()) << "the recorded run saw these very elements in frame " << k;
  }
  // The actual pairs of one frame, through `pairs` on the frame's rows.
  const TestFrame& f = frames[45];
  std::string csv = "x,y,r\n";
  {
    std::istringstream in(text);
    std::string line;
    bool inside = false;
    while (std::getline(in, line)) {
      if (line.rfind("frame ", 0) == 0) inside = line.rfind("frame 45 ", 0) == 0;
      else if (inside) csv += line + "\n";
    }
  }
  write_text(*dir_ + "/frame45.csv", csv);
  const auto p = run("pairs --input '" + *dir_ + "/frame45.csv' --algorithm nbs");
  ASSERT_EQ(p.exit_code, 0) << p.err;
  std::string expected = "i,j\n";
  for (const Pair& q : testdata::brute_pairs(f.elements)) expected += std::to_string(q.i) + "," + std::to_string(q.j) + "\n";
  EXPECT_EQ(p.out, expected);
  EXPECT_GT(lines(expected), 100u) << "a frame with many contacts";
}

TEST_F(Recorded, EveryAlgorithmPassesOnTheRecordedFrames) {
  const auto r = run("replay '" + rec() + "' --headless --algorithm all --report '" + *dir_ + "/all.json'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("A==R held in every frame for every algorithm"), std::string::npos) << r.out;
  const json rep = json::parse(read_text(*dir_ + "/all.json"));
  EXPECT_GE(rep["runs"].size(), 5u);
  for (const json& run0 : rep["runs"]) EXPECT_EQ(run0["frames_run"], 61) << run0["algorithm"];
}

TEST_F(Recorded, FramesLimitsTheReplay) {
  const auto r = run("replay '" + rec() + "' --headless --frames 7 --algorithm screen");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("replay: run, screen, 7 frames"), std::string::npos) << r.out;
}

// A 2D recording recorded again (replay --record) is the same file: no `dim` line, the scene's comment kept.
TEST_F(Recorded, RecordedAgainIsTheSameFile) {
  const std::string again = *dir_ + "/again.nbsrec";
  const auto r = run("replay '" + rec() + "' --headless --quiet --record '" + again + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::string text = read_text(rec());
  EXPECT_EQ(text.find("\ndim"), std::string::npos) << "2D is the default";
  EXPECT_NE(text.find("headless --record: scene "), std::string::npos);
  EXPECT_TRUE(read_text(again) == text);
  const auto part = run("replay '" + rec() + "' --headless --quiet --frames 7 --record '" + *dir_ + "/part.nbsrec'");
  ASSERT_EQ(part.exit_code, 0) << part.err;
  EXPECT_EQ(frames_of(read_text(*dir_ + "/part.nbsrec")).size(), 7u) << "the frames replayed";
}

// `replay --frames N` reads N frames: from a simulation's pipe (a FIFO fed by awk here) it replays
// them and stops. The pipe's 5 MB of frames end in a NUL byte, which a reader of the whole input
// refuses (exit 2): read whole first, an endless pipe ran to the 2 GB limit.
TEST(Replay, FramesOfAPipeAreReadOnlyAsFarAsTheyAreReplayed) {
  const std::string dir = scratch_dir("replay_long_pipe");
  const std::string fifo = dir + "/frames.nbsrec";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string writer = "(timeout 20 awk 'BEGIN { print \"nbsrec 1\"; for (i = 0; i < 200000; i++) printf \"frame %d %d\\n0,0,1\\n1.5,0,1\\n\", i, i }'; printf '\\000') > '" +
                             fifo + "' &";
  const auto r = run("replay '" + fifo + "' --headless --frames 2 --algorithm nbs --report '" + dir + "/r.json'", writer);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("replay: frames, nbs, 2 frames"), std::string::npos) << r.out;
  const json frames = json::parse(read_text(dir + "/r.json"))["runs"][0]["frames"];
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[1]["pairs"]["A"], 1);  // (0,0) and (1.5,0), radius 1: in contact
}

// ---- faults ------------------------------------------------------------------------------------

TEST_F(Recorded, FaultsThatNeedNoBox2dAreCaughtByAEqualsR) {
  for (const char* fault : {"drop-pair", "drop-mask-cell", "off-by-one-cell", "stale-positions"}) {
    const std::string report = *dir_ + "/fault-" + fault + ".json";
    const auto r = run("replay '" + rec() + "' --headless --frames 20 --inject-fault " + fault + " --report '" + report + "'");
    EXPECT_EQ(r.exit_code, 1) << fault << ": " << r.out << r.err;
    EXPECT_NE(r.out.find("(A==R "), std::string::npos) << fault << ": " << r.out;
    EXPECT_NE(r.out.find("not checked (recorded frames have no Box2D world)"), std::string::npos) << r.out;
    const json rep = json::parse(read_text(report));
    EXPECT_EQ(rep["passed"], false);
    EXPECT_GT(rep["runs"][0]["violations"]["by_invariant"]["A==R"].get<int>(), 0) << fault;
  }
}

TEST_F(Recorded, Box2dFaultIsRefused) {
  const auto r = run("replay '" + rec() + "' --headless --inject-fault drop-box2d-contact");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_EQ(r.err.rfind("nbscope: error: --inject-fault drop-box2d-contact: recorded frames have no Box2D contact list", 0), 0u) << r.err;
}

TEST(Replay, PinnedGridIsRecordedAndReplayed) {
  const std::string dir = scratch_dir("replay_book");
  const auto r = run("headless --scene '" + scene("book-fig-3-15") + "' --frames 5 --record '" + dir + "/book.nbsrec'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  std::string header;
  EXPECT_EQ(frames_of(read_text(dir + "/book.nbsrec"), &header).size(), 6u);
  EXPECT_NE(header.find("\ncell_size 1\n"), std::string::npos) << header;
  EXPECT_NE(header.find("\norigin 0,0\n"), std::string::npos) << header;
  EXPECT_NE(header.find("\ncells 10,10\n"), std::string::npos) << header;
  const auto p = run("replay '" + dir + "/book.nbsrec' --headless --algorithm all");
  EXPECT_EQ(p.exit_code, 0) << p.out << p.err;
}

// ---- bad input ---------------------------------------------------------------------------------

TEST(Replay, BadRecordingsExit2WithOneLineAndNoFiles) {
  struct Case {
    const char* name;
    std::string text;
    std::string expected;  // after "nbscope: error: <file>:"
  };
  const std::string head = "nbsrec 1\nframe 0 0\n0,0,1\n";
  const Case cases[] = {
      {"empty", "", "1: empty file"},
      {"no_header", "frame 0 0\n0,0,1\n", "1: expected 'nbsrec 1'"},
      {"bad_version", "nbsrec 7\nframe 0 0\n", "1: 'nbsrec 7': this nbscope reads version 1"},
      {"no_frames", "nbsrec 1\n# nothing\n", "2: no frames"},
      {"frame_not_increasing", head + "frame 0 1\n", "4: frame 0 after frame 0: frame numbers must increase"},
      {"time_decreasing", "nbsrec 1\nframe 0 1\nframe 1 0.5\n", "3: frame 1: time 0.5 is before frame 0's 1"},
      {"bad_row", head + "1,1,1\n1,one,1\n", "5: y: 'one' is not a number"},
      {"nan", head + "nan,1,1\n", "4: x: 'nan' is not a finite number"},
      {"r_zero", head + "1,1,0\n", "4: r: radius must be > 0"},
      {"r_negative", head + "1,1,-1\n", "4: r: radius must be > 0"},
      {"three_d", head + "1,1,1,1\n", "4: 4 columns (x,y,z,r) in a 2D recording: add 'dim 3' before the first frame"},
  };
  for (const Case& c : cases) {
    const std::string dir = scratch_dir(std::string("replay_bad_") + c.name);
    const std::string file = dir + "/in.nbsrec";
    write_text(file, c.text);
    const auto r = run("replay '" + file + "' --headless --report '" + dir + "/r.json'");
    EXPECT_EQ(r.exit_code, 2) << c.name;
    EXPECT_EQ(r.out, "") << c.name;
    EXPECT_EQ(lines(r.err), 1u) << c.name << ": " << r.err;
    const std::string prefix = "nbscope: error: " + file + ":" + c.expected;
    EXPECT_EQ(r.err.rfind(prefix, 0), 0u) << c.name << ":\n got: " << r.err << " want: " << prefix;
    EXPECT_EQ(files_in(dir), std::vector<std::string>{"in.nbsrec"}) << c.name;
  }
  const std::string dir = scratch_dir("replay_bad_usage");
  for (const std::string& args : {std::string("replay --headless"), "replay '" + dir + "/missing.nbsrec' --headless",
                                  std::string("replay a.nbsrec b.nbsrec --headless"), std::string("replay x.nbsrec --headless --frames 0")}) {
    const auto r = run(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(lines(r.err), 1u) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("nbscope: error: ", 0), 0u) << r.err;
  }
}

// ---- outputs -----------------------------------------------------------------------------------

TEST(Replay, UnwritableRecordIsRefusedBeforeAnyFrameRuns) {
  const std::string dir = scratch_dir("replay_unwritable");
  fs::create_directory(dir + "/adir");
  for (const std::string& out : {dir + "/no/such/dir/out.nbsrec", dir + "/adir"}) {
    // 10 million frames would take hours: exiting at once shows nothing ran.
    const auto r = run("headless --scene '" + scene("default") + "' --frames 10000000 --record '" + out + "' --report '" + dir + "/r.json'");
    EXPECT_EQ(r.exit_code, 2) << out;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(lines(r.err), 1u) << r.err;
    EXPECT_EQ(r.err.rfind("nbscope: error: " + out + ": cannot write", 0), 0u) << r.err;
    EXPECT_EQ(files_in(dir), std::vector<std::string>{"adir"});
    EXPECT_TRUE(fs::is_empty(dir + "/adir"));
  }
}

TEST(Replay, InterruptedRecordingLeavesNoFile) {
  const std::string dir = scratch_dir("replay_interrupted");
  const std::string cmd = "'" + testcli::binary() + "' headless --scene '" + scene("default") + "' --frames 10000000 --quiet --record '" + dir +
                          "/out.nbsrec' </dev/null >'" + dir + "/../replay_interrupted.out' 2>'" + dir +
                          "/../replay_interrupted.err' & pid=$!; "
                          // Once the recording's temporary exists (frames are running), stop it.
                          "for i in $(seq 200); do ls '" + dir + "' | grep -q tmp && break; sleep 0.05; done; sleep 0.3; "
                          "kill -TERM $pid; wait $pid";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const std::string err = read_text(dir + "/../replay_interrupted.err");
  EXPECT_EQ(err.rfind("nbscope: error: interrupted: " + dir + "/out.nbsrec not written", 0), 0u) << err;
  EXPECT_TRUE(fs::is_empty(dir)) << "neither the recording nor its temporary may remain";
}

#ifdef NBSCOPE_TEST_GUI
TEST_F(Recorded, HeadlessScreenshotOfTheLastRecordedFrame) {
  const std::string png = *dir_ + "/replay.png";
  const auto r = run("replay '" + rec() + "' --headless --screenshot '" + png + "' --size 960x540 --no-timings --select 12");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(fs::file_size(png) > 10000) << "a real picture";
}

// The window itself on a recording, scripted (plays to the last frame, saves, exits) under Xvfb.
TEST_F(Recorded, WindowPlaysTheRecordingUnderXvfb) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string png = *dir_ + "/window.png";
  const std::string cmd = testcli::on_display() + " '" + testcli::binary() + "' replay '" + rec() + "' --screenshot '" + png +
                          "' --size 640x360 --no-timings </dev/null >/dev/null 2>'" + *dir_ + "/window.err'";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << read_text(*dir_ + "/window.err");
  EXPECT_NE(read_text(*dir_ + "/window.err").find("nbscope: window: 61 frames"), std::string::npos) << read_text(*dir_ + "/window.err");
  EXPECT_TRUE(fs::exists(png));
}
#endif

}  // namespace
}  // namespace nbscope
