// `nbscope replay` on recordings that carry the simulation's own contact pairs (io/recording.hpp's
// `pairs` blocks): the algorithm `recorded` is what replay checks by default, with A==R per frame;
// each planted bug (a missing pair, an extra one, one given twice, an element paired with itself) is
// caught and named with its frame in the summary and the report; `recorded` beside a detector;
// `recorded` refused where it has no pairs, and with the faults that cannot act on it.
//
// The recordings are made from a real run: `headless --record` writes the elements, the reader
// reads them back, brute force (tests/support) gives the correct pairs, and RecordingWriter writes
// them with the pairs — the round trip the format promises.
//
// Index: helpers | correct pairs | planted bugs | beside a detector | refusals | base 1 | window.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>

#include "io/recording.hpp"
#include "support/generators.hpp"
#include "support/paths.hpp"
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

std::size_t lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

// ---- helpers -----------------------------------------------------------------------------------

// 20 steps of default.json recorded (frames 0..20, elements only), and each frame's brute-force pairs.
class RecordedPairs : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(scratch_dir("recorded_pairs_" + std::to_string(::getpid())));
    const auto r = run("headless --scene '" + testpaths::scene("default") + "' --frames 20 --quiet --record '" + plain() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    recording_ = new Recording(read_recording(plain()));
    ASSERT_FALSE(recording_->has_pairs);
    truth_ = new std::vector<PairList>;
    for (const RecordedFrame& f : recording_->frames) truth_->push_back(testdata::brute_pairs(f.elements));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
    delete recording_;
    delete truth_;
  }
  static std::string plain() { return *dir_ + "/plain.nbsrec"; }

  // The recording again as `name`.nbsrec with every frame's correct pairs, after `plant` changed
  // those of the frames it wants (frame index, pairs); returns its path.
  static std::string with_pairs(const std::string& name, const std::function<void(std::size_t, PairList&)>& plant = {}) {
    const std::string path = *dir_ + "/" + name + ".nbsrec";
    RecordingWriter w(path, recording_->grid, "the user's pairs: " + name);
    for (std::size_t k = 0; k < recording_->frames.size(); ++k) {
      const RecordedFrame& f = recording_->frames[k];
      PairList pairs = (*truth_)[k];
      if (plant) plant(k, pairs);
      w.write_frame(f.number, f.time, f.elements, &pairs);
    }
    w.commit();
    return path;
  }

  // The first violation of frame `frame` in report `path`'s run `run`.
  static json first_violation(const std::string& path, std::size_t run, std::size_t frame) {
    const json rep = json::parse(read_text(path));
    return rep["runs"][run]["frames"][frame]["violations"][0];
  }

  static std::string* dir_;
  static Recording* recording_;
  static std::vector<PairList>* truth_;
};
std::string* RecordedPairs::dir_ = nullptr;
Recording* RecordedPairs::recording_ = nullptr;
std::vector<PairList>* RecordedPairs::truth_ = nullptr;

// ---- correct pairs -----------------------------------------------------------------------------

TEST_F(RecordedPairs, CorrectPairsPassAndAreWhatReplayChecksByDefault) {
  // Every other pair written j,i: the order within a line is the user's choice.
  const std::string rec = with_pairs("correct", [](std::size_t, PairList& p) {
    for (std::size_t k = 0; k < p.size(); k += 2) std::swap(p[k].i, p[k].j);
  });
  const std::string report = *dir_ + "/correct.json";
  const auto r = run("replay '" + rec + "' --headless --report '" + report + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("replay: correct, recorded, 21 frames"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("A==R held in every frame"), std::string::npos) << r.out;
  const json rep = json::parse(read_text(report));
  EXPECT_EQ(rep["source"], "recording");
  EXPECT_EQ(rep["algorithms"], json({"recorded"}));
  EXPECT_EQ(rep["passed"], true);
  const json& frames = rep["runs"][0]["frames"];
  ASSERT_EQ(frames.size(), 21u);
  std::size_t with_contacts = 0;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    EXPECT_EQ(frames[k]["pairs"]["A"], (*truth_)[k].size()) << "frame " << k;
    EXPECT_EQ(frames[k]["held"]["A==R"], true);
    with_contacts += (*truth_)[k].empty() ? 0 : 1;
  }
  EXPECT_GT(with_contacts, 15u) << "frames with contacts to check";
}

