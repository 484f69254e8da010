// nbscope io: the lines of a LAMMPS/LIGGGHTS dump, from memory or streamed from a file or a pipe
// (io/input_source.hpp; gzip inflated as it arrives), with the text readers' checks (io/input_file.hpp).
#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace nbscope {

class InputSource;

// A dump's lines, one at a time; a file is read in 4 MB chunks and never held whole.
class DumpText {
 public:
  // Opens `path` (plain or gzip; a file or a pipe). Error "<path>: ..." for a missing file, a directory, a failed open.
  explicit DumpText(const std::string& path);
  // Opens `path` as above and starts at byte `offset` of its text, which is line `line` (an offset
  // offset() gave on an earlier read of the same file): a plain file seeks there, gzip inflates up to it.
  DumpText(const std::string& path, std::size_t offset, std::size_t line);
  // Reads `text` in memory (kept by reference: it must outlive this); `where` names it.
  DumpText(const std::string& text, const std::string& where);
  ~DumpText();
  DumpText(const DumpText&) = delete;
  DumpText& operator=(const DumpText&) = delete;

  // The next line without its "\n" (and "\r"), valid until the next call; false at the end.
  // Error for a NUL byte, a line longer than kMaxLineBytes, a gzip stream that is corrupt: each
  // once the lines before it have been given, so a file and a pipe, read in other pieces, fail alike.
  bool next(std::string_view& line);
  // The byte of the text the next line starts at (for DumpText(path, offset, line)).
  [[nodiscard]] std::size_t offset() const { return base_ + begin_; }
  // The number of the line next() gave last (1-based).
  [[nodiscard]] std::size_t line_number() const { return line_no_; }
  // At most how many bytes are left to read (a gzip file's: 1032 times its size, deflate's largest
  // ratio; a pipe's: 0, unknown), so that a reader does not take a header's word for memory the text cannot fill.
  [[nodiscard]] std::size_t bytes_left() const;
  // The file's name as messages give it.
  [[nodiscard]] const std::string& path() const { return path_; }
  // "<path>:<line>: " for the line next() gave last.
  [[nodiscard]] std::string at() const { return path_ + ":" + std::to_string(line_no_) + ": "; }

 private:
  bool fill();  // reads one more chunk behind the unread bytes; false at the end of the file
  void check_chunk(std::size_t from);
  std::size_t inflate_into(char* to, std::size_t room);  // a gzip input's next bytes of text; 0 at its end

  struct Gzip;
  std::string path_;
  std::unique_ptr<InputSource> source_;  // null for text in memory
  std::unique_ptr<Gzip> gzip_;           // a gzip input's inflater (null: plain text, read as it is)
  std::unique_ptr<char[]> buf_;  // a file's bytes: unread from begin_ (not zero-filled: no memset per chunk)
  std::size_t capacity_ = 0;
  std::size_t file_size_ = 0;  // a plain file's size at open; a gzip file's bound on its text
  std::string_view data_;   // the text being cut into lines (buf_ or the caller's)
  std::size_t begin_ = 0;
  std::size_t base_ = 0;    // offset in the input of data_[0]
  bool end_ = false;
  std::size_t nul_line_ = 0;  // the first NUL byte's line and byte (1-based; 0: none seen), where data_ ends
  std::size_t nul_byte_ = 0;
  std::size_t line_no_ = 0;
};

}  // namespace nbscope
