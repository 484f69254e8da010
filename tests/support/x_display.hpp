// nbscope tests: each test process's own X server (Xvfb -displayfd), and a window run on it that is
// closed by SIGTERM only once it is shown. It replaced the xvfb wrapper script, whose clean-up raced
// the tests that stopped the window, and `timeout`, which could end a window still starting (issue 36).
#pragma once
#include <string>

namespace nbscope::testcli {

// An Xvfb of its own (1280x720x24, no TCP, no reset) on the display it chose itself, stopped by the destructor.
class XServer {
 public:
  // Starts Xvfb (its output to `log_path`) and waits until it says its display (throws if it never does).
  explicit XServer(const std::string& log_path = "/dev/null");
  ~XServer();
  XServer(const XServer&) = delete;
  XServer& operator=(const XServer&) = delete;
  // ":N", the display this server serves.
  const std::string& display() const { return display_; }

 private:
  int pid_ = -1;
  int owner_ = -1;  // the process that started it: a forked copy must not stop it
  std::string log_path_;
  std::string display_;
};

// True when Xvfb is on PATH.
bool have_xvfb();

// "env -u WAYLAND_DISPLAY DISPLAY=:N" for this process's own XServer (started at the first call,
// stopped when the process ends): a prefix for run(). ctest runs each case in its own process.
std::string on_display();

// What a window run gave: the command's exit code (128 + signal when killed), its output, and
// whether its window was seen mapped before it was told to close.
struct WindowRun {
  int exit_code = -1;
  std::string out;
  std::string err;
  bool window_shown = false;
  bool killed = false;  // it outlived SIGTERM by 60 s and was SIGKILLed
};

// Runs `shell_command` on on_display()'s server until its window shows, then SIGTERMs it and waits.
// The command is exec'd after `env DISPLAY=:N` (so a simple command); "shows": a top-level window
// named "nbscope..." is mapped (waited for up to 120 s, or until the command exits), then it stays
// open `open_seconds`; SIGTERM goes to the command's process group (a wrapper's children too).
WindowRun run_until_window_then_term(const std::string& shell_command, double open_seconds = 1.0);

// run_until_window_then_term for `nbscope <nbscope_args>` after `env_assignments` (NAME=value ...).
WindowRun run_window(const std::string& nbscope_args, const std::string& env_assignments = "", double open_seconds = 1.0);

}  // namespace nbscope::testcli

// Skips a test that needs a window when there is no Xvfb to show it on.
#define NBSCOPE_SKIP_WITHOUT_XVFB()                                                          \
  do {                                                                                       \
    if (!::nbscope::testcli::have_xvfb()) GTEST_SKIP() << "Xvfb is not installed (package xvfb)"; \
  } while (false)
