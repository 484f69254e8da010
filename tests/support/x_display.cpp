#include "support/x_display.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "support/run_cli.hpp"

namespace nbscope::testcli {
namespace {

using Clock = std::chrono::steady_clock;
using Seconds = std::chrono::duration<double>;

constexpr double kXvfbStartSeconds = 60;    // generous: a loaded machine starts it in seconds
constexpr double kWindowShowSeconds = 120;  // the window's start: scene, physics, GL context
constexpr double kEndSeconds = 60;          // from SIGTERM to the process's end
constexpr auto kPoll = std::chrono::milliseconds(100);
const char* const kTitlePrefix = "\"nbscope";  // xwininfo quotes the window's name

// In a forked child before exec: dies with the test (no server or window left behind by a crash).
void die_with_parent(pid_t parent) {
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (::getppid() != parent) ::_exit(127);  // the parent ended before prctl
}

void redirect(int fd, const char* path, int flags) {
  const int opened = ::open(path, flags, 0644);
  if (opened < 0 || opened == fd) return;
  ::dup2(opened, fd);
  ::close(opened);
}

// waitpid with a deadline; true (and `status` set) once `pid` ended.
bool wait_until(pid_t pid, int& status, Clock::time_point deadline) {
  while (true) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return true;
    if (Clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

Clock::time_point after(double seconds) { return Clock::now() + std::chrono::duration_cast<Clock::duration>(Seconds(seconds)); }

// SIGTERM to `target` (`pid`, or -pid for its process group), then SIGKILL if `pid` has not ended
// within kEndSeconds; true if SIGTERM was enough.
bool terminate(pid_t pid, pid_t target, int& status) {
  ::kill(target, SIGTERM);
  if (wait_until(pid, status, after(kEndSeconds))) return true;
  ::kill(target, SIGKILL);
  ::waitpid(pid, &status, 0);
  return false;
}

int exit_code(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status); }

std::string xvfb_log_path() {
  const auto dir = std::filesystem::path(NBSCOPE_TEST_OUT) / "xvfb";
  std::filesystem::create_directories(dir);
  return (dir / (std::to_string(::getpid()) + ".log")).string();
}

XServer& own_server() {
  static XServer server(xvfb_log_path());
  return server;
}

// A shell command's stdout.
std::string capture(const std::string& command) {
  std::string text;
  if (FILE* p = ::popen(command.c_str(), "r")) {
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, p)) > 0;) text.append(buffer, n);
    ::pclose(p);
  }
  return text;
}

// True when a top-level window named "nbscope..." is mapped on `display` (no window manager under
// Xvfb: the top-level windows are the root's children).
bool nbscope_window_mapped(const std::string& display) {
  std::istringstream children(capture("xwininfo -root -children -display " + display + " 2>/dev/null"));
  for (std::string line; std::getline(children, line);) {
    const auto name = line.find(kTitlePrefix);
    if (name == std::string::npos) continue;
    std::istringstream words(line);
    std::string id;
    words >> id;
    if (capture("xwininfo -id " + id + " -display " + display + " 2>/dev/null").find("Map State: IsViewable") != std::string::npos)
      return true;
  }
  return false;
}

}  // namespace

XServer::XServer(const std::string& log_path) : owner_(::getpid()), log_path_(log_path) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("XServer: pipe2 failed");
  const std::string fd = std::to_string(fds[1]);
  // -noreset: by default the server resets when its last client leaves, and a client connecting then
  // (the window, while run_until_window_then_term's xwininfo has just left) fails to open the display.
  const char* argv[] = {"Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x720x24", "-nolisten", "tcp", "-noreset", nullptr};
  pid_ = ::fork();
  if (pid_ < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error("XServer: fork failed");
  }
  if (pid_ == 0) {
    die_with_parent(owner_);
    ::fcntl(fds[1], F_SETFD, 0);  // the one descriptor Xvfb keeps: where it writes its display
    redirect(0, "/dev/null", O_RDONLY);
    redirect(1, log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC);
    ::dup2(1, 2);
    ::execvp("Xvfb", const_cast<char* const*>(argv));
    ::_exit(127);
  }
  ::close(fds[1]);
  // Xvfb writes "N\n" once it accepts clients; EOF means it ended first.
  std::string said;
  const auto deadline = after(kXvfbStartSeconds);
  while (said.find('\n') == std::string::npos && Clock::now() < deadline) {
    pollfd p{fds[0], POLLIN, 0};
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (::poll(&p, 1, static_cast<int>(std::max<long long>(left, 0))) <= 0) continue;
    char buffer[32];
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n <= 0) break;
    said.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  if (said.find('\n') == std::string::npos) {
    int status = 0;
    terminate(pid_, pid_, status);
    throw std::runtime_error("Xvfb -displayfd gave no display within " + std::to_string(static_cast<int>(kXvfbStartSeconds)) +
                             " s (exit " + std::to_string(exit_code(status)) + "): " + read_text(log_path));
  }
  display_ = ":" + said.substr(0, said.find('\n'));
}

XServer::~XServer() {
  if (pid_ <= 0 || ::getpid() != owner_) return;
  int status = 0;
  std::error_code ec;  // a log that was a file goes with a server that stopped (never /dev/null)
  if (terminate(pid_, pid_, status) && std::filesystem::is_regular_file(log_path_, ec)) std::filesystem::remove(log_path_, ec);
}

bool have_xvfb() {
  static const bool found = std::system("command -v Xvfb >/dev/null 2>&1") == 0;
  return found;
}

std::string on_display() { return "env -u WAYLAND_DISPLAY DISPLAY=" + own_server().display(); }

WindowRun run_until_window_then_term(const std::string& shell_command, double open_seconds) {
  static const bool have_xwininfo = std::system("command -v xwininfo >/dev/null 2>&1") == 0;
  if (!have_xwininfo) throw std::runtime_error("xwininfo is not installed (package x11-utils): the window cannot be seen");
  const std::string display = own_server().display();
  static int counter = 0;
  const std::string dir = scratch_dir("window_run_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  const std::string line = "exec " + on_display() + " " + shell_command + " </dev/null >'" + dir + "/out' 2>'" + dir + "/err'";
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("run_until_window_then_term: fork failed");
  if (pid == 0) {
    ::setpgid(0, 0);  // its own group: SIGTERM reaches a wrapper's children too
    die_with_parent(parent);
    ::execl("/bin/sh", "sh", "-c", line.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // (as the child does: whichever runs first)
  WindowRun r;
  int status = 0;
  bool ended = false;
  for (const auto deadline = after(kWindowShowSeconds); !ended && !r.window_shown && Clock::now() < deadline;) {
    ended = ::waitpid(pid, &status, WNOHANG) == pid;
    r.window_shown = !ended && nbscope_window_mapped(display);
    if (!ended && !r.window_shown) std::this_thread::sleep_for(kPoll);
  }
  if (r.window_shown) ended = wait_until(pid, status, after(open_seconds));
  if (!ended) r.killed = !terminate(pid, -pid, status);
  r.exit_code = exit_code(status);
  r.out = read_text(dir + "/out");
  r.err = read_text(dir + "/err");
  std::filesystem::remove_all(dir);
  return r;
}

WindowRun run_window(const std::string& nbscope_args, const std::string& env_assignments, double open_seconds) {
  return run_until_window_then_term(env_assignments + " '" + binary() + "' " + nbscope_args, open_seconds);
}

}  // namespace nbscope::testcli
