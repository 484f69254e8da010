// nbscope io: what an error line may quote of a bad input — at most a short, escaped excerpt, so
// that a 20 MB field or a binary line never becomes a 20 MB or multi-line error.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace nbscope {

// How many bytes of the input an error message quotes at most.
inline constexpr std::size_t kExcerptBytes = 40;

// At most `max_bytes` bytes of `text` (cut at a UTF-8 character boundary), with control bytes and
// invalid UTF-8 escaped as \xNN (printable_line), and "..." appended when it was cut.
std::string excerpt(std::string_view text, std::size_t max_bytes = kExcerptBytes);

}  // namespace nbscope
