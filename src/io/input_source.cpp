#include "io/input_source.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>
#include <string_view>

#include "core/error.hpp"

namespace nbscope {

std::string kind_with_article(const char* kind) {
  const bool vowel = std::string_view("aeiou").find(kind[0]) != std::string_view::npos;
  return std::string(vowel ? "an " : "a ") + kind;
}

namespace {

// A pipe peeked and not yet opened by a reader: its descriptor and the bytes read from it.
struct Peeked {
  int fd = -1;
  std::string bytes;
};

// A pipe as the system knows it (device and inode, which stat(2) of /dev/stdin, /proc/self/fd/0 and
// /dev/fd/0 share), so that no other pipe, opened later under a name once used, is taken for it.
using PipeKey = std::pair<dev_t, ino_t>;

// Pipes peeked and not yet read. A pipe's bytes can be read once, so they live here between the
// sniffing and the reading; the reader takes its entry out.
std::mutex& peeked_mutex() {
  static std::mutex m;
  return m;
}
std::map<PipeKey, Peeked>& peeked() {
  static std::map<PipeKey, Peeked> inputs;
  return inputs;
}

// The key of `path` when it names something other than a regular file or a directory.
std::optional<PipeKey> pipe_key(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode) || S_ISDIR(st.st_mode)) return std::nullopt;
  return PipeKey{st.st_dev, st.st_ino};
}

// open(2) with open_input's checks and messages; the descriptor, never negative.
int open_checked(const std::string& path, const char* kind) {
  if (path.empty()) throw Error(std::string(kind) + " path is empty");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Error(path + ": is a directory, not " + kind_with_article(kind));
  int fd = -1;
  do fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  while (fd < 0 && errno == EINTR);
  if (fd < 0) throw Error(path + ": cannot open the " + kind + " (no such file or not readable)");
  return fd;
}

// read(2) until `n` bytes or the end; the count read.
std::size_t read_fully(int fd, char* to, std::size_t n, const std::string& path, const char* kind) {
  std::size_t done = 0;
  while (done < n) {
    const ssize_t got = ::read(fd, to + done, n - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw Error(path + ": cannot read the " + kind + ": " + std::strerror(errno));
    if (got == 0) break;
    done += static_cast<std::size_t>(got);
  }
  return done;
}

std::optional<std::size_t> regular_size(int fd) {
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) return static_cast<std::size_t>(st.st_size);
  return std::nullopt;
}

}  // namespace

InputSource::InputSource(const std::string& path, const char* kind) : path_(path), kind_(kind) {
  if (const auto key = pipe_key(path)) {
    const std::lock_guard lock(peeked_mutex());
    if (const auto it = peeked().find(*key); it != peeked().end()) {
      fd_ = it->second.fd;
      kept_ = std::move(it->second.bytes);
      peeked().erase(it);
      return;
    }
  }
  fd_ = open_checked(path, kind);
  file_size_ = regular_size(fd_);
}

InputSource::~InputSource() {
  if (fd_ >= 0) ::close(fd_);
}

std::size_t InputSource::read(char* to, std::size_t n) {
  if (kept_read_ < kept_.size()) {
    const std::size_t k = std::min(n, kept_.size() - kept_read_);
    std::memcpy(to, kept_.data() + kept_read_, k);
    kept_read_ += k;
    if (kept_read_ == kept_.size()) {
      std::string().swap(kept_);  // all given: its memory back
      kept_read_ = 0;
    }
    return k;
  }
  for (;;) {
    const ssize_t got = ::read(fd_, to, n);
    if (got >= 0) return static_cast<std::size_t>(got);
    if (errno != EINTR) throw Error(path_ + ": cannot read the " + kind_ + ": " + std::strerror(errno));
  }
}

bool InputSource::seek(std::size_t offset) {
  if (!file_size_ || kept_read_ < kept_.size()) return false;
  return ::lseek(fd_, static_cast<off_t>(offset), SEEK_SET) == static_cast<off_t>(offset);
}

std::string peek_input(const std::string& path, std::size_t n, const char* kind) {
  const std::optional<PipeKey> key = pipe_key(path);
  const std::lock_guard lock(peeked_mutex());
  if (const auto it = key ? peeked().find(*key) : peeked().end(); it != peeked().end()) {
    Peeked& p = it->second;
    if (p.bytes.size() < n) {
      const std::size_t old = p.bytes.size();
      p.bytes.resize(n);
      p.bytes.resize(old + read_fully(p.fd, p.bytes.data() + old, n - old, path, kind));
    }
    return p.bytes.substr(0, n);
  }
  const int fd = open_checked(path, kind);
  std::string head(n, '\0');
  if (regular_size(fd) || !key) {  // a file: read its start, and the reader opens it again
    std::size_t got = 0;
    try {
      got = read_fully(fd, head.data(), n, path, kind);
    } catch (...) {
      ::close(fd);
      throw;
    }
    ::close(fd);
    head.resize(got);
    return head;
  }
  Peeked p{fd, {}};
  try {
    head.resize(read_fully(fd, head.data(), n, path, kind));
  } catch (...) {
    ::close(fd);
    throw;
  }
  p.bytes = head;
  peeked().emplace(*key, std::move(p));
  return head;
}

void forget_peeked_inputs() {
  const std::lock_guard lock(peeked_mutex());
  for (auto& [key, p] : peeked()) ::close(p.fd);
  peeked().clear();
}

// ---- InputStream -----------------------------------------------------------------------------

class InputStream::Buffer : public std::streambuf {
 public:
  Buffer(const std::string& path, const char* kind) : source_(path, kind) {}

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    const std::size_t got = source_.read(buf_, sizeof buf_);
    if (got == 0) return traits_type::eof();
    setg(buf_, buf_, buf_ + got);
    return traits_type::to_int_type(*gptr());
  }
  std::streamsize xsgetn(char* to, std::streamsize n) override {
    // Large reads go straight into the caller's buffer: no copy through buf_.
    std::streamsize done = 0;
    while (done < n) {
      if (gptr() < egptr()) {
        const std::streamsize k = std::min<std::streamsize>(n - done, egptr() - gptr());
        std::memcpy(to + done, gptr(), static_cast<std::size_t>(k));
        gbump(static_cast<int>(k));
        done += k;
        continue;
      }
      const std::size_t got = source_.read(to + done, static_cast<std::size_t>(n - done));
      if (got == 0) break;
      done += static_cast<std::streamsize>(got);
    }
    return done;
  }

 private:
  InputSource source_;
  char buf_[std::size_t{64} << 10];
};

InputStream::InputStream(const std::string& path, const char* kind)
    : std::istream(nullptr), buffer_(std::make_unique<Buffer>(path, kind)) {
  rdbuf(buffer_.get());
}

InputStream::~InputStream() = default;

}  // namespace nbscope
