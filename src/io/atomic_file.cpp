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
}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& fill) {
  if (path.empty()) throw Error("output path is empty");
  if (std::filesystem::is_directory(path)) throw Error(path + ": cannot write: it is a directory");
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
  temp_ = temp_name_for(path_);
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    const std::string reason = std::strerror(errno);
    std::remove(temp_.c_str());
    throw Error(path_ + ": cannot write: " + reason);
  }
}

AtomicFileWriter::~AtomicFileWriter() {
  if (committed_) return;
  out_.close();
  std::remove(temp_.c_str());
}

void AtomicFileWriter::commit() {
  out_.flush();
  const bool written = static_cast<bool>(out_);
  out_.close();
  if (!written || !out_ || std::rename(temp_.c_str(), path_.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temp_.c_str());
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
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec)) throw Error(path + ": cannot write: no directory " + parent.string());
  const fs::path dir = parent.empty() ? fs::path(".") : parent;
  if (::access(dir.c_str(), W_OK) != 0) throw Error(path + ": cannot write: " + std::strerror(errno));
}

void write_bytes_atomically(const std::string& path, const void* data, std::size_t size) {
  write_file_atomically(path, [&](std::ostream& out) { out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size)); });
}

}  // namespace nbscope
