// nbscope io: ELEMENTS.csv in, PAIRS.csv out (formats in docs/formats.md).
#pragma once
#include <array>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "core/elements.hpp"
#include "core/pairs.hpp"
#include "io/input_file.hpp"

namespace nbscope {

// Reads `x,y,r` (2D) or `x,y,z,r` (3D) rows; one optional header line of names; `#` starts a
// comment; blank lines are skipped. The first row fixes the dimension. A file with no bytes but
// white space is an error; a header or comments with no rows is a valid empty set.
// Throws Error("<path>:<line>: <what>") on anything else: wrong column count, a non-number,
// NaN/Inf, r <= 0, more than `max_elements` rows, an unreadable file, a NUL byte, a line longer than
// kMaxLineBytes, a file larger than `max_bytes` (io/input_file.hpp). The rows are parsed as the
// file's lines arrive: a limit passed stops the read at that line, having held the rows before it.
Elements read_elements_csv(const std::string& path, std::int64_t max_elements = kMaxElements,
                           std::size_t max_bytes = kMaxElementsBytes);

// Parses the same format from memory; `where` names it in messages.
Elements parse_elements_csv(const std::string& text, const std::string& where, std::int64_t max_elements = kMaxElements);

// ---- the row parsing, shared with the recorded-frames reader (io/recording.hpp) ----

// Columns of an element set as its rows arrive (x, y, [z,] r: `count` of them). They grow by
// doubling through Eigen's realloc, which moves a large block by remapping its pages, so N rows
// hold their own bytes and not two or three times that (a vector's copy into an Eigen array).
class ElementColumns {
 public:
  explicit ElementColumns(int count);
  // Appends the first `count` values of `row`.
  void push(const std::array<double, 4>& row);
  [[nodiscard]] std::int64_t size() const { return size_; }
  // Column `c`, cut to size() and moved out (once per column).
  Eigen::ArrayXd take(int c);
  // No rows, no memory.
  void clear();

 private:
  int count_;
  Eigen::Index size_ = 0;
  Eigen::Index capacity_ = 0;
  Eigen::ArrayXd cols_[4];
};

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

// An ordinary row (3 or 4 numbers within the supported magnitudes, nothing else: `count` of them
// into `out`) parsed without building a message or a list of fields; false for anything else, which
// parse_element_row then reads or refuses with its message. Most rows of a large file take this path.
bool parse_plain_row(std::string_view line, int& count, std::array<double, 4>& out);

// Writes header `i,j` and then the pairs sorted, one a line, atomically; with `ids` (a dump's row ->
// atom id, ascending), header `id1,id2` and each element as its id.
void write_pairs_csv(const std::string& path, const PairList& sorted_pairs, const std::vector<std::int64_t>& ids = {});
// The same to a stream (e.g. std::cout), in chunks.
void write_pairs_csv(std::ostream& out, const PairList& sorted_pairs, const std::vector<std::int64_t>& ids = {});

}  // namespace nbscope
