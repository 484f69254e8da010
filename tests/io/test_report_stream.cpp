// The headless report streamed frame by frame (io/report_json.hpp), a run's aggregates
// (check/report.hpp), and temporaries removed when a signal ends the process (io/atomic_file.hpp).
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "check/report.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/report_json.hpp"

namespace nbscope {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Nothing per frame lives in a run's aggregates: memory cannot grow with --frames through them.
template <class T>
concept HasFrames = requires(T t) { t.frames; };
static_assert(!HasFrames<AlgorithmRun>, "AlgorithmRun aggregates; frames are streamed (RunReportWriter)");
static_assert(!HasFrames<RunReport>, "RunReport aggregates; frames are streamed (RunReportWriter)");

std::string fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("nbscope-report-stream-" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::vector<std::string> names_in(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Frame `n` of a made-up run: every third frame breaks A==R once (listed), every fifth T-in-A
// twice (one listed); timings grow with n.
FrameReport frame(std::int64_t n, std::uint64_t hash) {
  FrameReport f;
  f.frame = n;
  f.hash = hash;
  f.checked = true;
  f.box2d_stepped = true;
  f.reference = n % 2 == 0 ? "brute" : "sort";
  f.counts.elements = 10 + n;
  f.timings = {0.5 * static_cast<double>(n), 1.0, 2.0};
  if (n % 3 == 0) {
    f.broken[static_cast<std::size_t>(Invariant::AEqualsR)] = 1;
    f.violations.push_back({n, Invariant::AEqualsR, {1, 2}, {}, {}, "missing from A"});
  }
  if (n % 5 == 0) {
    f.broken[static_cast<std::size_t>(Invariant::TInA)] = 2;
    f.violations.push_back({n, Invariant::TInA, {3, 4}, {}, {}, "touching, not in A"});
  }
  return f;
}

RunReport report_of(const std::vector<std::string>& algorithms, std::int64_t frames) {
  RunReport r;
  r.scene_path = "made-up.json";
  r.scene_name = "made-up";
  r.fault = "none";
  r.frames_requested = frames;
  for (const std::string& a : algorithms) r.runs.push_back(AlgorithmRun{a});
  return r;
}

TEST(RunAggregate, CountsAndTimingsAsTheFramesCome) {
  AlgorithmRun run{"nbs"};
  for (std::int64_t n = 1; n <= 15; ++n) run.add(frame(n, 0));
  EXPECT_EQ(run.frames_run, 15);
  // Frames 3, 6, 9, 12, 15 break A==R once each; 5, 10, 15 break T-in-A twice each.
  EXPECT_EQ(run.broken[static_cast<std::size_t>(Invariant::AEqualsR)], 5);
  EXPECT_EQ(run.broken[static_cast<std::size_t>(Invariant::TInA)], 6);
  EXPECT_EQ(run.violations, 11);
  EXPECT_EQ(run.listed, 5 + 3);
  EXPECT_EQ(run.frames_with_violations, 7);  // 3 5 6 9 10 12 15
  EXPECT_EQ(run.first_violation_frame, 3);
  ASSERT_TRUE(run.first_listed);
  EXPECT_EQ(run.first_listed->frame, 3);
  EXPECT_FALSE(run.passed());
  EXPECT_EQ(run.references.at("brute"), 7);
  EXPECT_EQ(run.references.at("sort"), 8);
  EXPECT_EQ(run.last_elements, 25);
  EXPECT_DOUBLE_EQ(run.physics.total, 0.5 * 120);  // 0.5 * (1 + ... + 15)
  EXPECT_DOUBLE_EQ(run.physics.max, 7.5);
  EXPECT_DOUBLE_EQ(run.physics.mean(run.frames_run), 4.0);
  EXPECT_DOUBLE_EQ(run.check.mean(run.frames_run), 2.0);

  AlgorithmRun clean{"nbs"};
  for (std::int64_t n = 1; n <= 2; ++n) clean.add(frame(n, 0));
  EXPECT_TRUE(clean.passed());
  FrameReport unchecked = frame(1, 0);
  unchecked.checked = false;
  clean.add(unchecked);
  EXPECT_FALSE(clean.passed()) << "a frame not checked did not pass";
}

TEST(RunReportWriter, FramesReachTheDiskWhileTheRunGoesOnAndTheFileOnlyAtCommit) {
  const std::string dir = fresh_dir("streams");
  const std::string path = dir + "/r.json";
  RunReport report = report_of({"nbs", "screen"}, 300);
  std::vector<std::vector<FrameReport>> kept(2);  // what a whole-in-memory report would hold
  RunReportWriter writer(path, 2);
  std::int64_t before = writer.spooled_bytes();
  for (std::int64_t n = 1; n <= 300; ++n) {
    for (std::size_t r = 0; r < 2; ++r) {
      const FrameReport f = frame(n, static_cast<std::uint64_t>(n * 10 + r));
      report.runs[r].add(f);
      writer.add_frame(r, f);
      kept[r].push_back(f);
    }
    if (n % 50 == 0) {
      const std::int64_t now = writer.spooled_bytes();
      EXPECT_GT(now, before) << "frame " << n << "'s report is on disk, not held for the end";
      before = now;
    }
  }
  EXPECT_TRUE(names_in(dir).empty()) << "no file, named or temporary, is visible before commit";
  writer.commit(report);
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"r.json"});

  const std::string text = read_all(path);
  EXPECT_EQ(text, run_report_json(report, kept)) << "streamed and whole give the same bytes";
  const json j = json::parse(text);
  ASSERT_EQ(j["runs"].size(), 2u);
  for (std::size_t r = 0; r < 2; ++r) {
    const json& run = j["runs"][r];
    EXPECT_EQ(run["algorithm"], r == 0 ? "nbs" : "screen");
    EXPECT_EQ(run["frames_run"], 300);
    ASSERT_EQ(run["frames"].size(), 300u);
    for (std::size_t k = 0; k < 300; ++k) {
      EXPECT_EQ(run["frames"][k]["frame"], k + 1);
      char hash[24];
      std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>((k + 1) * 10 + r));
      EXPECT_EQ(run["frames"][k]["hash"], hash);
    }
    // 300 frames: 100 break A==R once, 60 T-in-A twice.
    EXPECT_EQ(run["violations"]["total"], 100 + 120);
    EXPECT_EQ(run["violations"]["first_frame"], 3);
  }
  EXPECT_EQ(j["violations_total"], 2 * 220);
  EXPECT_EQ(j["passed"], false);
}

