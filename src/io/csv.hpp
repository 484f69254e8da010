// nbscope io: ELEMENTS.csv in, PAIRS.csv out (formats in DESIGN.md "Command line").
#pragma once
#include <string>

#include "core/elements.hpp"
#include "core/pairs.hpp"

namespace nbscope {

// Reads `x,y,r` (2D) or `x,y,z,r` (3D) rows; one optional header line of names; `#` starts a
// comment; blank lines are skipped. The first row fixes the dimension. A file with no bytes but
// white space is an error; a header or comments with no rows is a valid empty set.
// Throws Error("<path>:<line>: <what>") on anything else: wrong column count, a non-number,
// NaN/Inf, r <= 0, more than kMaxElements rows, an unreadable file.
Elements read_elements_csv(const std::string& path);

// Parses the same format from memory; `where` names it in messages.
Elements parse_elements_csv(const std::string& text, const std::string& where);

// Writes header `i,j` and then the pairs sorted, one a line, atomically.
void write_pairs_csv(const std::string& path, const PairList& sorted_pairs);

}  // namespace nbscope
