// nbscope io: the dumps of a run under MPI, one file per rank (a dump name holding `%`:
// `atoms.%.*.dump` -> atoms.0.1000.dump, atoms.1.1000.dump), read as one frame per timestep.
//
// Each rank's `dump custom` file has its own header (its atoms' count, the global box) and rows; a
// `dump local` file has the header only in rank 0's file, the other ranks' files being bare rows whose
// timestep is in their name. With `newton off` a contact across two subdomains is listed by both
// ranks: read as one pair. The rank of each row is kept (RecordedFrame::ranks). docs/dem.md#mpi.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "io/dump_frames.hpp"
#include "io/lammps_dump.hpp"

namespace nbscope {

// `paths` split by rank: the digit run of the names that numbers the ranks (every group of names
// equal but for it holds ranks 0..P-1, P >= 2, the same P for every group), each rank's paths in the
// order given; one group (the paths themselves) when the names number no ranks.
std::vector<std::vector<std::string>> split_by_rank(const std::vector<std::string>& paths);

// Which digit run of the names numbers the ranks, as split_by_rank finds it (0 for "atoms.1.500.dump"
// when its rank is the 1), or -1 when they number none.
int rank_run_of(const std::vector<std::string>& paths);
// Digit run `run` of `path` (-1 when it has fewer, or one too long to be a number).
std::int64_t digit_run(const std::string& path, int run);
// `path` with its digit run `run` written as `value` (the same file of another rank).
std::string with_digit_run(const std::string& path, int run, std::int64_t value);

// Fills `files` (its options, columns, name and dt already set) with the frames of per-rank files:
// `atoms_by_rank` (split_by_rank, P >= 2 groups) and `contact_paths` (split alike; rank 0's with
// headers, the others' maybe bare rows), indexed and aligned by timestep, at most `max_frames`.
// Error naming the rank and file whose frames differ from rank 0's.
void index_rank_files(DumpFrameFiles& files, const std::vector<std::vector<std::string>>& atoms_by_rank,
                      const std::vector<std::string>& contact_paths, std::int64_t max_frames);

// One timestep's frames of every rank (rank r = pieces[r]) as one frame: rows of every rank in
// ascending id order, `ranks` saying whose each was; Error naming both files for an atom in two ranks.
DumpFrame merge_rank_frames(std::vector<DumpFrame> pieces);

// One timestep's contact frames of every rank as one: a pair listed by two ranks (newton off) once,
// a pair repeated within one rank's rows kept (the check names repeats).
DumpContacts merge_rank_contacts(std::vector<DumpContacts> pieces);

// True when `path` is a rank's bare `dump local` rows (no ITEM line first: only rank 0's file has them).
bool is_bare_rows(const std::string& path);

// The bare rows of `path` read as the contact frame of `header_at` (the rank-0 frame of the same
// timestep in `header_path`, whose ENTRIES line names the columns); its lines named as the file's own.
DumpContacts read_bare_contacts(const std::string& path, const std::string& header_path, const DumpFrameAt& header_at,
                                const ContactColumns& columns);

}  // namespace nbscope
