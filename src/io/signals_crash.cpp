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

void write_all(const char* text);

constexpr std::array<int, 5> kCrashSignals{SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
std::atomic<const char*> g_head{nullptr};  // non-null while a plugin's call runs
std::atomic<const char*> g_tail{nullptr};
std::atomic<const PluginProgress*> g_progress{nullptr};
std::array<struct sigaction, kCrashSignals.size()> g_previous{};
std::atomic<bool> g_installed{false};
static_assert(std::atomic<const char*>::is_always_lock_free && std::atomic<bool>::is_always_lock_free &&
                  std::atomic<std::int64_t>::is_always_lock_free && std::atomic<std::int32_t>::is_always_lock_free,
              "the signal handler reads them");

// `v` in decimal into `out` (at least 21 bytes), for the handler (no printf there).
const char* decimal(std::int64_t v, char* out) {
  char digits[21];
  int n = 0;
  do {
    digits[n++] = static_cast<char>('0' + v % 10);
    v /= 10;
  } while (v > 0 && n < 20);
  for (int k = 0; k < n; ++k) out[k] = digits[n - 1 - k];
  out[n] = '\0';
  return out;
}

// Where the call got to, in the words of progress_text(), written piece by piece.
void write_progress(const PluginProgress* p) {
  if (p == nullptr) return;
  const std::int64_t ops = p->operations.load(std::memory_order_relaxed);
  if (ops <= 0) return;
  char number[24];
  write_all(", after operation ");
  write_all(decimal(ops, number));
  write_all(" of its trace (");
  write_all(trace_op_name(static_cast<TraceOp>(p->op.load(std::memory_order_relaxed))));
  const std::int32_t line = p->line.load(std::memory_order_relaxed);
  if (line >= 0) {
    write_all(", pseudocode line ");
    write_all(decimal(line + 1, number));
  }
  write_all(")");
}

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
    write_progress(g_progress.load());
    write_all("\n");
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
std::string progress_text(const PluginProgress* p) {
  if (p == nullptr || p->operations.load() <= 0) return "";
  const std::int32_t line = p->line.load();
  return ", after operation " + std::to_string(p->operations.load()) + " of its trace (" +
         trace_op_name(static_cast<TraceOp>(p->op.load())) + (line >= 0 ? ", pseudocode line " + std::to_string(line + 1) : "") + ")";
}

void arm_crash_report(const char* head, const char* tail, const PluginProgress* progress) {
  g_tail.store(tail);
  g_progress.store(progress);
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
