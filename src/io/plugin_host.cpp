// nbscope's side of an isolated plugin (plugin_host.hpp): the host process, spawned on the first
// call, and every call as a request over its socket. Its stderr is read as it comes: the plugin's own
// prints go on to nbscope's stderr, the guard's "nbscope: error: " line is kept as its last words.
//
// Index: HostProcess (spawn, exchange, end) | IsolatedPluginDetector.
#include "io/plugin_host.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/plugin_wire.hpp"

extern char** environ;

namespace nbscope {

namespace {

constexpr double kGraceSeconds = 5;  // past the host's own watchdog, before nbscope kills it itself
constexpr const char* kErrorHead = "nbscope: error: ";

// `fd` moved to a number above the ones the host is given (3, 4), close-on-exec: no dup2 of the spawn
// overwrites another's source.
int above_host_fds(int fd) {
  if (fd < 0 || fd > 4) return fd;
  const int moved = ::fcntl(fd, F_DUPFD_CLOEXEC, 10);
  ::close(fd);
  return moved;
}

std::string signal_name(int sig) {
  const char* name = sigabbrev_np(sig);
  return name != nullptr ? std::string("SIG") + name : "signal " + std::to_string(sig);
}

}  // namespace

// One running host.
struct HostProcess {
  pid_t pid = -1;
  int socket = -1;
  int err = -1;                        // the read end of its stderr
  PluginProgress* progress = nullptr;  // the page shared with it
  std::string err_text;                // stderr not yet a whole line
  std::string last_words;              // its last "nbscope: error: " line, without that head
  bool ended = false;
  double timeout = 0;

