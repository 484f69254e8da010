// nbscope io: reading an input file whole, with a size limit, for every text format.
#pragma once
#include <cstddef>
#include <string>

namespace nbscope {

// Default limits per format: generous for real data, small enough that /dev/zero or a runaway
// pipe stops with an error instead of taking the machine's memory. No flag raises them.
inline constexpr std::size_t kMaxSceneBytes = std::size_t{256} << 20;      // generators keep scenes small
inline constexpr std::size_t kMaxElementsBytes = std::size_t{2} << 30;     // ~50 million x,y,r rows
inline constexpr std::size_t kMaxRecordingBytes = std::size_t{2} << 30;
// Longest line of the line-based formats (ELEMENTS.csv, PAIRS.csv, .nbsrec, the scaling CSV): a
// row is a few numbers, so a longer line is not one of theirs, and an endless line (a pipe that
// never sends a newline) is refused after this many bytes instead of after the size limit.
inline constexpr std::size_t kMaxLineBytes = std::size_t{64} << 10;

// The contents of `path`, a `kind` of file ("scene file", "elements file", ...). Throws Error
// "<path>: <what>" for an empty path, a directory, a file that cannot be opened or read, or more
// than `max_bytes` bytes (the read stops there: a device or pipe that never ends is refused too);
// Error "<path>:<line>: <what>" for a NUL byte (binary data or UTF-16: every format is text; seen
// in the first chunk read, so /dev/zero stops at once) and, when `max_line_bytes` is not 0, for a
// line longer than that (seen as soon as that many bytes without a newline have been read).
std::string read_input_file(const std::string& path, const char* kind, std::size_t max_bytes, std::size_t max_line_bytes = 0);

}  // namespace nbscope
