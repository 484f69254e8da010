// nbscope io: the dumps of a run that is still going (`nbscope watch`, docs/watch.md), as recorded
// frames (io/recorded_frames.hpp) whose list grows: a multi-frame file that grows and new files
// matching a glob are looked at again at every more(); a frame is taken once it is whole (every
// row of its NUMBER OF ATOMS written, with its newline), so a half-written frame is waited for,
// never an error. Atoms and contacts (`dump local`) are paired by timestep, as replay pairs them.
// Frames are then read where they lie, as replay reads them (io/dump_frames.hpp).
#pragma once
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/lammps_dump.hpp"
#include "io/recorded_frames.hpp"

namespace nbscope {

// What to watch and when the run has ended.
struct DumpWatchSpec {
  std::vector<std::string> dumps;     // `dump custom` files: paths or globs (files may not exist yet)
  std::vector<std::string> contacts;  // `dump local` files alike; none: no pairs
  ContactColumns columns;
  DumpOptions options;
  std::optional<double> dt;           // seconds per timestep (recording_from_dumps)
  // The run has ended after this many seconds without a new frame (--idle), or once a file it held
  // open is closed by every process with nothing new (the writer gone); infinity: never (the window).
  double idle_s = std::numeric_limits<double>::infinity();
  // Its first frame is waited for at least this long, whatever idle_s says (a simulation sets up first).
  double first_wait_s = 60;
  // True: more() waits until a frame arrives or the run ends (headless); false: it looks once (the window).
  bool wait = true;
  double poll_s = 0.02;               // how often the files are looked at while waiting
};

// The run's frames: waits for its first (Error "<spec>: no frame arrived in S s" after the longer of
// idle_s and first_wait_s). Errors as replay's for what a frame holds wrong, and: a file that shrinks (a new run
// writing over it), a frame whose timestep is not after the last one taken, a timestep in two files,
// a gzip file (it cannot be read while it is written), an atoms frame with no contact frame once a
// later contact frame is whole.
std::unique_ptr<RecordedFrames> watched_dumps(DumpWatchSpec spec);

}  // namespace nbscope
