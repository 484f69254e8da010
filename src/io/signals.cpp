// The one handler for the signals that end a run, its installation, and the stop marks the window
// and headless --record set (see signals.hpp for the order it decides in).
#include "io/signals.hpp"

#include <signal.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstddef>

namespace nbscope {

namespace {

constexpr std::array<int, 3> kEndingSignals{SIGINT, SIGTERM, SIGHUP};
// Per ending signal (kEndingSignals' order): 1 while a loop stops on it instead of ending.
std::array<std::atomic<int>, kEndingSignals.size()> g_stopping{};
std::atomic<int> g_stop_signal{0};
// The cleanups run before the process ends by a signal; free slots are null.
constexpr std::size_t kMaxCleanups = 8;
std::array<std::atomic<SignalCleanup>, kMaxCleanups> g_cleanups{};
static_assert(std::atomic<int>::is_always_lock_free && std::atomic<SignalCleanup>::is_always_lock_free,
              "the signal handler reads them");

int index_of(int sig) {
  for (std::size_t i = 0; i < kEndingSignals.size(); ++i)
    if (kEndingSignals[i] == sig) return static_cast<int>(i);
  return -1;
}

// The handler: a stop noted, or the cleanups and the default action. Async-signal-safe only.
extern "C" void on_ending_signal(int sig) {
  const int i = index_of(sig);
  if (i >= 0 && g_stopping[static_cast<std::size_t>(i)].load() != 0) {
    g_stop_signal.store(sig);
    return;
  }
  for (const auto& cleanup : g_cleanups)
    if (const SignalCleanup c = cleanup.load()) c();
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  ::raise(sig);  // pending until this handler returns (the signal is blocked while it runs)
}

bool has_default_action(const struct sigaction& a) { return (a.sa_flags & SA_SIGINFO) == 0 && a.sa_handler == SIG_DFL; }
bool is_ignored(const struct sigaction& a) { return (a.sa_flags & SA_SIGINFO) == 0 && a.sa_handler == SIG_IGN; }

// Puts on_ending_signal on `sig` (the other ending signals blocked while it runs: one cleanup at a
// time; interrupted calls restart, as std::signal's handlers did), the action before it in `old`.
void install_handler(int sig, struct sigaction* old) {
  struct sigaction ours {};
  ours.sa_handler = on_ending_signal;
  ours.sa_flags = SA_RESTART;
  sigemptyset(&ours.sa_mask);
  for (const int other : kEndingSignals) sigaddset(&ours.sa_mask, other);
  ::sigaction(sig, &ours, old);
}

}  // namespace

void arm_signal_cleanup(SignalCleanup cleanup) {
  for (auto& slot : g_cleanups) {
    SignalCleanup expected = nullptr;
    if (slot.load() == cleanup || slot.compare_exchange_strong(expected, cleanup)) break;
  }
  // Only where the action is the default one: an ignored signal stays ignored, and one a loop stops
  // on stays with it (that path unwinds and removes its temporaries itself).
  for (const int sig : kEndingSignals) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) == 0 && has_default_action(old)) install_handler(sig, nullptr);
  }
}

void install_stop_handlers() {
  for (const int sig : {SIGINT, SIGTERM}) {
    g_stopping[static_cast<std::size_t>(index_of(sig))].store(1);
    install_handler(sig, nullptr);
  }
}

bool stop_requested() { return g_stop_signal.load() != 0; }

int stop_signal() { return g_stop_signal.load(); }

const char* signal_name(int sig) {
  return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : sig == SIGHUP ? "SIGHUP" : "a signal";
}

struct StopOnSignals::Saved {
  std::array<struct sigaction, kEndingSignals.size()> action{};
  std::array<int, kEndingSignals.size()> stopping{};
  std::array<bool, kEndingSignals.size()> taken{};
};

StopOnSignals::StopOnSignals() : saved_(std::make_unique<Saved>()) {
  g_stop_signal.store(0);
  for (std::size_t i = 0; i < kEndingSignals.size(); ++i) {
    const int sig = kEndingSignals[i];
    if (sig == SIGHUP) {
      struct sigaction hup {};
      if (::sigaction(SIGHUP, nullptr, &hup) == 0 && is_ignored(hup)) continue;  // nohup's stays ignored
    }
    saved_->stopping[i] = g_stopping[i].exchange(1);
    install_handler(sig, &saved_->action[i]);
    saved_->taken[i] = true;
  }
}

StopOnSignals::~StopOnSignals() {
  for (std::size_t i = 0; i < kEndingSignals.size(); ++i) {
    if (!saved_->taken[i]) continue;
    ::sigaction(kEndingSignals[i], &saved_->action[i], nullptr);
    g_stopping[i].store(saved_->stopping[i]);
  }
}

}  // namespace nbscope
