// nbscope io: recorded frames, the .nbsrec text format (`nbscope headless --record` writes it,
// `nbscope replay` reads it; any simulation code can write it too).
//
//   nbsrec 1                 the first line that is not blank or a comment: format and version
//   # a comment              '#' starts a comment anywhere; blank lines are ignored
//   dim 3                    optional: 3D frames (rows x,y,z,r); `dim 2` (rows x,y,r) is the default
//   cell_size 1              optional header lines, before the first frame, pinning the grid as
//   origin 0,0               --cell-size / --origin / --cells and the scene keys do (3D: origin
//   cells 10,10              X,Y,Z and cells NX,NY,NZ)
//   frame 0 0                frame NUMBER TIME: a non-negative integer, increasing (gaps allowed),
//   x,y,r                    and the simulated time in seconds, finite and non-decreasing;
//   ...                      then one element a line, as ELEMENTS.csv rows (x,y,r; x,y,z,r in 3D)
//   frame 1 0.0166667        a frame may have no elements; element counts may change
//   pairs                    optional, after a frame's rows: the simulation's own contact pairs of
//   1,2                      the frame, `i,j` a line, until the next frame (every frame has a block, or none)
//
// `base 1` (a header line) numbers the pairs' elements from 1 (Fortran codes); the default is 0.
// Pairs are kept as given (either order, i == j, twice): those are the user's bugs the check finds.
// Numbers are written shortest-round-trip (std::to_chars), so a replay sees bit-identical doubles.
// Index: Recording | reading | writing.
#pragma once
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/elements.hpp"
#include "core/grid.hpp"
#include "check/report.hpp"
#include "core/pairs.hpp"
#include "core/subdomain_grid.hpp"
#include "io/input_file.hpp"
#include "physics/atom_columns.hpp"

