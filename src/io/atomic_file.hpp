// nbscope io: output files written whole or not at all.
#pragma once
#include <fstream>
#include <functional>
#include <ostream>
#include <string>

namespace nbscope {

// Writes `path` by calling `fill` on a stream to a temporary file beside it, then renaming it into
// place. On any failure (including an exception from `fill`) the temporary is removed, `path` is
// left as it was, and Error("<path>: cannot write: <reason>") is thrown.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& fill);

// Refuses, before any work is done, a path that cannot be written: empty, a directory, or in a
// directory that does not exist or is not writable. Throws Error("<path>: cannot write: <reason>").
void check_output_path(const std::string& path);

// A file written piece by piece over a long run (headless --record), whole or not at all: it
// streams to a temporary file beside `path`; commit() renames it into place. Destroyed without
// commit() (an error, an interruption turned into an exception) it removes the temporary, so
// neither `path` nor a temporary remains.
class AtomicFileWriter {
 public:
  // Creates the temporary; Error("<path>: cannot write: <reason>") when it cannot.
  explicit AtomicFileWriter(std::string path);
  // Removes the temporary unless committed.
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  // Where to write; a failed write is noticed by commit().
  std::ostream& stream() { return out_; }
  // Flushes, closes and renames into place; Error (temporary removed) on any failure.
  void commit();

 private:
  std::string path_, temp_;
  std::ofstream out_;
  bool committed_ = false;
};

// Same, for bytes already in memory (PNG encoders hand over a buffer).
void write_bytes_atomically(const std::string& path, const void* data, std::size_t size);

}  // namespace nbscope