  ~HostProcess() {
    if (socket >= 0) ::close(socket);
    if (err >= 0) ::close(err);
    if (progress != nullptr) ::munmap(progress, sizeof(PluginProgress));
    if (pid > 0 && !ended) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, nullptr, 0);
    }
  }

  // Starts nbscope-plugin-host on `library`; throws PluginError when it does not say it is ready.
  void spawn(const std::string& library, const std::string& who) {
    const std::string path = plugin_host_path();
    int pair[2], pipe_fds[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, pair) != 0) throw Error("plugin host: socketpair: " + std::string(std::strerror(errno)));
    socket = pair[0];
    pair[1] = above_host_fds(pair[1]);
    if (::pipe2(pipe_fds, O_CLOEXEC) != 0) {
      ::close(pair[1]);
      throw Error("plugin host: pipe: " + std::string(std::strerror(errno)));
    }
    err = pipe_fds[0];
    pipe_fds[1] = above_host_fds(pipe_fds[1]);
    const int page = above_host_fds(::memfd_create("nbscope-plugin-progress", MFD_CLOEXEC));
    if (page < 0 || ::ftruncate(page, sizeof(PluginProgress)) != 0 ||
        (progress = static_cast<PluginProgress*>(::mmap(nullptr, sizeof(PluginProgress), PROT_READ | PROT_WRITE, MAP_SHARED, page, 0))) ==
            MAP_FAILED) {
      progress = nullptr;
      for (const int fd : {pair[1], pipe_fds[1], page})
        if (fd >= 0) ::close(fd);
      throw Error("plugin host: shared memory: " + std::string(std::strerror(errno)));
    }
    new (progress) PluginProgress();
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pair[1], 3);
    posix_spawn_file_actions_adddup2(&actions, page, 4);
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    posix_spawnattr_setpgroup(&attributes, 0);  // the terminal's ^C goes to nbscope, which then closes the host
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.17g", timeout);
    std::string program = path, lib = library, time = seconds;
    char* argv[] = {program.data(), lib.data(), time.data(), nullptr};
    const int failed = ::posix_spawn(&pid, path.c_str(), &actions, &attributes, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    for (const int fd : {pair[1], pipe_fds[1], page}) ::close(fd);
    if (failed != 0) {
      pid = -1;
      throw Error("plugin host: cannot start " + path + ": " + std::strerror(failed));
    }
    std::vector<char> ready;
    if (!exchange(nullptr, ready))
      throw PluginError(who + (last_words.empty() ? "its host process ended before it was ready" : last_words));
  }

  // Sends `request` (none: only waits), then reads one whole reply into `reply`; false when the host
  // ended first (last_words say why).
  bool exchange(const std::vector<char>* request, std::vector<char>& reply) {
    if (request != nullptr && !send_message(socket, *request)) return finish();
    using Clock = std::chrono::steady_clock;
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout + kGraceSeconds));
    std::uint64_t size = 0;
    std::size_t got = 0;
    bool header = true;
    for (;;) {
      pollfd fds[2] = {{socket, POLLIN, 0}, {err, POLLIN, 0}};
      int wait_ms = -1;
      if (timeout > 0) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) {
          last_words = "did not return within " + std::string(seconds_text()) + " s (nbscope stopped its host process)";
          ::kill(pid, SIGKILL);
          return finish();
        }
        wait_ms = static_cast<int>(std::min<long long>(left, 1000 * 60));
      }
      const int ready = ::poll(fds, err >= 0 ? 2 : 1, wait_ms);
      if (ready < 0 && errno == EINTR) continue;
      if (ready < 0) return finish();
      if (err >= 0 && (fds[1].revents & (POLLIN | POLLHUP)) != 0) read_err();
      if ((fds[0].revents & (POLLIN | POLLHUP | POLLERR)) == 0) continue;
      char* into = header ? reinterpret_cast<char*>(&size) + got : reply.data() + got;
      const std::size_t want = header ? sizeof size - got : reply.size() - got;
      const ssize_t n = want == 0 ? 0 : ::read(socket, into, want);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0 && want != 0) return finish();
      got += static_cast<std::size_t>(n);
      if (header && got == sizeof size) {
        header = false;
        got = 0;
        reply.resize(static_cast<std::size_t>(size));
      }
      if (!header && got == reply.size()) return true;
    }
  }

  // The host has ended (or is ending): its remaining stderr read, its status taken; returns false.
  bool finish() {
    while (err >= 0) read_err();
    int status = 0;
    if (pid > 0 && ::waitpid(pid, &status, 0) == pid) {
      ended = true;
      if (last_words.empty())
        last_words = WIFSIGNALED(status) ? "its host process was ended by " + signal_name(WTERMSIG(status))
                                         : "its host process exited with status " + std::to_string(WEXITSTATUS(status));
    }
    return false;
  }

  // Reads what the host wrote to stderr: whole lines passed on, the guard's error line kept.
  void read_err() {
    char chunk[4096];
    const ssize_t n = ::read(err, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) return;
    if (n <= 0) {
      ::close(err);
      err = -1;
      if (!err_text.empty()) err_text += '\n';
    } else {
      err_text.append(chunk, static_cast<std::size_t>(n));
    }
    std::size_t end;
    while ((end = err_text.find('\n')) != std::string::npos) {
      const std::string line = err_text.substr(0, end);
      err_text.erase(0, end + 1);
      if (line.rfind(kErrorHead, 0) == 0) {
        last_words = line.substr(std::strlen(kErrorHead));
      } else {
        const std::string out = line + "\n";
        const ssize_t wrote = ::write(STDERR_FILENO, out.data(), out.size());
        (void)wrote;  // the plugin's own prints: best effort
      }
    }
  }

  [[nodiscard]] std::string seconds_text() const {
    char s[32];
    std::snprintf(s, sizeof s, "%g", timeout);
    return s;
  }
};

IsolatedPluginDetector::IsolatedPluginDetector(std::string library, std::shared_ptr<const PluginDescription> description,
                                               double timeout)
    : library_(std::move(library)), description_(std::move(description)), timeout_(timeout) {}

IsolatedPluginDetector::~IsolatedPluginDetector() {
  if (!host_ || host_->ended) return;
  ::shutdown(host_->socket, SHUT_WR);  // the host's loop ends; it releases the state and exits
  std::vector<char> none;
  host_->exchange(nullptr, none);  // returns at its end (or kills it past the timeout)
  if (host_->last_words.rfind(library_, 0) == 0) {  // the guard's line: a crash or a hang in release
    const std::string line = kErrorHead + host_->last_words + "\n";
    const ssize_t wrote = ::write(STDERR_FILENO, line.data(), line.size());
    (void)wrote;
    remove_live_temporaries();
    ::_exit(2);  // as the guard does in-process
  }
}

bool IsolatedPluginDetector::supports_dim(int dim) const { return description_->handles(dim); }

const std::vector<const char*>& IsolatedPluginDetector::pseudocode(int dim) const { return description_->lines_of(dim); }

