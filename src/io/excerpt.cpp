#include "io/excerpt.hpp"

#include "core/error.hpp"

namespace nbscope {

std::string excerpt(std::string_view text, std::size_t max_bytes) {
  if (text.size() <= max_bytes) return printable_line(text);
  std::size_t cut = max_bytes >= 3 ? max_bytes - 3 : 0;
  // Back off to the start of a UTF-8 character (at most 3 continuation bytes), so that an accented
  // name is not cut into an escaped half.
  for (int k = 0; k < 3 && cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80; ++k) --cut;
  return printable_line(text.substr(0, cut)) + "...";
}

}  // namespace nbscope
