// nbscope io: ELEMENTS.csv in, PAIRS.csv out (formats in DESIGN.md "Command line").
#pragma once
#include <array>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "core/elements.hpp"
#include "core/pairs.hpp"

namespace nbscope {

// Reads `x,y,r` (2D) or `x,y,z,r` (3D) rows; one optional header line of names; `#` starts a
// comment; blank lines are skipped. The first row fixes the dimension. A file with no bytes but
// white space is an error; a header or comments with no rows is a valid empty set.
// Throws Error("<path>:<line>: <what>") on anything else: wrong column count, a non-number,
// NaN/Inf, r <= 0, more than kMaxElements rows, an unreadable file, a NUL byte, a line longer than
// kMaxLineBytes, a file larger than kMaxElementsBytes (io/input_file.hpp).
Elements read_elements_csv(const std::string& path);

// Parses the same format from memory; `where` names it in messages.
Elements parse_elements_csv(const std::string& text, const std::string& where);

// ---- the row parsing, shared with the recorded-frames reader (io/recording.hpp) ----

// Longest number field read: a double needs at most 24 characters; this leaves room for any fixed
// notation a code may print, and a 20 MB "number" is refused (and quoted as an excerpt) at once.
inline constexpr std::size_t kMaxNumberBytes = 128;

// Error "<where>:<line_no>: a line of N bytes '...'" for a line longer than kMaxLineBytes
// (io/input_file.hpp), for text parsed from memory as read_input_file checks it for files.
void check_line_length(std::string_view line, const std::string& where, std::size_t line_no);

// `line` without a `#` comment and surrounding white space.
std::string_view strip_comment(std::string_view line);
// The comma-separated fields of `line`, each trimmed.
std::vector<std::string_view> split_fields(std::string_view line);
// The words of `line` between runs of white space (and of commas, with `commas_too`).
std::vector<std::string_view> split_words(std::string_view line, bool commas_too = false);
// A finite double from `field`; Error(at + name + ": '...' is not a (finite) number") otherwise,
// also for a field longer than kMaxNumberBytes. Messages quote an excerpt (io/excerpt.hpp).
double parse_finite_number(std::string_view field, const std::string& at, const char* name);
// One element row of 3 (x,y,r) or 4 (x,y,z,r) fields into `out` (x, y, [z,] r); Error(at + what) for
// another column count, a non-number, NaN/Inf or r <= 0. `at` is "<where>:<line>: ".
void parse_element_row(const std::vector<std::string_view>& fields, const std::string& at, std::array<double, 4>& out);

// Writes header `i,j` and then the pairs sorted, one a line, atomically.
void write_pairs_csv(const std::string& path, const PairList& sorted_pairs);
// The same to a stream (e.g. std::cout), in chunks.
void write_pairs_csv(std::ostream& out, const PairList& sorted_pairs);

}  // namespace nbscope
