// nbscope app: frames from LAMMPS and LIGGGHTS dumps on the command line (docs/dem.md): the flags that
// read them (replay --dump/--contacts, pairs/dump/verify --input FILE.dump), the contact convention
// (--touching, every command), and the periodic box of any input (--periodic, --box).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/command_table.hpp"
#include "core/pairs.hpp"
#include "io/lammps_dump.hpp"
#include "io/recorded_frames.hpp"

namespace nbscope {

// --touching inclusive|strict (default inclusive); Error naming the flag for another value (app/touching_flag.cpp).
Touching take_touching(Args& args);

// The flags of dump input a command was given.
struct DumpFlags {
  std::vector<std::string> dumps;     // replay --dump SPEC (repeatable: a path or a quoted glob)
  std::vector<std::string> contacts;  // replay --contacts SPEC (repeatable)
  ContactColumns columns;             // --contact-ids A,B (1-based numbers or ENTRIES names)
  DumpOptions options;                // --radius, --type-radius, --2d, --tolerance, --periodic, --box
  std::optional<double> dt;           // --dt S: a frame's time is S x its timestep (without ITEM: TIME)
  std::optional<std::int64_t> timestep;  // pairs/dump/verify --timestep S: which frame of the dump
  std::optional<DumpBox> box;         // --box XLO:XHI,YLO:YHI[,ZLO:ZHI]: the periodic box of an input that has none
};

// Takes the dump flags replay, pairs, dump and verify share: --contact-ids, --radius, --type-radius,
// --2d, --tolerance, --periodic, --box (replay takes --dump, --contacts, --dt itself; pairs, dump and
// verify --timestep).
DumpFlags take_dump_flags(Args& args);
// True when `path` is a dump (its first bytes are "ITEM:" or gzip's), not ELEMENTS.csv.
bool is_dump_file(const std::string& path);

// The frames replay runs: every frame of flags.dumps with flags.contacts as their pairs (io/lammps_dump.hpp),
// at most `max_frames`. Files are indexed now and each frame read when it is shown (io/dump_frames.hpp);
// a dump through a pipe, which cannot be read twice, is read whole.
std::unique_ptr<RecordedFrames> read_dump_recording(const DumpFlags& flags, std::int64_t max_frames);
// One frame of the dump `path` for pairs, dump and verify: the one of --timestep, or the only one
// (Error listing the timesteps when there are several and no --timestep, or none is that timestep).
DumpFrame read_dump_input(const std::string& path, const DumpFlags& flags);
// The elements of pairs', dump's and verify's --input: ELEMENTS.csv (with --periodic/--box), or one frame of a dump.
struct InputFrame {
  Elements elements;
  std::vector<std::int64_t> ids;  // a dump's row -> atom id (empty for ELEMENTS.csv: rows are the ids)
  double precision = 0;           // a dump frame's precision band (DumpFrame::precision)
  std::optional<DumpFrame> dump;  // the dump frame (for a dump local file's contacts), without its columns
};
// Reads --input `path` as a dump (is_dump_file) or as ELEMENTS.csv; Error for dump flags on a CSV file.
InputFrame read_input_frame(const std::string& path, const DumpFlags& flags);
// The recording gui --input reads: a dump's frames (at most `max_frames`), or ELEMENTS.csv as one
// frame (x,y,r or x,y,z,r; --periodic/--box applied); no pairs.
std::unique_ptr<RecordedFrames> read_input_recording(const std::string& path, const DumpFlags& flags, std::int64_t max_frames);

// --periodic and --box on elements read from ELEMENTS.csv: the periodic box set and centres wrapped
// into it; Error for --periodic without --box, or an axis the elements do not have.
void apply_periodic_flags(const DumpFlags& flags, Elements& elements);

// The option rows of the dump flags for the command table (replay's, and pairs/dump/verify's).
const std::vector<OptionSpec>& dump_replay_options();
const std::vector<OptionSpec>& dump_input_options();
// --touching's row, on every command.
OptionSpec touching_option();

}  // namespace nbscope