// ---- planted bugs ------------------------------------------------------------------------------

// Each planted bug in frame 7 fails the replay (exit 1) and is named, with its frame, in the summary
// and in the report.
TEST_F(RecordedPairs, EachPlantedBugIsCaughtAndNamedWithItsFrame) {
  const PairList& t7 = (*truth_)[7];
  ASSERT_GT(t7.size(), 2u);
  const Pair dropped = t7[t7.size() / 2];
  // A pair that is not in contact: element 0 with the first element it does not touch.
  Pair far{0, 1};
  while (std::binary_search(t7.begin(), t7.end(), far)) ++far.j;
  struct Plant {
    const char* name;
    std::function<void(PairList&)> change;
    Pair named;
    std::string what;
  };
  const Plant plants[] = {
      {"missing", [&](PairList& p) { p.erase(std::find(p.begin(), p.end(), dropped)); }, dropped,
       "in contact (in R) but missing from the recorded pairs"},
      {"extra", [&](PairList& p) { p.push_back({far.j, far.i}); }, far, "in the recorded pairs but not in contact (not in R)"},
      {"duplicated", [&](PairList& p) { p.push_back({t7[1].j, t7[1].i}); }, t7[1], "given twice in the recorded pairs"},
      {"self", [&](PairList& p) { p.push_back({5, 5}); }, Pair{5, 5}, "an element paired with itself in the recorded pairs"},
  };
  for (const Plant& plant : plants) {
    const std::string rec = with_pairs(plant.name, [&](std::size_t k, PairList& p) {
      if (k == 7) plant.change(p);
    });
    const std::string report = *dir_ + "/" + plant.name + ".json";
    const auto r = run("replay '" + rec + "' --headless --report '" + report + "'");
    EXPECT_EQ(r.exit_code, 1) << plant.name << ": " << r.out << r.err;
    const std::string named = "1 violation in 1 frame (A==R 1), first in frame 7: A==R (" + std::to_string(plant.named.i) + ", " +
                              std::to_string(plant.named.j) + ") " + plant.what;
    EXPECT_NE(r.out.find(named), std::string::npos) << plant.name << ":\n got: " << r.out << "\nwant: " << named;
    const json rep = json::parse(read_text(report));
    EXPECT_EQ(rep["passed"], false) << plant.name;
    EXPECT_EQ(rep["runs"][0]["violations"]["first_frame"], 7) << plant.name;
    const json v = first_violation(report, 0, 7);
    EXPECT_EQ(v["invariant"], "A==R") << plant.name;
    EXPECT_EQ(v["pair"], json({plant.named.i, plant.named.j})) << plant.name;
    EXPECT_EQ(v["what"], plant.what) << plant.name;
  }
}

