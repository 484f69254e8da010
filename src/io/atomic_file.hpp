// nbscope io: output files written whole or not at all.
#pragma once
#include <functional>
#include <ostream>
#include <string>

namespace nbscope {

// Writes `path` by calling `fill` on a stream to a temporary file beside it, then renaming it into
// place. On any failure (including an exception from `fill`) the temporary is removed, `path` is
// left as it was, and Error("<path>: cannot write: <reason>") is thrown.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& fill);

// Refuses, before any work is done, a path that cannot be written: empty, a directory, or in a
// directory that does not exist. Throws Error("<path>: cannot write: <reason>").
void check_output_path(const std::string& path);

// Same, for bytes already in memory (PNG encoders hand over a buffer).
void write_bytes_atomically(const std::string& path, const void* data, std::size_t size);

}  // namespace nbscope
