#include "io/dump_text.hpp"

#include <zlib.h>

#include <algorithm>
#include <limits>
#include <cstring>
#include <filesystem>

#include "core/error.hpp"
#include "io/input_file.hpp"
#include "io/input_source.hpp"

namespace nbscope {

namespace {
constexpr std::size_t kChunk = std::size_t{4} << 20;
constexpr std::size_t kGzipIn = std::size_t{1} << 20;  // compressed bytes read at a time
constexpr const char* kKind = "dump file";

Error long_line(const std::string& path, std::size_t line) {
  return Error(path + ":" + std::to_string(line) + ": a line longer than " + std::to_string(kMaxLineBytes >> 10) +
               " KB, the limit for a dump file (its lines are short rows; is this the right file?)");
}
}  // namespace

// zlib's inflater over the compressed bytes of the source, member after member (gzip -c a b > c).
struct DumpText::Gzip {
  z_stream z{};
  std::unique_ptr<char[]> in = std::make_unique_for_overwrite<char[]>(kGzipIn);
  bool input_end = false;   // the source has no more compressed bytes
  bool member_end = false;  // a member ended: another may follow
  // A corrupt stream's message, once the text inflated before the fault has been given out: the
  // fault is met where it lies in the text, as a pipe's small reads meet it, not a chunk early.
  std::string error;
  Gzip() {
    if (inflateInit2(&z, 16 + MAX_WBITS) != Z_OK) throw Error("zlib: cannot start inflating (out of memory)");
  }
  ~Gzip() { inflateEnd(&z); }
  Gzip(const Gzip&) = delete;
  Gzip& operator=(const Gzip&) = delete;
};

DumpText::DumpText(const std::string& path) : path_(path) {
  std::error_code ec;
  if (path.empty()) throw Error("dump file: an empty path");
  if (!std::filesystem::exists(path, ec)) throw Error(path + ": no such file");
  if (std::filesystem::is_directory(path, ec)) throw Error(path + ": a directory, not a dump file");
  const std::string magic = peek_input(path, 2, kKind);  // a pipe keeps the two bytes for source_
  const bool gzip = magic.size() == 2 && static_cast<unsigned char>(magic[0]) == 0x1f && static_cast<unsigned char>(magic[1]) == 0x8b;
  source_ = std::make_unique<InputSource>(path, kKind);
  if (gzip) gzip_ = std::make_unique<Gzip>();
  file_size_ = source_->file_size().value_or(0);
  if (gzip) file_size_ = file_size_ > (static_cast<std::size_t>(-1) >> 11) ? static_cast<std::size_t>(-1) : file_size_ * 1032;
  capacity_ = kChunk + kMaxLineBytes + 2;
  buf_ = std::make_unique_for_overwrite<char[]>(capacity_);
}

DumpText::DumpText(const std::string& path, std::size_t offset, std::size_t line) : DumpText(path) {
  line_no_ = line > 0 ? line - 1 : 0;
  const auto cut = [&] { return Error(path_ + ": ends before byte " + std::to_string(offset) + " (the file changed since it was read?)"); };
  if (!gzip_ && file_size_ != 0 && offset > file_size_) throw cut();
  if (!gzip_ && source_->seek(offset)) {
    base_ = offset;
    return;
  }
  // Inflated (or a pipe read) up to `offset`, the bytes before it dropped chunk by chunk.
  while (base_ + data_.size() < offset) {
    begin_ = data_.size();
    if (!fill()) throw cut();
  }
  begin_ = offset - base_;
}

DumpText::DumpText(const std::string& text, const std::string& where) : path_(where), data_(text), end_(true) {
  check_chunk(0);
}

std::size_t DumpText::bytes_left() const {
  if (source_ == nullptr) return data_.size() - begin_;
  const std::size_t done = base_ + begin_;
  return file_size_ > done ? file_size_ - done : 0;
}

DumpText::~DumpText() = default;

// A NUL byte in data_[from..] ends the text there: the lines before it are given out, and reading
// past it is refused with its line and byte. Refused at once, a file's NUL would come before the
// errors of the lines ahead of it in the same 4 MB chunk, which a pipe, read in smaller pieces, gives first.
void DumpText::check_chunk(std::size_t from) {
  const void* nul = std::memchr(data_.data() + from, 0, data_.size() - from);
  if (nul == nullptr) return;
  const auto at = static_cast<std::size_t>(static_cast<const char*>(nul) - data_.data());
  nul_line_ = line_no_ + 1;
  for (std::size_t k = begin_; k < at; ++k) nul_line_ += data_[k] == '\n' ? 1 : 0;
  nul_byte_ = base_ + at + 1;
  data_ = data_.substr(0, at);
}

bool DumpText::fill() {
  if (nul_byte_ != 0) throw nul_byte_in(path_, nul_line_, nul_byte_, kKind);
  if (end_) return false;
  const std::size_t rest = data_.size() - begin_;
  if (rest > 0) std::memmove(buf_.get(), data_.data() + begin_, rest);  // the first fill has no data_ (null) to move
  base_ += begin_;
  begin_ = 0;
  const std::size_t room = capacity_ - rest;
  const std::size_t got = gzip_ ? inflate_into(buf_.get() + rest, room) : source_->read(buf_.get() + rest, room);
  data_ = std::string_view(buf_.get(), rest + got);
  if (got == 0) {
    end_ = true;
    return false;
  }
  check_chunk(rest);
  return true;
}

std::size_t DumpText::inflate_into(char* to, std::size_t room) {
  z_stream& z = gzip_->z;
  const auto cannot = [&](const std::string& why) { return Error(path_ + ": cannot read the dump file: " + why); };
  z.next_out = reinterpret_cast<Bytef*>(to);
  z.avail_out = static_cast<uInt>(std::min<std::size_t>(room, std::numeric_limits<uInt>::max()));
  const uInt want = z.avail_out;
  if (!gzip_->error.empty()) throw Error(gzip_->error);
  while (z.avail_out == want) {
    if (z.avail_in == 0 && !gzip_->input_end) {
      z.next_in = reinterpret_cast<Bytef*>(gzip_->in.get());
      z.avail_in = static_cast<uInt>(source_->read(gzip_->in.get(), kGzipIn));
      gzip_->input_end = z.avail_in == 0;
    }
    if (gzip_->member_end) {
      // Another member follows when gzip's magic does; anything else after a member is ignored, as gzip -d does.
      if (z.avail_in == 0 || z.next_in[0] != 0x1f) return want - z.avail_out;
      if (inflateReset(&z) != Z_OK) throw cannot("zlib cannot restart");
      gzip_->member_end = false;
    }
    if (z.avail_in == 0) throw cannot("unexpected end of file (a gzip file cut short)");
    const int rc = inflate(&z, Z_NO_FLUSH);
    if (rc == Z_STREAM_END) gzip_->member_end = true;
    else if (rc != Z_OK && rc != Z_BUF_ERROR) {
      const Error e = cannot(z.msg != nullptr ? z.msg : zError(rc));
      if (z.avail_out == want) throw e;
      gzip_->error = e.what();  // the text before the fault first
      return want - z.avail_out;
    }
  }
  return want - z.avail_out;
}

bool DumpText::next(std::string_view& line) {
  for (;;) {
    // Nothing read yet: data_ is empty and its pointer may be null, which memchr must not be given.
    const void* nl = begin_ < data_.size() ? std::memchr(data_.data() + begin_, '\n', data_.size() - begin_) : nullptr;
    if (nl != nullptr || (end_ && nul_byte_ == 0)) {
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
