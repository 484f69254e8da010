// nbscope io: a dump's frames for replay, read from their files as they are asked for
// (io/recorded_frames.hpp): the files are indexed up front (every ITEM line read and checked, the
// rows counted, not parsed: io/lammps_dump.hpp), so a run of any length opens in the memory of one
// frame, and a frame dropped from memory is read again where it lies.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/lammps_dump.hpp"
#include "io/recorded_frames.hpp"

namespace nbscope {

// The frames `at` (index_dump_frames of `paths` with `options`) with `contacts` (empty: none) as
// their pairs, one contact frame per dump frame by timestep, each frame's time as
// recording_from_dumps gives it; `name` names the recording. Error naming the first frame that has
// no contact frame. A frame's rows are parsed when it is read (their errors come then).
std::unique_ptr<RecordedFrames> dump_frames(std::vector<std::string> paths, const DumpOptions& options, std::vector<DumpFrameAt> at,
                                            std::vector<DumpContacts> contacts, std::optional<double> dt, const std::string& name);

}  // namespace nbscope
