#include "io/json_limits.hpp"

#include "core/error.hpp"
#include "io/excerpt.hpp"

namespace nbscope {

void check_json_limits(std::string_view text, const std::string& where, const char* kind, std::size_t max_values) {
  const std::size_t n = text.size();
  std::size_t line = 1;
  int depth = 0;
  std::size_t values = 1;  // the document; then one per comma and per array or object
  const auto at = [&](std::size_t l) { return where + ":" + std::to_string(l) + ": "; };
  const auto count = [&] {
    if (++values > max_values)
      throw Error(at(line) + "more than " + std::to_string(max_values) + " values (arrays, objects and their entries), the limit for " +
                  kind + "s");
  };
  for (std::size_t i = 0; i < n; ++i) {
    switch (text[i]) {
      case '\n':
        ++line;
        break;
      case ',':
        count();
        break;
      case '[':
      case '{':
        count();
        if (++depth > kMaxJsonDepth)
          throw Error(at(line) + "arrays and objects nested deeper than " + std::to_string(kMaxJsonDepth) +
                      " levels, the limit for " + kind + "s");
        break;
      case ']':
      case '}':
        if (depth > 0) --depth;
        break;
      case '"': {
        const std::size_t start = ++i, start_line = line;
        for (; i < n && text[i] != '"'; ++i) {
          if (text[i] == '\\') ++i;
          else if (text[i] == '\n') ++line;
        }
        const std::size_t length = std::min(i, n) - start;
        if (length > kMaxJsonKeyBytes) {
          std::size_t k = i + 1;
          while (k < n && (text[k] == ' ' || text[k] == '\t' || text[k] == '\r' || text[k] == '\n')) ++k;
          if (k < n && text[k] == ':')
            throw Error(at(start_line) + "a key of " + std::to_string(length) + " bytes \"" + excerpt(text.substr(start, length)) +
                        "\": keys of " + kind + "s are names of at most " + std::to_string(kMaxJsonKeyBytes) + " bytes");
        }
        break;
      }
      case '/':
        if (i + 1 < n && text[i + 1] == '/') {
          while (i + 1 < n && text[i + 1] != '\n') ++i;
        } else if (i + 1 < n && text[i + 1] == '*') {
          for (i += 2; i < n && !(text[i] == '*' && i + 1 < n && text[i + 1] == '/'); ++i)
            if (text[i] == '\n') ++line;
          ++i;
        }
        break;
      default:
        break;
    }
  }
}

std::string json_error_text(const std::string& full) {
  std::string what = full;
  if (const auto col = what.find("column "); col != std::string::npos) {
    if (const auto colon = what.find(": ", col); colon != std::string::npos) what = what.substr(colon + 2);
  } else if (const auto bracket = what.find("] "); bracket != std::string::npos) {
    what = what.substr(bracket + 2);
  }
  // A suffix such as "; expected end of input" follows the token's closing quote: keep it.
  if (const auto lr = what.find("; last read: '"); lr != std::string::npos) {
    const std::size_t begin = lr + 14;
    std::size_t end = what.find("'; ", begin);
    if (end == std::string::npos) end = what.size() - (what.back() == '\'' ? 1 : 0);
    std::string token = what.substr(begin, end - begin);
    const std::string rest = end + 1 < what.size() ? what.substr(end + 1) : "";
    // "0,<U+000A> N" -> "N": keep only the offending token.
    const auto cut = token.find_last_of(" \t,:[{>");
    if (cut != std::string::npos && cut + 1 < token.size()) token = token.substr(cut + 1);
    what = what.substr(0, lr) + "; last read: '" + excerpt(token) + "'" + rest;
  }
  // "number overflow parsing '1111...'" (a 20 MB number is quoted whole) -> a short excerpt.
  if (const auto ov = what.find("number overflow parsing '"); ov != std::string::npos) {
    const std::size_t begin = ov + 25;
    const std::size_t end = what.rfind('\'');
    what = "number out of range '" + excerpt(what.substr(begin, end > begin ? end - begin : std::string::npos)) + "' (not a finite double)";
  }
  return excerpt(what, 200);
}

}  // namespace nbscope
