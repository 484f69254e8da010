#include "io/lammps_dump_parse.hpp"

#include <charconv>
#include <cmath>
#include <cstring>

#include "io/excerpt.hpp"

namespace nbscope::dump {

void Digits::add(std::string_view word, double value) {
  const char* b = word.data();
  const char* e = b + word.size();
  for (const char* q = e - 1; q >= b && q + 6 >= e; --q)  // an exponent is in the last few characters
    if (*q == 'e' || *q == 'E') {
      e = q;
      break;
    }
  if (b < e && (*b == '-' || *b == '+')) ++b;
  while (b < e && (*b == '0' || *b == '.')) ++b;  // leading zeros are no significant digits
  const auto count = static_cast<int>(e - b) - (std::memchr(b, '.', static_cast<std::size_t>(e - b)) != nullptr ? 1 : 0);
  significant = std::max(significant, count);
  largest = std::max(largest, std::abs(value));
}

double Digits::half_unit(int digits) const {
  digits = std::max(digits, significant);
  if (largest == 0 || digits == 0) return 0;
  const int lead = static_cast<int>(std::floor(std::log10(largest)));
  return 0.5 * std::pow(10.0, lead - digits + 1);
}

std::string_view item_of(std::string_view line) {
  if (line.rfind("ITEM:", 0) != 0) return {};
  line.remove_prefix(5);
  while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
  while (!line.empty() && (line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
  return line.empty() ? std::string_view("", 0) : line;
}

std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> out;
  const char* p = line.data();
  std::string_view w;
  while (next_word(p, line.data() + line.size(), w)) out.push_back(w);
  return out;
}

std::int64_t parse_integer(std::string_view word, const std::string& at, const char* what, bool allow_float) {
  std::int64_t v = 0;
  const char* end = word.data() + word.size();
  auto [ptr, ec] = std::from_chars(word.data() + (word.size() > 1 && word[0] == '+' ? 1 : 0), end, v);
  if (ec == std::errc() && ptr == end) return v;
  const std::string quoted = "'" + excerpt(word) + "'";
  if (ec == std::errc::result_out_of_range) throw Error(at + what + ": " + quoted + " is too large");
  if (allow_float && word.find_first_of("eE") != std::string_view::npos && word.find_first_of("0123456789") != std::string_view::npos)
    throw Error(at + what + ": " + quoted + " is written with an exponent, so digits may be lost (LAMMPS's %g): give the "
                "ids a %d or %.0f format (dump_modify format)");
  double d = 0;
  if (allow_float) {
    auto [dptr, dec] = std::from_chars(word.data(), end, d);
    if (dec == std::errc() && dptr == end && std::isfinite(d) && d == std::floor(d) && std::abs(d) <= 9.0e15)
      return static_cast<std::int64_t>(d);
  }
  throw Error(at + what + ": " + quoted + " is not an integer");
}

std::int64_t integer_line(DumpText& text, const char* item) {
  std::string_view line;
  if (!text.next(line)) throw Error(text.at() + "the file ends after ITEM: " + item + " (its value is missing)");
  const char* p = line.data();
  std::string_view w;
  if (!next_word(p, line.data() + line.size(), w)) throw Error(text.at() + "an empty line where ITEM: " + item + "'s value should be");
  const std::int64_t v = parse_integer(w, text.at(), item, false);
  if (next_word(p, line.data() + line.size(), w)) throw Error(text.at() + item + ": one integer expected, got '" + excerpt(line) + "'");
  return v;
}

void expect_indexed_timestep(const std::string& where, std::int64_t got, std::int64_t wanted) {
  if (got != wanted)
    throw Error(where + ": timestep " + std::to_string(got) + " where timestep " + std::to_string(wanted) +
                " was (the file changed since it was read?)");
}

void read_box(DumpText& text, std::string_view rest, DumpBox& box, Digits& digits) {
  const std::vector<std::string_view> words = words_of(rest);
  for (std::string_view w : words)
    if (w == "xy" || w == "xz" || w == "yz")
      throw Error(text.at() + "a triclinic box (BOX BOUNDS xy xz yz): nbscope reads orthogonal boxes only");
  // Flags are two letters from p f s m each; LIGGGHTS may add words after them (units): skipped.
  std::size_t axis = 0;
  for (std::string_view w : words) {
    if (axis == 3) break;
    if (w.size() == 2 && w.find_first_not_of("pfsm") == std::string_view::npos) box.flags[axis++] = std::string(w);
  }
  for (; axis < 3; ++axis) box.flags[axis] = "ff";  // an old dump without flags: a fixed box
  for (int a = 0; a < 3; ++a) {
    std::string_view line;
    if (!text.next(line)) throw Error(text.at() + "the file ends inside ITEM: BOX BOUNDS (3 lines of lo hi expected)");
    const char* p = line.data();
    const char* end = line.data() + line.size();
    double v[2] = {0, 0};
    for (double& x : v) {
      std::string_view w;
      if (!next_word(p, end, w)) throw Error(text.at() + "BOX BOUNDS: 'lo hi' expected, got '" + excerpt(line) + "'");
      auto [ptr, ec] = std::from_chars(w.data(), w.data() + w.size(), x);
      if (ec != std::errc() || ptr != w.data() + w.size() || !std::isfinite(x))
        throw Error(text.at() + "BOX BOUNDS: '" + excerpt(w) + "' is not a finite number");
      digits.add(w, x);
    }
    if (!(v[0] <= v[1])) throw Error(text.at() + "BOX BOUNDS: lo " + std::to_string(v[0]) + " is above hi " + std::to_string(v[1]));
    box.lo[a] = v[0];
    box.hi[a] = v[1];
  }
}

}  // namespace nbscope::dump
