#include "io/input_file.hpp"

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
  return std::to_string(bytes) + " bytes";
}
}  // namespace

std::string read_input_file(const std::string& path, const char* kind, std::size_t max_bytes) {
  if (path.empty()) throw Error(std::string(kind) + " path is empty");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Error(path + ": is a directory, not " + with_article(kind));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open the " + kind + " (no such file or not readable)");
  std::string text;
  constexpr std::size_t kChunk = std::size_t{1} << 20;
  while (in) {
    const std::size_t old = text.size();
    text.resize(old + kChunk);
    in.read(text.data() + old, static_cast<std::streamsize>(kChunk));
    text.resize(old + static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes)
      throw Error(path + ": larger than " + size_text(max_bytes) + ", the limit for " + with_article(kind));
  }
  if (in.bad()) throw Error(path + ": cannot read the " + kind);
  return text;
}

}  // namespace nbscope
