// nbscope io: counts in text. Every count the user reads (panels, headless/CLI output, status
// lines) goes through plural(), so that "1 violation" and "2 violations" always agree in number.
#pragma once
#include <string>
#include <string_view>

namespace nbscope {

// The word for `n` things: `one` when n is 1 (or -1), else `many` (default: `one` + "s").
inline std::string plural_word(long long n, std::string_view one, std::string_view many = {}) {
  if (n == 1 || n == -1) return std::string(one);
  return many.empty() ? std::string(one) + "s" : std::string(many);
}

// "1 violation", "0 violations", "2 bodies" (plural(2, "body", "bodies")).
inline std::string plural(long long n, std::string_view one, std::string_view many = {}) {
  return std::to_string(n) + " " + plural_word(n, one, many);
}

}  // namespace nbscope