TEST(RunReportWriter, GoingBackToAMarkDropsTheFramesAfterIt) {
  const std::string dir = fresh_dir("rewind");
  const std::string path = dir + "/r.json";
  RunReport report = report_of({"nbs"}, 10);
  RunReportWriter writer(path, 1);
  std::optional<RunReportWriter::Mark> mark;
  std::vector<AlgorithmRun> runs_at_mark;
  for (std::int64_t n = 1; n <= 8; ++n) {
    const FrameReport f = frame(n, 1000 + static_cast<std::uint64_t>(n));
    report.runs[0].add(f);
    writer.add_frame(0, f);
    if (n == 4) {
      mark = writer.mark();
      runs_at_mark = report.runs;
    }
  }
  writer.back_to(*mark);
  report.runs = runs_at_mark;
  for (std::int64_t n = 5; n <= 10; ++n) {  // run again, differently
    const FrameReport f = frame(n, 2000 + static_cast<std::uint64_t>(n));
    report.runs[0].add(f);
    writer.add_frame(0, f);
  }
  writer.commit(report);
  const json j = json::parse(read_all(path));
  const json& frames = j["runs"][0]["frames"];
  ASSERT_EQ(frames.size(), 10u) << "frames 5..8 of the first pass are gone";
  for (std::size_t k = 0; k < 10; ++k) {
    EXPECT_EQ(frames[k]["frame"], k + 1);
    char hash[24];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>((k < 4 ? 1000 : 2000) + k + 1));
    EXPECT_EQ(frames[k]["hash"], hash) << "frame " << k + 1;
  }
  EXPECT_EQ(j["runs"][0]["frames_run"], 10);
}

