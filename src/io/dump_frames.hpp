// nbscope io: a dump's frames for replay, read from their files as they are asked for
// (io/recorded_frames.hpp): the files are indexed up front (every ITEM line read and checked, the
// rows counted, not parsed: io/lammps_dump.hpp), so a run of any length opens in the memory of one
// frame, and a frame dropped from memory is read again where it lies. Contact lists alike.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/lammps_dump.hpp"
#include "io/recorded_frames.hpp"

namespace nbscope {

// A replay's dump files and where their frames are.
struct DumpFrameFiles {
  std::vector<std::string> paths;          // the `dump custom` files
  std::vector<DumpFrameAt> frames;         // index_dump_frames of them (with `options`), cut to what is replayed
  DumpOptions options;
  std::vector<std::string> contact_paths;  // the `dump local` files; none: no pairs
  std::vector<DumpFrameAt> contacts;       // index_dump_contacts of them (with `columns`)
  ContactColumns columns;
  std::optional<double> dt;                // seconds per timestep (recording_from_dumps)
  // Under MPI, ranks 1..P-1's files (io/dump_ranks.hpp; rank 0's are `paths` and `contact_paths`):
  // each rank's frames aligned with `frames` by index (its contacts with `contacts`); a rank's bare
  // `dump local` rows are read as the contact frame of rank 0's of the same index. Empty: one file set.
  struct Rank {
    std::vector<std::string> paths, contact_paths;
    std::vector<DumpFrameAt> frames, contacts;
    bool bare_contacts = false;  // its contact files are bare rows (DumpFrameAt: file and timestep only)
  };
  std::vector<Rank> other_ranks;
  std::string name;                        // names the recording
};

// The frames of `files`, each with its contact frame (by timestep) as its pairs, each frame's time
// as recording_from_dumps gives it. Error "<path>: no frames" for none, and naming the first frame
// without a contact frame when there are contacts. A frame's rows (and its contacts') are parsed
// when it is read: their errors come then.
std::unique_ptr<RecordedFrames> dump_frames(DumpFrameFiles files);

}  // namespace nbscope
