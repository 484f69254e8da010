#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "io/signals.hpp"

namespace nbscope {

// ---- live temporaries and the signals that end a run --------------------------------------

namespace {

// The temporaries being written, in storage a signal handler may read: fixed-size slots, each
// claimed with an atomic (lock-free, so async-signal-safe) state.
constexpr std::size_t kSlots = 64;
constexpr std::size_t kMaxPath = 4096;
enum SlotState : int { kFree = 0, kFilling = 1, kLive = 2 };
std::array<std::atomic<int>, kSlots> g_slot_state{};
char g_slot_path[kSlots][kMaxPath];
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slots' states");

}  // namespace

void remove_live_temporaries() {
  for (std::size_t k = 0; k < kSlots; ++k)
    if (g_slot_state[k].load() == kLive) ::unlink(g_slot_path[k]);
}

std::size_t live_temporary_count() {
  std::size_t n = 0;
  for (const auto& state : g_slot_state) n += state.load() == kLive ? 1 : 0;
  return n;
}

LiveTemporary::LiveTemporary(const std::string& path) {
  arm_signal_cleanup(&remove_live_temporaries);  // io/signals: removed when a signal ends the run
  if (path.size() >= kMaxPath) return;  // the open fails too (ENAMETOOLONG) or it is not removed on a signal
  for (std::size_t k = 0; k < kSlots; ++k) {
    int expected = kFree;
    if (!g_slot_state[k].compare_exchange_strong(expected, kFilling)) continue;
    std::memcpy(g_slot_path[k], path.c_str(), path.size() + 1);
    g_slot_state[k].store(kLive);
    slot_ = static_cast<int>(k);
    return;
  }
}

LiveTemporary::~LiveTemporary() { release(); }

void LiveTemporary::release() {
  if (slot_ >= 0) g_slot_state[static_cast<std::size_t>(slot_)].store(kFree);
  slot_ = -1;
}

// ---- writing whole or not at all ------------------------------------------------------------

namespace {
std::string temp_name_for(const std::string& path) {
  return path + ".tmp." + std::to_string(static_cast<long>(::getpid()));
}

// Whether process `pid` is gone: kill(pid, 0) fails with ESRCH. A process of another user
// (EPERM) or one that reused the number counts as running: its temporary is left alone.
bool process_is_gone(long pid) {
  return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

// Removes the temporaries that writers of `path` killed by SIGKILL (or a power cut) left behind:
// PATH.tmp.PID whose PID no longer runs. Each removal is said in a note, once, on stderr.
void remove_stale_temporaries_of(const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const std::string prefix = target.filename().string() + ".tmp.";
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  fs::directory_iterator it(dir, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const long pid = std::stol(digits);
    std::error_code type_ec;
    if (pid == static_cast<long>(::getpid()) || it->is_directory(type_ec) || !process_is_gone(pid)) continue;
    const fs::path stale = target.has_parent_path() ? dir / name : fs::path(name);
    if (fs::remove(stale, type_ec))
      std::fprintf(stderr, "nbscope: note: %s: removed the temporary of a writer that no longer runs (pid %ld)\n",
                   stale.c_str(), pid);
  }
}

// An existing path that is not a regular file: /dev/null, /dev/stdout, a FIFO. It is written in
// place: renaming a temporary over it would replace the device with a plain file (as root).
bool is_special_file(const std::string& path) {
  std::error_code ec;
  const auto st = std::filesystem::status(path, ec);
  return !ec && std::filesystem::exists(st) && !std::filesystem::is_regular_file(st) && !std::filesystem::is_directory(st);
}

void write_in_place(const std::string& path, const std::function<void(std::ostream&)>& fill) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw Error(path + ": cannot write: " + std::strerror(errno));
  fill(out);
  out.flush();
  if (!out) throw Error(path + ": cannot write: " + std::strerror(errno));
}
}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& fill) {
  if (path.empty()) throw Error("output path is empty");
  std::error_code ec;  // a name too long, a directory not searchable: the open below says what is wrong
  if (std::filesystem::is_directory(path, ec)) throw Error(path + ": cannot write: it is a directory");
  if (is_special_file(path)) return write_in_place(path, fill);
  remove_stale_temporaries_of(path);
  const std::string tmp = temp_name_for(path);
  LiveTemporary live(tmp);  // named before it exists: a signal from now on removes it
  try {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(path + ": cannot write: " + std::strerror(errno));
    fill(out);
    out.flush();
    if (!out) throw Error(path + ": cannot write: " + std::strerror(errno));
    out.close();
    if (std::rename(tmp.c_str(), path.c_str()) != 0) throw Error(path + ": cannot write: " + std::strerror(errno));
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
}

AtomicFileWriter::AtomicFileWriter(std::string path) : path_(std::move(path)) {
  if (path_.empty()) throw Error("output path is empty");
  std::error_code ec;
  if (std::filesystem::is_directory(path_, ec)) throw Error(path_ + ": cannot write: it is a directory");
  in_place_ = is_special_file(path_);
  temp_ = in_place_ ? path_ : temp_name_for(path_);
  if (!in_place_) remove_stale_temporaries_of(path_);
  if (!in_place_) live_ = std::make_unique<LiveTemporary>(temp_);
  out_.open(temp_, in_place_ ? std::ios::binary : std::ios::binary | std::ios::trunc);
  if (!out_) {
    const std::string reason = std::strerror(errno);
    if (!in_place_) std::remove(temp_.c_str());
    throw Error(path_ + ": cannot write: " + reason);
  }
}

AtomicFileWriter::~AtomicFileWriter() {
  if (committed_) return;
  out_.close();
  if (!in_place_) std::remove(temp_.c_str());
}

// ---- scratch files without a name -----------------------------------------------------------

namespace {
// An unnamed file in `dir` (O_TMPFILE, else a unique name unlinked at once); -1 when neither works.
int unnamed_file_in(const std::string& dir) {
#ifdef O_TMPFILE
  const int fd = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd >= 0) return fd;
#endif
  std::string name = (dir.empty() ? std::string(".") : dir) + "/.nbscope-scratch-XXXXXX";
  const int named = ::mkstemp(name.data());
  if (named < 0) return -1;
  ::unlink(name.c_str());
  return named;
}
}  // namespace

