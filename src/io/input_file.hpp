// nbscope io: reading an input file whole, with a size limit, for every text format.
#pragma once
#include <cstddef>
#include <string>

namespace nbscope {

// Default limits per format: generous for real data, small enough that /dev/zero or a runaway
// pipe stops with an error instead of taking the machine's memory.
inline constexpr std::size_t kMaxSceneBytes = std::size_t{256} << 20;      // generators keep scenes small
inline constexpr std::size_t kMaxElementsBytes = std::size_t{2} << 30;     // ~50 million x,y,r rows
inline constexpr std::size_t kMaxRecordingBytes = std::size_t{2} << 30;

// The contents of `path`, a `kind` of file ("scene file", "elements file", ...). Throws Error
// "<path>: <what>" for an empty path, a directory, a file that cannot be opened or read, or more
// than `max_bytes` bytes (the read stops there: a device or pipe that never ends is refused too).
std::string read_input_file(const std::string& path, const char* kind, std::size_t max_bytes);

}  // namespace nbscope