// drop-pair acts on the recorded pairs themselves (one dropped a frame), proving the check is live on them.
TEST_F(RecordedPairs, DropPairFaultIsCaughtOnCorrectRecordedPairs) {
  const std::string rec = with_pairs("correct_for_fault");
  const auto r = run("replay '" + rec + "' --headless --inject-fault drop-pair");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("replay: correct_for_fault, recorded, fault drop-pair"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(A==R "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("in contact (in R) but missing from the recorded pairs"), std::string::npos) << r.out;
}

// ---- beside a detector ------------------------------------------------------------------------

TEST_F(RecordedPairs, RecordedBesideNbsBlamesOnlyTheRecordedPairs) {
  const Pair dropped = (*truth_)[12].front();
  const std::string rec = with_pairs("side_by_side", [&](std::size_t k, PairList& p) {
    if (k == 12) p.erase(p.begin());
  });
  const std::string report = *dir_ + "/side_by_side.json";
  const auto r = run("replay '" + rec + "' --headless --algorithm nbs,recorded --report '" + report + "'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("replay: side_by_side, nbs,recorded, 21 frames"), std::string::npos) << r.out;
  const std::string named = "recorded: 1 violation in 1 frame (A==R 1), first in frame 12: A==R (" + std::to_string(dropped.i) + ", " +
                            std::to_string(dropped.j) + ") in contact (in R) but missing from the recorded pairs";
  EXPECT_NE(r.out.find(named), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("nbs: "), std::string::npos) << "nbs found every pair: " << r.out;
  const json rep = json::parse(read_text(report));
  ASSERT_EQ(rep["runs"].size(), 2u);
  EXPECT_EQ(rep["runs"][0]["algorithm"], "nbs");
  EXPECT_EQ(rep["runs"][0]["passed"], true);
  EXPECT_EQ(rep["runs"][1]["algorithm"], "recorded");
  EXPECT_EQ(rep["runs"][1]["passed"], false);
  EXPECT_EQ(rep["runs"][1]["frames"][12]["pairs"]["A"], (*truth_)[12].size() - 1);

  // `all` is every detector and, for a recording with pairs, `recorded` last.
  const auto all = run("replay '" + rec + "' --headless --algorithm all --report '" + *dir_ + "/all.json'");
  EXPECT_EQ(all.exit_code, 1) << all.out << all.err;
  const json a = json::parse(read_text(*dir_ + "/all.json"));
  EXPECT_EQ(a["algorithms"].front(), "nbs");
  EXPECT_EQ(a["algorithms"].back(), "recorded");
  for (const json& run0 : a["runs"]) EXPECT_EQ(run0["passed"], run0["algorithm"] != "recorded") << run0["algorithm"];
}

// ---- refusals ---------------------------------------------------------------------------------

// Exit 2, one line on stderr starting with `prefix`, nothing on stdout, no report written.
void expect_refused(const std::string& args, const std::string& prefix, const std::string& dir) {
  const std::string report = dir + "/refused.json";
  const auto r = run(args + " --report '" + report + "'");
  EXPECT_EQ(r.exit_code, 2) << args << ": " << r.out << r.err;
  EXPECT_EQ(r.out, "") << args;
  EXPECT_EQ(lines(r.err), 1u) << args << ": " << r.err;
  EXPECT_EQ(r.err.rfind("nbscope: error: " + prefix, 0), 0u) << args << ":\n got: " << r.err << "want: " << prefix;
  EXPECT_FALSE(fs::exists(report)) << args;
}

TEST_F(RecordedPairs, RecordedIsRefusedWhereItHasNoPairs) {
  // A recording without pairs blocks: replay checks nbs by default, and refuses `recorded`.
  const auto r = run("replay '" + plain() + "' --headless --frames 2");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("replay: plain, nbs, 2 frames"), std::string::npos) << r.out;
  for (const char* algorithm : {"recorded", "nbs,recorded"})
    expect_refused("replay '" + plain() + "' --headless --algorithm " + algorithm,
                   "recorded: " + plain() + " carries no pairs (no frame has a 'pairs' block)", *dir_);
  for (const char* algorithm : {"recorded", "nbs,recorded"})
    expect_refused("headless --scene '" + testpaths::scene("default") + "' --frames 2 --algorithm " + algorithm,
                   "--algorithm recorded: the pairs a recording carries (nbscope replay FILE.nbsrec); a scene has none", *dir_);
}

TEST_F(RecordedPairs, FaultsOnDetectionsInputAreRefusedForRecorded) {
  const std::string rec = with_pairs("faults");
  for (const char* fault : {"stale-positions", "drop-mask-cell", "off-by-one-cell"}) {
    // The default (recorded) and an explicit one alike.
    for (const char* algorithm : {"", " --algorithm recorded", " --algorithm nbs,recorded"})
      expect_refused("replay '" + rec + "' --headless --inject-fault " + fault + algorithm,
                     std::string("--inject-fault ") + fault + ": emulates a bug in a detector's input or cells, and the recorded pairs are read", *dir_);
    // A detector on the same file takes the fault, and the check catches it.
    const auto r = run("replay '" + rec + "' --headless --algorithm nbs --inject-fault " + fault);
    EXPECT_EQ(r.exit_code, 1) << fault << ": " << r.out << r.err;
  }
  expect_refused("replay '" + rec + "' --headless --step 3 --screenshot '" + *dir_ + "/x.png'",
                 "--step: recorded records no operations to step through", *dir_);
}

TEST_F(RecordedPairs, BadPairsBlocksExit2NamingTheLine) {
  const std::string dir = scratch_dir("recorded_pairs_bad");
  const std::string file = dir + "/in.nbsrec";
  write_text(file, "nbsrec 1\nbase 1\nframe 0 0\n0,0,1\n1,0,1\npairs\n1,2\nframe 1 0\n0,0,1\n1,0,1\npairs\n2,3\n");
  expect_refused("replay '" + file + "' --headless", file + ":12: pair 2,3: frame 1 has 2 elements (1..2)", dir);
  write_text(file, "nbsrec 1\nframe 0 0\n0,0,1\n1,0,1\npairs\n0,1\nframe 1 0\n0,0,1\n1,0,1\n");
  expect_refused("replay '" + file + "' --headless --algorithm nbs",
                 file + ":7: frame 1 has no pairs block, but frame 0 has one: give every frame its pairs, or none", dir);
}

// ---- base 1 ----------------------------------------------------------------------------------

TEST(RecordedPairsBase1, PlantedBugsAreNamedAsTheFileNumbersThemToo) {
  const std::string dir = scratch_dir("recorded_pairs_base1");
  const std::string file = dir + "/fortran.nbsrec";
  // Elements 1 and 2 touch, 3 is alone; frame 2 repeats the pair (written the other way round).
  write_text(file, "nbsrec 1\nbase 1\nframe 0 0\n0.5,0.5,0.5\n1.4,0.5,0.5\n5,5,0.5\npairs\n1,2\n"
                   "frame 1 0.1\n0.5,0.5,0.5\n1.4,0.5,0.5\n5,5,0.5\npairs\n2,1\n"
                   "frame 2 0.2\n0.5,0.5,0.5\n1.4,0.5,0.5\n5,5,0.5\npairs\n1,2\n2,1\n");
  const auto r = run("replay '" + file + "' --headless --report '" + dir + "/r.json'");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("first in frame 2: A==R (0, 1; the file's 1,2) given twice in the recorded pairs"), std::string::npos) << r.out;
  const json rep = json::parse(read_text(dir + "/r.json"));
  EXPECT_EQ(rep["runs"][0]["frames"][2]["violations"][0]["pair"], json({0, 1})) << "element ids stay 0-based rows";
  EXPECT_NE(rep["note"].get<std::string>().find("the recording numbers its pairs from 1"), std::string::npos) << rep["note"];
  // Frames 0 and 1 were right.
  EXPECT_EQ(rep["runs"][0]["frames"][0]["held"]["A==R"], true);
  EXPECT_EQ(rep["runs"][0]["frames"][1]["held"]["A==R"], true);
}

// ---- the window -----------------------------------------------------------------------------

#ifdef NBSCOPE_TEST_GUI
// The window on the user's pairs, scripted under Xvfb: it opens on `recorded`, plays every frame and
// fails (exit 1) on the planted bug; and the headless picture of the same.
TEST_F(RecordedPairs, WindowChecksTheRecordedPairsUnderXvfb) {
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const std::string rec = with_pairs("window", [](std::size_t k, PairList& p) {
    if (k == 9) p.push_back({3, 3});
  });
  const std::string png = *dir_ + "/window.png";
  const std::string cmd = testcli::on_display() + " '" + testcli::binary() + "' replay '" + rec + "' --screenshot '" + png +
                          "' --size 960x540 --no-timings --panels +violations,+timeline </dev/null >/dev/null 2>'" + *dir_ + "/window.err'";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1) << "the planted pair fails the check: " << read_text(*dir_ + "/window.err");
  EXPECT_NE(read_text(*dir_ + "/window.err").find("nbscope: window: 21 frames"), std::string::npos) << read_text(*dir_ + "/window.err");
  EXPECT_TRUE(fs::file_size(png) > 10000) << "a real picture";
  const auto h = run("replay '" + rec + "' --headless --screenshot '" + *dir_ + "/headless.png' --size 960x540 --no-timings --overlays +lists");
  EXPECT_EQ(h.exit_code, 1) << h.out << h.err;
  EXPECT_TRUE(fs::file_size(*dir_ + "/headless.png") > 10000);
}
#endif

}  // namespace
}  // namespace nbscope
