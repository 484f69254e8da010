// nbscope io: output files written whole or not at all, also when a signal ends the run.
//
// Every temporary an output is written through is registered while it exists (LiveTemporary); the
// first registration installs a handler for SIGINT, SIGTERM and SIGHUP (where their action is the
// default one) that removes the live temporaries and then ends the process by the same signal.
// SIGKILL cannot be caught: the temporary it leaves (PATH.tmp.PID) is removed, with a note on
// stderr, by the next write to the same PATH once process PID no longer runs.
//
// Index: write_file_atomically | check_output_path, check_outputs_distinct | AtomicFileWriter |
// write_bytes_atomically | LiveTemporary | ScratchFile.
#pragma once
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
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
class LiveTemporary;

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
  // The path it writes (for messages).
  [[nodiscard]] const std::string& path() const { return path_; }
  // Flushes, closes and renames into place; Error (temporary removed) on any failure.
  void commit();

 private:
  std::string path_, temp_;
  std::ofstream out_;
  bool committed_ = false;
  bool in_place_ = false;  // a device or FIFO: written directly, never renamed over
  std::unique_ptr<LiveTemporary> live_;  // the temporary, for the signal handler
};

// Same, for bytes already in memory (PNG encoders hand over a buffer).
void write_bytes_atomically(const std::string& path, const void* data, std::size_t size);

// A temporary file's name, registered for as long as this lives: SIGINT, SIGTERM or SIGHUP
// (with their default action, see the top of this file) removes it before the process ends.
// Register a name before creating the file, and release it after renaming or removing it.
class LiveTemporary {
 public:
  // Registers `path` (a name longer than 4095 bytes, or more than 64 at once, goes unregistered).
  explicit LiveTemporary(const std::string& path);
  // Releases the registration (the file itself is left alone).
  ~LiveTemporary();
  LiveTemporary(const LiveTemporary&) = delete;
  LiveTemporary& operator=(const LiveTemporary&) = delete;
  // Releases it early.
  void release();

 private:
  int slot_ = -1;
};

// Removes every registered temporary now (async-signal-safe: the handler's own work; tests).
void remove_live_temporaries();
// How many temporaries are registered (tests: none is left once a write has ended, however it ended).
[[nodiscard]] std::size_t live_temporary_count();

// A scratch file with no name, beside `beside` (else in $TMPDIR or /tmp): it takes disk, not
// memory, and vanishes with the process however it ends, so there is nothing to clean up.
// headless spools each algorithm's frame reports into one while the run goes on.
class ScratchFile {
 public:
  // Creates it; Error("<beside>: cannot write: ...") when no directory takes one.
  explicit ScratchFile(const std::string& beside);
  // Closes it (the system frees its space).
  ~ScratchFile();
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  // Appends `bytes`; Error naming `beside` when the disk refuses them.
  void write(std::string_view bytes);
  // Bytes written so far (after truncate(), its size).
  [[nodiscard]] std::int64_t size() const { return size_; }
  // Cuts the file back to its first `size` bytes; writing continues from there.
  void truncate(std::int64_t size);
  // The file's size on disk after flushing (tests: frames reach the disk while the run goes on).
  [[nodiscard]] std::int64_t bytes_on_disk();
  // Appends the whole content to `out`.
  void copy_to(std::ostream& out);
  // A path that opens the content afresh from its start (/proc/self/fd/N), after flushing it.
  [[nodiscard]] std::string reopen_path();

 private:
  std::FILE* file_ = nullptr;
  std::string where_;
  std::int64_t size_ = 0;
};

}  // namespace nbscope
