// nbscope app: frames from LAMMPS and LIGGGHTS dumps on the command line (docs/dem.md): the flags that
// read them (replay --dump/--contacts, pairs/dump/verify --input FILE.dump), the contact convention
// (--touching, every command), and the periodic box of any input (--periodic, --box).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/command_table.hpp"
#include "check/units.hpp"
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
  std::optional<std::string> units;   // --units lj|real|...: the run's units (else a data file's header, else --log's)
  std::optional<std::string> log;     // --log log.lammps: the run's `units` (and `timestep`, for --dt) from LAMMPS's log
};

// Takes the dump flags replay, pairs, dump and verify share: --contact-ids, --radius, --type-radius,
// --2d, --tolerance, --periodic, --box (replay takes --dump, --contacts, --dt itself; pairs, dump and
// verify --timestep).
DumpFlags take_dump_flags(Args& args);
// True when `path` is a dump (its first bytes are "ITEM:" or gzip's), not ELEMENTS.csv.
bool is_dump_file(const std::string& path);
// True when `path` is a LAMMPS data file (write_data's; io/lammps_data.hpp): one frame, read as a dump's.
bool is_data_file(const std::string& path);

// The units of a run from the files `inputs` (paths or globs): --units, else the first dump's ITEM:
// UNITS, else a data file's header (`units = lj`), else the `units` command of --log's LAMMPS log;
// nbscope's own (m, s) when none says. A run without a dt (--dt, the log's) or ITEM: TIME gets its
// times in "steps" (its frames' times are their timesteps).
// From the log also: flags.dt from its `timestep` when --dt is not given, and, for a data file among
// `inputs` (which has no boundary flags), --periodic from its `boundary` when --periodic is not given.
// Error for a units name nbscope does not know, or a log that cannot be read.
Units settle_units_and_log(DumpFlags& flags, const std::vector<std::string>& inputs);
// A `dimension 2` run read as 2D without --2d: when the first frame with atoms of `inputs` has every
// z exactly 0 in a thin z box (io/lammps_dump.hpp: is_planar), sets --2d and returns the one-line
// note that says so; "" otherwise (and for --2d given, or a pipe, which cannot be read twice).
std::string settle_planar(DumpFlags& flags, const std::vector<std::string>& inputs);
// The note for a planar input read as 2D: "<path>: every z is 0 in a thin z box (a `dimension 2` run): read as 2D, as --2d does".
std::string planar_note(const std::string& path);

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
  std::string note;               // a note for stderr once the command has succeeded (a planar frame read as 2D); "" for none
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
