// io/signals.hpp's crash report (the guard around a detector plugin's call): armed, a crash is one
// line and exit 2; disarmed, the signal goes to the action it replaced, so nbscope's own crashes
// (and AddressSanitizer's reports) stay what they were. Death tests: each case runs in a child.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <csignal>

#include "io/signals.hpp"

namespace nbscope {
namespace {

void no_core_file() {
  struct rlimit none {};
  ::setrlimit(RLIMIT_CORE, &none);
}

// A real fault, not UBSan's report of it (the sanitized build would abort first, as SIGABRT).
[[noreturn, gnu::no_sanitize("undefined")]] void write_through_null() {
  no_core_file();
  volatile int* nowhere = nullptr;
  *nowhere = 1;
  std::abort();  // not reached
}

// The child's end when the signal went back to the action the report replaced.
bool handed_back(int status, int sig) {
#ifdef NBSCOPE_SANITIZED_BUILD
  (void)sig;  // AddressSanitizer's handler reports and exits 1
  return !(WIFEXITED(status) && WEXITSTATUS(status) == 2);
#else
  return WIFSIGNALED(status) && WTERMSIG(status) == sig;
#endif
}

TEST(CrashReport, ArmedCrashIsOneLineAndExit2) {
  EXPECT_EXIT(
      {
        arm_crash_report("nbscope: error: lib.so (x): crashed with ", " in frame 3");
        write_through_null();
      },
      ::testing::ExitedWithCode(2), "^nbscope: error: lib.so \\(x\\): crashed with SIGSEGV in frame 3\n$");
  EXPECT_EXIT(
      {
        arm_crash_report("head ", " tail");
        std::abort();
      },
      ::testing::ExitedWithCode(2), "^head SIGABRT tail\n$");
}

// A traced call's crash names the last operation it traced (its progress, read in the handler).
TEST(CrashReport, ATracedCallsCrashNamesItsLastOperation) {
  EXPECT_EXIT(
      {
        static PluginProgress progress;
        progress.operations.store(812);
        progress.op.store(static_cast<std::int32_t>(TraceOp::VisitCell));
        progress.line.store(6);
        arm_crash_report("head ", " tail", &progress);
        write_through_null();
      },
      ::testing::ExitedWithCode(2), "^head SIGSEGV tail, after operation 812 of its trace \\(visit-cell, pseudocode line 7\\)\n$");
}

TEST(CrashReport, DisarmedSignalGoesToTheActionItReplaced) {
  EXPECT_EXIT(
      {
        arm_crash_report("head ", " tail");
        disarm_crash_report();
        write_through_null();
      },
      [](int status) { return handed_back(status, SIGSEGV); }, "");
  EXPECT_EXIT(
      {
        arm_crash_report("head ", " tail");
        disarm_crash_report();
        no_core_file();
        std::raise(SIGFPE);
        std::abort();
      },
      [](int status) { return handed_back(status, SIGFPE); }, "");
}

}  // namespace
}  // namespace nbscope
