// nbscope io: the JSON report of a headless run (the report types: check/report.hpp), streamed: each
// frame's report is written as the frame is made, so a run of any length takes the same memory.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "check/report.hpp"

namespace nbscope {

class ScratchFile;

// Writes a headless run's report (keys documented in report_json.cpp) whole or not at all. Each
// frame's line goes to a scratch file of its algorithm as the frame is made (disk, not memory;
// unnamed, so nothing is left behind however the run ends); commit() writes the report's head
// (which holds the run's aggregates, known only at the end), then each algorithm's frames, to
// `path` through a temporary renamed into place (io/atomic_file.hpp).
class RunReportWriter {
 public:
  // Where each algorithm's frames stand: a point to go back to (headless --rewind).
  struct SpoolMark {
    std::int64_t bytes = 0, frames = 0;
  };
  using Mark = std::vector<SpoolMark>;

  // One scratch file for each of `runs` algorithms; Error when none can be created. Without
  // `box2d_fields` (a dump's run: RunReport::box2d_fields) the frames leave out Box2D's sets.
  RunReportWriter(std::string path, std::size_t runs, bool box2d_fields = true);
  ~RunReportWriter();
  RunReportWriter(const RunReportWriter&) = delete;
  RunReportWriter& operator=(const RunReportWriter&) = delete;

  // Appends algorithm `run`'s report of one frame (frames in order), naming elements also by `ids`
  // (a dump's atom ids of the frame's rows) when given; Error when the disk refuses it.
  void add_frame(std::size_t run, const FrameReport& frame, const std::vector<std::int64_t>* ids = nullptr);
  // Where the frames stand now, and going back there (the frames added since are dropped).
  [[nodiscard]] Mark mark() const;
  void back_to(const Mark& mark);
  // Bytes of frames on disk so far, all algorithms (tests: they are written while the run goes on).
  [[nodiscard]] std::int64_t spooled_bytes();
  // Writes the report: `report`'s aggregates, then the frames added. Error("<path>: cannot write: ...").
  void commit(const RunReport& report);

 private:
  struct Spool {
    std::unique_ptr<ScratchFile> file;
    std::int64_t frames = 0;
  };
  std::string path_;
  bool box2d_ = true;
  std::vector<Spool> spools_;
};

// The same JSON as a string, from the aggregates in `report` and each algorithm's frames in `frames`
// (tests; a run's frames are in the file only).
std::string run_report_json(const RunReport& report, const std::vector<std::vector<FrameReport>>& frames);

}  // namespace nbscope
