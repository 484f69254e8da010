// nbscope io: the signals that end a run (SIGINT, SIGTERM, SIGHUP), handled in one place for the
// window, headless and the atomic outputs. One handler serves them all and asks, in order:
//   1. does a loop stop on this signal (the window's close, headless --record)? Then it only notes
//      the signal; the loop stops at its next frame and unwinds, removing its own temporaries.
//   2. else it runs the registered cleanups (the atomic outputs' live temporaries) and ends the
//      process by the same signal with its default action (the parent sees "killed by SIGTERM").
// An ignored signal (nohup's SIGHUP) is left ignored by the cleanup. Async-signal-safe: the handler
// only reads and writes lock-free atomics, calls the cleanups, sigaction and raise.
#pragma once
#include <memory>
#include <string>

#include "core/plugin_detector.hpp"

namespace nbscope {

// A cleanup for a signal that ends the process; it must be async-signal-safe.
using SignalCleanup = void (*)();

// Registers `cleanup` (once; at most 8) and installs the handler for each ending signal whose
// action is the default one; a signal ignored or handled by someone else is left alone.
void arm_signal_cleanup(SignalCleanup cleanup);

// From now on (for the rest of the process) SIGINT and SIGTERM only note the stop, as the window's
// close button does (so its loop can end cleanly and save what it writes).
void install_stop_handlers();
// True once a signal was noted as a stop (install_stop_handlers, StopOnSignals).
[[nodiscard]] bool stop_requested();
// The signal noted last as a stop (SIGINT, SIGTERM, SIGHUP), 0 for none.
[[nodiscard]] int stop_signal();
// "SIGINT", "SIGTERM", "SIGHUP", else "a signal".
[[nodiscard]] const char* signal_name(int sig);

// Until disarm_crash_report(), a crash (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT) writes `head`, the
// signal's name, `tail` and where `progress` (when not null) says the call got to, to stderr, removes
// the live temporaries and _exit(2)s: a detector plugin's crash as one error line
// (io/plugin_library.hpp, io/signals_crash.cpp). Both strings and the progress outlive the arming.
void arm_crash_report(const char* head, const char* tail, const PluginProgress* progress = nullptr);
// ", after operation 812 of its trace (visit-cell, pseudocode line 7)", or "" before any; not for a
// signal handler (the crash report writes the same words its own way).
[[nodiscard]] std::string progress_text(const PluginProgress* progress);
// Ends the report: from now on these signals go to the actions arm_crash_report() replaced.
void disarm_crash_report();

// While it lives, SIGINT, SIGTERM and SIGHUP only note the stop (an ignored SIGHUP, as under
// nohup, stays ignored); the actions before it come back when it ends. Clears the noted stop.
class StopOnSignals {
 public:
  StopOnSignals();
  ~StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

 private:
  struct Saved;  // the actions and stop marks it replaced
  std::unique_ptr<Saved> saved_;
};

}  // namespace nbscope
