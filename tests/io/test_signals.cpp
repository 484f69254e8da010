// io/signals: the one handler for SIGINT, SIGTERM and SIGHUP, as a chain — a loop stopping on the
// signal (the window, headless --record) notes it and lives on, its temporaries left for it to
// remove as it unwinds; with no loop listening, every registered cleanup (the atomic outputs' live
// temporaries and any other) runs and the process ends by that signal. Each case runs in a child
// process, so that the test binary's own signal actions stay untouched.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>

#include "io/atomic_file.hpp"
#include "io/signals.hpp"

namespace nbscope {
namespace {

namespace fs = std::filesystem;

std::string fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("nbscope-signals-" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

// Runs `body` in a child; returns its wait status (the child exits with body's value).
int in_child(const std::function<int()>& body) {
  const pid_t pid = ::fork();
  if (pid == 0) std::_Exit(body());
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

// A second cleanup beside the atomic outputs': it leaves a mark (async-signal-safe: open, close).
const char* g_mark_path = nullptr;
void leave_mark() {
  if (g_mark_path != nullptr) ::close(::open(g_mark_path, O_CREAT | O_WRONLY, 0600));
}

TEST(Signals, OneSigtermStopsTheLoopFirstThenEndsTheRunWithEveryCleanup) {
  const std::string dir = fresh_dir("chain");
  const std::string temp = dir + "/out.tmp.1", mark = dir + "/cleaned";
  const int status = in_child([&] {
    g_mark_path = mark.c_str();
    arm_signal_cleanup(&leave_mark);
    LiveTemporary live(temp);  // the atomic output's cleanup, registered like every AtomicFileWriter's
    std::ofstream(temp) << "half a file";
    {
      StopOnSignals loop;  // headless --record's loop
      ::raise(SIGTERM);
      if (stop_signal() != SIGTERM || !stop_requested()) return 10;  // the loop's flag: noted
      if (!fs::exists(temp) || fs::exists(mark)) return 11;          // no cleanup: the loop unwinds itself
    }
    ::raise(SIGTERM);  // the loop is gone: the cleanups run and the process ends by SIGTERM
    return 12;
  });
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit " << (WIFEXITED(status) ? WEXITSTATUS(status) : -1);
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_FALSE(fs::exists(temp)) << "the atomic output's temporary was left";
  EXPECT_TRUE(fs::exists(mark)) << "the other cleanup did not run";
}

TEST(Signals, TheWindowsStopHoldsForTheRestOfTheRunAndLeavesHangupToTheCleanup) {
  const std::string dir = fresh_dir("window");
  const std::string temp = dir + "/shot.png.tmp.1";
  const int status = in_child([&] {
    install_stop_handlers();
    for (const int sig : {SIGINT, SIGTERM}) {
      ::raise(sig);
      if (stop_signal() != sig) return 10;
    }
    LiveTemporary live(temp);  // the screenshot written after the window closed
    std::ofstream(temp) << "half a picture";
    ::raise(SIGTERM);
    if (!fs::exists(temp)) return 11;  // still the window's: noted, not removed
    ::raise(SIGHUP);                   // nobody stops on it: removed, and the run ends
    return 12;
  });
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit " << (WIFEXITED(status) ? WEXITSTATUS(status) : -1);
  EXPECT_EQ(WTERMSIG(status), SIGHUP);
  EXPECT_FALSE(fs::exists(temp));
}

TEST(Signals, AnIgnoredHangupStaysIgnoredAndTheActionsBeforeALoopComeBack) {
  const int status = in_child([] {
    std::signal(SIGHUP, SIG_IGN);  // nohup
    struct sigaction term_before {};
    ::sigaction(SIGTERM, nullptr, &term_before);
    {
      StopOnSignals loop;
      ::raise(SIGHUP);
      if (stop_signal() != 0) return 10;  // ignored, not noted
    }
    struct sigaction term {};
    ::sigaction(SIGTERM, nullptr, &term);
    if (term.sa_handler != term_before.sa_handler) return 11;  // what was there before the loop
    struct sigaction hup {};
    ::sigaction(SIGHUP, nullptr, &hup);
    return hup.sa_handler == SIG_IGN ? 0 : 12;
  });
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

TEST(Signals, NamesTheEndingSignals) {
  EXPECT_STREQ(signal_name(SIGINT), "SIGINT");
  EXPECT_STREQ(signal_name(SIGTERM), "SIGTERM");
  EXPECT_STREQ(signal_name(SIGHUP), "SIGHUP");
  EXPECT_STREQ(signal_name(SIGUSR1), "a signal");
}

}  // namespace
}  // namespace nbscope
