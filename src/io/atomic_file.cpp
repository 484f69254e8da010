#include "io/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <utility>

#include "core/error.hpp"

namespace nbscope {

namespace {
std::string temp_name_for(const std::string& path) {
  return path + ".tmp." + std::to_string(static_cast<long>(::getpid()));
}

// An existing path that is not a regular file: /dev/null, /dev/stdout, a FIFO. It is written in
// place: renaming a temporary over it would replace the device with a plain file (as root).
bool is_special_file(const std::string& path) {
  std::error_code ec;
  const auto st = std::filesystem::status(path, ec);
  return !ec && std::filesystem::exists(st) && !std::filesystem::is_regular_file(st) && !std::filesystem::is_directory(st);
}

void write_in_place(const std::string& path, const std::function<void(std::ostream&)>& fill) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw Error(path + ": cannot write: " + std::strerror(errno));
  fill(out);
  out.flush();
  if (!out) throw Error(path + ": cannot write: " + std::strerror(errno));
}
}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& fill) {
  if (path.empty()) throw Error("output path is empty");
  std::error_code ec;  // a name too long, a directory not searchable: the open below says what is wrong
  if (std::filesystem::is_directory(path, ec)) throw Error(path + ": cannot write: it is a directory");
  if (is_special_file(path)) return write_in_place(path, fill);
  const std::string tmp = temp_name_for(path);
  try {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(path + ": cannot write: " + std::strerror(errno));
    fill(out);
    out.flush();
    if (!out) throw Error(path + ": cannot write: " + std::strerror(errno));
    out.close();
    if (std::rename(tmp.c_str(), path.c_str()) != 0) throw Error(path + ": cannot write: " + std::strerror(errno));
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
}

AtomicFileWriter::AtomicFileWriter(std::string path) : path_(std::move(path)) {
  if (path_.empty()) throw Error("output path is empty");
  if (std::filesystem::is_directory(path_)) throw Error(path_ + ": cannot write: it is a directory");
  in_place_ = is_special_file(path_);
  temp_ = in_place_ ? path_ : temp_name_for(path_);
  out_.open(temp_, in_place_ ? std::ios::binary : std::ios::binary | std::ios::trunc);
  if (!out_) {
    const std::string reason = std::strerror(errno);
    if (!in_place_) std::remove(temp_.c_str());
    throw Error(path_ + ": cannot write: " + reason);
  }
}

AtomicFileWriter::~AtomicFileWriter() {
  if (committed_) return;
  out_.close();
  if (!in_place_) std::remove(temp_.c_str());
}

void AtomicFileWriter::commit() {
  out_.flush();
  const bool written = static_cast<bool>(out_);
  out_.close();
  if (!written || !out_ || (!in_place_ && std::rename(temp_.c_str(), path_.c_str()) != 0)) {
    const std::string reason = std::strerror(errno);
    if (!in_place_) std::remove(temp_.c_str());
    committed_ = true;  // nothing left to remove
    throw Error(path_ + ": cannot write: " + reason);
  }
  committed_ = true;
}

void check_output_path(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.empty()) throw Error("output path is empty");
  if (fs::is_directory(path, ec)) throw Error(path + ": cannot write: it is a directory");
  if (is_special_file(path)) {  // written in place: the file itself must be writable, not its directory
    if (::access(path.c_str(), W_OK) != 0) throw Error(path + ": cannot write: " + std::strerror(errno));
    return;
  }
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec)) throw Error(path + ": cannot write: no directory " + parent.string());
  const fs::path dir = parent.empty() ? fs::path(".") : parent;
  if (::access(dir.c_str(), W_OK) != 0) throw Error(path + ": cannot write: " + std::strerror(errno));
}

namespace {
// True when a and b name one file: the same inode when both exist, else the same normalised path.
bool same_file(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
  const fs::path ca = fs::weakly_canonical(fs::absolute(a, ec), ec);
  const fs::path cb = fs::weakly_canonical(fs::absolute(b, ec), ec);
  return !ca.empty() && ca == cb;
}
}  // namespace

void check_outputs_distinct(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const NamedPath& out = outputs[k];
    if (is_special_file(out.path)) continue;  // /dev/null may take every output
    for (const NamedPath& in : inputs)
      if (same_file(out.path, in.path)) throw Error(out.path + ": cannot write: it is also the " + in.name);
    for (std::size_t m = 0; m < k; ++m)
      if (same_file(out.path, outputs[m].path)) throw Error(out.path + ": cannot write: it is also the " + outputs[m].name);
  }
}

void write_bytes_atomically(const std::string& path, const void* data, std::size_t size) {
  write_file_atomically(path, [&](std::ostream& out) { out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size)); });
}

}  // namespace nbscope
