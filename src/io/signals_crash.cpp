// The crash report around a detector plugin's call (signals.hpp): SIGSEGV and its kin, caught only
// while the plugin runs, become one error line and exit 2 instead of a core dump. Async-signal-safe:
// the handler reads atomics, calls write(2), the temporaries' cleanup and _exit(2).
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstring>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/signals.hpp"

namespace nbscope {

namespace {

constexpr std::array<int, 5> kCrashSignals{SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
std::atomic<const char*> g_head{nullptr};
std::atomic<const char*> g_tail{nullptr};
std::array<struct sigaction, kCrashSignals.size()> g_previous{};
bool g_armed = false;

const char* crash_name(int sig) {
  switch (sig) {
    case SIGSEGV: return "SIGSEGV";
    case SIGBUS: return "SIGBUS";
    case SIGFPE: return "SIGFPE";
    case SIGILL: return "SIGILL";
    case SIGABRT: return "SIGABRT";
    default: return "a signal";
  }
}

void write_all(const char* text) {
  if (text == nullptr) return;
  std::size_t left = std::strlen(text);
  while (left > 0) {
    const ssize_t n = ::write(STDERR_FILENO, text, left);
    if (n <= 0) return;
    text += n;
    left -= static_cast<std::size_t>(n);
  }
}

extern "C" void on_crash_signal(int sig) {
  write_all(g_head.load());
  write_all(crash_name(sig));
  write_all(g_tail.load());
  remove_live_temporaries();
  ::_exit(2);
}

// A stack of its own for the handler, so a plugin's stack overflow is reported too; one that is
// already there (AddressSanitizer's) is kept.
void ensure_alternate_stack() {
  stack_t current{};
  if (::sigaltstack(nullptr, &current) != 0 || (current.ss_flags & SS_DISABLE) == 0) return;
  thread_local std::vector<char> memory(std::size_t{1} << 16);
  stack_t ours{};
  ours.ss_sp = memory.data();
  ours.ss_size = memory.size();
  ::sigaltstack(&ours, nullptr);
}

}  // namespace

void arm_crash_report(const char* head, const char* tail) {
  g_head.store(head);
  g_tail.store(tail);
  if (g_armed) return;
  ensure_alternate_stack();
  struct sigaction ours {};
  ours.sa_handler = on_crash_signal;
  ours.sa_flags = SA_ONSTACK;
  sigemptyset(&ours.sa_mask);
  for (std::size_t i = 0; i < kCrashSignals.size(); ++i) ::sigaction(kCrashSignals[i], &ours, &g_previous[i]);
  g_armed = true;
}

void disarm_crash_report() {
  if (!g_armed) return;
  for (std::size_t i = 0; i < kCrashSignals.size(); ++i) ::sigaction(kCrashSignals[i], &g_previous[i], nullptr);
  g_armed = false;
}

}  // namespace nbscope