TEST(RunReportWriter, ARunWithNoFramesIsStillAReport) {
  const std::string dir = fresh_dir("empty");
  RunReport report = report_of({"nbs"}, 0);
  RunReportWriter writer(dir + "/r.json", 1);
  writer.commit(report);
  const json j = json::parse(read_all(dir + "/r.json"));
  EXPECT_TRUE(j["runs"][0]["frames"].empty());
  EXPECT_EQ(read_all(dir + "/r.json"), run_report_json(report, {}));
}

TEST(RunReportWriter, AFullDeviceIsAnErrorAtCommit) {
  RunReport report = report_of({"nbs"}, 3);
  RunReportWriter writer("/dev/full", 1);  // its frames go to a scratch file in $TMPDIR or /tmp
  for (std::int64_t n = 1; n <= 3; ++n) writer.add_frame(0, frame(n, 0));
  try {
    writer.commit(report);
    FAIL() << "writing to /dev/full succeeded";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("/dev/full: cannot write", 0), 0u) << e.what();
  }
}

// ---- temporaries and signals --------------------------------------------------------------

TEST(LiveTemporary, RegisteredWhileWrittenAndReleasedAfterwards) {
  const std::string dir = fresh_dir("live");
  const std::size_t before = live_temporary_count();
  write_file_atomically(dir + "/a.txt", [&](std::ostream& out) {
    EXPECT_EQ(live_temporary_count(), before + 1) << "the temporary is registered while it is written";
    out << "a";
  });
  EXPECT_EQ(live_temporary_count(), before);
  EXPECT_THROW(write_file_atomically(dir + "/b.txt", [](std::ostream&) { throw Error("fill failed"); }), Error);
  EXPECT_EQ(live_temporary_count(), before) << "released when the write fails too";
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"a.txt"});
  {
    AtomicFileWriter w(dir + "/c.txt");
    EXPECT_EQ(live_temporary_count(), before + 1);
  }
  EXPECT_EQ(live_temporary_count(), before);
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"a.txt"});
}

TEST(LiveTemporary, RemovingTheLiveOnesLeavesOthers) {
  const std::string dir = fresh_dir("remove");
  std::ofstream(dir + "/live.tmp") << "x";
  std::ofstream(dir + "/released.tmp") << "x";
  LiveTemporary live(dir + "/live.tmp");
  LiveTemporary released(dir + "/released.tmp");
  released.release();
  remove_live_temporaries();
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"released.tmp"});
}

// In a child process: `ignore_hup` or not, a temporary registered and partly written, then `sig`.
// Returns the child's wait status.
int child_raising(int sig, const std::string& temp, bool ignore_hup) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (ignore_hup) std::signal(SIGHUP, SIG_IGN);
    LiveTemporary live(temp);
    std::ofstream(temp) << "half a file";
    ::raise(sig);
    std::_Exit(0);  // only when the signal is ignored
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

TEST(LiveTemporary, EachEndingSignalRemovesItAndEndsTheProcessByThatSignal) {
  const std::string dir = fresh_dir("signals");
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
    const int status = child_raising(sig, dir + "/out.tmp.1", false);
    ASSERT_TRUE(WIFSIGNALED(status)) << "signal " << sig;
    EXPECT_EQ(WTERMSIG(status), sig);
    EXPECT_TRUE(names_in(dir).empty()) << "signal " << sig << " left the temporary";
  }
}

TEST(LiveTemporary, AnIgnoredHangupStaysIgnored) {
  const std::string dir = fresh_dir("nohup");
  const int status = child_raising(SIGHUP, dir + "/out.tmp.1", true);
  ASSERT_TRUE(WIFEXITED(status)) << "nohup's SIGHUP ended the process";
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(names_in(dir), std::vector<std::string>{"out.tmp.1"}) << "nothing ended, so nothing was removed";
}

TEST(ScratchFile, HasNoNameAndCutsBack) {
  const std::string dir = fresh_dir("scratch");
  ScratchFile f(dir + "/out.json");
  f.write("hello, ");
  f.write("world");
  EXPECT_EQ(f.size(), 12);
  EXPECT_EQ(f.bytes_on_disk(), 12);
  EXPECT_TRUE(names_in(dir).empty());
  f.truncate(5);
  f.write("!");
  std::ostringstream out;
  f.copy_to(out);
  EXPECT_EQ(out.str(), "hello!");
}

}  // namespace
}  // namespace nbscope
