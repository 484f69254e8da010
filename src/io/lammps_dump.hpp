// nbscope io: frames and contact lists from LAMMPS and LIGGGHTS dumps, text or gzip (docs/dem.md).
//
//   dump custom  ITEM: TIMESTEP, [ITEM: TIME,] ITEM: NUMBER OF ATOMS, ITEM: BOX BOUNDS pp pp ff,
//                ITEM: ATOMS id type x y z radius ... (columns by name; frames one after another)
//   dump local   ITEM: TIMESTEP, ITEM: NUMBER OF ENTRIES, ITEM: BOX BOUNDS ..., ITEM: ENTRIES c_pgl[1] ...
//
// An element *is* its atom id: each frame's rows are its atoms in ascending id order, `ids` says
// which, and every message names ids, never rows. Numbers are parsed with std::from_chars.
// Index: options | DumpFrame, DumpContacts | reading | to a Recording.
#pragma once
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/elements.hpp"
#include "core/subdomain_grid.hpp"
#include "io/recording.hpp"

namespace nbscope {

// How `dump custom` columns become elements (the command line's --radius, --type-radius, --2d, ...).
struct DumpOptions {
  std::optional<double> radius;                // --radius R: every atom's, when the dump has no radius/diameter column
  std::map<std::int64_t, double> type_radius;  // --type-radius 1:0.0015,2:0.00225: by the `type` column
  bool force_2d = false;                       // --2d: drop z (LIGGGHTS's `dimension 2` writes z = 0)
  std::optional<double> tolerance;             // --tolerance L: the precision band, in place of the printed digits'
  // --periodic x,y[,z]: these axes periodic whatever BOX BOUNDS says (with the dump's box as the period).
  std::optional<std::array<bool, 3>> periodic;
  std::int64_t max_frames = std::numeric_limits<std::int64_t>::max();  // --frames N: the first N frames (by timestep)
  // --color-by, --export-vtk: keep each frame's other numeric columns (DumpFrame::columns); else they are skipped unparsed.
  bool keep_columns = false;
};

// ITEM: BOX BOUNDS as read.
struct DumpBox {
  double lo[3] = {0, 0, 0};
  double hi[3] = {0, 0, 0};
  std::array<std::string, 3> flags;  // per axis as printed ("pp", "ff", "fm", ...; LIGGGHTS's unit suffix dropped)
};

// One `dump custom` frame.
struct DumpFrame {
  std::int64_t timestep = 0;
  std::optional<double> time;        // ITEM: TIME, when the dump has it
  DumpBox box;
  // Rows in ascending id order; dim 2 without a z column or with --2d; elements.box holds the
  // periodic axes (`pp`, or DumpOptions::periodic) and their centres are wrapped into [lo, hi).
  Elements elements;
  std::vector<std::int64_t> ids;     // row -> atom id, ascending, unique
  std::vector<std::int32_t> types;   // row -> `type` column (empty without one)
  std::vector<std::int32_t> ranks;   // row -> the MPI rank whose file held it (per-rank files, io/dump_ranks.hpp; else empty)
  std::shared_ptr<const Subdomains> subdomains;  // per-rank files: how the box was split among the ranks (else null)
  // With DumpOptions::keep_columns: `type` and every other numeric column but id, positions and radius, by row.
  std::shared_ptr<const AtomColumns> columns;
  // Bound on the error of a pair's gap |c_i - c_j| - (r_i + r_j) from the digits printed in this frame
  // (half a unit of the last printed digit, the largest over its coordinates and radii, scaled by the
  // box for xs ys zs), or DumpOptions::tolerance. 0 only when every number is exact.
  double precision = 0;
  std::string where;                 // "<path>:<line>" of its ITEM: TIMESTEP, for messages
};

// True when a 3D frame is a `dimension 2` run's: every z exactly 0, and a thin z box (LAMMPS's 2D
// -0.5..0.5, or thinner than two of its largest diameters: no second layer fits).
bool is_planar(const DumpFrame& frame);
// `frame` made 2D, as --2d reads it: z and its periodicity dropped.
void make_planar(DumpFrame& frame);
// The first frame with atoms of the `dump custom` file `path` (else its last; Error when it has none),
// parsed as read_dump_frames parses it, when its BOX BOUNDS flag z periodic (`pp`), as a `dimension 2`
// run's must; none otherwise, its rows not parsed. What a run looks like, without reading it all.
std::optional<DumpFrame> first_z_periodic_frame(const std::string& path, const DumpOptions& options);

// What the first frame's ITEM lines of a `dump custom` file say of the run (only they are read).
struct DumpHead {
  bool has_time = false;  // ITEM: TIME (`dump_modify time yes`): the frames' times are times, not timesteps
  std::string units;      // ITEM: UNITS (`dump_modify units yes`, first frame only): "lj", ...; "" without
};
DumpHead read_dump_head(const std::string& path);

// Which two columns of a `dump local` file hold a contact's ids.
struct ContactColumns {
  std::optional<std::array<int, 2>> numbers;          // --contact-ids 7,8: 1-based column numbers
  std::optional<std::array<std::string, 2>> names;    // --contact-ids c_pgl[7],c_pgl[8]: ENTRIES names
  // Neither: `id1 id2` (or `i j`, `atom1 atom2`) by name, else LIGGGHTS's compute pair/gran/local order
  // `pos id ...` (columns 7, 8) when the file's values fit it; else an Error asking for --contact-ids.
};

// One `dump local` frame: the contacts of one timestep as pairs of atom ids, in file order.
struct DumpContacts {
  std::int64_t timestep = 0;
  std::vector<std::array<std::int64_t, 2>> ids;
  std::vector<std::int64_t> lines;   // the file line of each pair, for messages
  std::string path;                  // the file it came from
  std::string where;                 // "<path>:<line>" of its ITEM: TIMESTEP
};

// The files `spec` names: a path, or a glob (`post/atoms.*.dump`, quoted on the command line).
// Error "<flag>: '<spec>': no file matches" for a glob matching nothing, or a path that does not exist.
std::vector<std::string> expand_dump_spec(const std::string& flag, const std::string& spec);

// Every `dump custom` frame of `paths` (text, or gzip: read through zlib either way), ordered by
// timestep across the files (not by name), at most options.max_frames. Throws Error("<path>:<line>:
// <what>") on: a missing ITEM, an ATOMS line without an `id` column or without x y [z] / xs ys [zs] /
// xu yu [zu], no radius (no radius/diameter column, --radius or --type-radius for that type), a
// triclinic box ("xy xz yz": refused by name), a frame with fewer rows than NUMBER OF ATOMS or a row
// with another column count, a non-number, NaN/Inf, r <= 0, a repeated id (naming it and both lines),
// timesteps out of order within one file, a timestep in two files, more than kMaxElements atoms.
std::vector<DumpFrame> read_dump_frames(const std::vector<std::string>& paths, const DumpOptions& options);
// The same from memory (text); `where` names it in messages.
std::vector<DumpFrame> parse_dump_frames(const std::string& text, const std::string& where, const DumpOptions& options);

// Where one `dump custom` frame lies in its file (index_dump_frames), to be read alone later.
struct DumpFrameAt {
  std::int64_t timestep = 0;
  std::optional<double> time;  // ITEM: TIME, when the dump has it
  std::int64_t atoms = 0;      // NUMBER OF ATOMS
  std::size_t file = 0;        // which of the paths given
  std::size_t offset = 0;      // the byte of the file's text where the frame's items start
  std::size_t line = 0;        // and its line
  std::string where;           // "<path>:<line>" of its ITEM: TIMESTEP
};

// Every `dump custom` frame of `paths` located, ordered by timestep as read_dump_frames orders them,
// at most options.max_frames: the ITEM lines read and checked as read_dump_frames checks them (the
// same errors), the rows counted, not parsed (a bad number is met when DumpCursor reads that frame).
std::vector<DumpFrameAt> index_dump_frames(const std::vector<std::string>& paths, const DumpOptions& options);

class DumpText;

// Every `dump local` frame of `paths` located (DumpFrameAt, `atoms` its NUMBER OF ENTRIES), ordered
// by timestep: the ITEM lines read and checked as read_dump_contacts checks them, the rows counted
// (a bad id is met when DumpCursor::read_contacts reads that frame).
std::vector<DumpFrameAt> index_dump_contacts(const std::vector<std::string>& paths, const ContactColumns& columns);

// Reads the frames of one file at the places index_dump_frames or index_dump_contacts found: on from
// the frame read last when the next one is asked for, else the file opened again at the frame (a
// seek; gzip inflates up to it).
class DumpCursor {
 public:
  explicit DumpCursor(std::string path);
  ~DumpCursor();
  DumpCursor(const DumpCursor&) = delete;
  DumpCursor& operator=(const DumpCursor&) = delete;
  // `dump custom` frame `at` (of this file) parsed as read_dump_frames parses it, with the same errors.
  DumpFrame read_frame(const DumpFrameAt& at, const DumpOptions& options);
  // `dump local` frame `at` parsed as read_dump_contacts parses it (lammps_dump_local.cpp).
  DumpContacts read_contacts(const DumpFrameAt& at, const ContactColumns& columns);
  // The file it reads.
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  DumpText& text_at(const DumpFrameAt& at);  // the text positioned at `at`
  std::string path_;
  std::unique_ptr<DumpText> text_;
};

// What a seek (seek_dump_frame) found in one `dump custom` file.
struct DumpSeek {
  std::optional<DumpFrame> frame;      // the frame asked for; none when the file has no frame of that timestep
  std::int64_t frames = 0;             // frames scanned: every frame of the file unless the seek stopped at its frame
  std::int64_t first_timestep = 0;     // of the first frame scanned (when frames > 0)
  std::int64_t last_timestep = 0;      // of the last frame scanned
  std::size_t offset = 0;              // the byte the frame's items start at
};

// Where the frame of `timestep` starts in the plain `dump custom` file `path` (the byte of its items),
// or where to read on in order to find it, found by probing offsets instead of reading the frames
// before it (timesteps increase within a file); none for a gzip or small file, a pipe, a file that
// does not start with a frame, or timesteps found out of order (then read the file in order).
// Nothing is checked: the frame is parsed from there, and the file read in order on any error.
std::optional<std::size_t> find_dump_frame(const std::string& path, std::int64_t timestep);

// One frame of the `dump custom` file `path` (text or gzip): the one of `timestep`, or without one
// the first, the rest of the file scanned to count its frames. A big plain file is jumped into
// (find_dump_frame): the frames before are not read, their count is not known (`frames` counts from
// the jump) and the frame's `where` names its byte, not its line; any error there reads it in order. Only that frame's rows are parsed and
// kept: every other frame's ITEM lines are read as read_dump_frames reads them (the same errors,
// timesteps increasing included) and its NUMBER OF ATOMS rows are counted, not parsed (a frame with
// fewer rows is still refused); the read stops after the frame of `timestep`. Without `timestep`, a
// bad row of the first frame is thrown only when it is the file's one frame (else `frame` is empty).
DumpSeek seek_dump_frame(const std::string& path, std::optional<std::int64_t> timestep, const DumpOptions& options);
// The same from memory (text); `where` names it in messages.
DumpSeek seek_dump_frame_in(const std::string& text, const std::string& where, std::optional<std::int64_t> timestep,
                            const DumpOptions& options);

// Every `dump local` frame of `paths` (text or gzip), ordered by timestep. Throws Error on a missing
// ITEM, fewer rows than NUMBER OF ENTRIES, a row with another column count, an id that is not an
// integer (`2753` and `2753.0` are; `2753.5` is refused), columns that cannot be found.
std::vector<DumpContacts> read_dump_contacts(const std::vector<std::string>& paths, const ContactColumns& columns);
// The same from memory (text); `where` names it in messages.
std::vector<DumpContacts> parse_dump_contacts(const std::string& text, const std::string& where, const ContactColumns& columns);

// The contacts of `frame` as 0-based rows (order within a pair and repeats kept as given: the check
// names those); Error "<path>:<line>: contact (17, 99): atom 99 is not in the frame of timestep 500
// (<where>)" for an id the frame does not have.
PairList contacts_as_rows(const DumpFrame& frame, const DumpContacts& contacts);

// The frames as a Recording (io/recording.hpp) that replay, the pipeline and the window use unchanged:
// frame number = timestep; time = ITEM: TIME, else dt x timestep when `dt` is given, else the
// timestep; ids and precision carried over; `contacts` (empty: none) become each frame's pairs, one
// contact frame per dump frame by timestep (Error naming the timestep that has no contact frame, or a
// contact frame no dump frame has). `path` names the recording in reports.
// A frame's time as recording_from_dumps gives it: ITEM: TIME, else dt x timestep, else the timestep.
double dump_frame_time(std::int64_t timestep, std::optional<double> time, std::optional<double> dt);
// One dump frame as recording_from_dumps makes it, with `contacts` (null: none) as its pairs.
RecordedFrame recorded_from_dump(DumpFrame frame, const DumpContacts* contacts, std::optional<double> dt);
Recording recording_from_dumps(std::vector<DumpFrame> frames, const std::vector<DumpContacts>& contacts,
                               std::optional<double> dt, const std::string& path);

}  // namespace nbscope
