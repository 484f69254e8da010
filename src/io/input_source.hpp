// nbscope io: where every reader's bytes come from. A file can be read again; a pipe, a FIFO,
// /dev/stdin or a process substitution only once. A reader that sniffs an input (is it a dump or a
// CSV? gzip?) peeks through peek_input(), which keeps the bytes a pipe gave, and the next
// InputSource opened on that path gives them first: no reader loses what another one looked at.
#pragma once
#include <cstddef>
#include <istream>
#include <memory>
#include <optional>
#include <streambuf>
#include <string>

namespace nbscope {

// An open input: a file, or a pipe/FIFO/device (with the bytes peeked from it before, if any).
class InputSource {
 public:
  // Opens `path` as a `kind` of input. Error "<kind> path is empty", "<path>: is a directory, not a
  // <kind>", "<path>: cannot open the <kind> (no such file or not readable)".
  InputSource(const std::string& path, const char* kind);
  ~InputSource();
  InputSource(const InputSource&) = delete;
  InputSource& operator=(const InputSource&) = delete;

  // Up to `n` bytes into `to`, at least one unless at the end (0); as read(2), a pipe may give fewer. Error "<path>: cannot read the <kind>: <why>".
  std::size_t read(char* to, std::size_t n);
  // Moves a regular file's next read to byte `offset` (replay reads a frame again where it starts);
  // false, unmoved, for a pipe, a FIFO or a device, which cannot go back.
  bool seek(std::size_t offset);
  // The size of a regular file when it was opened; nullopt for a pipe, a FIFO or a device.
  [[nodiscard]] std::optional<std::size_t> file_size() const { return file_size_; }
  // The path as messages name it.
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  std::string path_;
  const char* kind_;
  int fd_ = -1;
  std::string kept_;          // bytes peeked before this source was opened, given first
  std::size_t kept_read_ = 0;
  std::optional<std::size_t> file_size_;
};

// The first `n` bytes of `path` (fewer when it is shorter), without losing them: a regular file is
// read at its start; a pipe's bytes are kept for the next InputSource on `path`. Errors as InputSource.
std::string peek_input(const std::string& path, std::size_t n, const char* kind);
// Closes the pipes peeked and never read (a reader refused the input first): for a process that
// reads many inputs, such as a fuzz target; a command ends instead.
void forget_peeked_inputs();

// "a scene file", "an elements file": a kind of input as messages name it.
std::string kind_with_article(const char* kind);

// An std::istream over an InputSource, for the readers written against streams (the JSON parser).
class InputStream : public std::istream {
 public:
  // Opens `path` as InputSource does (same errors).
  InputStream(const std::string& path, const char* kind);
  ~InputStream() override;
  InputStream(const InputStream&) = delete;
  InputStream& operator=(const InputStream&) = delete;

 private:
  class Buffer;
  std::unique_ptr<Buffer> buffer_;
};

}  // namespace nbscope
