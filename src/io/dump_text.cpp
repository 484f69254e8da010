#include "io/dump_text.hpp"

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
  gzFile gz = gzopen(path.c_str(), "rb");
  if (gz == nullptr) throw Error(path + ": cannot open: " + std::strerror(errno));
  gzbuffer(gz, 1U << 20);
  gz_ = gz;
}

DumpText::DumpText(const std::string& text, const std::string& where) : path_(where), data_(text), end_(true) {
  check_chunk(0);
}

DumpText::~DumpText() {
  if (gz_ != nullptr) gzclose(static_cast<gzFile>(gz_));
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
  buf_.erase(0, begin_);
  base_ += begin_;
  begin_ = 0;
  const std::size_t old = buf_.size();
  buf_.resize(old + kChunk);
  const int got = gzread(static_cast<gzFile>(gz_), buf_.data() + old, static_cast<unsigned>(kChunk));
  if (got < 0) {
    int code = 0;
    const char* what = gzerror(static_cast<gzFile>(gz_), &code);
    throw Error(path_ + ": cannot read the dump file: " + (code == Z_ERRNO ? std::strerror(errno) : what));
  }
  buf_.resize(old + static_cast<std::size_t>(got));
  data_ = buf_;
  if (got == 0) {
    end_ = true;
    return false;
  }
  check_chunk(old);
  return true;
}

bool DumpText::next(std::string_view& line) {
  for (;;) {
    const void* nl = std::memchr(data_.data() + begin_, '\n', data_.size() - begin_);
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
