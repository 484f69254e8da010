// Long runs through the binary: peak memory that does not grow with --frames, signals that end a
// run leaving no temporary file, and an error that is the only line on stderr.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <thread>
#include <gtest/gtest.h>

#include "support/run_cli.hpp"

namespace nbscope {
namespace {

namespace fs = std::filesystem;
using testcli::read_text;
using testcli::scratch_dir;
using testcli::write_text;

// A started nbscope: stdout and stderr to files, optionally without a display.
struct Child {
  pid_t pid = -1;
  std::string out, err;
};

Child start(const std::vector<std::string>& args, const std::string& dir, bool no_display = false,
            const std::string& stdout_path = "") {
  Child c;
  c.out = stdout_path.empty() ? dir + "/stdout.txt" : stdout_path;
  c.err = dir + "/stderr.txt";
  c.pid = ::fork();
  if (c.pid == 0) {
    if (no_display) {
      ::unsetenv("DISPLAY");
      ::unsetenv("WAYLAND_DISPLAY");
    }
    const int in = ::open("/dev/null", O_RDONLY);
    const int out = ::open(c.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(c.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(in, 0);
    ::dup2(out, 1);
    ::dup2(err, 2);
    std::vector<char*> argv{const_cast<char*>(testcli::binary().c_str())};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    std::_Exit(127);
  }
  return c;
}

// Waits for `c`; its wait status, and its peak resident memory in KB when `max_rss_kb` is given.
int wait_for(const Child& c, long* max_rss_kb = nullptr) {
  int status = 0;
  struct rusage ru {};
  ::wait4(c.pid, &status, 0, &ru);
  if (max_rss_kb != nullptr) *max_rss_kb = ru.ru_maxrss;
  return status;
}

std::size_t lines(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

std::vector<std::string> names_in(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// True once a file whose name contains `part` is in `dir` (waits up to 20 s).
bool appears(const std::string& dir, const std::string& part) {
  for (int i = 0; i < 2000; ++i) {
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().find(part) != std::string::npos) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

// Three circles on a ground box: a frame costs microseconds, so a long run is quick.
std::string small_scene(const std::string& dir) {
  const std::string path = dir + "/small.json";
  write_text(path, R"({"name": "small", "bodies": [
    {"type": "static", "shape": "box", "half_extents": [10, 0.5], "position": [0, -0.5]},
    {"type": "dynamic", "shape": "circle", "radius": 0.5, "position": [0, 2]},
    {"type": "dynamic", "shape": "circle", "radius": 0.5, "position": [0.6, 4]},
    {"type": "dynamic", "shape": "circle", "radius": 0.5, "position": [-0.6, 6]}]})");
  return path;
}

std::string assets_scene(const std::string& name) { return std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/" + name + ".json"; }

// ---- memory -----------------------------------------------------------------------------------

// Peak RSS of `headless --frames N --report R` on a small scene, in KB; the report is checked to hold N frames.
long peak_rss_kb(const std::string& dir, std::int64_t frames) {
  const std::string report = dir + "/r" + std::to_string(frames) + ".json";
  const Child c = start({"headless", "--scene", small_scene(dir), "--frames", std::to_string(frames), "--quiet", "--report", report}, dir);
  long kb = 0;
  const int status = wait_for(c, &kb);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(c.err);
  // Every frame is in it: one "hash" key each (parsing 20 MB of JSON would cost more than the run).
  const std::string text = read_text(report);
  std::size_t hashes = 0;
  for (std::size_t at = text.find("\"hash\":\""); at != std::string::npos; at = text.find("\"hash\":\"", at + 1)) ++hashes;
  EXPECT_EQ(hashes, static_cast<std::size_t>(frames + 1));  // frames 0..N
  fs::remove(report);
  return kb;
}

TEST(LongRun, PeakMemoryDoesNotGrowWithFrames) {
#ifdef NBSCOPE_SANITIZED_BUILD
  GTEST_SKIP() << "the sanitizers' shadow memory and quarantine make RSS meaningless";
#endif
  const std::string dir = scratch_dir("longrun_rss");
  const long small = peak_rss_kb(dir, 2'000);
  const long large = peak_rss_kb(dir, 40'000);
  // Kept per frame, the 38,000 frames more took ~25 MB (a report of every frame in memory).
  EXPECT_LE(large, small * 12 / 10 + 4 * 1024) << "2,000 frames: " << small << " KB; 40,000 frames: " << large << " KB";
}

// ---- signals ----------------------------------------------------------------------------------

// headless --record stops at the next frame on SIGINT, SIGTERM and SIGHUP: exit 2, one line, no file.
TEST(LongRun, SignalsStopARecordingAndLeaveNoFile) {
  for (const int sig : {SIGHUP, SIGINT}) {
    const std::string dir = scratch_dir("longrun_record_" + std::to_string(sig));
    const std::string run_dir = dir + "/run";
    fs::create_directory(run_dir);
    const Child c = start({"headless", "--scene", assets_scene("default"), "--frames", "10000000", "--quiet", "--record",
                           run_dir + "/rec.nbsrec", "--report", run_dir + "/r.json"},
                          dir);
    ASSERT_TRUE(appears(run_dir, ".tmp.")) << "the recording's temporary never appeared";
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // some frames written
    ::kill(c.pid, sig);
    const int status = wait_for(c);
    ASSERT_TRUE(WIFEXITED(status)) << "signal " << sig;
    EXPECT_EQ(WEXITSTATUS(status), 2);
    const std::string err = read_text(c.err);
    EXPECT_EQ(lines(err), 1u) << err;
    EXPECT_EQ(err.rfind("nbscope: error: interrupted: " + run_dir + "/rec.nbsrec not written", 0), 0u) << err;
    EXPECT_NE(err.find(sig == SIGHUP ? "SIGHUP" : "SIGINT"), std::string::npos) << err;
    EXPECT_TRUE(names_in(run_dir).empty()) << "neither the recording, the report nor a temporary may remain";
  }
}

// SIGKILL cannot be caught, so a killed --record leaves REC.tmp.PID; the next write of REC removes
// it (its writer no longer runs) and says so in a note, and the run itself succeeds.
TEST(LongRun, TheNextWriteRemovesTheTemporaryOfAKilledWriter) {
  const std::string dir = scratch_dir("longrun_record_kill");
  const std::string run_dir = dir + "/run";
  fs::create_directory(run_dir);
  const std::string rec = run_dir + "/rec.nbsrec";
  const Child c = start({"headless", "--scene", assets_scene("default"), "--frames", "10000000", "--quiet", "--record", rec}, dir);
  ASSERT_TRUE(appears(run_dir, ".tmp.")) << "the recording's temporary never appeared";
  ::kill(c.pid, SIGKILL);
  int status = wait_for(c);
  ASSERT_TRUE(WIFSIGNALED(status));
  const std::string temp = "rec.nbsrec.tmp." + std::to_string(c.pid);
  ASSERT_EQ(names_in(run_dir), std::vector<std::string>{temp}) << "SIGKILL leaves the temporary";
  // A temporary of a writer that still runs (this test) is not touched.
  const std::string live = "rec.nbsrec.tmp." + std::to_string(::getpid());
  write_text(run_dir + "/" + live, "still being written");

  const Child again = start({"headless", "--scene", assets_scene("default"), "--frames", "2", "--quiet", "--record", rec}, dir);
  status = wait_for(again);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << read_text(again.err);
  const std::string err = read_text(again.err);
  EXPECT_EQ(lines(err), 1u) << err;
  EXPECT_EQ(err, "nbscope: note: " + run_dir + "/" + temp + ": removed the temporary of a writer that no longer runs (pid " +
                     std::to_string(c.pid) + ")\n");
  EXPECT_EQ(names_in(run_dir), (std::vector<std::string>{"rec.nbsrec", live}));
}

// A run without --record ends by the signal itself; its report's frames were in an unnamed file.
TEST(LongRun, ATerminatedReportRunLeavesNoFile) {
  const std::string dir = scratch_dir("longrun_report_term");
  const std::string run_dir = dir + "/run";
  fs::create_directory(run_dir);
  const Child c = start({"headless", "--scene", small_scene(dir), "--frames", "10000000", "--quiet", "--report", run_dir + "/r.json"}, dir);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ::kill(c.pid, SIGTERM);
  const int status = wait_for(c);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_TRUE(names_in(run_dir).empty());
}

// `pairs --output OUT` killed while it writes: the temporary OUT.tmp.PID is removed and the process
// ends by the signal. The temporary is made a FIFO here (created under the child's pid before the
// binary starts), so the write blocks until the test has seen it begin: no race with a fast disk.
TEST(LongRun, ASignalWhilePairsWritesRemovesItsTemporary) {
  for (const int sig : {SIGTERM, SIGINT, SIGHUP}) {
    const std::string dir = scratch_dir("longrun_pairs_" + std::to_string(sig));
    const std::string run_dir = dir + "/run";
    fs::create_directory(run_dir);
    std::string csv = "x,y,r\n";
    for (int k = 0; k < 400; ++k) csv += "0,0,1\n";  // 79,800 pairs: more than a pipe holds
    write_text(dir + "/in.csv", csv);
    const std::string out = run_dir + "/out.csv";

    int go[2];
    ASSERT_EQ(::pipe(go), 0);
    const pid_t pid = ::fork();
    if (pid == 0) {
      char byte = 0;
      ::close(go[1]);
      if (::read(go[0], &byte, 1) != 1) std::_Exit(126);
      const int null = ::open("/dev/null", O_RDWR);
      ::dup2(null, 0);
      ::dup2(null, 1);
      ::dup2(null, 2);
      ::execl(testcli::binary().c_str(), testcli::binary().c_str(), "pairs", "--input", (dir + "/in.csv").c_str(), "--output", out.c_str(),
              static_cast<char*>(nullptr));
      std::_Exit(127);
    }
    ::close(go[0]);
    const std::string temp = out + ".tmp." + std::to_string(pid);
    ASSERT_EQ(::mkfifo(temp.c_str(), 0600), 0);
    ASSERT_EQ(::write(go[1], "x", 1), 1);
    ::close(go[1]);
    const int fifo = ::open(temp.c_str(), O_RDONLY);  // returns once pairs opens its temporary
    ASSERT_GE(fifo, 0);
    char head[4] = {};
    ASSERT_EQ(::read(fifo, head, 4), 4);
    EXPECT_EQ(std::string(head, 4), "i,j\n") << "pairs is writing";
    ::kill(pid, sig);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ::close(fifo);
    ASSERT_TRUE(WIFSIGNALED(status)) << "signal " << sig;
    EXPECT_EQ(WTERMSIG(status), sig);
    EXPECT_TRUE(names_in(run_dir).empty()) << "signal " << sig << ": the temporary (or the output) remains";
  }
}

// ---- one error, one line ----------------------------------------------------------------------

TEST(LongRun, PairsWritingToAFullDeviceSaysOnlyTheError) {
  const std::string dir = scratch_dir("longrun_full");
  write_text(dir + "/in.csv", "x,y,r\n0,0,1\n1,0,1\n");
  const Child c = start({"pairs", "--input", dir + "/in.csv", "--output", "/dev/full"}, dir);
  int status = wait_for(c);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::string err = read_text(c.err);
  EXPECT_EQ(lines(err), 1u) << err;
  EXPECT_EQ(err.rfind("nbscope: error: /dev/full: cannot write", 0), 0u) << err;

  // The pairs on stdout, stdout the full device.
  const Child s = start({"pairs", "--input", dir + "/in.csv"}, dir, false, "/dev/full");
  status = wait_for(s);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  err = read_text(s.err);
  EXPECT_EQ(lines(err), 1u) << err;
  EXPECT_EQ(err.rfind("nbscope: error: stdout: cannot write", 0), 0u) << err;
}

TEST(LongRun, ReplayOfABadFileWithoutADisplaySaysOnlyTheError) {
  const std::string dir = scratch_dir("longrun_replay_bad");
  write_text(dir + "/bad.nbsrec", "nbsrec 1\nframe 0 0\n0,0\n");
  const Child c = start({"replay", dir + "/bad.nbsrec"}, dir, true);
  const int status = wait_for(c);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const std::string err = read_text(c.err);
  EXPECT_EQ(lines(err), 1u) << err;
  EXPECT_EQ(err.rfind("nbscope: error: " + dir + "/bad.nbsrec:3", 0), 0u) << err;

  // A good recording still says why no window opened, after the run.
  write_text(dir + "/good.nbsrec", "nbsrec 1\nframe 0 0\n0,0,1\n1,0,1\n");
  const Child g = start({"replay", dir + "/good.nbsrec"}, dir, true);
  const int ok = wait_for(g);
  ASSERT_TRUE(WIFEXITED(ok));
  EXPECT_EQ(WEXITSTATUS(ok), 0) << read_text(g.err);
  EXPECT_NE(read_text(g.err).find("replayed headless"), std::string::npos) << read_text(g.err);
}

#ifdef NBSCOPE_TEST_GUI
TEST(LongRun, TheWindowFallbackWithABadShaderDirSaysOnlyTheError) {
  const std::string dir = scratch_dir("longrun_gui_fallback");
  const Child c = start({"gui", "--scene", assets_scene("default"), "--frames", "1", "--shader-dir", dir + "/no-such-dir", "--screenshot",
                         dir + "/s.png"},
                        dir, true);
  const int status = wait_for(c);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const std::string err = read_text(c.err);
  EXPECT_EQ(lines(err), 1u) << err;
  EXPECT_EQ(err.rfind("nbscope: error: ", 0), 0u) << err;
}
#endif

}  // namespace
}  // namespace nbscope