namespace nbscope {

// Most frames read from one recording (about 1 GB of frame records before any element); `replay
// --frames N` reads only the first N, so a longer recording can be replayed in parts.
inline constexpr std::size_t kMaxRecordedFrames = 10'000'000;
// Most bytes of the header's comment kept (Recording::comment); lines past it are read, not kept.
inline constexpr std::size_t kMaxKeptComment = 64 * 1024;

// One recorded frame.
struct RecordedFrame {
  std::int64_t number = 0;
  double time = 0;
  Elements elements;
  PairList pairs;  // the `pairs` block: 0-based, as given (order within a pair, i == j, repeats kept)
  // The element of each row as its source names it (a dump's atom ids, ascending); empty: the row itself.
  std::vector<std::int64_t> ids;
  // The MPI rank whose file held each row (a run's per-rank dumps, io/dump_ranks.hpp); empty: one file set.
  std::vector<std::int32_t> ranks;
  // Largest error the file's printed digits allow in a pair's gap |c_i - c_j| - (r_i + r_j) (0: exact,
  // as a .nbsrec's round-trip numbers are): disagreements within it are at the boundary, not violations.
  double precision = 0;
  // The frame's other per-atom columns (a dump's type, vx, proc, ... when they are asked for), or null.
  std::shared_ptr<const AtomColumns> columns;
  // With ranks: each rank's subdomain as LAMMPS split the box (core/subdomain_grid.hpp), when found.
  std::shared_ptr<const Subdomains> subdomains;
};

// Row `row` as its frame names it: the atom id `ids` gives it (a dump's), else the row itself (no
// ids, or a row outside them).
[[nodiscard]] inline std::int64_t element_id(const std::vector<std::int64_t>* ids, std::int64_t row) {
  return ids != nullptr && row >= 0 && static_cast<std::size_t>(row) < ids->size() ? (*ids)[static_cast<std::size_t>(row)] : row;
}

// A whole recording as read.
struct Recording {
  std::string path;  // as given
  int dim = 2;       // `dim`: every frame's elements are 2D (x,y,r) or 3D (x,y,z,r)
  GridOptions grid;  // the grid the header pins (2D: origin z 0, cells nz 1; unset: derived each frame)
  // The whole-line comments before the first frame, each without '#' and one space, '\n' between:
  // a recording recorded again (replay --record) keeps them, so it stays the same file.
  std::string comment;
  std::vector<RecordedFrame> frames;  // at least one
  bool has_pairs = false;  // every frame has a `pairs` block (the reader refuses some without)
  int pair_base = 0;       // `base`: the file numbers its pairs' elements from 0 or 1
  // What the frames' numbers are: a .nbsrec's are frames, a dump's are the simulation's timesteps.
  // The one place a run's messages and panels learn it from (FrameUnit, check/report.hpp).
  FrameUnit frame_unit = FrameUnit::frame;
};

// Reads and validates a .nbsrec file, at most `max_frames` frames (the rest is not read). Throws
// Error("<path>:<line>: <what>") on anything wrong: an unreadable or empty file, a missing "nbsrec 1"
// line or another version, an unknown line, a header line after the first frame or given twice
// ("cell_size given twice (first on line 2)"), a NUL byte, a line longer than kMaxLineBytes
// (io/input_file.hpp), a bad cell_size/origin/cells value, a `dim` other than 2 or 3, origin or cells
// with values for another dimension than `dim`'s, a frame number that does not increase, a
// time that decreases, a row before the first frame, a bad row (as ELEMENTS.csv: column count,
// non-number, NaN/Inf, r <= 0), a 4-column row in a 2D recording or a 3-column row in a 3D one
// (each names the fix), an element wider than the pinned
// cell_size, no frames at all; a `base` other than 0 or 1 or after the first frame; a `pairs` line
// before the first frame or twice in a frame, an element row after it, a pair row that is not two
// integers or names an element the frame does not have; a frame without a pairs block when another has
// one.
// The lines are parsed as they arrive: the read stops after `max_frames` frames (an endless pipe
// included) and at the first line past a limit: more than `frame_limit` frames (before `max_frames`
// stops the read: "more than N frames, the limit for a recording"), kMaxElements rows in a frame,
// `max_bytes` bytes.
Recording read_recording(const std::string& path, std::int64_t max_frames = std::numeric_limits<std::int64_t>::max(),
                         std::size_t frame_limit = kMaxRecordedFrames, std::size_t max_bytes = kMaxRecordingBytes);
// Same from memory; `where` names it in messages.
Recording parse_recording(const std::string& text, const std::string& where,
                          std::int64_t max_frames = std::numeric_limits<std::int64_t>::max(),
                          std::size_t frame_limit = kMaxRecordedFrames);

// Streams frames to `path` through a temporary file (io/atomic_file.hpp): the file appears only at
// commit(); destroyed before that (an error, an interruption) it leaves nothing behind.
class RecordingWriter {
 public:
  // Creates the temporary and writes the "nbsrec 1" line, `comment` (one '#' line per line), `dim 3`
  // for 3D frames (a 2D recording has no dim line), the header lines of `grid` (its x and y, and z
  // in 3D) and `base 1` when `pair_base` is 1 (pairs written from 1). Error when the file cannot be created.
  RecordingWriter(const std::string& path, const GridOptions& grid, const std::string& comment, int dim = 2, int pair_base = 0);
  ~RecordingWriter();
  RecordingWriter(const RecordingWriter&) = delete;
  RecordingWriter& operator=(const RecordingWriter&) = delete;

  // Appends one frame, with a `pairs` block of `pairs` (0-based, written as given) when not null;
  // Error for elements of another dimension than the header's, a periodic frame (the format has no
  // box), a pair naming an element the frame does not have, or pairs given for some frames and not
  // others (the reader would refuse the file).
  void write_frame(std::int64_t number, double time, const Elements& elements, const PairList* pairs = nullptr);
  // Renames the finished file into place; Error when anything could not be written.
  void commit();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace nbscope
