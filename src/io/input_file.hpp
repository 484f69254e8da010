// nbscope io: reading a text input, whole or line by line, with size limits, for every text format.
#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "core/error.hpp"

namespace nbscope {

// Default limits per format: generous for real data, small enough that /dev/zero or a runaway
// pipe stops with an error instead of taking the machine's memory. No flag raises them.
inline constexpr std::size_t kMaxSceneBytes = std::size_t{256} << 20;      // generators keep scenes small
inline constexpr std::size_t kMaxElementsBytes = std::size_t{2} << 30;     // ~50 million x,y,r rows
inline constexpr std::size_t kMaxRecordingBytes = std::size_t{2} << 30;
// Longest line of the line-based formats (ELEMENTS.csv, PAIRS.csv, .nbsrec, the scaling CSV): a
// row is a few numbers, so a longer line is not one of theirs, and an endless line (a pipe that
// never sends a newline) is refused after this many bytes instead of after the size limit.
inline constexpr std::size_t kMaxLineBytes = std::size_t{64} << 10;

// The contents of `path`, a `kind` of file ("scene file", "elements file", ...). Throws Error
// "<path>: <what>" for an empty path, a directory, a file that cannot be opened or read, or more
// than `max_bytes` bytes (the read stops there: a device or pipe that never ends is refused too);
// Error "<path>:<line>: <what>" for a NUL byte (binary data or UTF-16: every format is text; seen
// in the first chunk read, so /dev/zero stops at once) and, when `max_line_bytes` is not 0, for a
// line longer than that (seen as soon as that many bytes without a newline have been read).
std::string read_input_file(const std::string& path, const char* kind, std::size_t max_bytes, std::size_t max_line_bytes = 0);

// The errors every text reader gives: "<path>: larger than 2048 MB, the limit for an elements file",
// and "<path>:<line>: a NUL byte (byte N): an elements file is text, this is binary data (...)".
Error input_too_large(const std::string& path, const char* kind, std::size_t max_bytes);
Error nul_byte_in(const std::string& path, std::size_t line, std::size_t byte, const char* kind);

class TextCheck;
class InputStream;

// The lines of a text input as they arrive, with read_input_file's checks and messages: a reader
// that refuses its input at a row (too many elements, frames) stops there, having held one chunk
// of text, and a reader that needs only the first frames stops reading an endless pipe. Opening
// throws as read_input_file does; next() throws for a NUL byte, a line longer than
// `max_line_bytes` or more than `max_bytes` bytes, each as soon as the chunk holding it is read.
class InputLines {
 public:
  // `open_path`, when given, is opened in place of `path` (a spooled copy); messages name `path`.
  InputLines(const std::string& path, const char* kind, std::size_t max_bytes, std::size_t max_line_bytes,
             const std::string& open_path = {});
  ~InputLines();
  InputLines(const InputLines&) = delete;
  InputLines& operator=(const InputLines&) = delete;

  // The next line, without its '\n', into `line` (valid until the next call); false at the end.
  bool next(std::string_view& line);
  // The number of the line next() gave last (1-based; 0 before the first).
  [[nodiscard]] std::size_t line_number() const { return line_no_; }
  // The byte of the input that line starts at; and the bytes read past its lines so far (at the end: the input's size).
  [[nodiscard]] std::size_t line_offset() const { return line_start_; }
  [[nodiscard]] std::size_t offset() const { return base_ + begin_; }

 private:
  void fill();  // reads one more chunk behind the unread bytes

  std::string path_;
  const char* kind_;
  std::size_t max_bytes_;
  std::unique_ptr<InputStream> in_;  // a file or a pipe, with what was peeked from it (io/input_source.hpp)
  std::unique_ptr<TextCheck> check_;
  std::string buf_;          // unread bytes start at begin_
  std::size_t begin_ = 0;
  std::size_t base_ = 0;     // offset in the input of buf_[0]
  std::size_t chunk_;        // small at first: /dev/zero or a binary file stops after one
  bool end_ = false;
  std::size_t line_no_ = 0;
  std::size_t line_start_ = 0;
};

}  // namespace nbscope
