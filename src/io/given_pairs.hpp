// nbscope io: a user's PAIRS.csv in, for `nbscope verify --pairs`: what a DEM code wrote, read as it
// is — either order within a line, duplicates and i == j kept (they are what verify reports).
#pragma once
#include <string>
#include <vector>

#include "core/pairs.hpp"
#include "core/verify.hpp"
#include "io/lammps_dump.hpp"

namespace nbscope {

// A pairs file's header line, when it has one: `id1,id2` says its numbers are atom ids (what
// `nbscope pairs --input FILE.dump` writes), anything else (`i,j`) rows.
struct GivenPairsHeader {
  std::int64_t line = 0;  // its line, 0 without a header
  bool atom_ids = false;  // `id1,id2`
};

// Reads one pair a line, `i,j` (commas or white space between the two), 0- or 1-based (`base`,
// shifted to 0-based on reading); an optional header line (`i,j`, or `id1,id2`: atom ids, said in
// `header`); `#` comments and blank lines.
// Throws Error("<path>:<line>: what") on a line that is not two whole numbers, on more than
// kDefaultMaxPairs pairs, a line longer than kMaxLineBytes, a NUL byte, and on an unreadable or
// empty file.
std::vector<verify::GivenPair> read_given_pairs_csv(const std::string& path, int base, GivenPairsHeader* header = nullptr);
// The same from memory; `where` names it in messages; more than `max_pairs` pairs is an error.
std::vector<verify::GivenPair> parse_given_pairs_csv(const std::string& text, const std::string& where, int base,
                                                     std::size_t max_pairs = kDefaultMaxPairs, GivenPairsHeader* header = nullptr);
// The pairs of a dump's frame name atoms by id (as `nbscope pairs --input FILE.dump` writes them):
// each id replaced by its row of `frame`. Error("<where>:<line>: pair (17, 99): atom 99 is not in the
// frame of timestep T (<frame.where>)") for an id the frame does not have.
void given_pairs_ids_to_rows(const DumpFrame& frame, const std::string& where, std::vector<verify::GivenPair>& pairs);

}  // namespace nbscope
