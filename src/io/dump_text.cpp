#include "io/dump_text.hpp"

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"
#include "io/input_file.hpp"

namespace nbscope {

namespace {
constexpr std::size_t kChunk = std::size_t{4} << 20;
constexpr const char* kKind = "dump file";

Error long_line(const std::string& path, std::size_t line) {
  return Error(path + ":" + std::to_string(line) + ": a line longer than " + std::to_string(kMaxLineBytes >> 10) +
               " KB, the limit for a dump file (its lines are short rows; is this the right file?)");
}
}  // namespace

DumpText::DumpText(const std::string& path) : path_(path) {
  std::error_code ec;
  if (path.empty()) throw Error("dump file: an empty path");
  if (!std::filesystem::exists(path, ec)) throw Error(path + ": no such file");
  if (std::filesystem::is_directory(path, ec)) throw Error(path + ": a directory, not a dump file");
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) throw Error(path + ": cannot open: " + std::strerror(errno));
  unsigned char magic[2] = {0, 0};
  const bool gzip = ::pread(fd_, magic, 2, 0) == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
  if (gzip) {
    gzFile gz = gzdopen(fd_, "rb");  // owns fd_ from here
    if (gz == nullptr) {
      ::close(fd_);
      throw Error(path + ": cannot open: " + std::strerror(errno));
    }
    fd_ = -1;
    gzbuffer(gz, 1U << 20);
    gz_ = gz;
  }
  file_size_ = static_cast<std::size_t>(std::filesystem::file_size(path, ec));
  if (ec) file_size_ = 0;
  if (gzip) file_size_ = file_size_ > (static_cast<std::size_t>(-1) >> 11) ? static_cast<std::size_t>(-1) : file_size_ * 1032;
  capacity_ = kChunk + kMaxLineBytes + 2;
  buf_ = std::make_unique_for_overwrite<char[]>(capacity_);
}

DumpText::DumpText(const std::string& text, const std::string& where) : path_(where), data_(text), end_(true) {
  check_chunk(0);
}

std::size_t DumpText::bytes_left() const {
  if (gz_ == nullptr && fd_ < 0) return data_.size() - begin_;
  const std::size_t done = base_ + begin_;
  return file_size_ > done ? file_size_ - done : 0;
}

DumpText::~DumpText() {
  if (gz_ != nullptr) gzclose(static_cast<gzFile>(gz_));
  if (fd_ >= 0) ::close(fd_);
}

// A NUL byte in data_[from..] is refused with its line and byte.
void DumpText::check_chunk(std::size_t from) {
  const void* nul = std::memchr(data_.data() + from, 0, data_.size() - from);
  if (nul == nullptr) return;
  const auto at = static_cast<std::size_t>(static_cast<const char*>(nul) - data_.data());
  std::size_t line = line_no_ + 1;
  for (std::size_t k = begin_; k < at; ++k) line += data_[k] == '\n' ? 1 : 0;
  throw nul_byte_in(path_, line, base_ + at + 1, kKind);
}

bool DumpText::fill() {
  if (end_) return false;
  const std::size_t rest = data_.size() - begin_;
  if (rest > 0) std::memmove(buf_.get(), data_.data() + begin_, rest);  // the first fill has no data_ (null) to move
  base_ += begin_;
  begin_ = 0;
  const std::size_t room = capacity_ - rest;
  long got = 0;
  if (gz_ != nullptr) {
    got = gzread(static_cast<gzFile>(gz_), buf_.get() + rest, static_cast<unsigned>(room));
    if (got < 0) {
      int code = 0;
      const char* what = gzerror(static_cast<gzFile>(gz_), &code);
      throw Error(path_ + ": cannot read the dump file: " + (code == Z_ERRNO ? std::strerror(errno) : what));
    }
  } else {
    do got = ::read(fd_, buf_.get() + rest, room);
    while (got < 0 && errno == EINTR);
    if (got < 0) throw Error(path_ + ": cannot read the dump file: " + std::strerror(errno));
  }
  data_ = std::string_view(buf_.get(), rest + static_cast<std::size_t>(got));
  if (got == 0) {
    end_ = true;
    return false;
  }
  check_chunk(rest);
  return true;
}

bool DumpText::next(std::string_view& line) {
  for (;;) {
    // Nothing read yet: data_ is empty and its pointer may be null, which memchr must not be given.
    const void* nl = begin_ < data_.size() ? std::memchr(data_.data() + begin_, '\n', data_.size() - begin_) : nullptr;
    if (nl != nullptr || end_) {
      if (nl == nullptr && begin_ == data_.size()) return false;
      const std::size_t stop = nl == nullptr ? data_.size() : static_cast<std::size_t>(static_cast<const char*>(nl) - data_.data());
      line = data_.substr(begin_, stop - begin_);
      begin_ = nl == nullptr ? stop : stop + 1;
      ++line_no_;
      if (line.size() > kMaxLineBytes) throw long_line(path_, line_no_);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      return true;
    }
    if (data_.size() - begin_ > kMaxLineBytes) throw long_line(path_, line_no_ + 1);
    fill();
  }
}

}  // namespace nbscope