void IsolatedPluginDetector::detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) {
  run(elements, options, out_pairs, nullptr);
}

void IsolatedPluginDetector::detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                                           TraceLog& out_trace) {
  out_trace.reset();
  run(elements, options, out_pairs, &out_trace);
}

std::string IsolatedPluginDetector::where(std::int64_t frame) const {
  return library_ + " (" + description_->name + "): frame " + std::to_string(frame) + ": ";
}

std::size_t IsolatedPluginDetector::own_bytes() const {
  if (own_bytes_) return *own_bytes_;
  if (!host_ || host_->ended) return 0;
  message_.assign(1, static_cast<char>(HostRequest::own_bytes));
  if (!host_->exchange(&message_, message_))
    throw PluginError(host_->last_words);  // the guard's line names the library and the call
  WireReader in(message_.data(), message_.size());
  own_bytes_ = static_cast<std::size_t>(in.value<std::uint64_t>());
  return *own_bytes_;
}

void IsolatedPluginDetector::run(const Elements& elements, const DetectOptions& options, PairList& out_pairs, TraceLog* trace) {
  if (!supports_dim(elements.dim))
    throw Error(description_->name + ": " + std::to_string(elements.dim) + "D elements are not supported by this detector");
  refuse_periodic(elements, description_->name);
  grid_ = make_grid(elements, options.grid);  // as the host's PluginDetector makes it
  own_bytes_.reset();
  misbehaviour_.reset();
  has_cells_ = walks_checked_ = false;
  if (!host_ || host_->ended) {
    host_ = std::make_unique<HostProcess>();
    host_->timeout = timeout_;
    host_->spawn(library_, library_ + " (" + description_->name + "): ");
  }
  host_->progress->operations.store(0);
  DetectRequest request;  // the columns are copied into the message, not here
  WireWriter& out = request_;
  out.restart(256 + static_cast<std::size_t>(elements.size()) * (elements.dim + 1) * sizeof(double));
  out.value(HostRequest::detect);
  request.options = options;
  request.traced = trace != nullptr;
  request.keep_tests = trace == nullptr || trace->keeps_tests();
  request.operation_limit = operation_limit_;
  encode(elements, request, out);
  if (!host_->exchange(&out.bytes(), message_)) return host_ended(elements, options, out_pairs, trace);
  WireReader in(message_.data(), message_.size());
  DetectReply reply;
  reply.pairs = std::move(out_pairs);
  decode_reply(in, reply, trace, events_);
  out_pairs = std::move(reply.pairs);
  if (reply.error == WireError::plugin_error) throw PluginError(reply.message);
  if (reply.error == WireError::detector_bug) throw DetectorBug(reply.message);
  if (reply.error == WireError::error) throw Error(reply.message);
  has_cells_ = reply.has_cells;
  cells_ = std::move(reply.cells);
  walks_checked_ = reply.walks_checked;
  walks_ = std::move(reply.walks);
  misbehaviour_ = std::move(reply.misbehaviour);
}

void IsolatedPluginDetector::host_ended(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                                        TraceLog* trace) {
  const std::int64_t operations = host_->progress->operations.load();
  std::string words = host_->last_words;
  const std::string who = library_ + " (" + description_->name + "): ";
  if (words.rfind(who, 0) == 0) words.erase(0, who.size());
  host_.reset();
  out_pairs.clear();
  if (trace != nullptr && operations >= 2 && record_again_) {
    // The trace up to there, recorded again by a new host stopped after as many operations (a plugin
    // whose frame depends on its state from earlier frames may take another path on a fresh state).
    IsolatedPluginDetector again(library_, description_, timeout_);
    again.set_operation_limit(operations - 1);
    again.record_again_ = false;  // one more death there is the end of it
    try {
      again.run(elements, options, out_pairs, trace);
    } catch (const Error&) {
      out_pairs.clear();
      trace->reset();
    }
    again.host_.reset();  // killed: its state was left where the call was stopped
  }
  Misbehaviour m;
  m.text = words + " (the next frame starts a new host process: the plugin's state from earlier frames is gone)";
  m.operations = trace != nullptr ? std::min(static_cast<std::size_t>(std::max<std::int64_t>(operations, 0)), trace->events().size()) : 0;
  m.cut = true;
  m.where = where(options.frame);
  misbehaviour_ = std::move(m);
}

}  // namespace nbscope
