#include "io/input_file.hpp"

#include <cstring>
#include <string_view>

#include "core/error.hpp"
#include "io/input_source.hpp"

namespace nbscope {

namespace {
std::string with_article(const char* kind) { return kind_with_article(kind); }
std::string size_text(std::size_t bytes) {
  if (bytes >= (std::size_t{1} << 20) && bytes % (std::size_t{1} << 20) == 0) return std::to_string(bytes >> 20) + " MB";
  if (bytes >= (std::size_t{1} << 10) && bytes % (std::size_t{1} << 10) == 0) return std::to_string(bytes >> 10) + " KiB";
  return std::to_string(bytes) + " bytes";
}

}  // namespace

Error input_too_large(const std::string& path, const char* kind, std::size_t max_bytes) {
  return Error(path + ": larger than " + size_text(max_bytes) + ", the limit for " + with_article(kind));
}

Error nul_byte_in(const std::string& path, std::size_t line, std::size_t byte, const char* kind) {
  return Error(path + ":" + std::to_string(line) + ": a NUL byte (byte " + std::to_string(byte) + "): " + with_article(kind) +
               " is text, this is binary data (or UTF-16 text: save it as UTF-8)");
}

namespace {

constexpr std::size_t kFirstChunk = std::size_t{64} << 10;
constexpr std::size_t kChunk = std::size_t{1} << 20;
}  // namespace

// Checks each chunk as it arrives, counting lines once: a NUL byte, and a line longer than the
// limit (also one still open at the end of what has been read). Offsets are in the whole input.
class TextCheck {
 public:
  TextCheck(const std::string& path, const char* kind, std::size_t max_line) : path_(path), kind_(kind), max_line_(max_line) {}

  // Checks the `size` bytes at `data`, which start at `offset` in the input.
  void chunk(const char* data, std::size_t size, std::size_t offset) {
    const char* const end = data + size;
    const void* nul = std::memchr(data, '\0', size);
    const char* const stop = nul != nullptr ? static_cast<const char*>(nul) : end;
    const auto at = [&](const char* p) { return offset + static_cast<std::size_t>(p - data); };
    for (const char* p = data; p < stop;) {
      const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(stop - p));
      if (nl == nullptr) break;
      p = static_cast<const char*>(nl);
      check_line(at(p));
      line_start_ = at(p) + 1;
      ++line_;
      ++p;
    }
    if (nul != nullptr)
      throw nul_byte_in(path_, line_, at(stop), kind_);
    check_line(at(end));
  }

 private:
  // The line that started at line_start_ has reached `end` bytes.
  void check_line(std::size_t end) const {
    if (max_line_ != 0 && end - line_start_ > max_line_)
      throw Error(path_ + ":" + std::to_string(line_) + ": a line longer than " + size_text(max_line_) + ", the limit for " +
                  with_article(kind_) + " (its lines are short rows; is this the right file?)");
  }
  std::string path_;
  const char* kind_;
  std::size_t max_line_;
  std::size_t line_ = 1;
  std::size_t line_start_ = 0;
};

std::string read_input_file(const std::string& path, const char* kind, std::size_t max_bytes, std::size_t max_line_bytes) {
  InputStream in(path, kind);
  std::string text;
  TextCheck check(path, kind, max_line_bytes);
  // A small first chunk: /dev/zero, a binary file or an endless line are refused after reading it.
  std::size_t chunk = kFirstChunk;
  while (in) {
    const std::size_t old = text.size();
    text.resize(old + chunk);
    in.read(text.data() + old, static_cast<std::streamsize>(chunk));
    text.resize(old + static_cast<std::size_t>(in.gcount()));
    check.chunk(text.data() + old, text.size() - old, old);
    if (text.size() > max_bytes)
      throw input_too_large(path, kind, max_bytes);
    chunk = kChunk;
  }
  if (in.bad()) throw Error(path + ": cannot read the " + kind);
  return text;
}

// ---- InputLines ------------------------------------------------------------------------------

InputLines::InputLines(const std::string& path, const char* kind, std::size_t max_bytes, std::size_t max_line_bytes,
                       const std::string& open_path)
    : path_(path), kind_(kind), max_bytes_(max_bytes), chunk_(kFirstChunk) {
  if (open_path.empty()) {
    in_ = std::make_unique<InputStream>(path, kind);
  } else {
    try {
      in_ = std::make_unique<InputStream>(open_path, kind);
    } catch (const Error&) {
      throw Error(path + ": cannot read the " + kind + " back from its spooled copy");
    }
  }
  check_ = std::make_unique<TextCheck>(path, kind, max_line_bytes);
}

InputLines::~InputLines() = default;

void InputLines::fill() {
  // Only the unread part of a line is kept: the text held is one chunk and one line at most.
  buf_.erase(0, begin_);
  base_ += begin_;
  begin_ = 0;
  const std::size_t old = buf_.size();
  buf_.resize(old + chunk_);
  in_->read(buf_.data() + old, static_cast<std::streamsize>(chunk_));
  const auto got = static_cast<std::size_t>(in_->gcount());
  buf_.resize(old + got);
  check_->chunk(buf_.data() + old, got, base_ + old);
  if (base_ + buf_.size() > max_bytes_)
    throw input_too_large(path_, kind_, max_bytes_);
  chunk_ = kChunk;
  if (!*in_) {
    if (in_->bad()) throw Error(path_ + ": cannot read the " + kind_);
    end_ = true;
  }
}

bool InputLines::next(std::string_view& line) {
  for (;;) {
    const char* const from = buf_.data() + begin_;
    const std::size_t left = buf_.size() - begin_;
    if (const void* nl = std::memchr(from, '\n', left); nl != nullptr) {
      const auto length = static_cast<std::size_t>(static_cast<const char*>(nl) - from);
      line = std::string_view(from, length);
      line_start_ = base_ + begin_;
      begin_ += length + 1;
      ++line_no_;
      return true;
    }
    if (end_) {
      if (left == 0) return false;
      line = std::string_view(from, left);  // the last line, without a newline
      line_start_ = base_ + begin_;
      begin_ = buf_.size();
      ++line_no_;
      return true;
    }
    fill();
  }
}

}  // namespace nbscope