ScratchFile::ScratchFile(const std::string& beside) {
  namespace fs = std::filesystem;
  const fs::path parent = fs::path(beside).parent_path();
  int fd = is_special_file(beside) ? -1 : unnamed_file_in(parent.empty() ? "." : parent.string());
  if (fd < 0) {  // a device as the output (/dev/stdout), or a directory that takes no unnamed file
    const char* tmp = std::getenv("TMPDIR");
    fd = unnamed_file_in(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp");
  }
  if (fd < 0 || (file_ = ::fdopen(fd, "w+b")) == nullptr) {
    const std::string reason = std::strerror(errno);
    if (fd >= 0) ::close(fd);
    throw Error(beside + ": cannot write: no scratch file for it: " + reason);
  }
  where_ = beside;
}

ScratchFile::~ScratchFile() {
  if (file_ != nullptr) std::fclose(file_);
}

void ScratchFile::write(std::string_view bytes) {
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
    throw Error(where_ + ": cannot write: " + std::strerror(errno));
  size_ += static_cast<std::int64_t>(bytes.size());
}

std::string ScratchFile::reopen_path() {
  if (std::fflush(file_) != 0) throw Error(where_ + ": cannot write: " + std::strerror(errno));
  return "/proc/self/fd/" + std::to_string(::fileno(file_));
}

void ScratchFile::truncate(std::int64_t size) {
  if (std::fflush(file_) != 0 || ::ftruncate(::fileno(file_), size) != 0 || std::fseek(file_, size, SEEK_SET) != 0)
    throw Error(where_ + ": cannot write: " + std::strerror(errno));
  size_ = size;
}

std::int64_t ScratchFile::bytes_on_disk() {
  struct stat st {};
  if (std::fflush(file_) != 0 || ::fstat(::fileno(file_), &st) != 0) return -1;
  return static_cast<std::int64_t>(st.st_size);
}

void ScratchFile::copy_to(std::ostream& out) {
  if (std::fflush(file_) != 0) throw Error(where_ + ": cannot write: " + std::strerror(errno));
  std::vector<char> buffer(std::size_t{1} << 20);
  for (std::int64_t at = 0; at < size_;) {
    const auto want = static_cast<std::size_t>(std::min<std::int64_t>(size_ - at, static_cast<std::int64_t>(buffer.size())));
    const ssize_t got = ::pread(::fileno(file_), buffer.data(), want, at);
    if (got <= 0) throw Error(where_ + ": cannot write: reading back its scratch file: " + std::strerror(got < 0 ? errno : EIO));
    out.write(buffer.data(), got);
    at += got;
  }
}

void AtomicFileWriter::commit() {
  out_.flush();
  const bool written = static_cast<bool>(out_);
  out_.close();
  if (!written || !out_ || (!in_place_ && std::rename(temp_.c_str(), path_.c_str()) != 0)) {
    const std::string reason = std::strerror(errno);
    if (!in_place_) std::remove(temp_.c_str());
    committed_ = true;  // nothing left to remove
    live_.reset();
    throw Error(path_ + ": cannot write: " + reason);
  }
  committed_ = true;
  live_.reset();  // renamed: a signal now must not remove the name (it is gone anyway)
}

void check_output_path(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.empty()) throw Error("output path is empty");
  if (fs::is_directory(path, ec)) throw Error(path + ": cannot write: it is a directory");
  if (is_special_file(path)) {  // written in place: the file itself must be writable, not its directory
    if (::access(path.c_str(), W_OK) != 0) throw Error(path + ": cannot write: " + std::strerror(errno));
    return;
  }
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec)) throw Error(path + ": cannot write: no directory " + parent.string());
  const fs::path dir = parent.empty() ? fs::path(".") : parent;
  if (::access(dir.c_str(), W_OK) != 0) throw Error(path + ": cannot write: " + std::strerror(errno));
}

namespace {
// True when a and b name one file: the same inode when both exist, else the same normalised path.
bool same_file(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
  const fs::path ca = fs::weakly_canonical(fs::absolute(a, ec), ec);
  const fs::path cb = fs::weakly_canonical(fs::absolute(b, ec), ec);
  return !ca.empty() && ca == cb;
}
}  // namespace

void check_outputs_distinct(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const NamedPath& out = outputs[k];
    if (is_special_file(out.path)) continue;  // /dev/null may take every output
    for (const NamedPath& in : inputs)
      if (same_file(out.path, in.path)) throw Error(out.path + ": cannot write: it is also the " + in.name);
    for (std::size_t m = 0; m < k; ++m)
      if (same_file(out.path, outputs[m].path)) throw Error(out.path + ": cannot write: it is also the " + outputs[m].name);
  }
}

void write_bytes_atomically(const std::string& path, const void* data, std::size_t size) {
  write_file_atomically(path, [&](std::ostream& out) { out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size)); });
}

}  // namespace nbscope
