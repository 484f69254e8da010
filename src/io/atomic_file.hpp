// nbscope io: output files written whole or not at all.
#pragma once
#include <fstream>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace nbscope {

// Writes `path` by calling `fill` on a stream to a temporary file beside it, then renaming it into
// place. On any failure (including an exception from `fill`) the temporary is removed, `path` is
// left as it was, and Error("<path>: cannot write: <reason>") is thrown. An existing path that is
// not a regular file (/dev/null, /dev/stdout, a FIFO) is written in place instead: renaming over
// it would replace the device with a plain file.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& fill);

// Refuses, before any work is done, a path that cannot be written: empty, a directory, or in a
// directory that does not exist or is not writable. Throws Error("<path>: cannot write: <reason>").
void check_output_path(const std::string& path);

// A path a command reads or writes, and what names it on the command line ("--scene").
struct NamedPath {
  const char* name;
  std::string path;
};
// Refuses an output that is the same file as an input or as an earlier output, by any spelling
// (so --report cannot overwrite the --scene it reads): Error("<output>: cannot write: it is also
// the <name>"). Call it with the optional paths that were given.
void check_outputs_distinct(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

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
  bool in_place_ = false;  // a device or FIFO: written directly, never renamed over
};

// Same, for bytes already in memory (PNG encoders hand over a buffer).
void write_bytes_atomically(const std::string& path, const void* data, std::size_t size);

}  // namespace nbscope
