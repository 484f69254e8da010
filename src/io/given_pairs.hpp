// nbscope io: a user's PAIRS.csv in, for `nbscope verify --pairs`: what a DEM code wrote, read as it
// is — either order within a line, duplicates and i == j kept (they are what verify reports).
#pragma once
#include <string>
#include <vector>

#include "core/verify.hpp"

namespace nbscope {

// Reads one pair a line, `i,j` (commas or white space between the two), 0- or 1-based (`base`,
// shifted to 0-based on reading); an optional header line (`i,j`); `#` comments and blank lines.
// Throws Error("<path>:<line>: what") on a line that is not two whole numbers, and on an unreadable
// or empty file.
std::vector<verify::GivenPair> read_given_pairs_csv(const std::string& path, int base);
// The same from memory; `where` names it in messages.
std::vector<verify::GivenPair> parse_given_pairs_csv(const std::string& text, const std::string& where, int base);

}  // namespace nbscope
