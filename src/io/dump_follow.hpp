// nbscope io (internal): dump files followed while they are written, for the watched run
// (dump_watch.cpp): only the bytes added since the last look are read, the rows counted; a rank's bare
// `dump local` rows (no header: io/dump_ranks.hpp) are whole once they stop growing; the processes
// that write them are found and followed until they end.
#pragma once
#include <chrono>
#include <cstddef>
#include <deque>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "io/lammps_dump.hpp"

namespace nbscope::follow {

using Clock = std::chrono::steady_clock;

// Seconds since `t`.
inline double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// A whole frame found in a file: where it starts, its timestep and rows, when the file was written.
struct WholeFrame {
  DumpFrameAt at;
  double written_at = 0;  // the file's modification time when the frame was found whole
};

// One dump file read as it grows: only the bytes added since the last look are read, the rows
// counted (not parsed: DumpCursor parses a whole frame later), the header lines kept.
class FollowedFile {
 public:
  // `bare_rows`: the file may be a rank's bare `dump local` rows (contacts under MPI), not an error.
  FollowedFile(std::string path, std::size_t file, bool bare_rows) : path_(std::move(path)), file_(file), may_be_bare_(bare_rows) {}
  // The frames made whole by what was written since the last look.
  std::vector<WholeFrame> look();
  // A frame begun and not yet whole, as "N of M rows" (empty when none).
  [[nodiscard]] std::string unfinished() const;
  [[nodiscard]] const std::string& path() const { return path_; }
  // True once the file is known to be a rank's bare rows (or is empty: a rank with no contacts) and has
  // not changed for 0.1 s: whole, as far as anything can tell.
  [[nodiscard]] bool bare_settled() const { return may_be_bare_ && pos_ == 0 && seconds_since(bare_since_) >= 0.1 && (bare_ || bare_size_ == 0) && seen_; }

 private:
  void take(std::string_view text, double written, std::vector<WholeFrame>& found);
  void header_line(const std::string& line, double written, std::vector<WholeFrame>& found);
  void finish(double written, std::vector<WholeFrame>& found);

  enum class Expect { none, timestep, time, count };
  std::string path_;
  std::size_t file_ = 0;
  std::size_t pos_ = 0;         // bytes taken in
  std::size_t line_ = 0;        // lines taken in
  std::size_t line_start_ = 0;  // the byte the line being read starts at
  std::string partial_;         // a header line not yet ended
  bool in_rows_ = false;
  std::int64_t rows_left_ = 0;
  int lines_in_header_ = 0;
  Expect expect_ = Expect::none;
  DumpFrameAt frame_;           // the frame being read
  bool may_be_bare_ = false;
  bool seen_ = false;           // the file exists
  bool bare_ = false;           // a rank's bare rows: followed by size alone
  std::size_t bare_size_ = 0;
  Clock::time_point bare_since_ = Clock::now();  // since when bare_size_ has not changed
};

// The files of `specs` now (a glob matching nothing yet: none; a path not written yet: none).
std::vector<std::string> files_of(const std::vector<std::string>& specs);

// The files of one kind (atoms, or contacts): every file matching, each followed.
class FollowedFiles {
 public:
  // `bare_rows`: as FollowedFile's (the contacts' files).
  FollowedFiles(std::vector<std::string> specs, bool bare_rows) : specs_(std::move(specs)), bare_rows_(bare_rows) {}
  // Frames made whole since the last look, in every file (new files included).
  std::vector<WholeFrame> look();
  [[nodiscard]] const std::string& path(std::size_t file) const { return files_[file].path(); }
  // The file followed at `path`, or null.
  [[nodiscard]] const FollowedFile* find(const std::string& path) const;
  [[nodiscard]] std::size_t size() const { return files_.size(); }
  [[nodiscard]] const std::deque<FollowedFile>& files() const { return files_; }

 private:
  std::vector<std::string> specs_;
  bool bare_rows_ = false;
  std::set<std::string> known_;
  std::deque<FollowedFile> files_;  // a deque: paths handed out stay valid as files are added
};

// The processes that hold the watched files open: found while they write, then followed until they
// are gone (a file LAMMPS writes frame after frame stays open until the run ends; one file a frame
// is open only while written, and may never be seen: then only --idle ends the run).
class Writers {
 public:
  // Looks for processes holding one of `paths` open (at most every 0.1 s; none once one is found).
  void look(const std::vector<std::string>& paths);
  // True while no writer has been found and a look is due (the caller gathers the paths only then).
  [[nodiscard]] bool looking() const { return pids_.empty() && seconds_since(last_look_) >= 0.1; }
  // The writers seen, as "pid 123" or "pids 123, 124".
  [[nodiscard]] std::string named() const;
  // True once a writer was seen and every one seen has ended (or waits for its parent: a zombie).
  [[nodiscard]] bool gone() const;

 private:
  std::set<std::string> pids_;
  Clock::time_point last_look_{};
};

}  // namespace nbscope::follow
