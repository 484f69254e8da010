// nbscope io: the frames a replay runs, handed out one at a time: a whole Recording held in memory
// (a .nbsrec file, a dump through a pipe), or a dump's frames read from their files when they are
// asked for (io/dump_frames.hpp), so that a run larger than memory replays in the memory of the
// frames its history budget keeps (io/recording_source.hpp keeps them).
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/recording.hpp"

namespace nbscope {

// What is known of a frame without reading it.
struct RecordedEntry {
  std::int64_t number = 0;
  double time = 0;
  std::int64_t elements = 0;
};

class RecordedFrames {
 public:
  virtual ~RecordedFrames() = default;
  // The recording's facts (path, dim, grid, comment, has_pairs, pair_base); its `frames` are empty:
  // the frames are entries() and read().
  [[nodiscard]] virtual const Recording& header() const = 0;
  // Every frame's number, time and element count, in order; at least one.
  [[nodiscard]] virtual const std::vector<RecordedEntry>& entries() const = 0;
  // Frame `index` (< entries().size()): held, or read from its file now. Error "<path>:<line>: <what>"
  // for what that frame's text holds wrong (a file read as asked for meets a bad row only there).
  [[nodiscard]] virtual std::shared_ptr<const RecordedFrame> read(std::size_t index) = 0;
  // True when read() reads a file (the caller keeps the frames it wants), false when every frame is held.
  [[nodiscard]] virtual bool reads_files() const = 0;
  // A run still being written (io/dump_watch.hpp): looks for frames made whole since the last look
  // (waiting for one, or looking once, as it was told); true when entries() grew. Known frames: false.
  virtual bool more() { return false; }
  // True while more() may still add frames.
  [[nodiscard]] virtual bool growing() const { return false; }
  // When frame `index` was written (seconds since the epoch: its file's time), where known.
  [[nodiscard]] virtual std::optional<double> written_at(std::size_t index) const {
    (void)index;
    return std::nullopt;
  }
};

// The frames of the .nbsrec file `path` (at most `max_frames`): every line but the element rows read
// and checked now, as read_recording does (the same errors), the rows counted; each frame parsed from
// its place when it is read (a bad row refused then, with its line). A pipe, which cannot be read
// twice, is read whole (read_recording, held_frames). In recording.cpp.
std::unique_ptr<RecordedFrames> read_recorded_frames(const std::string& path, std::int64_t max_frames);

// A recording read whole, every frame held. Error "<path>: no frames" for none.
std::unique_ptr<RecordedFrames> held_frames(Recording recording);

// The bytes a frame holds (elements, ids, pairs), as a history budget counts them.
[[nodiscard]] std::size_t recorded_frame_bytes(const RecordedFrame& frame);

}  // namespace nbscope
