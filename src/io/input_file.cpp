#include "io/input_file.hpp"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "core/error.hpp"

namespace nbscope {

namespace {
// "a scene file", "an elements file".
std::string with_article(const char* kind) {
  const bool vowel = std::string_view("aeiou").find(kind[0]) != std::string_view::npos;
  return std::string(vowel ? "an " : "a ") + kind;
}
std::string size_text(std::size_t bytes) {
  if (bytes >= (std::size_t{1} << 20) && bytes % (std::size_t{1} << 20) == 0) return std::to_string(bytes >> 20) + " MB";
  if (bytes >= (std::size_t{1} << 10) && bytes % (std::size_t{1} << 10) == 0) return std::to_string(bytes >> 10) + " KiB";
  return std::to_string(bytes) + " bytes";
}

// Checks each chunk as it arrives, counting lines once: a NUL byte, and a line longer than the
// limit (also one still open at the end of what has been read).
class TextCheck {
 public:
  TextCheck(const std::string& path, const char* kind, std::size_t max_line) : path_(path), kind_(kind), max_line_(max_line) {}

  // Checks text[from, text.size()), the bytes just read.
  void chunk(const std::string& text, std::size_t from) {
    const char* const base = text.data();
    const char* const end = base + text.size();
    const void* nul = std::memchr(base + from, '\0', text.size() - from);
    const char* const stop = nul != nullptr ? static_cast<const char*>(nul) : end;
    for (const char* p = base + from; p < stop;) {
      const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(stop - p));
      if (nl == nullptr) break;
      p = static_cast<const char*>(nl);
      check_line(static_cast<std::size_t>(p - base));
      line_start_ = static_cast<std::size_t>(p - base) + 1;
      ++line_;
      ++p;
    }
    if (nul != nullptr)
      throw Error(path_ + ":" + std::to_string(line_) + ": a NUL byte (byte " + std::to_string(stop - base) + "): " +
                  with_article(kind_) + " is text, this is binary data (or UTF-16 text: save it as UTF-8)");
    check_line(text.size());
  }

 private:
  // The line that started at line_start_ has reached `end` bytes.
  void check_line(std::size_t end) const {
    if (max_line_ != 0 && end - line_start_ > max_line_)
      throw Error(path_ + ":" + std::to_string(line_) + ": a line longer than " + size_text(max_line_) + ", the limit for " +
                  with_article(kind_) + " (its lines are short rows; is this the right file?)");
  }
  const std::string& path_;
  const char* kind_;
  std::size_t max_line_;
  std::size_t line_ = 1;
  std::size_t line_start_ = 0;
};
}  // namespace

std::string read_input_file(const std::string& path, const char* kind, std::size_t max_bytes, std::size_t max_line_bytes) {
  if (path.empty()) throw Error(std::string(kind) + " path is empty");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Error(path + ": is a directory, not " + with_article(kind));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open the " + kind + " (no such file or not readable)");
  std::string text;
  TextCheck check(path, kind, max_line_bytes);
  // A small first chunk: /dev/zero, a binary file or an endless line are refused after reading it.
  std::size_t chunk = std::size_t{64} << 10;
  while (in) {
    const std::size_t old = text.size();
    text.resize(old + chunk);
    in.read(text.data() + old, static_cast<std::streamsize>(chunk));
    text.resize(old + static_cast<std::size_t>(in.gcount()));
    check.chunk(text, old);
    if (text.size() > max_bytes)
      throw Error(path + ": larger than " + size_text(max_bytes) + ", the limit for " + with_article(kind));
    chunk = std::size_t{1} << 20;
  }
  if (in.bad()) throw Error(path + ": cannot read the " + kind);
  return text;
}

}  // namespace nbscope
