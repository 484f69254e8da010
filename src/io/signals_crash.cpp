// The crash report around a detector plugin's call (signals.hpp): SIGSEGV and its kin, caught only
// while the plugin runs, become one error line and exit 2 instead of a core dump. Async-signal-safe:
// the handler reads atomics, calls write(2), the temporaries' cleanup, sigaction, raise and _exit(2).
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
std::atomic<const char*> g_head{nullptr};  // non-null while a plugin's call runs
std::atomic<const char*> g_tail{nullptr};
std::array<struct sigaction, kCrashSignals.size()> g_previous{};
std::atomic<bool> g_installed{false};
static_assert(std::atomic<const char*>::is_always_lock_free && std::atomic<bool>::is_always_lock_free,
              "the signal handler reads them");

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

// Puts back every action the report replaced (the next arming installs it again).
void restore_previous() {
  for (std::size_t i = 0; i < kCrashSignals.size(); ++i) ::sigaction(kCrashSignals[i], &g_previous[i], nullptr);
  g_installed.store(false);
}

extern "C" void on_crash_signal(int sig, siginfo_t* info, void* /*context*/) {
  if (const char* head = g_head.load()) {
    write_all(head);
    write_all(crash_name(sig));
    write_all(g_tail.load());
    remove_live_temporaries();
    ::_exit(2);
  }
  // Not in a plugin's call: the signal is not ours. With the replaced actions back, a fault happens
  // again when this returns (the instruction runs again), and a sent signal is sent again.
  restore_previous();
  if (info == nullptr || info->si_code <= 0) ::raise(sig);
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

// Installed at the first arming and left in place (ten sigaction calls a frame cost more than a small
// plugin's detection); between calls the handler hands any signal back to the action it replaced.
void arm_crash_report(const char* head, const char* tail) {
  g_tail.store(tail);
  if (!g_installed.load()) {
    ensure_alternate_stack();
    struct sigaction ours {};
    ours.sa_sigaction = on_crash_signal;
    ours.sa_flags = SA_ONSTACK | SA_SIGINFO;
    sigemptyset(&ours.sa_mask);
    for (std::size_t i = 0; i < kCrashSignals.size(); ++i) ::sigaction(kCrashSignals[i], &ours, &g_previous[i]);
    g_installed.store(true);
  }
  g_head.store(head);
}

void disarm_crash_report() { g_head.store(nullptr); }

}  // namespace nbscope
